// PCCD/Proximity/internal/closest_pairs.h -- the closest point pairs of two posed clouds, as traits
// of the one pair walk of Hierarchy/traversal.h (doc/algorithms.md "Proximity queries", the
// separation distance's branch and bound): node pairs are pruned by a lower bound on the distance
// of their points (the boxes' separating axes, the slabs' and the bounding spheres'), leaf pairs
// compared point by point. Keeps the k closest pairs found in distinct leaf pairs, which the
// distance query refines onto the surfaces, and, when asked, certifies a lower bound of the
// surfaces' distance in the same walk (the smallest |p - q| - reach(p) - reach(q), surface_reach.h).
// Under a budget the walk stops descending and records the smallest bound of the pairs it left, so
// the lower bound it reports stays honest.
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
#include <PCCD/Hierarchy/point_queries.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Proximity/internal/surface_reach.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// A point pair of two hierarchies: positions in hierarchy order (columns of ordered_points()) and
/// their distance.
struct Point_pair {
    std::size_t first = 0;
    std::size_t second = 0;
    double distance = std::numeric_limits<double>::infinity();
};

/// A box of s seen from t's frame: its centre mapped, its half extents, their length, and its
/// extent along t's axes (|r| h). A walk meets each node of s in several consecutive pairs.
struct Mapped_box {
    Eigen::Vector3d centre;
    Eigen::Vector3d half;
    Eigen::Vector3d half_in_t;
    double radius;

    Mapped_box() = default;
    Mapped_box(const Eigen::AlignedBox3d& a, const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r, const Eigen::Vector3d& shift)
        : centre(r * a.center() + shift), half(0.5 * (a.max() - a.min())), half_in_t(abs_r * half), radius(half.norm())
    {
    }
};

