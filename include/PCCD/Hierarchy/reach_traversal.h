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
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/PairObserver.h>

namespace PCCD {

/// How a query scales the reaches stored in a hierarchy: a point's reach is min(scale * stored, cap).
/// Monotone in the stored reach, so a node's largest reach maps to the largest of its points.
struct Reach_rule {
    /// Factor on the stored reach, > 0 (1: the surface's domain; the contact core of a verified
    /// contact, Intersection_options::contact_core, for where a contact can lie).
    double scale = 1.0;
    /// Upper bound on any reach (e.g. the kernel's support radius: f needs a point that close), > 0.
    double cap = std::numeric_limits<double>::infinity();

    double operator()(double stored) const { return std::min(scale * stored, cap); }
};

/// What a reach traversal visited.
struct Reach_counters {
    /// Node pairs tested.
    std::size_t node_pairs = 0;
    /// Leaf pairs whose points were compared.
    std::size_t leaf_pairs = 0;
    /// Node pairs still waiting when the visitor stopped the traversal (their subtrees were not
    /// visited); 0 when the traversal ran to its end.
    std::size_t pending = 0;
};

/// Whether box `a` mapped by `a_to_b` and grown by `margin_a`, and the axis-aligned box `b` grown by
/// `margin_b`, may overlap: false only when one of the six face normals separates them (the grown
/// boxes contain the Minkowski sums of the boxes with balls of those radii, so a false answer means
/// no point within margin_a of box a is within margin_b of box b). O(1); pure.
namespace internal {

/// grown_boxes_may_overlap() with the rotation r of the motion, |r| and a's centre already mapped
/// (a traversal computes |r| once).
inline bool grown_boxes_may_overlap(const Eigen::AlignedBox3d& a, const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r,
                                    const Eigen::Vector3d& mapped_centre_a, double margin_a, const Eigen::AlignedBox3d& b,
                                    double margin_b)
{
    const Eigen::Vector3d ha = 0.5 * (a.max() - a.min()) + Eigen::Vector3d::Constant(margin_a);
    const Eigen::Vector3d hb = 0.5 * (b.max() - b.min()) + Eigen::Vector3d::Constant(margin_b);
    const Eigen::Vector3d t = mapped_centre_a - b.center();
    for (int i = 0; i < 3; ++i)
        if (std::abs(t(i)) > hb(i) + abs_r.row(i).dot(ha)) return false;
    for (int j = 0; j < 3; ++j)
        if (std::abs(t.dot(r.col(j))) > ha(j) + abs_r.col(j).dot(hb)) return false;
    return true;
}

/// An interval holding m . p for the points p of `node` (its local frame; without a slab, the box's projection):
/// with m = a n + w, w normal to the slab's normal n, a n . p lies in the slab's interval scaled by
/// a and w . p in the box's projection onto w. For m along n it is the slab's own interval, however
/// thick the box; for m normal to n, the box's projection.
inline std::pair<double, double> node_extent_along(const Point_cloud_hierarchy::Node& node, const Eigen::Vector3d& m)
{
    const Eigen::Vector3d c = node.box.center(), h = 0.5 * (node.box.max() - node.box.min());
    if (!node.has_slab()) { // no slab (a refitted tree): the box's projection
        const double mc = m.dot(c), mh = m.cwiseAbs().dot(h);
        return {mc - mh, mc + mh};
    }
    const double a = m.dot(node.slab_normal);
    const Eigen::Vector3d w = m - a * node.slab_normal;
    const double wc = w.dot(c), wh = w.cwiseAbs().dot(h);
    return {(a >= 0.0 ? a * node.slab_min : a * node.slab_max) + wc - wh,
            (a >= 0.0 ? a * node.slab_max : a * node.slab_min) + wc + wh};
}

/// Node `ns` of s as seen from t's frame: its box centre, its slab normal and the shift of its
/// slab's interval, its sphere's centre (a node pair's test needs them; a walk meets each node in
/// several pairs).
struct Mapped_node {
    Point_cloud_hierarchy::Index node = std::numeric_limits<Point_cloud_hierarchy::Index>::max();
    Eigen::Vector3d centre;
    Eigen::Vector3d slab_normal;
    double slab_shift = 0.0;
    Eigen::Vector3d sphere_centre;
};

/// Which tests a traversal of s against t applies to its node pairs: the boxes' separating axes
/// unless both hierarchies use spheres, the spheres when both have them, and the slabs of the
/// nodes that have one (a box_and_slab hierarchy's, not refitted).
struct Pair_tests {
    bool boxes;
    bool spheres;

