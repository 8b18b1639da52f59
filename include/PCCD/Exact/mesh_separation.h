// PCCD/Exact/mesh_separation.h -- a signed separation measure of two posed triangle meshes and the
// pose classification of doc/algorithms.md, "Benchmark procedure": a pose whose exact separation
// (gap between the surfaces) or penetration is below one sampling radius is *grazing*, because a
// point cloud with that resolution cannot decide it; such poses are counted apart when PCCD's
// answers are validated against the exact reference (doc/design.md, "Exact checks").
//
// Includes CGAL's Polygon_mesh_processing (through Exact_mesh.h): keep it out of the core headers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_intersection.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// The result of exact_separation.
struct Exact_separation {
    /// Whether the surfaces intersect (exactly as exact_do_intersect).
    bool surfaces_intersect = false;
    /// When the surfaces do not intersect: how the volumes are nested (exact); Containment::none
    /// when they intersect.
    Containment containment = Containment::none;
    /// When the surfaces do not intersect: the minimum distance between them (> 0); 0 otherwise.
    double distance = 0.0;
    /// When the surfaces intersect: the largest distance from a vertex of one mesh lying inside
    /// the other's volume to the other's surface (>= 0); 0 otherwise.
    double penetration_depth = 0.0;

    /// The signed measure: `distance` when the surfaces are apart, `-penetration_depth` when they
    /// intersect.
    double signed_measure() const { return surfaces_intersect ? -penetration_depth : distance; }
};

/// The class of a pose with respect to a sampling radius (see classify_pose).
enum class Pose_class {
    /// The surfaces are apart by at least one sampling radius (possibly nested, see
    /// Exact_separation::containment: the surfaces do not meet either way).
    separated,
    /// The gap or the penetration is below one sampling radius: a point cloud cannot decide it.
    grazing,
    /// The surfaces intersect with a penetration of at least one sampling radius.
    intersecting
};

namespace internal {

inline double squared_distance_to_box(const Exact_mesh::Point_3& p, const CGAL::Bbox_3& box)
{
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double gap = std::max({box.min(i) - p[i], p[i] - box.max(i), 0.0});
        sum += gap * gap;
    }
    return sum;
}

/// A node of the source mesh's vertex ball tree seen from the target mesh: its centre mapped into
/// the target's frame, the closest point of the target's surface to it and their distance.
struct Ball_view {
    std::size_t node;
    Exact_mesh::Point_3 centre;
    Exact_mesh::Point_3 closest;
    double distance;
};

inline Exact_mesh::Point_3 ball_centre(const Exact_mesh& source, std::size_t node,
                                       const Rigid_transform_3<double>& source_to_target)
{
    const Exact_mesh::Point_3& c = source.vertex_ball_tree()[node].centre;
    const Eigen::Vector3d q = source_to_target.transform_point(Eigen::Vector3d(c.x(), c.y(), c.z()));
    return {q.x(), q.y(), q.z()};
}

/// The view of `node` with its centre at `centre`; `hint` (a point of the target's surface, e.g.
/// the parent's closest point) speeds up the closest-point query.
inline Ball_view view_ball(std::size_t node, const Exact_mesh::Point_3& centre, const Exact_mesh& target,
                           const Exact_mesh::Point_3* hint)
{
    const Exact_mesh::Point_3 closest = hint ? target.tree().closest_point(centre, *hint)
                                             : target.tree().closest_point(centre);
    return {node, centre, closest, std::sqrt(CGAL::squared_distance(centre, closest))};
}

/// The distance of a vertex (`p`, in the target's frame) to the target's surface.
inline double vertex_distance(const Exact_mesh::Point_3& p, const Exact_mesh& target, const Ball_view& leaf)
{
    return std::sqrt(CGAL::squared_distance(p, target.tree().closest_point(p, leaf.closest)));
}

/// The closest pair found so far between a source and a target surface: `distance` and the two
/// points realizing it, `on_source` and `on_target`, in the target's frame (meaningless while
/// `distance` is +infinity).
struct Closest_pair {
    double distance = std::numeric_limits<double>::infinity();
    Exact_mesh::Point_3 on_source;
    Exact_mesh::Point_3 on_target;
};

