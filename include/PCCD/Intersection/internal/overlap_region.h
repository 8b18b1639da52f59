// PCCD/Intersection/internal/overlap_region.h -- the part of the overlap of two objects a query
// searches (doc/manual/intersection.md, WSCG05's "Box(A,B)"; the flat traversal): the points of one object that lie in the other's
// leaf boxes (or root box) grown by a margin, and the boxes where randomized sampling draws.
#pragma once

#include <algorithm>
#include <optional>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/overlapping_leaves.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// Calls `visit(node_s, node_t)` for the leaf pairs of the region: overlapping leaves of both
/// hierarchies (leaf_boxes) or leaves of s against t's root (object_boxes).
/// t's descent stops at nodes no larger than `t_stop_size`.
template <class Visitor>
void for_each_region_pair(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                          const Rigid_transform_3<double>& s_to_t, double margin, Overlap_region region,
                          Intersection_counters& counters, Visitor&& visit, double t_stop_size = 0.0)
{
    if (region == Overlap_region::leaf_boxes) {
        const Traversal_counters c = for_each_overlapping_leaf_pair(s, t, s_to_t, margin, visit, t_stop_size);
        counters.node_pairs += c.node_pairs;
        counters.leaf_pairs += c.leaf_pairs;
        return;
    }
    // Object boxes: s's leaves against t's root box only.
    struct Traits {
        const Point_cloud_hierarchy& s;
        const Rigid_transform_3<double>& s_to_t;
        const Eigen::AlignedBox3d& root;
        double margin;
        Visitor& visit;
        std::size_t leaves = 0;
        bool go_further() const { return true; }
        bool enter(Point_cloud_hierarchy::Index i) const { return boxes_may_overlap(s.node(i).box, s_to_t, root, margin); }
        void leaf(Point_cloud_hierarchy::Index i)
        {
            ++leaves;
            visit(i, Point_cloud_hierarchy::Index(0));
        }
        bool left_first(Point_cloud_hierarchy::Index) const { return true; }
    } traits{s, s_to_t, t.root().box, margin, visit};
    counters.node_pairs += traverse(s, Point_cloud_hierarchy::Index(0), traits).tested;
    counters.leaf_pairs += traits.leaves;
}

/// The points of s (indices) whose position, mapped by s_to_t, lies in a region box of t grown by
/// `margin` (see in_region()), in a deterministic order (by leaf of s, then by the leaf's point
/// order). `position(i)` gives s's local coordinates. The sampler below draws from the same set.
template <class Position>
std::vector<std::uint32_t> region_points(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                                         const Rigid_transform_3<double>& s_to_t, double margin, Overlap_region region,
                                         const Position& position, Intersection_counters& counters);

/// Whether the point q (t's frame) lies in a region box of t's subtree at `node`, grown by
/// `margin`: a leaf box (leaf_boxes) or the root box (object_boxes). O(height) boxes for points near
/// one leaf, more where grown boxes overlap.
inline bool in_region(const Point_cloud_hierarchy& t, Point_cloud_hierarchy::Index node, const Eigen::Vector3d& q,
                      double margin, Overlap_region region)
{
    const auto inside = [&](const Eigen::AlignedBox3d& box) {
        return (q.array() >= box.min().array() - margin).all() && (q.array() <= box.max().array() + margin).all();
    };
    if (region == Overlap_region::object_boxes) return inside(t.root().box);
    struct Traits {
        const Point_cloud_hierarchy& t;
        const decltype(inside)& in_box;
        bool found = false;
        bool go_further() const { return !found; }
        bool enter(Point_cloud_hierarchy::Index i) const { return in_box(t.node(i).box); }
        void leaf(Point_cloud_hierarchy::Index) { found = true; }
        bool left_first(Point_cloud_hierarchy::Index) const { return true; }
    } traits{t, inside};
    traverse(t, node, traits);
    return traits.found;
}

template <class Position>
std::vector<std::uint32_t> region_points(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                                         const Rigid_transform_3<double>& s_to_t, double margin, Overlap_region region,
                                         const Position& position, Intersection_counters& counters)
{
    using Index = Point_cloud_hierarchy::Index;
    std::vector<std::pair<Index, Index>> pairs;
    // t is descended to nodes of about twice the margin only: finer boxes prune little more and
    // multiply the pairs; in_region() finishes the test per point.
    for_each_region_pair(
        s, t, s_to_t, margin, region, counters, [&](Index i, Index j) { pairs.emplace_back(i, j); }, 2.0 * margin);
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::uint32_t> points;
    for (std::size_t k = 0; k < pairs.size();) {
        std::size_t end = k;
        while (end < pairs.size() && pairs[end].first == pairs[k].first) ++end;
        for (std::uint32_t p : s.points_of(pairs[k].first)) {
            const Eigen::Vector3d q = s_to_t.transform_point(position(p));
            for (std::size_t m = k; m < end; ++m)
                if (in_region(t, pairs[m].second, q, margin, region)) {
                    points.push_back(p);
                    break;
                }
        }
        k = end;
    }
    return points;
}

