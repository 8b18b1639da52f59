// PCCD/Exact/mesh_distance.h -- the exact reference for the proximity queries on two posed triangle
// meshes (doc/design.md, "Exact checks"; the truth behind the distance and penetration figures of
// the validation, on the poses of doc/algorithms.md, "Benchmark procedure"): exact_distance, the
// minimum distance between the two surfaces with the two closest points, and exact_max_depth, the
// largest local depth of each surface inside the other's volume with its witnesses and the contact
// normal, over the vertices and area samples of the triangles (an adaptive midpoint subdivision),
// within a stated sampling error. Both reuse the trees of Exact_mesh and the searches of mesh_separation.h.
//
// Includes CGAL's Polygon_mesh_processing (through Exact_mesh.h): keep it out of the core headers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_intersection.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// The result of exact_distance. Points in world coordinates.
struct Exact_distance {
    /// Whether the surfaces intersect (exactly as exact_do_intersect).
    bool surfaces_intersect = false;
    /// The minimum distance between the two surfaces; 0 when they intersect. For surfaces that do
    /// not meet it is > 0, nested ones included (then it is the gap between the inner and the
    /// outer surface).
    double distance = 0.0;
    /// Surfaces apart: a point of surface A and a point of surface B at distance `distance`
    /// (|point_a - point_b| == distance up to rounding). NaN when the surfaces intersect.
    Eigen::Vector3d point_a = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    Eigen::Vector3d point_b = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// The result of exact_max_depth. Points and normals in world coordinates.
///
/// Sign convention of the normals, on a 1D example: A = [-5, 1], B = [0, 10] (B's surface is
/// {0, 10}, A's is {-5, 1}). The point x = 1 of A lies inside B at depth 1, its closest point on B
/// is y = 0; B leaves A by moving +1, and normal_a = unit(deepest_a - closest_b) = unit(1 - 0) =
/// +1. The point x = 0 of B lies inside A at depth 1, its closest point on A is y = 1; B again
/// leaves A by moving +1 (from its deep point toward A's surface), and normal_b =
/// unit(closest_a - deepest_b) = unit(1 - 0) = +1. Both normals are the direction in which B must
/// move to undo that local penetration, and moving B by depth along it does so locally.
struct Exact_depth {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// Whether the surfaces intersect (exactly as exact_do_intersect).
    bool surfaces_intersect = false;
    /// The spacing of the area samples the depths were computed with (the error bound).
    double sample_spacing = nan;
    /// The largest distance to surface B of a sampled point of surface A lying strictly inside B's
    /// volume; 0 when no sample of A is inside B.
    double depth_a = 0.0;
    /// The sample of A realizing depth_a and its closest point on surface B; NaN when depth_a is 0.
    Eigen::Vector3d deepest_a = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d closest_b = Eigen::Vector3d::Constant(nan);
    /// unit(deepest_a - closest_b): the direction in which B must move to leave A there. NaN when
    /// depth_a is 0.
    Eigen::Vector3d normal_a = Eigen::Vector3d::Constant(nan);
    /// The same with the roles swapped: the largest distance to surface A of a sampled point of
    /// surface B strictly inside A's volume, that point, its closest point on A, and
    /// normal_b = unit(closest_a - deepest_b), again the direction in which B must move to leave A.
    double depth_b = 0.0;
    Eigen::Vector3d deepest_b = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d closest_a = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d normal_b = Eigen::Vector3d::Constant(nan);
    /// max(depth_a, depth_b), and the normal of that side (normal_a on a tie); NaN when depth is 0.
    double depth = 0.0;
    Eigen::Vector3d contact_normal = Eigen::Vector3d::Constant(nan);
};

namespace internal {

inline Eigen::Vector3d to_vector(const Exact_mesh::Point_3& p) { return {p.x(), p.y(), p.z()}; }

/// The deepest sample of a source surface inside a target volume (target frame).
struct Deepest_sample {
    double depth = 0.0;
    Exact_mesh::Point_3 deepest;
    Exact_mesh::Point_3 closest;
};

/// The largest distance to `target`'s surface of a sample of `source`'s surface (vertices mapped
/// to `source_points` in the target's frame) lying strictly inside the target's volume. The
/// samples: the vertices of each triangle, then the vertices and centroids of its midpoint
/// subdivision (each step splits a triangle into four by its edge midpoints) down to pieces whose
/// edges are at most `spacing`, so every point of the surface lies within `spacing` of a sample of
/// its piece. The subdivision is a branch and bound that only descends where a point can beat the
/// best depth found.
///
/// Pruning, all of it safe: a point of a triangle is within max(|v - u|, |v - w|) of its vertex v,
/// and both are edges incident to v. Each triangle is owned by its vertex of smallest index, so all
/// the points of the triangles owned by the vertices of a node of the source's vertex ball tree lie
/// within radius + (longest incident edge) of the node's centre: their distance to the target's
/// surface is at most (centre distance) + radius + edge (best-first by that bound, stopping when
/// it cannot beat the best depth), a node whose enlarged ball misses the target's box is outside
/// the volume, and a node whose enlarged ball does not reach the target's surface lies on its
/// centre's side (one exact inside test for the whole node). A piece of a triangle is likewise
/// skipped when its centroid distance plus its centroid radius cannot beat the best depth, and
/// decided by one inside test when its centroid ball does not reach the surface; only samples that
/// beat the best depth in pieces straddling the surface take an inside test each.
inline Deepest_sample max_sampled_depth(const Exact_mesh& source, const std::vector<Exact_mesh::Point_3>& source_points,
                                        const Rigid_transform_3<double>& source_to_target, const Exact_mesh& target,
                                        double spacing)
{
    struct Item {
        Ball_view view;
        bool all_inside;
    };
    const Exact_mesh::Triangle_mesh& mesh = source.mesh();
    const auto& balls = source.vertex_ball_tree();
    const CGAL::Bbox_3 box = target.tree().bbox();
    const auto reach = [&](std::size_t node) { return balls[node].radius + balls[node].longest_incident_edge; };
    const auto upper = [&](const Item& x) { return x.view.distance + reach(x.view.node); };
    const auto later = [&](const Item& x, const Item& y) { return upper(x) < upper(y); };
    std::priority_queue<Item, std::vector<Item>, decltype(later)> queue(later);
    const auto push = [&](std::size_t node, bool all_inside, const Exact_mesh::Point_3* hint) {
        const Exact_mesh::Point_3 centre = ball_centre(source, node, source_to_target);
        const double r = reach(node);
        if (!all_inside && squared_distance_to_box(centre, box) > r * r) return;
        const Ball_view view = view_ball(node, centre, target, hint);
        if (!all_inside && view.distance > r) {
            if (target.bounded_side(centre) != CGAL::ON_BOUNDED_SIDE) return;
            all_inside = true;
        }
        queue.push({view, all_inside});
    };

    Deepest_sample best;
    const auto consider = [&](const Eigen::Vector3d& x, const Exact_mesh::Point_3& hint, bool all_inside) {
        const Exact_mesh::Point_3 p(x.x(), x.y(), x.z());
        const Exact_mesh::Point_3 closest = target.tree().closest_point(p, hint);
        const double d = std::sqrt(CGAL::squared_distance(p, closest));
        if (d > best.depth && (all_inside || target.bounded_side(p) == CGAL::ON_BOUNDED_SIDE)) best = {d, p, closest};
    };
    // The piece (p0, p1, p2) of a triangle whose vertices have been considered already.
    const auto refine = [&](const auto& self, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Exact_mesh::Point_3& hint, bool all_inside) -> void {
        const Eigen::Vector3d c = (p0 + p1 + p2) / 3.0;
        const double radius = std::max({(p0 - c).norm(), (p1 - c).norm(), (p2 - c).norm()}) * (1.0 + 1e-12);
        const Exact_mesh::Point_3 centroid(c.x(), c.y(), c.z());
        const Exact_mesh::Point_3 closest = target.tree().closest_point(centroid, hint);
        const double centroid_distance = std::sqrt(CGAL::squared_distance(centroid, closest));
        if (centroid_distance + radius <= best.depth) return;
        if (!all_inside && centroid_distance > radius) {
            if (target.bounded_side(centroid) != CGAL::ON_BOUNDED_SIDE) return;
            all_inside = true;
        }
        if (centroid_distance > best.depth && (all_inside || target.bounded_side(centroid) == CGAL::ON_BOUNDED_SIDE))
            best = {centroid_distance, centroid, closest};
        const double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
        if (longest <= spacing) return;
        const Eigen::Vector3d m01 = (p0 + p1) / 2.0, m12 = (p1 + p2) / 2.0, m20 = (p2 + p0) / 2.0;
        for (const Eigen::Vector3d& m : {m01, m12, m20}) consider(m, closest, all_inside);
        self(self, p0, m01, m20, closest, all_inside);
        self(self, m01, p1, m12, closest, all_inside);
        self(self, m20, m12, p2, closest, all_inside);
        self(self, m01, m12, m20, closest, all_inside);
    };
    const auto sample_triangle = [&](Exact_mesh::Face_index f, const Item& item) {
        const auto h = mesh.halfedge(f);
        const Eigen::Vector3d p0 = to_vector(source_points[mesh.source(h)]);
        const Eigen::Vector3d p1 = to_vector(source_points[mesh.target(h)]);
        const Eigen::Vector3d p2 = to_vector(source_points[mesh.target(mesh.next(h))]);
        for (const Eigen::Vector3d& p : {p0, p1, p2}) consider(p, item.view.closest, item.all_inside);
        refine(refine, p0, p1, p2, item.view.closest, item.all_inside);
    };

    push(0, false, nullptr);
    while (!queue.empty()) {
        const Item item = queue.top();
        queue.pop();
        if (upper(item) <= best.depth) break;
        const Exact_mesh::Vertex_ball& ball = balls[item.view.node];
        if (!ball.is_leaf()) {
            for (const std::size_t child : ball.children) push(child, item.all_inside, &item.view.closest);
            continue;
        }
        for (std::size_t i = ball.begin; i < ball.end; ++i) {
            const Exact_mesh::Vertex_index v = source.ball_tree_vertices()[i];
            for (const Exact_mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
                if (f == Exact_mesh::Triangle_mesh::null_face()) continue;
                const auto h = mesh.halfedge(f);
                const Exact_mesh::Vertex_index owner =
                    std::min({mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))});
                if (owner == v) sample_triangle(f, item);
            }
        }
    }
    return best;
}

