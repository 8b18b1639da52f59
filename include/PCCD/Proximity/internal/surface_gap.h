// PCCD/Proximity/internal/surface_gap.h -- a certified lower bound of the distance between the
// implicit surfaces of two posed objects, from their hierarchies alone (doc/algorithms.md
// "Continuous collision", the advancement's bound): a surface is defined only within the reach of
// its nearest cloud point (the domain radius, capped by the kernel's support radius), so no two
// surface points are closer than min over point pairs of |p - q| - reach(p) - reach(q). The walk is
// a traits class of the pair walk of Hierarchy/traversal.h, pruned by the node bounds of the
// closest-pair walk (closest_pairs.h) lowered by the nodes' largest reaches.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/Reach_rule.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Proximity/internal/closest_pairs.h>
#include <PCCD/Proximity/internal/surface_reach.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// What surface_gap_lower_bound() found.
struct Surface_gap_bound {
    /// A lower bound of the distance between the two surfaces (<= 0: they may meet), or, when
    /// `below` is true, the gap of one point pair that lies below the caller's threshold.
    double lower = std::numeric_limits<double>::infinity();
    /// The walk stopped at a point pair whose gap |p - q| - reach(p) - reach(q) is below the
    /// threshold: the surfaces may come that close, `lower` is that pair's gap (not a bound).
    bool below = false;
    /// Node pairs tested.
    std::size_t node_pairs = 0;
};

/// Traits of the pair walk for surface_gap_lower_bound(): minimizes |T p - q| - reach(p) -
/// reach(q) over the point pairs (T = s_to_t), visiting a node pair only while its bound (the
/// closest-pair walk's node bound minus both nodes' largest reaches) is below the best gap so far.
struct Surface_gap_traits {
    using Index = Point_cloud_hierarchy::Index;
    struct Never {
        bool operator()() const { return false; }
    };

    Closest_pairs_traits<Never> boxes; // the node bounds, split and child order of the closest-pair walk
    const Rigid_transform_3<double>& s_to_t;
    Surface_reach reach_s, reach_t;
    double best;          // the smallest gap found (starts at the caller's limit)
    double enough;        // stop once a gap below this is found
    std::size_t budget;   // node pairs entered before the walk stops descending
    std::size_t entered = 0;
    double pending_lower = std::numeric_limits<double>::infinity();
    bool below = false;

    Surface_gap_traits(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t, const Rigid_transform_3<double>& s_to_t_,
                       Surface_reach rs, Surface_reach rt, double limit, double enough_, std::size_t budget_)
        : boxes(s, t, s_to_t_, 1, std::numeric_limits<double>::infinity(), 0.0, Never{}), s_to_t(s_to_t_), reach_s(rs),
          reach_t(rt), best(limit), enough(enough_), budget(budget_)
    {
    }

    bool go_further() const { return !below; }
    bool enter(Index i, Index j)
    {
        const double reaches = reach_s(boxes.s.node(i).reach) + reach_t(boxes.t.node(j).reach);
        const double lower = boxes.lower_bound(i, j, best + reaches) - reaches;
        if (!(lower < best)) return false;
        if (entered >= budget) { // out of budget: what is left is bounded by its node bound
            pending_lower = std::min(pending_lower, lower);
            return false;
        }
        ++entered;
        return true;
    }
    Pair_split split(Index i, Index j) const { return boxes.split(i, j); }
    bool first_left_first(Index i, Index j) const { return boxes.first_left_first(i, j); }
    bool second_left_first(Index i, Index j) { return boxes.second_left_first(i, j); }
    void leaf_pair(Index i, Index j)
    {
        const double gap = leaf_pair_gap(boxes.s, i, boxes.t, j, s_to_t, reach_s.rule, reach_t.rule) - reach_s.extra - reach_t.extra;
        if (gap < best) best = gap;
        if (best < enough) below = true;
    }
};

/// A lower bound of the distance between the surfaces of hierarchies s and t (s mapped into t's
/// frame by `s_to_t`) whose points reach as far as `reach_s` and `reach_t` say: the smallest
/// |T p - q| - reach_s(p) - reach_t(q) over all point pairs, or a value >= `limit` when none is
/// below `limit`. Certified whatever the fit: every zero of f lies within the reach of its nearest
/// cloud point. The walk enters at most `budget` node pairs; what it leaves is bounded by its node
/// bounds (so the bound loosens, never fails). Once a pair's gap falls below `enough` the walk
/// stops and reports it with `below` set. Deterministic. Complexity: O(node pairs entered) node
/// tests plus the leaf pairs' point pairs.
inline Surface_gap_bound surface_gap_lower_bound(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                                                 const Rigid_transform_3<double>& s_to_t, const Surface_reach& reach_s,
                                                 const Surface_reach& reach_t, double limit, double enough, std::size_t budget)
{
    Surface_gap_bound result;
    if (s.empty() || t.empty()) return result; // an empty cloud has no surface: nothing is ever close
    Surface_gap_traits traits(s, t, s_to_t, reach_s, reach_t, limit, enough, budget);
    const Walk_counters w = traverse(s, Point_cloud_hierarchy::Index(0), t, Point_cloud_hierarchy::Index(0), traits);
    result.node_pairs = w.tested;
    result.below = traits.below;
    result.lower = traits.below ? traits.best : std::min(traits.best, traits.pending_lower);
    return result;
}

} // namespace PCCD::internal