/// A uniformly random permutation of [0, n), drawn one element at a time without materializing it
/// (sparse Fisher-Yates: only the displaced entries are stored). O(1) expected per draw.
class Sparse_permutation {
public:
    explicit Sparse_permutation(std::size_t n) : m_size(n) {}

    /// The next element. \pre fewer than n drawn
    std::uint32_t next(Random_engine& engine)
    {
        const std::size_t pick = m_drawn + std::size_t(uniform_index(engine, m_size - m_drawn));
        const std::uint32_t chosen = value_at(pick);
        m_swapped[std::uint32_t(pick)] = value_at(m_drawn);
        ++m_drawn;
        return chosen;
    }

private:
    std::uint32_t value_at(std::size_t k) const
    {
        const auto it = m_swapped.find(std::uint32_t(k));
        return it == m_swapped.end() ? std::uint32_t(k) : it->second;
    }

    std::size_t m_size;
    std::size_t m_drawn = 0;
    std::unordered_map<std::uint32_t, std::uint32_t> m_swapped;
};

/// Draws the points of a region of a cloud s one at a time, uniformly at random without
/// replacement, in two phases that keep a first-hit query cheap when the objects overlap deeply and
/// exact when they barely touch: first, rejection sampling from all of s, testing each drawn point
/// against the region (O(log N) each); once fewer than one draw in 16 lands in the region (after
/// 128 draws), the region is enumerated, minus the points already drawn, and drawn from that list.
/// Both phases draw uniformly from the region points not yet drawn, so the sequence is a uniform
/// random permutation of the region either way.
///
/// `Region` provides: size() (the points of s, drawn as k in [0, size)); id(k) (the cloud index of
/// the k-th); contains(k); enumerate(counters) (the cloud indices of all region points);
/// eager(counters) (the whole region at once when it is cheap to know, e.g. empty, else nullopt).
template <class Region>
class Two_phase_sampler {
public:
    Two_phase_sampler(Region region, Intersection_counters& counters)
        : m_region(std::move(region)), m_counters(&counters), m_size(m_region.size()), m_permutation(m_size)
    {
        if (std::optional<std::vector<std::uint32_t>> list = m_region.eager(counters)) {
            m_enumerated = true;
            m_list = std::move(*list);
            m_counters->candidate_points += m_list.size();
        }
    }

    /// The next region point (an index of s's cloud), or false when the region is exhausted.
    bool next(Random_engine& engine, std::uint32_t& point)
    {
        while (!m_enumerated) {
            if (m_drawn == m_size) return false;
            if (m_drawn >= 128 && 16 * m_accepted < m_drawn) {
                enumerate();
                break;
            }
            const std::uint32_t k = m_permutation.next(engine);
            ++m_drawn;
            const std::uint32_t id = m_region.id(k);
            m_drawn_points.push_back(id);
            if (m_region.contains(k)) {
                ++m_accepted;
                ++m_counters->candidate_points;
                point = id;
                return true;
            }
        }
        if (m_next == m_list.size()) return false;
        const std::size_t pick = m_next + std::size_t(uniform_index(engine, m_list.size() - m_next));
        std::swap(m_list[m_next], m_list[pick]);
        point = m_list[m_next++];
        return true;
    }

    /// The number of region points, once known (after enumeration or when all of s was drawn);
    /// otherwise an estimate from the acceptance rate so far.
    double region_size() const
    {
        if (m_enumerated) return double(m_accepted + m_list.size());
        if (m_drawn == 0) return double(m_size);
        return double(m_size) * double(m_accepted) / double(m_drawn);
    }
    /// True when region_size() is exact.
    bool region_size_known() const { return m_enumerated || m_drawn == m_size; }
    std::size_t accepted() const { return m_accepted + (m_enumerated ? m_next : 0); }

private:
    void enumerate()
    {
        m_enumerated = true;
        std::sort(m_drawn_points.begin(), m_drawn_points.end());
        m_list = m_region.enumerate(*m_counters);
        std::erase_if(m_list, [&](std::uint32_t p) {
            return std::binary_search(m_drawn_points.begin(), m_drawn_points.end(), p);
        });
        m_counters->candidate_points += m_list.size();
    }

