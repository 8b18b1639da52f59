// PCCD/Proximity/internal/penetration.h -- the points of one posed cloud inside the other object and
// the deepest point of one surface inside the other (doc/algorithms.md "Proximity queries",
// penetration): a walk over the first cloud's hierarchy inside the second's box finds the points
// whose nearest point of the other cloud sees them behind its oriented normal; the deepest of them
// are projected onto their own surface and their closest point on the other surface is found, which
// gives the local depth, the witnesses and the contact normal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/point_queries.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Proximity/internal/surface_projection.h>

namespace PCCD::internal {

/// A point of one cloud inside the other object: its world position, the distance to the nearest
/// point of the other cloud (an estimate of its depth) and that point's index.
struct Inside_point {
    Eigen::Vector3d world;
    double estimate;
    std::uint32_t nearest;
};

/// The points of s inside the object t: points of s in t's bounding box (a walk of s's hierarchy
/// pruned by that box) whose nearest point q of t has n_q . (p - q) < 0 (n_q its outward normal).
template <class OS, class OT>
std::vector<Inside_point> points_inside(const Posed_object<OS>& s, const Posed_object<OT>& t, Proximity_state& state)
{
    std::vector<Inside_point> inside;
    const Point_cloud_hierarchy& hs = s.object->hierarchy();
    const Point_cloud_hierarchy& ht = t.object->hierarchy();
    if (hs.empty() || ht.empty()) return inside;
    const Rigid_transform_3<double> s_to_t = t.from_world * s.to_world;
    const Eigen::AlignedBox3d& box = ht.root().box;
    const Eigen::Matrix3Xd& normals = t.object->normals();
    struct Traits {
        const Point_cloud_hierarchy& hs;
        const Point_cloud_hierarchy& ht;
        const Rigid_transform_3<double>& s_to_t;
        const Eigen::AlignedBox3d& box;
        const Eigen::Matrix3Xd& normals;
        const Posed_object<OS>& s;
        Proximity_state& state;
        std::vector<Inside_point>& inside;

        bool go_further() { return !state.out_of_budget(); }
        bool enter(Point_cloud_hierarchy::Index i) const { return boxes_may_overlap(hs.node(i).box, s_to_t, box, 0.0); }
        bool left_first(Point_cloud_hierarchy::Index) const { return true; }
        void leaf(Point_cloud_hierarchy::Index i)
        {
            const auto& node = hs.node(i);
            for (auto k = node.first; k < node.first + node.count; ++k) {
                const Eigen::Vector3d p = s_to_t.transform_point(Eigen::Vector3d(hs.ordered_points().col(k).head<3>()));
                if (!box.contains(p)) continue;
                ++state.counters.inside_tests;
                const auto [at, d2] = nearest_point(ht, p);
                const std::uint32_t q = ht.order()[at];
                if (normals.col(q).dot(p - ht.ordered_points().col(at).head<3>()) < 0.0)
                    inside.push_back({s.to_world.transform_point(Eigen::Vector3d(hs.ordered_points().col(k).head<3>())),
                                      std::sqrt(d2), q});
            }
        }
    } traits{hs, ht, s_to_t, box, normals, s, state, inside};
    traverse(hs, Point_cloud_hierarchy::Index(0), traits);
    return inside;
}

/// A local depth: the point of surface s inside t (`deep`), its closest point on surface t
/// (`surface`), their distance and the contact normal (the direction in which B must move to undo
/// it: the reversed outward normal of t at `surface` when s is A, that normal when s is B).
struct Local_depth {
    Surface_point deep;
    Surface_point surface;
    double depth;
};

/// The local depth at the inside point `p` of s: p projected onto surface s, then the closest
/// point of surface t found from t's nearest cloud point (projected onto t). nullopt when a
/// projection fails or the projected point is no longer inside t.
template <class OS, class OT>
std::optional<Local_depth> local_depth(const Posed_object<OS>& s, const Posed_object<OT>& t, const Inside_point& p,
                                       double tolerance, double max_step, Proximity_state& state)
{
    const std::optional<Surface_point> x = project_onto_surface(s, p.world, tolerance, max_step, state);
    if (!x) return std::nullopt;
    const std::optional<Surface_point> start =
        project_onto_surface(t, t.to_world.transform_point(t.position(p.nearest)), tolerance, max_step, state);
    if (!start) return std::nullopt;
    const double reach = std::max(max_step, 2.0 * (start->x - x->x).norm());
    const Surface_point y = closest_on_surface(t, x->x, *start, tolerance, reach, state, 4);
    const double side = (x->x - y.x).dot(y.normal);
    if (!(side < 0.0)) return std::nullopt;
    return Local_depth{*x, y, (x->x - y.x).norm()};
}

/// The deepest local depth among the `tries` inside points of largest estimate (nullopt when none
/// of them gives one).
template <class OS, class OT>
std::optional<Local_depth> deepest(const Posed_object<OS>& s, const Posed_object<OT>& t, std::vector<Inside_point> inside,
                                   std::size_t tries, double tolerance, double max_step, Proximity_state& state)
{
    const std::size_t n = std::min(tries, inside.size());
    std::partial_sort(inside.begin(), inside.begin() + std::ptrdiff_t(n), inside.end(),
                      [](const Inside_point& l, const Inside_point& r) { return l.estimate > r.estimate; });
    std::optional<Local_depth> best;
    for (std::size_t k = 0; k < n && !state.out_of_budget(); ++k) {
        const std::optional<Local_depth> d = local_depth(s, t, inside[k], tolerance, max_step, state);
        if (d && (!best || d->depth > best->depth)) best = d;
    }
    return best;
}

} // namespace PCCD::internal