/// The distances to `target`'s surface of the vertices of `source` (mapped to `source_points` in
/// the target's frame) that can end an edge closer to the target than `best.distance`, the smallest
/// vertex distance (updated here, with the vertex and its closest point on the target when a vertex
/// beats it); +infinity for the others. Best-first search of the source's ball tree: a node whose
/// vertices are all farther than best + (their longest incident edge) is pruned, so an uncomputed
/// vertex v has distance >= best + (every edge at v).
inline std::vector<double> near_vertex_distances(const Exact_mesh& source,
                                                 const std::vector<Exact_mesh::Point_3>& source_points,
                                                 const Rigid_transform_3<double>& source_to_target,
                                                 const Exact_mesh& target, Closest_pair& best)
{
    const auto& balls = source.vertex_ball_tree();
    std::vector<double> distance(source_points.size(), std::numeric_limits<double>::infinity());
    const auto key = [&](const Ball_view& v) {
        return v.distance - balls[v.node].radius - balls[v.node].longest_incident_edge;
    };
    const auto later = [&](const Ball_view& x, const Ball_view& y) { return key(x) > key(y); };
    std::priority_queue<Ball_view, std::vector<Ball_view>, decltype(later)> queue(later);
    queue.push(view_ball(0, ball_centre(source, 0, source_to_target), target, nullptr));
    while (!queue.empty()) {
        const Ball_view view = queue.top();
        queue.pop();
        if (key(view) >= best.distance) break;
        const Exact_mesh::Vertex_ball& ball = balls[view.node];
        if (ball.is_leaf()) {
            for (std::size_t i = ball.begin; i < ball.end; ++i) {
                const Exact_mesh::Vertex_index v = source.ball_tree_vertices()[i];
                const Exact_mesh::Point_3& p = source_points[v];
                const Exact_mesh::Point_3 closest = target.tree().closest_point(p, view.closest);
                distance[v] = std::sqrt(CGAL::squared_distance(p, closest));
                if (distance[v] < best.distance) best = {distance[v], p, closest};
            }
        } else {
            for (const std::size_t child : ball.children)
                queue.push(view_ball(child, ball_centre(source, child, source_to_target), target, &view.closest));
        }
    }
    return distance;
}

/// The edges of `mesh` (coordinates `points`) whose two endpoints are closer to the other mesh,
/// according to `distance`, than `best` plus the edge's length: only such an edge can have a point
/// closer than `best` (the distance to a surface is 1-Lipschitz).
inline std::vector<Exact_mesh::Segment_3> near_edges(const Exact_mesh& mesh, const std::vector<Exact_mesh::Point_3>& points,
                                                     const std::vector<double>& distance, double best)
{
    std::vector<Exact_mesh::Segment_3> segments;
    for (const auto e : edges(mesh.mesh())) {
        const auto h = mesh.mesh().halfedge(e);
        const Exact_mesh::Vertex_index u = mesh.mesh().source(h), w = mesh.mesh().target(h);
        if (!(distance[u] < std::numeric_limits<double>::infinity() && distance[w] < std::numeric_limits<double>::infinity()))
            continue;
        const double limit = best + std::sqrt(CGAL::squared_distance(points[u], points[w]));
        if (distance[u] < limit && distance[w] < limit) segments.emplace_back(points[u], points[w]);
    }
    return segments;
}