/// A lower bound on the distance between the points of box `a` (mapped into b's frame by rotation
/// r, |r| = abs_r) and those of box `b`: the largest gap along the six face normals, and the gap of
/// the boxes' circumscribed spheres. Projections onto a unit axis and distances to a centre shrink
/// distances, so every gap is a lower bound. 0 when none separates.
inline double box_distance_lower_bound(const Mapped_box& a, const Eigen::Matrix3d& r, const Eigen::Matrix3d& abs_r,
                                       const Eigen::AlignedBox3d& b)
{
    const Eigen::Vector3d hb = 0.5 * (b.max() - b.min());
    const Eigen::Vector3d t = a.centre - b.center();
    double gap = (t.cwiseAbs() - hb - a.half_in_t).maxCoeff();
    const Eigen::Vector3d ts = r.transpose() * t, hbs = abs_r.transpose() * hb;
    gap = std::max(gap, (ts.cwiseAbs() - a.half - hbs).maxCoeff());
    gap = std::max(gap, t.norm() - a.radius - hb.norm());
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

/// A locally closest point pair of hierarchies s and t (s mapped into t's frame by `s_to_t`), found
/// by alternating nearest-point queries from the point of t near the centre of s's box: a cheap
/// first bound for the closest-pair walk. Each query is exact, so the distance never grows.
inline Point_pair local_closest_pair(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                                     const Rigid_transform_3<double>& s_to_t, int rounds = 4)
{
    const Rigid_transform_3<double> t_to_s = s_to_t.inverse();
    Point_pair pair;
    pair.second = descend_to_near_point(t, s_to_t.transform_point(s.root().box.center())).first;
    for (int k = 0; k < rounds; ++k) {
        const auto [first, d_s] =
            nearest_point(s, t_to_s.transform_point(Eigen::Vector3d(t.ordered_points().col(pair.second).head<3>())));
        const auto [second, d_t] =
            nearest_point(t, s_to_t.transform_point(Eigen::Vector3d(s.ordered_points().col(first).head<3>())));
        const bool same = first == pair.first && second == pair.second;
        pair = {first, second, std::sqrt(d_t)};
        if (same) break;
    }
    return pair;
}

/// What a closest-pair walk certifies besides its pairs (Closest_pairs_traits::certificate): the
/// smallest gap |T p - q| - reach_s(p) - reach_t(q) over the point pairs (T = s_to_t), as far as it
/// lies below `limit`. Every point of a surface lies within the reach of its nearest cloud point
/// (surface_reach.h), so the surfaces are at least lower() apart, whatever the fit.
struct Gap_certificate {
    Surface_reach reach_s, reach_t;
    /// Gaps at or above it need not be known (a clearance margin, max_distance; +inf: none).
    double limit = std::numeric_limits<double>::infinity();
    /// The smallest gap of a point pair compared so far.
    double found = std::numeric_limits<double>::infinity();
    /// The smallest node bound minus the nodes' largest reaches of the pairs a budget left.
    double pending = std::numeric_limits<double>::infinity();

    /// The certified lower bound of the surfaces' distance.
    double lower() const { return std::min({found, pending, limit}); }
    /// The gaps still worth a node pair's descent.
    double cut() const { return std::min(found, limit); }
};

/// The k closest point pairs of hierarchies s and t (s mapped into t's frame by `s_to_t`), no two
/// in the same leaf pair, within `slack` of the true k closest, as traits of traverse(s, 0, t, 0, traits). A node pair is entered when
/// its lower bound is below the k-th best distance so far (or below `bound` while fewer are known).
/// `stop()` is asked at every node pair; once it says yes the walk descends no further and keeps
/// in `pending_lower` the smallest lower bound of the pairs it then met, i.e. of everything left
/// unvisited. With a `certificate`, a node pair is also entered while its bound minus the nodes'
/// largest reaches lies below the certificate's cut(), and every leaf pair's point pairs update it.
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
    /// Pairs whose lower bound is within `slack` of the k-th best distance are not entered either
    /// (their bound is kept in pending_lower): the pairs found are then within slack of the closest.
    const double slack;
    Stop stop;
    std::vector<Point_pair> best{}; // ascending distance, at most k
    double pending_lower = std::numeric_limits<double>::infinity();
    bool stopped = false;
    std::size_t leaf_pairs = 0;
    std::size_t point_pairs = 0;
    Mapped_box mapped{};
    Index mapped_node = std::numeric_limits<Index>::max();
    /// Set by the caller to certify a lower bound of the surfaces' distance in the same walk.
    Gap_certificate* certificate = nullptr;

    Closest_pairs_traits(const Point_cloud_hierarchy& s_, const Point_cloud_hierarchy& t_, const Rigid_transform_3<double>& s_to_t,
                         std::size_t k_, double bound_, double slack_, Stop stop_)
        : s(s_), t(t_), r(s_to_t.rotation()), abs_r(r.cwiseAbs()), shift(s_to_t.translation()), k(k_), bound(bound_),
          slack(slack_), stop(std::move(stop_))
    {
        best.reserve(k + 1);
    }

    double cutoff() const { return best.size() < k ? bound : best.back().distance; }
    /// The boxes' bound.
    double box_bound(Index i, Index j)
    {
        if (i != mapped_node) {
            mapped = Mapped_box(s.node(i).box, r, abs_r, shift);
            mapped_node = i;
        }
        return box_distance_lower_bound(mapped, r, abs_r, t.node(j).box);
    }
    /// The boxes' bound, raised by the slabs' and then by the gap along the line through the two
    /// box centres (the nodes' extents, box and slab, projected onto it) while none prunes at `cut`.
    /// For distant nodes the face normals of rotated boxes are oblique to the line between them,
    /// and that line is the tight axis (it cut the node pairs of the bunny's far poses 2-2.5x).
    double lower_bound(Index i, Index j, double cut)
    {
        const double boxes = box_bound(i, j);
        if (!(boxes < cut)) return boxes;
        const double slabs = std::max(boxes, slab_gap(s.node(i), r, shift, t.node(j)));
        if (!(slabs < cut)) return slabs;
        const Eigen::Vector3d d = t.node(j).box.center() - mapped.centre;
        const double length = d.norm();
        if (!(length > 0.0)) return slabs;
        const Eigen::Vector3d u = d / length;
        const double s_high = node_extent_along(s.node(i), r.transpose() * u).second + u.dot(shift);
        const double t_low = node_extent_along(t.node(j), u).first;
        return std::max(slabs, t_low - s_high);
    }

    bool go_further() const { return true; }
    bool enter(Index i, Index j)
    {
        if (certificate) return enter_certifying(i, j);
        const double cut = cutoff();
        const double lower = lower_bound(i, j, cut);
        if (!(lower < cut)) return false;
        // The slack applies only once k pairs are known: until then the cutoff is the caller's bound
        // (a clearance margin, max_distance), and a pair within it must not be skipped.
        if (best.size() == k && !(lower < cut - slack)) {
            pending_lower = std::min(pending_lower, lower);
            return false;
        }
        if (!stopped && stop()) stopped = true;
        if (stopped) {
            pending_lower = std::min(pending_lower, lower);
            return false;
        }
        return true;
    }
    /// enter() with a certificate: the pair is entered for the closest pairs (as enter()) or for the
    /// certificate (its bound minus both nodes' largest reaches below the certificate's cut).
    bool enter_certifying(Index i, Index j)
    {
        const double cut = cutoff();
        const double reaches = certificate->reach_s(s.node(i).reach) + certificate->reach_t(t.node(j).reach);
        const double gap_cut = certificate->cut();
        const double lower = lower_bound(i, j, std::max(cut, gap_cut + reaches));
        bool for_gap = lower - reaches < gap_cut;
        // As for the pairs: within the slack of the smallest gap found, the pair's bound itself
        // stands for it (the certified bound is then at most `slack` below the smallest gap).
        if (for_gap && certificate->found < certificate->limit && !(lower - reaches < gap_cut - slack)) {
            certificate->pending = std::min(certificate->pending, lower - reaches);
            for_gap = false;
        }
        bool for_pairs = lower < cut;
        if (for_pairs && best.size() == k && !(lower < cut - slack)) {
            pending_lower = std::min(pending_lower, lower);
            for_pairs = false;
        }
        if (!for_pairs && !for_gap) return false;
        if (!stopped && stop()) stopped = true;
        if (stopped) {
            pending_lower = std::min(pending_lower, lower);
            if (for_gap) certificate->pending = std::min(certificate->pending, lower - reaches);
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
    // The child of the smaller lower bound first.
    bool first_left_first(Index i, Index j) const
    {
        const auto& b = t.node(j).box;
        return box_distance_lower_bound(Mapped_box(s.node(s.left(i)).box, r, abs_r, shift), r, abs_r, b) <=
               box_distance_lower_bound(Mapped_box(s.node(s.right(i)).box, r, abs_r, shift), r, abs_r, b);
    }
    bool second_left_first(Index i, Index j)
    {
        return box_bound(i, t.left(j)) <= box_bound(i, t.right(j));
    }

    /// Starts the walk with a known pair (e.g. from a local search): the pruning is tight from the
    /// first node pair on.
    void seed(const Point_pair& pair)
    {
        best.insert(best.begin(), pair);
        if (certificate) {
            const double reaches = certificate->reach_s(s.ordered_points()(3, Eigen::Index(pair.first))) +
                                   certificate->reach_t(t.ordered_points()(3, Eigen::Index(pair.second)));
            certificate->found = std::min(certificate->found, pair.distance - reaches);
        }
    }

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
        // Two loops, so that the default's inner loop (a quarter of the walk's time) stays as lean as
        // without certificates; the certifying one also lowers the certificate's gap pair by pair.
        if (certificate) {
            double gap = certificate->cut();
            for (auto a = ns.first; a < ns.first + ns.count; ++a) {
                const Eigen::Vector3d p = r * ps.col(a).head<3>() + shift;
                const double reach_a = certificate->reach_s(ps(3, a));
                for (auto b = nt.first; b < nt.first + nt.count; ++b) {
                    const double d = (pt.col(b).head<3>() - p).squaredNorm();
                    if (d < local.distance) {
                        local = {a, b, d};
                        found = true;
                    }
                    const double reaches = reach_a + certificate->reach_t(pt(3, b));
                    const double within = gap + reaches; // |p - q| below it lowers the gap
                    if (within > 0.0 && d < within * within) gap = std::sqrt(d) - reaches;
                }
            }
            certificate->found = std::min(certificate->found, gap);
        } else {
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
        }
        point_pairs += std::size_t(ns.count) * nt.count;
        if (!found) return;
        local.distance = std::sqrt(local.distance);
        for (const Point_pair& known : best)
            if (known.first == local.first && known.second == local.second) return; // the seed, found again
        const auto at = std::upper_bound(best.begin(), best.end(), local.distance,
                                         [](double d, const Point_pair& p) { return d < p.distance; });
        best.insert(at, local);
        if (best.size() > k) best.pop_back();
    }
};

} // namespace PCCD::internal
