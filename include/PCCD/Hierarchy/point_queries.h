// PCCD/Hierarchy/point_queries.h -- queries of one point against a point cloud hierarchy
// (doc/algorithms.md "Point cloud hierarchy", doc/manual/hierarchy.md "Reaches"): whether the point
// lies within the reach of some point of the cloud (where the cloud's surface can be defined), the
// nearest point of the cloud, and a cheap near point found by one descent. Each is a traits class
// of the walks of traversal.h (traverse(), descend()).
#pragma once

#include <cstddef>
#include <limits>
#include <utility>

#include <Eigen/Core>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/Reach_rule.h>
#include <PCCD/Hierarchy/traversal.h>

namespace PCCD {

namespace internal {

/// within_reach() as traits of traverse(): a node is entered when q lies in its box grown by the
/// node's largest reach; a leaf compares its points.
struct Within_reach_traits {
    const Point_cloud_hierarchy& t;
    const Eigen::Matrix4Xd& points;
    const Eigen::Vector3d& q;
    const Reach_rule& rule;
    bool found = false;

    bool go_further() const { return !found; }
    bool enter(Point_cloud_hierarchy::Index i) const
    {
        const auto& node = t.node(i);
        const double margin = rule(node.reach);
        return !((q.array() < node.box.min().array() - margin).any() || (q.array() > node.box.max().array() + margin).any());
    }
    void leaf(Point_cloud_hierarchy::Index i)
    {
        const auto& node = t.node(i);
        for (auto k = node.first; k < node.first + node.count; ++k) {
            const double reach = rule(points(3, k));
            if ((points.col(k).head<3>() - q).squaredNorm() <= reach * reach) {
                found = true;
                return;
            }
        }
    }
    bool left_first(Point_cloud_hierarchy::Index) const { return true; }
};

/// The nearest point of a leaf's points to q, kept in `best` (position in hierarchy order, squared
/// distance).
inline void nearest_in_leaf(const Point_cloud_hierarchy& t, const Eigen::Matrix4Xd& points, Point_cloud_hierarchy::Index i,
                            const Eigen::Vector3d& q, std::pair<std::size_t, double>& best)
{
    const auto& node = t.node(i);
    std::pair<std::size_t, double> local = best; // in registers while the leaf is scanned
    for (auto k = node.first; k < node.first + node.count; ++k) {
        const double d = (points.col(k).head<3>() - q).squaredNorm();
        if (d < local.second) local = {k, d};
    }
    best = local;
}

/// nearest_point() as traits of traverse(): branch and bound over the boxes, the nearer child first.
struct Nearest_point_traits {
    const Point_cloud_hierarchy& t;
    const Eigen::Matrix4Xd& points;
    const Eigen::Vector3d q; // a copy: `best` is written during the walk and could alias a reference
    std::pair<std::size_t, double> best{t.size(), std::numeric_limits<double>::infinity()};

    bool go_further() const { return true; }
    bool enter(Point_cloud_hierarchy::Index i) const { return t.node(i).box.squaredExteriorDistance(q) < best.second; }
    void leaf(Point_cloud_hierarchy::Index i) { nearest_in_leaf(t, points, i, q, best); }
    bool left_first(Point_cloud_hierarchy::Index i) const
    {
        return !(t.node(t.right(i)).box.squaredExteriorDistance(q) < t.node(t.left(i)).box.squaredExteriorDistance(q));
    }
};

/// descend_to_near_point() as traits of descend(): into the child whose box lies nearer q, the one
/// whose centre is nearer when the boxes are equally near.
struct Near_point_descent_traits {
    const Point_cloud_hierarchy& t;
    const Eigen::Matrix4Xd& points;
    const Eigen::Vector3d q; // a copy, as above
    std::pair<std::size_t, double> best{t.size(), std::numeric_limits<double>::infinity()};

    void leaf(Point_cloud_hierarchy::Index i) { nearest_in_leaf(t, points, i, q, best); }
    Point_cloud_hierarchy::Index next(Point_cloud_hierarchy::Index i) const
    {
        const Point_cloud_hierarchy::Index l = t.left(i), r = t.right(i);
        const double dl = t.node(l).box.squaredExteriorDistance(q), dr = t.node(r).box.squaredExteriorDistance(q);
        if (dl != dr) return dl < dr ? l : r;
        return (t.node(l).box.center() - q).squaredNorm() <= (t.node(r).box.center() - q).squaredNorm() ? l : r;
    }
};

} // namespace internal

/// Whether the point q (t's local frame) lies within the reach of some point of t: |q - p_k| <=
/// rule(reach_k) for some k. Exact (compares points at the leaves). O(height) nodes for a point
/// near one leaf; more where grown boxes overlap.
inline bool within_reach(const Point_cloud_hierarchy& t, const Eigen::Vector3d& q, const Reach_rule& rule)
{
    if (t.empty()) return false;
    internal::Within_reach_traits traits{t, t.ordered_points(), q, rule};
    traverse(t, Point_cloud_hierarchy::Index(0), traits);
    return traits.found;
}

/// The point of t nearest to q (t's local frame): its position in hierarchy order (a column of
/// t.ordered_points()) and its squared distance; {t.size(), +inf} for an empty hierarchy. Exact
/// (branch and bound over the boxes, nearer child first). O(height) nodes for a point near t.
inline std::pair<std::size_t, double> nearest_point(const Point_cloud_hierarchy& t, const Eigen::Vector3d& q)
{
    if (t.empty()) return {t.size(), std::numeric_limits<double>::infinity()};
    internal::Nearest_point_traits traits{t, t.ordered_points(), q};
    traverse(t, Point_cloud_hierarchy::Index(0), traits);
    return traits.best;
}

/// A point of t near q (t's local frame), found by one descent without backtracking: from the root,
/// into the child whose box lies nearer q (the one whose centre is nearer when q is inside both),
/// then the nearest point of that leaf. Returns its position in hierarchy order and its squared
/// distance ({t.size(), +inf} for an empty hierarchy). Not always the nearest point: it is when q
/// lies inside the boxes on one root-to-leaf path only (e.g. on the sampled surface, away from box
/// boundaries), otherwise a point of a leaf whose box is nearest at each level. A cheap step for
/// heuristics (the probes of the walked traversals); nearest_point() is the exact query.
/// Complexity: O(height + leaf size).
inline std::pair<std::size_t, double> descend_to_near_point(const Point_cloud_hierarchy& t, const Eigen::Vector3d& q)
{
    if (t.empty()) return {t.size(), std::numeric_limits<double>::infinity()};
    internal::Near_point_descent_traits traits{t, t.ordered_points(), q};
    descend(t, Point_cloud_hierarchy::Index(0), traits);
    return traits.best;
}

} // namespace PCCD