/// The closest points of the segments [p0, p1] and [q0, q1] (the first on [p0, p1]), in double.
/// The minimum of the squared distance over the two parameters is reached either at an interior
/// critical point of both (the solution of the 2x2 normal equations, when the segments are not
/// parallel and it lies inside both parameter ranges) or with one parameter at an end of its range,
/// where it is the closest point of the other segment to that endpoint. Every candidate is a pair
/// of points of the two segments, so the smallest of these (at most five) is the answer, also for
/// parallel or degenerate segments, whatever the rounding of the interior solution.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> closest_points_of_segments(const Eigen::Vector3d& p0,
                                                                              const Eigen::Vector3d& p1,
                                                                              const Eigen::Vector3d& q0,
                                                                              const Eigen::Vector3d& q1)
{
    const auto on_segment = [](const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        const Eigen::Vector3d ab = b - a;
        const double length2 = ab.squaredNorm();
        const double t = length2 > 0.0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
        return Eigen::Vector3d(a + t * ab);
    };
    std::pair<Eigen::Vector3d, Eigen::Vector3d> best{p0, on_segment(p0, q0, q1)};
    double best_squared = (best.first - best.second).squaredNorm();
    const auto consider = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
        const double squared = (x - y).squaredNorm();
        if (squared < best_squared) {
            best_squared = squared;
            best = {x, y};
        }
    };
    consider(p1, on_segment(p1, q0, q1));
    consider(on_segment(q0, p0, p1), q0);
    consider(on_segment(q1, p0, p1), q1);
    const Eigen::Vector3d u = p1 - p0, v = q1 - q0, w = p0 - q0;
    const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
    const double denominator = a * c - b * b; // |u x v|^2 >= 0, 0 for parallel segments
    if (denominator > 0.0) {
        const double s = (b * e - c * d) / denominator, t = (a * e - b * d) / denominator;
        if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) consider(p0 + s * u, q0 + t * v);
    }
    return best;
}

/// The minimum distance between the surfaces of two posed meshes known not to intersect, with the
/// two points realizing it (`on_source` on the moved mesh, `on_target` on the fixed one, both in
/// the fixed frame): for disjoint triangle meshes it is reached at a vertex-triangle or an
/// edge-edge pair. The vertex distances come from near_vertex_distances (both ways); the edges
/// that can beat the smallest of them (near_edges) are then paired each with each, with a
/// box-distance rejection. The distance of an edge pair is CGAL's; its points, computed only for
/// the pairs that improve the minimum, are closest_points_of_segments'.
inline Closest_pair surface_gap(const Exact_pair_view& view)
{
    const Rigid_transform_3<double> fixed_to_moved = view.moved_to_fixed.inverse();
    const std::vector<Exact_mesh::Point_3> fixed_points = view.fixed.transformed_points(fixed_to_moved);
    std::vector<Exact_mesh::Point_3> fixed_local;
    fixed_local.reserve(view.fixed.number_of_vertices());
    for (const auto v : vertices(view.fixed.mesh())) fixed_local.push_back(view.fixed.mesh().point(v));

    Closest_pair moved_pair; // moved vertex -> fixed surface, fixed frame
    const std::vector<double> moved_distance =
        near_vertex_distances(view.moved, view.moved_points, view.moved_to_fixed, view.fixed, moved_pair);
    Closest_pair fixed_pair{moved_pair.distance, {}, {}}; // fixed vertex -> moved surface, moved frame
    const std::vector<double> fixed_distance =
        near_vertex_distances(view.fixed, fixed_points, fixed_to_moved, view.moved, fixed_pair);
    Closest_pair best = moved_pair;
    if (fixed_pair.distance < moved_pair.distance) {
        const auto to_fixed = [&](const Exact_mesh::Point_3& p) {
            const Eigen::Vector3d q = view.moved_to_fixed.transform_point(Eigen::Vector3d(p.x(), p.y(), p.z()));
            return Exact_mesh::Point_3(q.x(), q.y(), q.z());
        };
        best = {fixed_pair.distance, to_fixed(fixed_pair.on_target), to_fixed(fixed_pair.on_source)};
    }

    // Both edge sets in the fixed frame.
    const std::vector<Exact_mesh::Segment_3> moved_edges =
        near_edges(view.moved, view.moved_points, moved_distance, best.distance);
    const std::vector<Exact_mesh::Segment_3> fixed_edges = near_edges(view.fixed, fixed_local, fixed_distance, best.distance);
    double best_squared = best.distance * best.distance;
    const auto vector = [](const Exact_mesh::Point_3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); };
    for (const Exact_mesh::Segment_3& s : moved_edges) {
        const CGAL::Bbox_3 s_box = s.bbox();
        for (const Exact_mesh::Segment_3& t : fixed_edges) {
            const CGAL::Bbox_3 t_box = t.bbox();
            double box_gap = 0.0;
            for (int i = 0; i < 3; ++i) {
                const double gap = std::max({s_box.min(i) - t_box.max(i), t_box.min(i) - s_box.max(i), 0.0});
                box_gap += gap * gap;
            }
            if (box_gap >= best_squared) continue;
            const double squared = CGAL::squared_distance(s, t);
            if (squared >= best_squared) continue;
            best_squared = squared;
            const auto [x, y] = closest_points_of_segments(vector(s.source()), vector(s.target()), vector(t.source()),
                                                           vector(t.target()));
            best.on_source = {x.x(), x.y(), x.z()};
            best.on_target = {y.x(), y.y(), y.z()};
        }
    }
    best.distance = std::sqrt(best_squared);
    return best;
}

