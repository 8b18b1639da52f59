// PCCD/Proximity/internal/closest_pairs.h -- the closest point pairs of two posed clouds, as traits
// of the one pair walk of Hierarchy/traversal.h (doc/algorithms.md "Proximity queries", the
// separation distance's branch and bound): node pairs are pruned by a lower bound on the distance
// of their points (the boxes' separating axes, the slabs' and the bounding spheres'), leaf pairs
// compared point by point. Keeps the k closest pairs found in distinct leaf pairs, which the
// distance query refines onto the surfaces. Under a budget the walk stops descending and records
// the smallest bound of the pairs it left, so the lower bound it reports stays honest.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// A point pair of two hierarchies: positions in hierarchy order (columns of ordered_points()) and
/// their distance.
struct Point_pair {
    std::size_t first = 0;
    std::size_t second = 0;
    double distance = std::numeric_limits<double>::infinity();
};

/// A lower bound on the distance between the points of box `a` (mapped into b's frame by rotation
/// r, |r| = abs_r, its centre mapped to `ca`) and those of box `b`: the largest gap along the six
/// face normals, and the gap of the bounding spheres. Projections onto a unit axis and distances to
/// a centre shrink distances, so every gap is a lower bound. 0 when none separates.
inline double box_distance_lower_bound(const Eigen::AlignedBox3d& a, const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r,
                                       const Eigen::Vector3d& ca, const Eigen::AlignedBox3d& b)
{
    const Eigen::Vector3d ha = 0.5 * (a.max() - a.min());
    const Eigen::Vector3d hb = 0.5 * (b.max() - b.min());
    const Eigen::Vector3d t = ca - b.center();
    double gap = t.norm() - ha.norm() - hb.norm();
    for (int i = 0; i < 3; ++i) gap = std::max(gap, std::abs(t(i)) - hb(i) - abs_r.row(i).dot(ha));
    for (int j = 0; j < 3; ++j) gap = std::max(gap, std::abs(t.dot(r.col(j))) - ha(j) - abs_r.col(j).dot(hb));
    return std::max(gap, 0.0);
}

/// The lower bound of box_distance_lower_bound() raised by the nodes' slabs (node_extent_along):
/// along each slab normal, the gap between the slab's interval and the other node's extent.
inline double slab_gap(const Point_cloud_hierarchy::Node& s, const Eigen::Matrix3d& r, const Eigen::Vector3d& shift,
                       const Point_cloud_hierarchy::Node& t)
{
    double gap = 0.0;
    if (s.has_slab()) {
        const Eigen::Vector3d m = r * s.slab_normal; // s's slab normal in t's frame
        const double offset = m.dot(shift);
        const auto [lo, hi] = node_extent_along(t, m);
        gap = std::max({gap, lo - (s.slab_max + offset), (s.slab_min + offset) - hi});
    }
    if (t.has_slab()) {
        const Eigen::Vector3d u = r.transpose() * t.slab_normal;
        const double offset = t.slab_normal.dot(shift);
        const auto [lo, hi] = node_extent_along(s, u);
        gap = std::max({gap, lo + offset - t.slab_max, t.slab_min - (hi + offset)});
    }
    return gap;
}

/// The k closest point pairs of hierarchies s and t (s mapped into t's frame by `s_to_t`), no two
/// in the same leaf pair, as traits of traverse(s, 0, t, 0, traits). A node pair is entered when
/// its lower bound is below the k-th best distance so far (or below `bound` while fewer are known).
/// `stop()` is asked at every node pair; once it says yes the walk descends no further and keeps
/// in `pending_lower` the smallest lower bound of the pairs it then met, i.e. of everything left
/// unvisited.
template <class Stop>
struct Closest_pairs_traits {
    using Index = Point_cloud_hierarchy::Index;
    const Point_cloud_hierarchy& s;
    const Point_cloud_hierarchy& t;
    const Eigen::Matrix3d r;
    const Eigen::Matrix3d abs_r;
    const Eigen::Vector3d shift;
    const std::size_t k;
    const double bound;
    Stop stop;
    std::vector<Point_pair> best{}; // ascending distance, at most k
    double pending_lower = std::numeric_limits<double>::infinity();
    bool stopped = false;
    std::size_t leaf_pairs = 0;
    std::size_t point_pairs = 0;

    Closest_pairs_traits(const Point_cloud_hierarchy& s_, const Point_cloud_hierarchy& t_, const Rigid_transform_3<double>& s_to_t,
                         std::size_t k_, double bound_, Stop stop_)
        : s(s_), t(t_), r(s_to_t.rotation()), abs_r(r.cwiseAbs()), shift(s_to_t.translation()), k(k_), bound(bound_),
          stop(std::move(stop_))
    {
        best.reserve(k + 1);
    }

    double cutoff() const { return best.size() < k ? bound : best.back().distance; }
    double lower_bound(Index i, Index j) const
    {
        const auto& ns = s.node(i);
        const auto& nt = t.node(j);
        const double boxes = box_distance_lower_bound(ns.box, r, abs_r, r * ns.box.center() + shift, nt.box);
        return std::max(boxes, slab_gap(ns, r, shift, nt));
    }

    bool go_further() const { return true; }
    bool enter(Index i, Index j)
    {
        const double lower = lower_bound(i, j);
        if (!(lower < cutoff())) return false;
        if (!stopped && stop()) stopped = true;
        if (stopped) {
            pending_lower = std::min(pending_lower, lower);
            return false;
        }
        return true;
    }
    Pair_split split(Index i, Index j) const
    {
        const bool ls = s.is_leaf(i), lt = t.is_leaf(j);
        if (ls && lt) return Pair_split::leaves;
        if (lt) return Pair_split::first;
        if (ls) return Pair_split::second;
        const double vs = s.node(i).box.diagonal().squaredNorm(), vt = t.node(j).box.diagonal().squaredNorm();
        return vs >= vt ? Pair_split::first : Pair_split::second;
    }
    bool first_left_first(Index i, Index j) const { return lower_bound(s.left(i), j) <= lower_bound(s.right(i), j); }
    bool second_left_first(Index i, Index j) const { return lower_bound(i, t.left(j)) <= lower_bound(i, t.right(j)); }

    void leaf_pair(Index i, Index j)
    {
        ++leaf_pairs;
        const auto& ns = s.node(i);
        const auto& nt = t.node(j);
        const Eigen::Matrix4Xd& ps = s.ordered_points();
        const Eigen::Matrix4Xd& pt = t.ordered_points();
        const double cut = cutoff();
        Point_pair local{0, 0, cut * cut}; // squared while scanning
        bool found = false;
        for (auto a = ns.first; a < ns.first + ns.count; ++a) {
            const Eigen::Vector3d p = r * ps.col(a).head<3>() + shift;
            for (auto b = nt.first; b < nt.first + nt.count; ++b) {
                const double d = (pt.col(b).head<3>() - p).squaredNorm();
                if (d < local.distance) {
                    local = {a, b, d};
                    found = true;
                }
            }
        }
        point_pairs += std::size_t(ns.count) * nt.count;
        if (!found) return;
        local.distance = std::sqrt(local.distance);
        const auto at = std::upper_bound(best.begin(), best.end(), local.distance,
                                         [](double d, const Point_pair& p) { return d < p.distance; });
        best.insert(at, local);
        if (best.size() > k) best.pop_back();
    }
};

} // namespace PCCD::internal