    Region m_region;
    Intersection_counters* m_counters;
    std::size_t m_size;
    Sparse_permutation m_permutation;
    bool m_enumerated = false;
    std::size_t m_drawn = 0, m_accepted = 0, m_next = 0;
    std::vector<std::uint32_t> m_drawn_points;
    std::vector<std::uint32_t> m_list;
};

/// The flat traversal's region: the points of s whose position, mapped into t's frame, lies in a
/// leaf box of t (or its root box, Overlap_region::object_boxes) grown by `margin`.
template <class Position>
struct Box_region {
    const Point_cloud_hierarchy* s;
    const Point_cloud_hierarchy* t;
    Rigid_transform_3<double> s_to_t;
    double margin;
    Overlap_region region;
    Position position;

    std::size_t size() const { return s->size(); }
    std::uint32_t id(std::uint32_t k) const { return k; }
    bool contains(std::uint32_t k) const { return in_region(*t, 0, s_to_t.transform_point(position(k)), margin, region); }
    std::vector<std::uint32_t> enumerate(Intersection_counters& counters) const
    {
        return region_points(*s, *t, s_to_t, margin, region, position, counters);
    }
    /// A pair of disjoint objects needs no draws at all.
    std::optional<std::vector<std::uint32_t>> eager(Intersection_counters& counters) const
    {
        ++counters.node_pairs;
        if (!boxes_may_overlap(s->root().box, s_to_t, t->root().box, margin)) return std::vector<std::uint32_t>{};
        return std::nullopt;
    }
};

/// Draws the points of s in the flat traversal's region (Box_region) uniformly at random without
/// replacement (Two_phase_sampler).
template <class Position>
class Region_sampler : public Two_phase_sampler<Box_region<Position>> {
public:
    Region_sampler(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t, const Rigid_transform_3<double>& s_to_t,
                   double margin, Overlap_region region, const Position& position, Intersection_counters& counters)
        : Two_phase_sampler<Box_region<Position>>(Box_region<Position>{&s, &t, s_to_t, margin, region, position}, counters)
    {
    }
};

/// A box of the randomized sampling, in t's frame, and its volume.
struct Sampling_box {
    Eigen::AlignedBox3d box;
    double volume;
};

/// The boxes where randomized sampling draws, in t's frame: for each pair of overlapping leaves
/// (leaf_boxes), or for the two root boxes (object_boxes: WSCG05's Box(A, B)), the bounding box of
/// s's box mapped into t's frame intersected with t's box grown by `margin`. Empty intersections
/// are dropped.
inline std::vector<Sampling_box> sampling_boxes(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                                                const Rigid_transform_3<double>& s_to_t, double margin,
                                                Overlap_region region, Intersection_counters& counters)
{
    using Index = Point_cloud_hierarchy::Index;
    std::vector<Sampling_box> boxes;
    const Eigen::Matrix3d abs_r = s_to_t.rotation().cwiseAbs();
    const Eigen::Vector3d grow = Eigen::Vector3d::Constant(margin);
    const auto add = [&](Index i, Index j) {
        const Eigen::AlignedBox3d& bs = s.node(i).box;
        const Eigen::Vector3d centre = s_to_t.transform_point(0.5 * (bs.min() + bs.max()));
        const Eigen::Vector3d half = abs_r * (0.5 * (bs.max() - bs.min())) + grow;
        Eigen::AlignedBox3d mapped(centre - half, centre + half);
        const Eigen::AlignedBox3d& bt = t.node(j).box;
        const Eigen::AlignedBox3d grown(bt.min() - grow, bt.max() + grow);
        const Eigen::AlignedBox3d both = mapped.intersection(grown);
        if (both.isEmpty()) return;
        const double volume = both.sizes().prod();
        if (volume > 0.0) boxes.push_back({both, volume});
    };
    if (region == Overlap_region::object_boxes) {
        // WSCG05's Box(A, B): the two root boxes only.
        ++counters.node_pairs;
        if (boxes_may_overlap(s.root().box, s_to_t, t.root().box, margin)) {
            ++counters.leaf_pairs;
            add(0, 0);
        }
        return boxes;
    }
    for_each_region_pair(s, t, s_to_t, margin, region, counters, add);
    return boxes;
}

} // namespace PCCD::internal
