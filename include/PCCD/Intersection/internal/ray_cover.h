// PCCD/Intersection/internal/ray_cover.h -- the parts of a ray where a cloud's surface can be
// defined, for ray_intersection() (doc/algorithms.md "Ray queries"): the union of the ray's
// intervals through the reach balls of the cloud's points, produced lazily in increasing t by a
// best-first walk of the point cloud hierarchy (nodes ordered by where the ray enters their volume
// grown by their reach). A best-first walk rather than the depth-first traverse() of
// Hierarchy/traversal.h: the march along the ray may evaluate f at t only once every ball the ray
// enters before t is known, and a priority queue on the entry parameter gives exactly that.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Intersection/Ray_hit.h>

namespace PCCD::internal {

/// The covered parts of the ray o + t d (|d| = 1, local frame of the hierarchy), t in [0, t_max]:
/// where some point p_k has |o + t d - p_k| <= reach_k, reach_k = min(stored reach, cap) (the cap
/// alone for a hierarchy without reaches). Outside them f is undefined (the CollisionObject concept).
/// Queried with non-decreasing t: seek() finds the first covered t at or after a given one,
/// stretch_end() how far the covered stretch holding t reaches.
class Ray_reach_cover {
public:
    using Index = Point_cloud_hierarchy::Index;

    Ray_reach_cover(const Point_cloud_hierarchy& tree, double cap, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& direction, double t_max, Ray_counters& counters)
        : m_tree(tree), m_points(tree.ordered_points()), m_cap(cap), m_origin(origin), m_direction(direction),
          m_t_max(t_max), m_counters(counters)
    {
        for (int i = 0; i < 3; ++i) {
            // Components below 1e-12 do not restrict a box (conservative: the ray may drift into it);
            // exactly 0 is tested as parallel. The inverse then stays below 1e12: no overflow.
            m_axis[i] = direction(i) == 0.0 ? Axis::parallel : std::abs(direction(i)) < 1e-12 ? Axis::free : Axis::sloped;
            m_inverse(i) = m_axis[i] == Axis::sloped ? 1.0 / direction(i) : 0.0;
        }
        m_nodes.reserve(64);
        m_intervals.reserve(64);
        if (!tree.empty()) consider(0);
    }

    /// Moves t to the first covered parameter >= t; false when there is none in [t, t_max].
    bool seek(double& t)
    {
        open_until(t);
        merge_entered(t);
        if (m_end >= t) return true;
        t = next_start(); // +infinity when no ball is left; every ball's interval ends by t_max
        if (std::isinf(t)) return false;
        merge_entered(t);
        return true;
    }

    /// The end of the covered stretch holding t (t covered, as seek() left it), exact up to
    /// `limit`: every ball the ray enters before min(limit, the returned end) is merged in.
    double stretch_end(double t, double limit)
    {
        open_until(limit);
        while (!m_intervals.empty() && m_intervals.front().first <= std::min(limit, std::max(m_end, t))) pop_interval();
        return m_end;
    }

    /// The first covered parameter after the current stretch (+infinity when none): call when
    /// stretch_end() stopped short of its limit.
    double next_start()
    {
        for (;;) {
            const double node = m_nodes.empty() ? infinity : m_nodes.front().first;
            const double ball = m_intervals.empty() ? infinity : m_intervals.front().first;
            if (ball <= node) return ball;
            open_next();
        }
    }

private:
    static constexpr double infinity = std::numeric_limits<double>::infinity();
    enum class Axis : unsigned char { sloped, parallel, free };
    /// (entry parameter, node) and (entry, exit) pairs, kept as min-heaps on the entry.
    using Node_entry = std::pair<double, Index>;
    using Interval = std::pair<double, double>;
    struct Later {
        template <class P>
        bool operator()(const P& a, const P& b) const
        {
            return a.first > b.first;
        }
    };

    void open_until(double t)
    {
        while (!m_nodes.empty() && m_nodes.front().first <= t) open_next();
    }