inline void check_sample_spacing(double spacing, const Exact_mesh& a, const Exact_mesh& b)
{
    if (!(std::isfinite(spacing) && spacing > 0.0))
        throw Invalid_input(concat("exact_max_depth: sample spacing ", spacing, " must be finite and > 0"));
    const double longest = std::max(a.longest_edge_length(), b.longest_edge_length());
    if (spacing < 1e-6 * longest)
        throw Invalid_input(concat("exact_max_depth: sample spacing ", spacing, " is below 1e-6 times the longest edge (",
                                   longest, "): a triangle would need more than 20 halvings"));
}

} // namespace internal

/// \name Distance and penetration depth of posed meshes
/// @{

/// The minimum distance between the surface of `a` placed by `pose_a` and that of `b` placed by
/// `pose_b`, with the two closest points (doc/manual/exact.md, "Distance and depth").
///
/// What is computed: `surfaces_intersect` exactly as exact_do_intersect; when it is false, the
/// minimum over all vertex-triangle pairs (each mesh's vertices against the other's triangles) and
/// all edge-edge pairs, which is the distance between two disjoint triangle meshes. The search is
/// that of exact_separation, exhaustive up to pruning that provably cannot drop the minimum:
/// closest-point queries on the AABB trees for the vertices (a ball of the vertex ball tree is
/// skipped only when all its vertices are farther than the best distance plus their longest edge),
/// then segment-segment distances between all the edges both of whose endpoints are within the
/// best vertex distance plus the edge's length of the other surface. An edge with a point closer
/// than the best vertex distance has both endpoints that close plus its length (the distance to a
/// surface is 1-Lipschitz), so no edge pair that can be the minimum is left out. Distances are
/// computed in double (CGAL's Epick constructions): a few ulps of the coordinates, not certified.
/// The witnesses are the vertex and its closest point on the other triangle, or the closest points
/// of the two edges, mapped to world coordinates (another rounding of a few ulps).
///
/// Meshes that are not closed are accepted (the distance between surfaces needs no volume).
/// Complexity: as exact_separation for separated poses, plus the intersection test. Thread-safe.
inline Exact_distance exact_distance(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a, const Exact_mesh& b,
                                     const Rigid_transform_3<double>& pose_b)
{
    const internal::Exact_pair_view view(a, pose_a, b, pose_b);
    Exact_distance result;
    result.surfaces_intersect = internal::some_triangles_intersect(view);
    if (result.surfaces_intersect) return result;
    const internal::Closest_pair gap = internal::surface_gap(view);
    const Rigid_transform_3<double>& fixed_pose = view.first_is_fixed ? pose_a : pose_b;
    const Eigen::Vector3d on_moved = fixed_pose.transform_point(internal::to_vector(gap.on_source));
    const Eigen::Vector3d on_fixed = fixed_pose.transform_point(internal::to_vector(gap.on_target));
    result.distance = gap.distance;
    result.point_a = view.first_is_fixed ? on_fixed : on_moved;
    result.point_b = view.first_is_fixed ? on_moved : on_fixed;
    return result;
}

