// PCCD/concepts/KineticPrimitive.h -- concept of the primitives a kinetic AABB tree is built over
// (doc/algorithms.md, "Kinetic AABB tree"): a fixed number of vertex indices whose flightplans
// bound the primitive.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>

namespace PCCD {

/// \concept KineticPrimitive
/// A primitive of a kinetic bounding volume hierarchy, seen only through its vertices: at time t
/// its bounding box is the box of its vertices' positions (the vertices' flightplans are stored by
/// the tree, indexed by vertex).
///
/// Requirements, for `const P& p` and `std::size_t i`:
/// - `P` is copyable and default constructible;
/// - `P::vertex_count` is a `std::size_t` constant >= 1 (the number of vertices, fixed per type);
/// - `p.vertex(i)` for i < P::vertex_count returns the index of the i-th vertex, convertible to
///   `std::uint32_t`.
///
/// Models shipped by PCCD (PCCD/Kinetic/Kinetic_primitives.h): Kinetic_point (a point of a cloud,
/// one vertex) and Kinetic_triangle (a triangle of a polygon soup, three vertices; ray casting is
/// offered for this model). Two primitives are *adjacent* when they share a vertex index; the
/// self-overlap query skips adjacent pairs.
template <class P>
concept KineticPrimitive = std::copyable<P> && std::default_initializable<P> && requires(const P& p, std::size_t i) {
    { P::vertex_count } -> std::convertible_to<std::size_t>;
    requires P::vertex_count >= 1;
    { p.vertex(i) } -> std::convertible_to<std::uint32_t>;
};

} // namespace PCCD
