// PCCD/Intersection/internal/isearch_walk.h -- first-hit interpolation search over a walk of the two
// objects' hierarchies (doc/manual/hierarchy.md, "Traversal policies"): random probes, then the
// leaf pairs of for_each_leaf_pair_within_reach, whose points within the other leaf's reach are
// sampled in their role once each, skipping points a sample already covers. Internal to
// Interpolation_search.h.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/internal/Covering_grid.h>
#include <PCCD/Intersection/internal/Position_set.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Intersection/internal/isearch_role.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::internal {

/// One probe of s for a point within the reach of t: from a random point of s (uniform, with
/// replacement), up to `steps` alternating nearest-point steps (a point of t near it, then a point
/// of s near that, each by descend_to_near_point: a heuristic needs no exact neighbour), which
/// descend to where the two clouds come closest, i.e. to where they cross in a deep overlap. The
/// first point of s found within the reach of t is sampled in `role` unless it was sampled or
/// covered already. Returns false when the query must stop.
template <class Role_type>
inline bool probe(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t, const Reach_rule& rule_t,
                  std::size_t cap, Position_set& done, Covering_grid& cover, Role_type& role,
                  std::size_t steps)
{
    if (role.taken >= cap || s.empty()) return true;
    const Rigid_transform_3<double> t_to_s = role.s_to_t.inverse();
    auto k = std::size_t(uniform_index(role.state.engine, s.size()));
    for (std::size_t step = 0;; ++step) {
        const Eigen::Vector3d local = s.ordered_points().col(Eigen::Index(k)).head<3>();
        const auto [m, squared] = descend_to_near_point(t, role.s_to_t.transform_point(local));
        const double reach = rule_t(t.ordered_points()(3, Eigen::Index(m)));
        if (squared <= reach * reach) {
            if (cover.covers(local) || !done.insert(std::uint32_t(k))) return true;
            cover.add(local);
            ++role.state.counters.candidate_points;
            return role.sample(s.order()[k]) && !role.state.stop();
        }
        if (step >= steps) return true;
        const Eigen::Vector3d back = t_to_s.transform_point(t.ordered_points().col(Eigen::Index(m)).head<3>());
        const auto next = descend_to_near_point(s, back).first;
        if (next == k) return true; // the clouds come closest here, out of reach
        k = next;
    }
}

/// Takes the region point k of s (hierarchy order) in `role`, unless the role has considered it
/// already or a sample it took covers it (a covered point is remembered in role.skipped, when
/// set). Returns false when the query must stop.
template <class Role_type>
bool consider_point(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index k, Position_set& done,
                    Covering_grid& cover, Role_type& role)
{
    if (!done.insert(k)) return true;
    ++role.state.counters.candidate_points;
    const Eigen::Vector3d local = s.ordered_points().col(k).head<3>();
    if (cover.covers(local)) {
        if (role.skipped) role.skipped->push_back(k);
        return true;
    }
    cover.add(local);
    return role.sample(s.order()[k]) && !role.state.stop();
}

/// Samples, in `role`, the points of leaf `ls` of s within the reach of leaf `lt` of t that the
/// role has not sampled yet, up to `cap` samples. Returns false when the query must stop.
template <class Role_type>
bool sample_leaf(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index ls, const Point_cloud_hierarchy& t,
                 Point_cloud_hierarchy::Index lt, const Reach_rule& rule_t, std::size_t cap,
                 Position_set& done, Covering_grid& cover, Role_type& role)
{
    const auto& ns = s.node(ls);
    const auto& nt = t.node(lt);
    const Eigen::Matrix4Xd& ps = s.ordered_points();
    const Eigen::Matrix4Xd& pt = t.ordered_points();
    for (auto k = ns.first; k < ns.first + ns.count; ++k) {
        if (role.taken >= cap) return true;
        const Eigen::Vector3d q = role.s_to_t.transform_point(Eigen::Vector3d(ps.col(k).head<3>()));
        bool inside = false;
        for (auto m = nt.first; m < nt.first + nt.count && !inside; ++m) {
            const double reach = rule_t(pt(3, m));
            inside = (pt.col(m).head<3>() - q).squaredNorm() <= reach * reach;
        }
        if (inside && !consider_point(s, k, done, cover, role)) return false;
    }
    return true;
}

