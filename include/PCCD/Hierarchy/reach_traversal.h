// PCCD/Hierarchy/reach_traversal.h -- exact proximity tests between two point cloud hierarchies
// built with reaches (doc/algorithms.md "Point cloud hierarchy", doc/manual/hierarchy.md): whether
// a point lies within the reach of some point of a cloud, which points of one cloud lie within the
// reach of the other, and whether two clouds have a pair of points closer than the sum of their
// reaches. The implicit surface of a cloud is defined only within the reach of its points, so these
// tests bound where f is defined and where two surfaces can share a zero, without evaluating f.
// The hierarchies' bounding volumes (boxes, slabs or spheres, Bounding_volume), grown by a node's
// largest reach, prune node pairs; leaves compare points.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/Reach_rule.h>
#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/point_queries.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/PairObserver.h>

namespace PCCD {

namespace internal {

/// for_each_leaf_pair_within_reach() as traits of the pair walk of traversal.h: the node-pair tests
/// of node_pair_tests.h with the margins of the two reach rules, the four child pairs of two inner
/// nodes at once, the children nearer the other node first with `closest_first`.
template <class Visitor, class Observer>
struct Reach_pair_traits {
    const Point_cloud_hierarchy& s;
    const Point_cloud_hierarchy& t;
    const Rigid_transform_3<double>& s_to_t;
    const Reach_rule& rule_s;
    const Reach_rule& rule_t;
    Visitor& visit;
    Observer& observer;
    bool closest_first;
    bool either;
    const Eigen::Matrix3d r; // copies: read at every node pair
    const Eigen::Matrix3d abs_r;
    const Pair_tests tests;
    /// The nodes of s mapped lately (each appears in several pairs), by node index modulo 64 (left
    /// default-initialized: only their `node` is set, to "none").
    std::array<Mapped_node, 64> mapped_nodes;
    std::size_t leaf_pairs = 0;
    bool stopped = false;

    using Index = Point_cloud_hierarchy::Index;

    Reach_pair_traits(const Point_cloud_hierarchy& s_, const Point_cloud_hierarchy& t_, const Rigid_transform_3<double>& s_to_t_,
                      const Reach_rule& rule_s_, const Reach_rule& rule_t_, Visitor& visit_, Observer& observer_,
                      bool closest_first_, bool either_)
        : s(s_), t(t_), s_to_t(s_to_t_), rule_s(rule_s_), rule_t(rule_t_), visit(visit_), observer(observer_),
          closest_first(closest_first_), either(either_), r(s_to_t_.rotation()), abs_r(r.cwiseAbs()), tests(s_, t_)
    {
    }

