// PCCD/Intersection/internal/reach_region.h -- the region of a role under the hierarchy traversals
// (doc/manual/hierarchy.md): the points of the sampled cloud S that lie within the reach of the
// tested cloud T, i.e. where f_T can be defined, drawn one at a time at random without replacement.
// Internal to Interpolation_search.h.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/internal/overlap_region.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// The walked traversals' region for intersection_points(): the points of s within the reach of t
/// (Reach_rule `rule`; s mapped by s_to_t), drawn as positions k of s's hierarchy order. Enumerated
/// at once when the walk finds at most `eager_leaf_pairs` leaf pairs (a near miss or a small
/// contact: the list is short and exact, and an empty region costs no draw). The traversal's node
/// and leaf pairs go to `pairs` (a query's visitor).
struct Reach_region {
    static constexpr std::size_t eager_leaf_pairs = 64;

    const Point_cloud_hierarchy* s;
    const Point_cloud_hierarchy* t;
    Rigid_transform_3<double> s_to_t;
    Reach_rule rule;
    Visitor_pairs pairs;

    std::size_t size() const { return s->size(); }
    std::uint32_t id(std::uint32_t k) const { return s->order()[k]; }
    bool contains(std::uint32_t k) const
    {
        return within_reach(*t, s_to_t.transform_point(Eigen::Vector3d(s->ordered_points().col(k).head<3>())), rule);
    }
    std::vector<std::uint32_t> enumerate(Intersection_counters& counters) const { return *list(counters, std::nullopt); }
    std::optional<std::vector<std::uint32_t>> eager(Intersection_counters& counters) const
    {
        return list(counters, eager_leaf_pairs);
    }

private:
    std::optional<std::vector<std::uint32_t>> list(Intersection_counters& counters,
                                                   std::optional<std::size_t> max_leaf_pairs) const
    {
        std::vector<std::uint32_t> out;
        Reach_counters c;
        const bool complete = points_within_reach(*s, *t, s_to_t, rule, out, c,
                                                  max_leaf_pairs.value_or(std::numeric_limits<std::size_t>::max()), pairs);
        counters.node_pairs += c.node_pairs;
        counters.leaf_pairs += c.leaf_pairs;
        if (!complete) return std::nullopt;
        return out;
    }
};

/// Draws the points of s within the reach of t uniformly at random without replacement
/// (Two_phase_sampler over Reach_region).
class Reach_region_sampler : public Two_phase_sampler<Reach_region> {
public:
    Reach_region_sampler(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t,
                         const Rigid_transform_3<double>& s_to_t, const Reach_rule& rule_t,
                         Intersection_counters& counters, Visitor_pairs pairs = {})
        : Two_phase_sampler<Reach_region>(Reach_region{&s, &t, s_to_t, rule_t, pairs}, counters)
    {
    }
};

} // namespace PCCD::internal