    /// Merges every known ball interval the ray enters at or before t.
    void merge_entered(double t)
    {
        while (!m_intervals.empty() && m_intervals.front().first <= t) pop_interval();
    }

    void pop_interval()
    {
        m_end = std::max(m_end, m_intervals.front().second);
        std::pop_heap(m_intervals.begin(), m_intervals.end(), Later{});
        m_intervals.pop_back();
    }

    void open_next()
    {
        const Index i = m_nodes.front().second;
        std::pop_heap(m_nodes.begin(), m_nodes.end(), Later{});
        m_nodes.pop_back();
        if (m_tree.is_leaf(i)) {
            ++m_counters.leaf_visits;
            const auto& node = m_tree.node(i);
            const bool has_reach = m_tree.has_reach();
            for (Index k = node.first; k < node.first + node.count; ++k) {
                const double reach = has_reach ? std::min(m_points(3, k), m_cap) : m_cap;
                if (!(reach > 0.0)) continue;
                const Eigen::Vector3d v = m_points.col(k).head<3>() - m_origin;
                const double along = v.dot(m_direction);
                const double off2 = (v - along * m_direction).squaredNorm();
                const double r2 = reach * reach;
                if (off2 > r2) continue;
                const double half = std::sqrt(r2 - off2);
                const double enter = std::max(along - half, 0.0), exit = std::min(along + half, m_t_max);
                if (enter > exit) continue;
                m_intervals.emplace_back(enter, exit);
                std::push_heap(m_intervals.begin(), m_intervals.end(), Later{});
            }
            return;
        }
        consider(m_tree.left(i));
        consider(m_tree.right(i));
    }

    /// Queues node i if the ray crosses its volume grown by its reach within [0, t_max].
    void consider(Index i)
    {
        ++m_counters.node_visits;
        const auto& node = m_tree.node(i);
        const double margin = m_tree.has_reach() ? std::min(node.reach, m_cap) : m_cap;
        double enter = 0.0, exit = m_t_max;
        for (int a = 0; a < 3; ++a) {
            const double lo = node.box.min()(a) - margin, hi = node.box.max()(a) + margin;
            if (m_axis[a] == Axis::parallel) {
                if (m_origin(a) < lo || m_origin(a) > hi) return;
            } else if (m_axis[a] == Axis::sloped) {
                double t1 = (lo - m_origin(a)) * m_inverse(a), t2 = (hi - m_origin(a)) * m_inverse(a);
                if (t1 > t2) std::swap(t1, t2);
                enter = std::max(enter, t1);
                exit = std::min(exit, t2);
            }
        }
        if (node.has_slab()) {
            // The slab grown by the margin holds every reach ball of the node's points too.
            const double along = node.slab_normal.dot(m_direction), at = node.slab_normal.dot(m_origin);
            const double lo = node.slab_min - margin, hi = node.slab_max + margin;
            if (std::abs(along) >= 1e-12) {
                double t1 = (lo - at) / along, t2 = (hi - at) / along;
                if (t1 > t2) std::swap(t1, t2);
                enter = std::max(enter, t1);
                exit = std::min(exit, t2);
            } else if (along == 0.0 && (at < lo || at > hi)) {
                return;
            }
        }
        if (enter > exit) return;
        m_nodes.emplace_back(enter, i);
        std::push_heap(m_nodes.begin(), m_nodes.end(), Later{});
    }

    const Point_cloud_hierarchy& m_tree;
    const Eigen::Matrix4Xd& m_points;
    double m_cap;
    Eigen::Vector3d m_origin;
    Eigen::Vector3d m_direction;
    double m_t_max;
    Ray_counters& m_counters;
    Axis m_axis[3];
    Eigen::Vector3d m_inverse;
    std::vector<Node_entry> m_nodes;
    std::vector<Interval> m_intervals;
    /// The end of the covered stretch merged so far (-infinity before the first).
    double m_end = -infinity;
};

} // namespace PCCD::internal
