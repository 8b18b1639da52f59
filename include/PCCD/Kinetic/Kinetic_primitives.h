// PCCD/Kinetic/Kinetic_primitives.h -- the KineticPrimitive models PCCD ships: a point of a
// deforming point cloud and a triangle of a deforming polygon soup (doc/algorithms.md, "Kinetic AABB tree": "any
// static AABB tree ... over the primitives (points, triangles, ...)").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace PCCD {

/// One point of a cloud, given by its vertex index. Models KineticPrimitive.
struct Kinetic_point {
    static constexpr std::size_t vertex_count = 1;
    std::uint32_t index = 0;

    std::uint32_t vertex(std::size_t) const { return index; }
    friend bool operator==(const Kinetic_point&, const Kinetic_point&) = default;
};

/// One triangle of a polygon soup, given by its three vertex indices (any orientation).
/// Models KineticPrimitive; the trees offer ray casting for this primitive.
struct Kinetic_triangle {
    static constexpr std::size_t vertex_count = 3;
    std::array<std::uint32_t, 3> indices{0, 0, 0};

    std::uint32_t vertex(std::size_t i) const { return indices[i]; }
    friend bool operator==(const Kinetic_triangle&, const Kinetic_triangle&) = default;
};

} // namespace PCCD