/// The maximum local penetration depth of each surface inside the other's volume, with its
/// witnesses and the contact normal (doc/manual/exact.md, "Distance and depth").
///
/// Definition: depth_a is the maximum, over the points x of surface A lying inside B's volume, of
/// dist(x, surface B); deepest_a is such an x and closest_b its closest point on surface B; depth_b
/// likewise with the roles swapped. See Exact_depth for the normals and their sign.
///
/// How and how exactly: the maximum is taken over the vertices of each mesh and the vertices and
/// centroids of a midpoint subdivision of each triangle into pieces with edges at most
/// `sample_spacing` (every point of the surface is within `sample_spacing` of a sample), refined
/// only where a point can beat the best depth found (internal::max_sampled_depth). Inside tests
/// are exact (CGAL::Side_of_triangle_mesh through Exact_mesh::bounded_side, after the rounding
/// described in Exact_mesh); point-surface distances are exact closest-point queries on the AABB
/// tree, in double. Error bound: each reported depth is that of an actual point of the surface, so
/// it is at most the true maximum, and at least the true maximum minus `sample_spacing`. Either
/// the true deepest point x lies in a part skipped because none of its points could beat the depth
/// already found, which is then >= the true maximum; or a sample s of x's piece has |s - x| <=
/// spacing, and as the distance to a surface is 1-Lipschitz, dist(s, B) >= depth - spacing; when
/// depth > spacing, s lies in the ball of radius depth around x, which is inside B's volume, so s
/// counts. The witnesses are exact for the reported depth (the closest point of the deepest
/// sample). The cost follows the deep region, not the whole surface.
///
/// Computed for any pose: when the surfaces do not intersect, the depths are 0 unless one surface
/// is nested inside the other's volume (then depth_a or depth_b is the largest distance from the
/// inner surface to the outer one, as the definition says).
///
/// \pre both meshes enclose a volume (closed, no self-intersection); else throws Invalid_input.
/// \throws Invalid_input if `sample_spacing` is not finite and > 0, or below 1e-6 times the longest
///         edge of either mesh (a triangle would need more than 20 halvings).
/// Complexity: a closest-point query per visited ball-tree node, per triangle of the visited leaves
/// and per sample of the pieces that can beat the best depth: about log(edge / spacing) levels
/// around an isolated deepest point, up to (area / spacing^2) samples where the depth is constant
/// over an area (parallel faces). Thread-safe.
inline Exact_depth exact_max_depth(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a, const Exact_mesh& b,
                                   const Rigid_transform_3<double>& pose_b, double sample_spacing)
{
    internal::require_volume(a, "first", "exact_max_depth");
    internal::require_volume(b, "second", "exact_max_depth");
    internal::check_sample_spacing(sample_spacing, a, b);
    Exact_depth result;
    result.sample_spacing = sample_spacing;
    result.surfaces_intersect = exact_do_intersect(a, pose_a, b, pose_b);

    const Rigid_transform_3<double> a_to_b = pose_b.inverse() * pose_a;
    const Rigid_transform_3<double> b_to_a = pose_a.inverse() * pose_b;
    const internal::Deepest_sample in_b =
        internal::max_sampled_depth(a, a.transformed_points(a_to_b), a_to_b, b, sample_spacing);
    const internal::Deepest_sample in_a =
        internal::max_sampled_depth(b, b.transformed_points(b_to_a), b_to_a, a, sample_spacing);
    if (in_b.depth > 0.0) {
        result.depth_a = in_b.depth;
        result.deepest_a = pose_b.transform_point(internal::to_vector(in_b.deepest));
        result.closest_b = pose_b.transform_point(internal::to_vector(in_b.closest));
        result.normal_a = (result.deepest_a - result.closest_b).normalized();
    }
    if (in_a.depth > 0.0) {
        result.depth_b = in_a.depth;
        result.deepest_b = pose_a.transform_point(internal::to_vector(in_a.deepest));
        result.closest_a = pose_a.transform_point(internal::to_vector(in_a.closest));
        result.normal_b = (result.closest_a - result.deepest_b).normalized();
    }
    result.depth = std::max(result.depth_a, result.depth_b);
    if (result.depth > 0.0) result.contact_normal = result.depth_a >= result.depth_b ? result.normal_a : result.normal_b;
    return result;
}

/// @}

} // namespace PCCD
