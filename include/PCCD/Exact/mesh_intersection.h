// PCCD/Exact/mesh_intersection.h -- the exact reference for two posed triangle meshes
// (doc/design.md, "Exact checks"): whether their surfaces intersect, whether one lies inside the
// other without surface contact, and the intersection curves as polylines. It is the truth against
// which the stochastic intersection tests of doc/algorithms.md, "Randomized sampling" and
// "Interpolation search", are validated on the poses of its "Benchmark procedure".
//
// Surface intersection is what the point-cloud methods detect (a sign change of the implicit
// functions along a surface), so exact_do_intersect answers "do the surfaces touch or cross"; a
// mesh nested inside the other without contact is *not* an intersection here and is reported apart
// by exact_containment.
//
// Includes CGAL's Polygon_mesh_processing (through Exact_mesh.h): keep it out of the core headers.
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

#include <CGAL/Polygon_mesh_processing/intersection.h>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// How two posed meshes whose surfaces do not intersect are nested (see exact_containment).
enum class Containment {
    /// No volume of one contains any part of the other (or the surfaces intersect).
    none,
    /// Every connected component of the first mesh lies inside the volume of the second.
    first_inside_second,
    /// Every connected component of the second mesh lies inside the volume of the first.
    second_inside_first,
    /// Some but not all components of one mesh lie inside the other (multi-component meshes only).
    partial
};

namespace internal {

/// Two posed meshes seen from the frame of one of them: `moved_points` are the vertices of `moved`
/// mapped into the local frame of `fixed`. The mesh with fewer triangles is the moved one, since a
/// query costs one tree descent per moved triangle or vertex.
struct Exact_pair_view {
    const Exact_mesh& fixed;
    const Exact_mesh& moved;
    /// Whether `fixed` is the first mesh of the call.
    bool first_is_fixed;
    /// The relative motion from the local frame of `moved` to that of `fixed`.
    Rigid_transform_3<double> moved_to_fixed;
    std::vector<Exact_mesh::Point_3> moved_points;

    Exact_pair_view(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a, const Exact_mesh& b,
                    const Rigid_transform_3<double>& pose_b)
        : fixed(b.number_of_triangles() <= a.number_of_triangles() ? a : b),
          moved(b.number_of_triangles() <= a.number_of_triangles() ? b : a),
          first_is_fixed(b.number_of_triangles() <= a.number_of_triangles()),
          moved_to_fixed(first_is_fixed ? pose_a.inverse() * pose_b : pose_b.inverse() * pose_a),
          moved_points(moved.transformed_points(moved_to_fixed))
    {
    }
};

/// Whether a triangle of the moved mesh intersects a triangle of the fixed one (exact predicates on
/// the rounded moved coordinates). Stops at the first intersecting triangle.
inline bool some_triangles_intersect(const Exact_pair_view& view)
{
    const CGAL::Bbox_3 fixed_box = view.fixed.tree().bbox();
    for (const Exact_mesh::Face_index f : faces(view.moved.mesh())) {
        const Exact_mesh::Triangle_3 t = view.moved.triangle(f, view.moved_points);
        if (!CGAL::do_overlap(t.bbox(), fixed_box)) continue;
        if (view.fixed.tree().do_intersect(t)) return true;
    }
    return false;
}

/// The containment of two meshes whose surfaces are known not to intersect: since a connected
/// closed surface that does not cross another lies entirely on one side of it, one vertex per
/// component decides. \pre both meshes enclose a volume.
inline Containment containment_without_contact(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a,
                                               const Exact_mesh& b, const Rigid_transform_3<double>& pose_b)
{
    const auto count_inside = [](const Exact_mesh& inner, const Exact_mesh& outer,
                                 const Rigid_transform_3<double>& inner_to_outer) {
        std::size_t inside = 0;
        for (const Exact_mesh::Vertex_index v : inner.component_representatives()) {
            const Exact_mesh::Point_3& p = inner.mesh().point(v);
            const Eigen::Vector3d q = inner_to_outer.transform_point(Eigen::Vector3d(p.x(), p.y(), p.z()));
            if (outer.bounded_side(Exact_mesh::Point_3(q.x(), q.y(), q.z())) == CGAL::ON_BOUNDED_SIDE) ++inside;
        }
        return inside;
    };
    const std::size_t b_in_a = count_inside(b, a, pose_a.inverse() * pose_b);
    if (b_in_a == b.component_representatives().size()) return Containment::second_inside_first;
    const std::size_t a_in_b = count_inside(a, b, pose_b.inverse() * pose_a);
    if (a_in_b == a.component_representatives().size()) return Containment::first_inside_second;
    return b_in_a + a_in_b > 0 ? Containment::partial : Containment::none;
}

inline void require_volume(const Exact_mesh& mesh, const char* which, const char* function)
{
    if (!mesh.encloses_volume())
        throw Invalid_input(concat(function, ": the ", which, " mesh does not enclose a volume (",
                                   mesh.is_closed() ? "it self-intersects" : "it is not closed", ")"));
}

} // namespace internal