    Pair_tests(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t)
        : boxes(!(s.volume() == Bounding_volume::sphere && t.volume() == Bounding_volume::sphere)),
          spheres(s.has_spheres() && t.has_spheres())
    {
    }
};

/// Whether node `ns` of s (seen from t's frame as `mapped`; r the rotation of the motion) and node
/// `nt` of t may hold points closer than `margin`, by their slabs: along each node's slab normal,
/// the node's slab against the other node's extent (node_extent_along). False only when one of the
/// two normals separates them. A node without a slab (zero normal, infinite interval) never separates.
inline bool slabs_may_overlap(const Point_cloud_hierarchy::Node& ns, const Mapped_node& mapped, const Eigen::Matrix3d& r,
                              const Eigen::Vector3d& shift, const Point_cloud_hierarchy::Node& nt, double margin)
{
    if (ns.has_slab()) {
        // s's slab in t's frame: normal r n_s, interval shifted by (r n_s) . shift.
        const auto [lo, hi] = node_extent_along(nt, mapped.slab_normal);
        if (lo > ns.slab_max + mapped.slab_shift + margin || hi < ns.slab_min + mapped.slab_shift - margin) return false;
    }
    if (nt.has_slab()) {
        // t's slab normal n_t seen from s: n_t . (r p + shift) = (r^T n_t) . p + n_t . shift.
        const Eigen::Vector3d u = r.transpose() * nt.slab_normal;
        const double offset = nt.slab_normal.dot(shift);
        const auto [lo, hi] = node_extent_along(ns, u);
        if (lo + offset > nt.slab_max + margin || hi + offset < nt.slab_min - margin) return false;
    }
    return true;
}

} // namespace internal

inline bool grown_boxes_may_overlap(const Eigen::AlignedBox3d& a, const Rigid_transform_3<double>& a_to_b,
                                    double margin_a, const Eigen::AlignedBox3d& b, double margin_b)
{
    const Eigen::Matrix3d& r = a_to_b.rotation();
    const Eigen::Matrix3d abs_r = r.cwiseAbs();
    return internal::grown_boxes_may_overlap(a, r, abs_r, a_to_b.transform_point(a.center()), margin_a, b, margin_b);
}

/// Whether the point q (t's local frame) lies within the reach of some point of t: |q - p_k| <=
/// rule(reach_k) for some k. Exact (compares points at the leaves). O(height) nodes for a point
/// near one leaf; more where grown boxes overlap.
/// (A query-path loop, written out like nearest_point()'s: one depth-first helper for both, taking
/// the node visit as a lambda, measured 3 % slower interpolation-search queries.)
inline bool within_reach(const Point_cloud_hierarchy& t, const Eigen::Vector3d& q, const Reach_rule& rule)
{
    if (t.empty()) return false;
    using Index = Point_cloud_hierarchy::Index;
    const Eigen::Matrix4Xd& points = t.ordered_points();
    // A fixed stack: a depth-first walk holds at most one sibling per level, and a median-split tree
    // of < 2^32 points has fewer than 64 levels.
    Index stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Index i = stack[--top];
        const auto& node = t.node(i);
        const double margin = rule(node.reach);
        if ((q.array() < node.box.min().array() - margin).any() || (q.array() > node.box.max().array() + margin).any())
            continue;
        if (node.is_leaf()) {
            for (Index k = node.first; k < node.first + node.count; ++k) {
                const double reach = rule(points(3, k));
                if ((points.col(k).head<3>() - q).squaredNorm() <= reach * reach) return true;
            }
            continue;
        }
        stack[top++] = t.right(i);
        stack[top++] = t.left(i);
    }
    return false;
}