/// Samples, in `role`, the points of leaf `ls` of s whose bit is set in `inside` (bit k: the leaf's
/// k-th point in hierarchy order) that the role has not sampled yet and that no sample covers, up
/// to `cap` samples. Returns false when the query must stop.
template <class Role_type>
bool sample_marked(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index ls, std::uint64_t inside,
                   std::size_t cap, Position_set& done, Covering_grid& cover, Role_type& role)
{
    const auto& ns = s.node(ls);
    for (; inside != 0; inside &= inside - 1) {
        if (role.taken >= cap) return true;
        const auto k = ns.first + Point_cloud_hierarchy::Index(std::countr_zero(inside));
        if (!consider_point(s, k, done, cover, role)) return false;
    }
    return true;
}

/// Both roles at a leaf pair: the points of leaf `la` of a within the reach of a point of leaf `lb`
/// of b are sampled in `role_a` (when `use_a`), then those of `lb` within the reach of a point of
/// `la` in `role_b` (when `use_b`), as two calls of sample_leaf() would, but with each point
/// mapped and each distance computed once for both. Returns false when the query must stop.
template <class Role_a, class Role_b>
bool sample_leaf_pair(const Point_cloud_hierarchy& ha, Point_cloud_hierarchy::Index la, const Point_cloud_hierarchy& hb,
                      Point_cloud_hierarchy::Index lb, const Reach_rule& rule_a, const Reach_rule& rule_b,
                      std::size_t cap, bool use_a, bool use_b, Position_set& done_a,
                      Covering_grid& cover_a, Role_a& role_a, Position_set& done_b,
                      Covering_grid& cover_b, Role_b& role_b)
{
    using Index = Point_cloud_hierarchy::Index;
    constexpr Index most = 64; // one bit per point of a leaf
    const auto& na = ha.node(la);
    const auto& nb = hb.node(lb);
    if (na.count > most || nb.count > most) { // leaves larger than the masks: one side at a time
        if (use_a && !sample_leaf(ha, la, hb, lb, rule_b, cap, done_a, cover_a, role_a)) return false;
        return !use_b || sample_leaf(hb, lb, ha, la, rule_a, cap, done_b, cover_b, role_b);
    }
    // The points each role still has to consider; a pair whose points are all done is skipped.
    const auto all = [](Index count) { return count == most ? ~std::uint64_t(0) : (std::uint64_t(1) << count) - 1; };
    const std::uint64_t need_a = use_a && role_a.taken < cap ? all(na.count) & ~done_a.mask(na.first, na.count) : 0;
    const std::uint64_t need_b = use_b && role_b.taken < cap ? all(nb.count) & ~done_b.mask(nb.first, nb.count) : 0;
    if (need_a == 0 && need_b == 0) return true;
    const Eigen::Matrix4Xd& pa = ha.ordered_points();
    const Eigen::Matrix4Xd& pb = hb.ordered_points();
    double reach_b[most];
    for (Index m = 0; m < nb.count; ++m) {
        reach_b[m] = rule_b(pb(3, nb.first + m));
        reach_b[m] *= reach_b[m];
    }
    // Point k of la against the points of lb: all of them when k is needed, else only the needed
    // points of lb not yet found inside. Each distance serves both roles.
    std::uint64_t inside_a = 0, inside_b = 0; // bit k: point k of the leaf is within the other's reach
    for (Index k = 0; k < na.count; ++k) {
        const bool want = (need_a >> k) & 1;
        std::uint64_t row = want ? all(nb.count) : need_b & ~inside_b;
        if (row == 0) continue;
        const Eigen::Vector3d mapped = role_a.s_to_t.transform_point(Eigen::Vector3d(pa.col(na.first + k).head<3>()));
        double reach_k = rule_a(pa(3, na.first + k));
        reach_k *= reach_k;
        for (; row != 0; row &= row - 1) {
            const auto m = Index(std::countr_zero(row));
            const double squared = (pb.col(nb.first + m).head<3>() - mapped).squaredNorm();
            if (squared <= reach_b[m]) inside_a |= std::uint64_t(want) << k;
            if (squared <= reach_k) inside_b |= std::uint64_t(1) << m;
        }
    }
    inside_b &= need_b;
    if (use_a && !sample_marked(ha, la, inside_a, cap, done_a, cover_a, role_a)) return false;
    return !use_b || sample_marked(hb, lb, inside_b, cap, done_b, cover_b, role_b);
}