/// The largest distance from a vertex of `source` (mapped to `source_points` in the target's frame)
/// lying strictly inside the volume of `target` to the target's surface, or `best` if larger.
///
/// Best-first search of the source's ball tree by decreasing upper bound (centre distance plus
/// radius) until the bound falls to the best depth found. A ball outside the target's box is
/// outside the volume; a ball that does not reach the target's surface (centre distance above the
/// radius) lies wholly on its centre's side, so one exact inside test decides its whole subtree.
/// Only the leaves straddling the surface need per-vertex inside tests.
inline double max_inside_depth(const Exact_mesh& source, const std::vector<Exact_mesh::Point_3>& source_points,
                               const Rigid_transform_3<double>& source_to_target, const Exact_mesh& target, double best)
{
    struct Item {
        Ball_view view;
        bool all_inside;
    };
    const auto& balls = source.vertex_ball_tree();
    const CGAL::Bbox_3 box = target.tree().bbox();
    const auto upper = [&](const Item& x) { return x.view.distance + balls[x.view.node].radius; };
    const auto later = [&](const Item& x, const Item& y) { return upper(x) < upper(y); };
    std::priority_queue<Item, std::vector<Item>, decltype(later)> queue(later);
    const auto push = [&](std::size_t node, bool all_inside, const Exact_mesh::Point_3* hint) {
        const Exact_mesh::Point_3 centre = ball_centre(source, node, source_to_target);
        const double radius = balls[node].radius;
        if (!all_inside && squared_distance_to_box(centre, box) > radius * radius) return;
        const Ball_view view = view_ball(node, centre, target, hint);
        if (!all_inside && view.distance > radius) {
            if (target.bounded_side(centre) != CGAL::ON_BOUNDED_SIDE) return;
            all_inside = true;
        }
        queue.push({view, all_inside});
    };
    push(0, false, nullptr);
    while (!queue.empty()) {
        const Item item = queue.top();
        queue.pop();
        if (upper(item) <= best) break;
        const Exact_mesh::Vertex_ball& ball = balls[item.view.node];
        if (ball.is_leaf()) {
            for (std::size_t i = ball.begin; i < ball.end; ++i) {
                const Exact_mesh::Point_3& p = source_points[source.ball_tree_vertices()[i]];
                const double d = vertex_distance(p, target, item.view);
                if (d <= best) continue;
                if (item.all_inside || target.bounded_side(p) == CGAL::ON_BOUNDED_SIDE) best = d;
            }
        } else {
            for (const std::size_t child : ball.children) push(child, item.all_inside, &item.view.closest);
        }
    }
    return best;
}

inline void check_sampling_radius(double sampling_radius)
{
    if (!(std::isfinite(sampling_radius) && sampling_radius > 0.0))
        throw Invalid_input(concat("classify_pose: sampling radius ", sampling_radius, " must be finite and > 0"));
}

} // namespace internal

/// \name Separation and grazing classification
/// @{