/// The point of t nearest to q (t's local frame): its position in hierarchy order (a column of
/// t.ordered_points()) and its squared distance; {t.size(), +inf} for an empty hierarchy. Exact
/// (branch and bound over the boxes, nearer child first). O(height) nodes for a point near t.
inline std::pair<std::size_t, double> nearest_point(const Point_cloud_hierarchy& t, const Eigen::Vector3d& q)
{
    std::pair<std::size_t, double> best{t.size(), std::numeric_limits<double>::infinity()};
    if (t.empty()) return best;
    using Index = Point_cloud_hierarchy::Index;
    const Eigen::Matrix4Xd& points = t.ordered_points();
    Index stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Index i = stack[--top];
        const auto& node = t.node(i);
        if (node.box.squaredExteriorDistance(q) >= best.second) continue;
        if (node.is_leaf()) {
            for (Index k = node.first; k < node.first + node.count; ++k) {
                const double d = (points.col(k).head<3>() - q).squaredNorm();
                if (d < best.second) best = {k, d};
            }
            continue;
        }
        Index near = t.left(i), far = t.right(i);
        if (t.node(far).box.squaredExteriorDistance(q) < t.node(near).box.squaredExteriorDistance(q)) std::swap(near, far);
        stack[top++] = far;
        stack[top++] = near;
    }
    return best;
}

