// PCCD/Intersection/internal/reach_region.h -- the region of a role under the hierarchy traversals
// (doc/manual/hierarchy.md): the points of the sampled cloud S that lie within the reach of the
// tested cloud T, i.e. where f_T can be defined, drawn one at a time at random without replacement.
// Internal to Interpolation_search.h.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/internal/overlap_region.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// Draws the points of s within the reach of t (Reach_rule `rule_t`; s mapped by s_to_t) uniformly
/// at random without replacement.
///
/// The region is enumerated at once when the traversal finds at most `eager_leaf_pairs` leaf pairs
/// (a near miss or a small contact: the list is short and exact, and an empty region costs no draw).
/// Otherwise (a deep overlap) points are drawn from all of s and kept when within reach (O(log N)
/// each), which finds a contact after a few draws; once fewer than one draw in 16 is kept (after 128
/// draws) the region is enumerated, minus the points already drawn. Every phase draws uniformly from
/// the region points not yet drawn. Same interface as Region_sampler.
class Reach_region_sampler {
public:
    static constexpr std::size_t eager_leaf_pairs = 64;

    Reach_region_sampler(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                         const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_t,
                         Intersection_counters& counters)
        : m_s(&s), m_t(&t), m_s_to_t(s_to_t), m_rule(rule_t), m_counters(&counters), m_size(s.size()),
          m_permutation(s.size())
    {
        Reach_counters c;
        m_enumerated = points_within_reach(s, t, s_to_t, rule_t, m_list, c, eager_leaf_pairs);
        count(c);
        if (m_enumerated)
            m_counters->candidate_points += m_list.size();
        else
            m_list.clear();
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
            const std::uint32_t p = draw_from_all(engine);
            const Eigen::Vector3d q = m_s_to_t.transform_point(m_s->ordered_points().col(p).head<3>());
            if (within_reach(*m_t, q, m_rule)) {
                ++m_accepted;
                ++m_counters->candidate_points;
                point = m_s->order()[p];
                return true;
            }
        }
        if (m_next == m_list.size()) return false;
        const std::size_t pick = m_next + std::size_t(uniform_index(engine, m_list.size() - m_next));
        std::swap(m_list[m_next], m_list[pick]);
        point = m_list[m_next++];
        return true;
    }

    /// The number of region points once known, else an estimate from the acceptance rate so far.
    double region_size() const
    {
        if (m_enumerated) return double(m_accepted + m_list.size());
        if (m_drawn == 0) return double(m_size);
        return double(m_size) * double(m_accepted) / double(m_drawn);
    }
    bool region_size_known() const { return m_enumerated || m_drawn == m_size; }
    std::size_t accepted() const { return m_accepted + (m_enumerated ? m_next : 0); }

private:
    void count(const Reach_counters& c)
    {
        m_counters->node_pairs += c.node_pairs;
        m_counters->leaf_pairs += c.leaf_pairs;
    }

    /// A position in s's hierarchy order, uniformly among those not drawn yet.
    std::uint32_t draw_from_all(Random_engine& engine)
    {
        const std::uint32_t chosen = m_permutation.next(engine);
        m_drawn_points.push_back(m_s->order()[chosen]);
        ++m_drawn;
        return chosen;
    }

    void enumerate()
    {
        m_enumerated = true;
        std::sort(m_drawn_points.begin(), m_drawn_points.end());
        Reach_counters c;
        points_within_reach(*m_s, *m_t, m_s_to_t, m_rule, m_list, c);
        count(c);
        std::erase_if(m_list, [&](std::uint32_t p) {
            return std::binary_search(m_drawn_points.begin(), m_drawn_points.end(), p);
        });
        m_counters->candidate_points += m_list.size();
    }

    const Point_cloud_hierarchy* m_s;
    const Point_cloud_hierarchy* m_t;
    Rigid_transform_3<double> m_s_to_t;
    Reach_rule m_rule;
    Intersection_counters* m_counters;
    std::size_t m_size;
    bool m_enumerated = false;
    std::size_t m_drawn = 0, m_accepted = 0, m_next = 0;
    Sparse_permutation m_permutation;
    std::vector<std::uint32_t> m_drawn_points;
    std::vector<std::uint32_t> m_list;
};

} // namespace PCCD::internal