/// The exact-reference separation of two posed meshes (doc/algorithms.md, "Benchmark procedure").
///
/// What is computed:
/// - `surfaces_intersect`: exact, as exact_do_intersect.
/// - surfaces apart: `distance` is the minimum distance between the two surfaces. For disjoint
///   triangle meshes it is reached at a vertex-triangle or an edge-edge pair, and both kinds are
///   searched exhaustively up to pruning that provably cannot drop the minimum: closest-point
///   queries on the AABB trees for the vertices of each mesh (best-first over each mesh's vertex
///   ball tree, a ball skipped when its centre distance minus its radius cannot beat the best), then
///   segment-segment distances between the edges that can still beat the smallest vertex distance
///   (both endpoints within that distance plus the edge's length of the other surface). The pair distances are computed in double (CGAL's Epick
///   constructions): accurate to a few ulps of the coordinates (~1e-15 on normalized objects), not
///   certified. `containment` says whether one is nested inside the other (exact).
/// - surfaces intersect: `penetration_depth` is the largest distance from a vertex of one mesh
///   lying strictly inside the other's volume to the other's surface (inside tests exact, distances
///   in double). It is a vertex estimate of the deepest penetration of one surface into the other's
///   volume: a lower bound on the maximum over all surface points, short of it by at most the longer
///   of the two meshes' longest edges (the distance to a surface is 1-Lipschitz). 0 when no vertex is
///   inside (e.g. two triangles crossing at their edges).
///
/// \pre both meshes enclose a volume (closed, no self-intersection); else throws Invalid_input.
/// Complexity: one closest-point query per visited node of each mesh's vertex ball tree
/// (Exact_mesh::vertex_ball_tree) and per vertex of the visited leaves; the visited nodes are
/// those that can matter: near the closest region (apart), or deeper than the best depth found
/// (intersecting; a ball wholly inside or outside takes one exact inside test, only leaves
/// straddling the surface one per vertex); plus the edge pairs of the closest region (quadratic in
/// their number, which is small unless the surfaces run parallel at the minimum distance). Typically a few milliseconds to a few tens
/// of milliseconds for two 75k-triangle meshes (see doc/manual/exact.md). No tree is rebuilt.
/// Thread-safe.
inline Exact_separation exact_separation(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a,
                                         const Exact_mesh& b, const Rigid_transform_3<double>& pose_b)
{
    internal::require_volume(a, "first", "exact_separation");
    internal::require_volume(b, "second", "exact_separation");
    const internal::Exact_pair_view view(a, pose_a, b, pose_b);
    Exact_separation result;
    result.surfaces_intersect = internal::some_triangles_intersect(view);
    if (result.surfaces_intersect) {
        const Rigid_transform_3<double> fixed_to_moved = view.moved_to_fixed.inverse();
        const double depth = internal::max_inside_depth(view.moved, view.moved_points, view.moved_to_fixed, view.fixed, 0.0);
        result.penetration_depth = internal::max_inside_depth(
            view.fixed, view.fixed.transformed_points(fixed_to_moved), fixed_to_moved, view.moved, depth);
        return result;
    }
    result.distance = internal::surface_gap(view).distance;
    result.containment = internal::containment_without_contact(a, pose_a, b, pose_b);
    return result;
}

/// The class of a pose given its separation and the sampling radius of the clouds: grazing when
/// |separation.signed_measure()| < sampling_radius, else intersecting or separated according to
/// `separation.surfaces_intersect` (nested surfaces that do not meet are separated).
/// \throws Invalid_input if `sampling_radius` is not finite and > 0. O(1).
inline Pose_class classify_pose(const Exact_separation& separation, double sampling_radius)
{
    internal::check_sampling_radius(sampling_radius);
    if (std::abs(separation.signed_measure()) < sampling_radius) return Pose_class::grazing;
    return separation.surfaces_intersect ? Pose_class::intersecting : Pose_class::separated;
}

/// classify_pose(exact_separation(a, pose_a, b, pose_b), sampling_radius).
/// \pre as exact_separation. \throws Invalid_input as both. Thread-safe.
inline Pose_class classify_pose(const Exact_mesh& a, const Rigid_transform_3<double>& pose_a, const Exact_mesh& b,
                                const Rigid_transform_3<double>& pose_b, double sampling_radius)
{
    internal::check_sampling_radius(sampling_radius); // before the costly part
    return classify_pose(exact_separation(a, pose_a, b, pose_b), sampling_radius);
}

/// @}

} // namespace PCCD