/// \name Exact reference for posed triangle meshes
/// @{

/// Whether the surface of `a` placed by `pose_a` intersects (touches or crosses) the surface of `b`
/// placed by `pose_b`: some pair of triangles, one of each, has a common point.
///
/// Exact for the rounded coordinates: the vertices of the mesh with fewer triangles are mapped into
/// the local frame of the other (see Exact_mesh for the rounding, ~1e-15 on normalized objects) and
/// every triangle pair is decided with CGAL's exact triangle-triangle predicate, found through the
/// other mesh's AABB tree. Containment without surface contact returns false (see
/// exact_containment). `a` and `b` may be the same object.
///
/// Complexity: O(n) to map the vertices plus one tree descent per triangle whose box meets the
/// other mesh's box, stopping at the first intersection; no tree is rebuilt. Thread-safe.
inline bool exact_do_intersect(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a, const Exact_mesh& b,
                               const Rigid_transform_3<double>& pose_b)
{
    return internal::some_triangles_intersect(internal::Exact_pair_view(a, pose_a, b, pose_b));
}

/// How the posed meshes are nested when their surfaces do not intersect: Containment::none when the
/// surfaces intersect or neither volume holds any part of the other, else which one is inside.
/// Exact (ray parity with exact predicates, after the rounding described in Exact_mesh).
/// \pre both meshes enclose a volume (closed, no self-intersection); else throws Invalid_input.
/// Complexity: that of exact_do_intersect plus one inside test per connected component. Thread-safe.
inline Containment exact_containment(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a, const Exact_mesh& b,
                                     const Rigid_transform_3<double>& pose_b)
{
    internal::require_volume(a, "first", "exact_containment");
    internal::require_volume(b, "second", "exact_containment");
    if (exact_do_intersect(a, pose_a, b, pose_b)) return Containment::none;
    return internal::containment_without_contact(a, pose_a, b, pose_b);
}

/// The intersection curves of the two posed surfaces, in world coordinates, as polylines: each a
/// sequence of points in which consecutive points are joined by a segment; a closed curve repeats
/// its first point at its end. Empty when the surfaces do not intersect.
///
/// Computed by CGAL::Polygon_mesh_processing::surface_intersection in the local frame of `a` (with
/// `b`'s vertices mapped and rounded as in Exact_mesh), which builds the intersection points with
/// exact constructions and connects them exactly; the points are then rounded to double and mapped
/// to world coordinates by `pose_a` (another rounding of a few ulps). Where the surfaces overlap in
/// a coplanar region, its boundary and the edges crossing it are reported.
///
/// \pre neither mesh self-intersects (CGAL's precondition); else throws Invalid_input.
/// Complexity: O((n + m) log(n + m) + k) for n and m triangles and k intersection points; copies
/// `b`'s mesh once. Thread-safe.
inline std::vector<std::vector<Eigen::Vector3d>> exact_intersection_polylines(const Exact_mesh& a,
                                                                           const Rigid_transform_3<double>& pose_a,
                                                                           const Exact_mesh& b,
                                                                           const Rigid_transform_3<double>& pose_b)
{
    if (a.is_self_intersecting())
        throw Invalid_input("exact_intersection_polylines: the first mesh self-intersects");
    if (b.is_self_intersecting())
        throw Invalid_input("exact_intersection_polylines: the second mesh self-intersects");
    // A separate copy even when b is a: CGAL treats the same object twice as self-intersection.
    Exact_mesh::Triangle_mesh b_in_a = b.mesh();
    const std::vector<Exact_mesh::Point_3> points = b.transformed_points(pose_a.inverse() * pose_b);
    for (const Exact_mesh::Vertex_index v : vertices(b_in_a)) b_in_a.point(v) = points[v];

    std::vector<std::vector<Exact_mesh::Point_3>> local;
    CGAL::Polygon_mesh_processing::surface_intersection(a.mesh(), b_in_a, std::back_inserter(local));

    std::vector<std::vector<Eigen::Vector3d>> polylines;
    polylines.reserve(local.size());
    for (const auto& line : local) {
        std::vector<Eigen::Vector3d>& out = polylines.emplace_back();
        out.reserve(line.size());
        for (const Exact_mesh::Point_3& p : line) out.push_back(pose_a.transform_point(Eigen::Vector3d(p.x(), p.y(), p.z())));
    }
    return polylines;
}

/// @}

} // namespace PCCD