/// A point of t near q (t's local frame), found by one descent without backtracking: from the root,
/// into the child whose box lies nearer q (the one whose centre is nearer when q is inside both),
/// then the nearest point of that leaf. Returns its position in hierarchy order and its squared
/// distance ({t.size(), +inf} for an empty hierarchy). Not always the nearest point: it is when q
/// lies inside the boxes on one root-to-leaf path only (e.g. on the sampled surface, away from box
/// boundaries), otherwise a point of a leaf whose box is nearest at each level. A cheap step for
/// heuristics (the probes of the walked traversals); nearest_point() is the exact query.
/// Complexity: O(height + leaf size), no stack.
inline std::pair<std::size_t, double> descend_to_near_point(const Point_cloud_hierarchy& t, const Eigen::Vector3d& q)
{
    std::pair<std::size_t, double> best{t.size(), std::numeric_limits<double>::infinity()};
    if (t.empty()) return best;
    using Index = Point_cloud_hierarchy::Index;
    Index i = 0;
    while (!t.node(i).is_leaf()) {
        const Index l = t.left(i), r = t.right(i);
        const double dl = t.node(l).box.squaredExteriorDistance(q), dr = t.node(r).box.squaredExteriorDistance(q);
        if (dl != dr) {
            i = dl < dr ? l : r;
        } else {
            i = (t.node(l).box.center() - q).squaredNorm() <= (t.node(r).box.center() - q).squaredNorm() ? l : r;
        }
    }
    const auto& leaf = t.node(i);
    const Eigen::Matrix4Xd& points = t.ordered_points();
    for (Index k = leaf.first; k < leaf.first + leaf.count; ++k) {
        const double d = (points.col(k).head<3>() - q).squaredNorm();
        if (d < best.second) best = {k, d};
    }
    return best;
}

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
    using Index = Point_cloud_hierarchy::Index;
    const Eigen::Matrix3d& r = s_to_t.rotation();
    const Eigen::Matrix3d abs_r = r.cwiseAbs();
    // A depth-first walk holds at most three pending sibling pairs per level of the two trees.
    std::vector<std::pair<Index, Index>> stack;
    stack.reserve(128);
    stack.emplace_back(0, 0);
    // The nodes of s mapped lately (each appears in several pairs), by node index modulo 64.
    std::array<internal::Mapped_node, 64> mapped_nodes;
    const internal::Pair_tests tests(s, t);
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        ++counters.node_pairs;
        observer.node_pair(i, j);
        const auto& ns = s.node(i);
        const auto& nt = t.node(j);
        internal::Mapped_node& mapped = mapped_nodes[i & 63];
        if (mapped.node != i) {
            mapped.node = i;
            mapped.centre = s_to_t.transform_point(ns.box.center());
            mapped.slab_normal = r * ns.slab_normal;
            mapped.slab_shift = mapped.slab_normal.dot(s_to_t.translation());
            if (tests.spheres) mapped.sphere_centre = s_to_t.transform_point(s.sphere(i).centre);
        }
        const Eigen::Vector3d& centre_s = mapped.centre;
        const double ms = rule_s(ns.reach), mt = rule_t(nt.reach);
        if (tests.boxes && !internal::grown_boxes_may_overlap(ns.box, r, abs_r, centre_s, either ? 0.0 : ms, nt.box,
                                                              either ? std::max(ms, mt) : mt))
            continue;
        const double margin = either ? std::max(ms, mt) : ms + mt;
        if (tests.spheres) {
            const double apart = s.sphere(i).radius + t.sphere(j).radius + margin;
            if ((mapped.sphere_centre - t.sphere(j).centre).squaredNorm() > apart * apart) continue;
        }
        if (!internal::slabs_may_overlap(ns, mapped, r, s_to_t.translation(), nt, margin)) continue;
        if (ns.is_leaf() && nt.is_leaf()) {
            ++counters.leaf_pairs;
            observer.leaf_pair(i, j);
            if (!visit(i, j)) {
                counters.pending = stack.size();
                return counters;
            }
            continue;
        }
        if (!ns.is_leaf() && !nt.is_leaf()) {
            // Both inner: the four child pairs at once (a pair of an inner node and a child is
            // mostly kept where the walk goes on, so testing it first is wasted).
            Index sc[2] = {s.left(i), s.right(i)}, tc[2] = {t.left(j), t.right(j)};
            if (closest_first) {
                const Eigen::Vector3d c = r.transpose() * (nt.box.center() - s_to_t.translation());
                if ((s.node(sc[1]).box.center() - c).squaredNorm() < (s.node(sc[0]).box.center() - c).squaredNorm())
                    std::swap(sc[0], sc[1]);
                if ((t.node(tc[1]).box.center() - centre_s).squaredNorm() < (t.node(tc[0]).box.center() - centre_s).squaredNorm())
                    std::swap(tc[0], tc[1]);
            }
            stack.emplace_back(sc[1], tc[1]);
            stack.emplace_back(sc[1], tc[0]);
            stack.emplace_back(sc[0], tc[1]);
            stack.emplace_back(sc[0], tc[0]);
            continue;
        }
        if (!ns.is_leaf()) {
            Index first = s.left(i), second = s.right(i);
            if (closest_first) {
                // Distances are the same in s's frame: one mapping of t's centre instead of two of s's.
                const Eigen::Vector3d c = r.transpose() * (nt.box.center() - s_to_t.translation());
                const auto distance = [&](Index k) { return (s.node(k).box.center() - c).squaredNorm(); };
                if (distance(second) < distance(first)) std::swap(first, second);
            }
            stack.emplace_back(second, j);
            stack.emplace_back(first, j);
        } else {
            Index first = t.left(j), second = t.right(j);
            if (closest_first) {
                const auto distance = [&](Index k) { return (t.node(k).box.center() - centre_s).squaredNorm(); };
                if (distance(second) < distance(first)) std::swap(first, second);
            }
            stack.emplace_back(i, second);
            stack.emplace_back(i, first);
        }
    }
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