    bool go_further() const { return !stopped; }
    const Mapped_node& mapped(Index i)
    {
        Mapped_node& m = mapped_nodes[i & 63];
        if (m.node != i) {
            const auto& ns = s.node(i);
            m.node = i;
            m.centre = s_to_t.transform_point(ns.box.center());
            m.slab_normal = r * ns.slab_normal;
            m.slab_shift = m.slab_normal.dot(s_to_t.translation());
            if (tests.spheres) m.sphere_centre = s_to_t.transform_point(s.sphere(i).centre);
        }
        return m;
    }
    bool enter(Index i, Index j)
    {
        observer.node_pair(i, j);
        const auto& ns = s.node(i);
        const auto& nt = t.node(j);
        const Mapped_node& m = mapped(i);
        const double ms = rule_s(ns.reach), mt = rule_t(nt.reach);
        if (tests.boxes &&
            !grown_boxes_may_overlap(ns.box, r, abs_r, m.centre, either ? 0.0 : ms, nt.box, either ? std::max(ms, mt) : mt))
            return false;
        const double margin = either ? std::max(ms, mt) : ms + mt;
        if (tests.spheres) {
            const double apart = s.sphere(i).radius + t.sphere(j).radius + margin;
            if ((m.sphere_centre - t.sphere(j).centre).squaredNorm() > apart * apart) return false;
        }
        return slabs_may_overlap(ns, m, r, s_to_t.translation(), nt, margin);
    }
    Pair_split split(Index i, Index j) const
    {
        // Both inner: the four child pairs at once (a pair of an inner node and a child is mostly
        // kept where the walk goes on, so testing it first is wasted).
        const bool leaf_s = s.is_leaf(i), leaf_t = t.is_leaf(j);
        if (leaf_s && leaf_t) return Pair_split::leaves;
        if (!leaf_s && !leaf_t) return Pair_split::both;
        return leaf_s ? Pair_split::second : Pair_split::first;
    }
    void leaf_pair(Index i, Index j)
    {
        ++leaf_pairs;
        observer.leaf_pair(i, j);
        if (!visit(i, j)) stopped = true;
    }
    bool first_left_first(Index i, Index j) const
    {
        if (!closest_first) return true;
        // Distances are the same in s's frame: one mapping of t's centre instead of two of s's.
        const Eigen::Vector3d c = r.transpose() * (t.node(j).box.center() - s_to_t.translation());
        return !((s.node(s.right(i)).box.center() - c).squaredNorm() < (s.node(s.left(i)).box.center() - c).squaredNorm());
    }
    bool second_left_first(Index i, Index j) const
    {
        if (!closest_first) return true;
        const Eigen::Vector3d& centre_s = mapped_nodes[i & 63].centre; // entered just before
        return !((t.node(t.right(j)).box.center() - centre_s).squaredNorm() <
                 (t.node(t.left(j)).box.center() - centre_s).squaredNorm());
    }
};

} // namespace internal

/// Calls `visit(leaf_s, leaf_t)` for every pair of leaves whose bounding volumes may hold a point of
/// s within the reach (per `rule_t`) of a point of t: s's box mapped by `s_to_t`, t's box grown by
/// its node's largest reach (`either`: s's box grown by s's reach or t's by t's, i.e. pairs where a
/// point of either leaf may lie within the reach of the other's: the margin is the larger reach, not
/// the sum). A node pair is also pruned when either node's slab (Point_cloud_hierarchy::Node)
/// separates it from the other node's box by more than the margin: a surface's slabs are thin, so
/// two patches whose boxes overlap without the patches coming close are pruned early. Which tests
/// run depends on the two hierarchies' Bounding_volume: the boxes unless both are sphere trees,
/// their spheres (grown by the margin: pruned when farther apart than the two radii and the margin)
/// when both are, the slabs where the nodes have them. Depth-first:
/// a pair of inner nodes is replaced by its four child pairs at once (12 % faster first-hit queries
/// on the coarse models than descending one node at a time, doc/benchmarks.md), a pair with a leaf
/// by the other node's two children; with `closest_first` each node's child whose box centre lies
/// nearer the other node's centre comes first (the pairs most likely to touch early: near child of
/// s with near child of t, then near with far, far with near, far with far), otherwise the left
/// child. Deterministic. `visit` returns false to stop the traversal. `observer` (a PairObserver)
/// is told of every node pair tested and every leaf pair handed to `visit`. Returns the counters.
/// Complexity: O(node pairs visited), each at most once; O(height) extra space.
template <class Visitor, PairObserver Observer = Ignore_pairs>
Reach_counters for_each_leaf_pair_within_reach(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                                               const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_s,
                                               const Reach_rule& rule_t, Visitor&& visit, bool closest_first = false,
                                               bool either = false, Observer&& observer = Observer())
{
    Reach_counters counters;
    if (s.empty() || t.empty()) return counters;
    internal::Reach_pair_traits<std::remove_reference_t<Visitor>, std::remove_reference_t<Observer>> traits(
        s, t, s_to_t, rule_s, rule_t, visit, observer, closest_first, either);
    const Walk_counters walk = traverse(s, Point_cloud_hierarchy::Index(0), t, Point_cloud_hierarchy::Index(0), traits);
    counters.node_pairs = walk.tested;
    counters.leaf_pairs = traits.leaf_pairs;
    counters.pending = walk.pending;
    return counters;
}

namespace internal {

/// Calls `body(squared distance, reach_p + reach_q)` for the point pairs of leaf `leaf_s` of s
/// (mapped by s_to_t) and leaf `leaf_t` of t, until it returns false. Returns false if it stopped.
template <class Body>
bool for_each_leaf_point_pair(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index leaf_s,
                              const Point_cloud_hierarchy& t, Point_cloud_hierarchy::Index leaf_t,
                              const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_s, const Reach_rule& rule_t,
                              Body&& body)
{
    const auto& ns = s.node(leaf_s);
    const auto& nt = t.node(leaf_t);
    const Eigen::Matrix4Xd& ps = s.ordered_points();
    const Eigen::Matrix4Xd& pt = t.ordered_points();
    for (auto a = ns.first; a < ns.first + ns.count; ++a) {
        const Eigen::Vector3d p = s_to_t.transform_point(Eigen::Vector3d(ps.col(a).head<3>()));
        const double ra = rule_s(ps(3, a));
        for (auto b = nt.first; b < nt.first + nt.count; ++b)
            if (!body((pt.col(b).head<3>() - p).squaredNorm(), ra + rule_t(pt(3, b)))) return false;
    }
    return true;
}

} // namespace internal

/// The smallest value of |T p - q| - rule_s(reach_p) - rule_t(reach_q) over the points p of leaf
/// `leaf_s` of s and q of leaf `leaf_t` of t (T = s_to_t): <= 0 exactly when some pair of their
/// points lies within the sum of its reaches. O(|leaf_s| |leaf_t|).
inline double leaf_pair_gap(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index leaf_s,
                            const Point_cloud_hierarchy& t, Point_cloud_hierarchy::Index leaf_t,
                            const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_s, const Reach_rule& rule_t)
{
    double gap = std::numeric_limits<double>::infinity();
    internal::for_each_leaf_point_pair(s, leaf_s, t, leaf_t, s_to_t, rule_s, rule_t, [&](double squared, double reach) {
        gap = std::min(gap, std::sqrt(squared) - reach);
        return true;
    });
    return gap;
}

/// Whether some point p of leaf `leaf_s` of s and q of leaf `leaf_t` of t satisfy |T p - q| <=
/// rule_s(reach_p) + rule_t(reach_q) (T = s_to_t); leaf_pair_gap() <= 0 without its square roots.
inline bool leaf_reaches_meet(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index leaf_s,
                              const Point_cloud_hierarchy& t, Point_cloud_hierarchy::Index leaf_t,
                              const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_s, const Reach_rule& rule_t)
{
    return !internal::for_each_leaf_point_pair(s, leaf_s, t, leaf_t, s_to_t, rule_s, rule_t,
                                               [](double squared, double reach) { return squared > reach * reach; });
}

/// Whether s and t (s mapped by `s_to_t`) have a pair of points p, q with |T p - q| <= rule_s(reach_p)
/// + rule_t(reach_q): the condition for the balls of their reaches to meet, so for a point that lies
/// within reach of both clouds. Exact; stops at the first such pair. `counters` accumulates the work.
/// `max_leaf_pairs`: after comparing this many leaf pairs without finding one, answers true (they
/// may meet; a conservative answer that bounds the work of deep overlaps, where the boxes of many
/// leaf pairs overlap). `observer`: as for for_each_leaf_pair_within_reach().
template <PairObserver Observer = Ignore_pairs>
bool reaches_meet(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t, const Rigid_transform_3<double>& s_to_t,
                  const Reach_rule& rule_s, const Reach_rule& rule_t, Reach_counters& counters,
                  std::size_t max_leaf_pairs = std::numeric_limits<std::size_t>::max(), Observer&& observer = Observer())
{
    bool met = false;
    std::size_t compared = 0;
    const Reach_counters c = for_each_leaf_pair_within_reach(
        s, t, s_to_t, rule_s, rule_t, [&](Point_cloud_hierarchy::Index i, Point_cloud_hierarchy::Index j) {
            met = ++compared > max_leaf_pairs || leaf_reaches_meet(s, i, t, j, s_to_t, rule_s, rule_t);
            return !met;
        },
        false, false, observer);
    counters.node_pairs += c.node_pairs;
    counters.leaf_pairs += c.leaf_pairs;
    return met;
}

/// The points of s (indices of the cloud, in hierarchy order of s) that lie within the reach of
/// some point of t (per `rule_t`) once mapped by `s_to_t`. `max_leaf_pairs`: give up (return false,
/// `out` partial) once the traversal has compared more leaf pairs than this; true when `out` is
/// complete. Exact. `observer`: as for for_each_leaf_pair_within_reach().
template <PairObserver Observer = Ignore_pairs>
bool points_within_reach(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                         const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_t,
                         std::vector<std::uint32_t>& out, Reach_counters& counters,
                         std::size_t max_leaf_pairs = std::numeric_limits<std::size_t>::max(),
                         Observer&& observer = Observer())
{
    using Index = Point_cloud_hierarchy::Index;
    out.clear();
    std::vector<std::pair<Index, Index>> pairs;
    bool complete = true;
    const Reach_counters c =
        for_each_leaf_pair_within_reach(s, t, s_to_t, Reach_rule{.scale = 0.0, .cap = 0.0}, rule_t, [&](Index i, Index j) {
            if (pairs.size() >= max_leaf_pairs) {
                complete = false;
                return false;
            }
            pairs.emplace_back(i, j);
            return true;
        },
        false, false, observer);
    counters.node_pairs += c.node_pairs;
    counters.leaf_pairs += c.leaf_pairs;
    if (!complete) return false;
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    const Eigen::Matrix4Xd& ps = s.ordered_points();
    const Eigen::Matrix4Xd& pt = t.ordered_points();
    for (std::size_t k = 0; k < pairs.size();) {
        std::size_t end = k;
        while (end < pairs.size() && pairs[end].first == pairs[k].first) ++end;
        const auto& ns = s.node(pairs[k].first);
        for (auto a = ns.first; a < ns.first + ns.count; ++a) {
            const Eigen::Vector3d p = s_to_t.transform_point(Eigen::Vector3d(ps.col(a).head<3>()));
            bool inside = false;
            for (std::size_t m = k; m < end && !inside; ++m) {
                const auto& nt = t.node(pairs[m].second);
                for (auto b = nt.first; b < nt.first + nt.count && !inside; ++b) {
                    const double reach = rule_t(pt(3, b));
                    inside = (pt.col(b).head<3>() - p).squaredNorm() <= reach * reach;
                }
            }
            if (inside) out.push_back(s.order()[a]);
        }
        k = end;
    }
    return true;
}

} // namespace PCCD