/// First-hit queries under the depth_first and likelihood traversals: the two hierarchies are
/// walked together (for_each_leaf_pair_within_reach) and, at each leaf pair, the points of
/// either leaf within the reach of the other leaf's points are sampled at once in both roles
/// (each point once per role; per role at most `samples` or max_samples). The walk stops at the
/// first verified contact, when the budget is spent, or when both roles have their samples.
///
/// `complete` (a "separate" is to be certified, Intersection_options::certify_separation): when the
/// walk ends without a contact, the region points its covering skipped are sampled too, so that
/// every point of the region within reach has been sampled once in each role. Each sample's outcome
/// depends on the point alone (predicted partners, the stored or computed path, the projection), so
/// the walk then finds a contact whenever intersection_points(), which samples the same region, does.
/// Returns true when that holds or the query stopped; false otherwise: without `complete`, when a
/// role reached its sample cap first, or when the partners are drawn at random (the caller must
/// then search the region in full before a "separate").
template <class Policy, class A, class B>
bool walk_first_hit(const Policy& policy, const Posed_object<A>& a, const Posed_object<B>& b,
                    const Intersection_options& options, double epsilon, Query_state& state, bool complete = false)
{
    using Index = Point_cloud_hierarchy::Index;
    const bool use_a = options.symmetric || a.size() <= b.size();
    const bool use_b = options.symmetric || a.size() > b.size();
    // The covering bounds the samples; max_samples (or a fixed count) still caps them.
    const std::size_t cap = policy.samples ? *policy.samples : policy.max_samples;
    constexpr double tiny = 1e-300; // a covering radius must be > 0 for the grid
    const Point_cloud_hierarchy& ha = a.object->hierarchy();
    const Point_cloud_hierarchy& hb = b.object->hierarchy();
    const Reach_rule rule_a{.scale = 1.0, .cap = a.support_radius()};
    const Reach_rule rule_b{.scale = 1.0, .cap = b.support_radius()};
    // Completion needs each sample's outcome to depend on the point alone.
    complete = complete && policy.partner_choice == std::remove_cvref_t<decltype(policy.partner_choice)>::predicted;
    bool whole = false;
    with_path_source(policy, a, [&](const auto& source_a) {
        with_path_source(policy, b, [&](const auto& source_b) {
            Isearch_role<Policy, A, B, std::remove_cvref_t<decltype(source_a)>> role_a{policy, a, b, source_a, state, epsilon};
            Isearch_role<Policy, B, A, std::remove_cvref_t<decltype(source_b)>> role_b{policy, b, a, source_b, state, epsilon};
            Position_set done_a, done_b;
            Covering_grid cover_a(std::max(policy.walk_cover * role_a.rho, tiny));
            Covering_grid cover_b(std::max(policy.walk_cover * role_b.rho, tiny));
            std::vector<std::uint32_t> skipped_a, skipped_b;
            role_a.cover = &cover_a;
            role_b.cover = &cover_b;
            if (complete) {
                role_a.skipped = &skipped_a;
                role_b.skipped = &skipped_b;
            }
            const auto active = [&] { return (use_a && role_a.taken < cap) || (use_b && role_b.taken < cap); };
            // A deep overlap has contacts all over: a few random points within reach find one
            // sooner than the walk, which goes to the leaves first.
            for (std::size_t k = 0; k < policy.probe_draws && !state.stop(); ++k) {
                if (use_a && !probe(ha, hb, rule_b, cap, done_a, cover_a, role_a, policy.probe_steps)) return;
                if (use_b && !state.stop() && !probe(hb, ha, rule_a, cap, done_b, cover_b, role_b, policy.probe_steps))
                    return;
            }
            if (state.stop()) return;
            const Reach_counters c = for_each_leaf_pair_within_reach(
                ha, hb, role_a.s_to_t, rule_a, rule_b,
                [&](Index la, Index lb) {
                    if (state.out_of_budget()) return false;
                    if (!sample_leaf_pair(ha, la, hb, lb, rule_a, rule_b, cap, use_a, use_b, done_a, cover_a, role_a,
                                          done_b, cover_b, role_b))
                        return false;
                    return active();
                },
                options.traversal == Traversal::likelihood, true, Visitor_pairs{state.visitor});
            state.counters.node_pairs += c.node_pairs;
            state.counters.leaf_pairs += c.leaf_pairs;
            state.counters.pending_node_pairs += c.pending;
            if (!complete || state.stop()) {
                whole = state.stop();
                return;
            }
            // A role that reached its cap left region points unconsidered: not complete.
            if ((use_a && role_a.taken >= cap) || (use_b && role_b.taken >= cap)) return;
            role_a.cover = nullptr;
            role_b.cover = nullptr;
            ++state.counters.certification_passes;
            for (const std::uint32_t k : skipped_a)
                if (!role_a.sample(ha.order()[k]) || state.stop()) break;
            for (const std::uint32_t k : skipped_b)
                if (state.stop() || !role_b.sample(hb.order()[k])) break;
            whole = true;
        });
    });
    return whole;
}

} // namespace PCCD::internal
