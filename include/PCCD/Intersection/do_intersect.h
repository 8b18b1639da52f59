// PCCD/Intersection/do_intersect.h -- the public entry points of the stochastic intersection
// (doc/manual/intersection.md; the walk of doc/manual/hierarchy.md): do_intersect() answers at the first
// intersection found, intersection_points() samples the intersection curves at a chosen spacing.
// Objects are preprocessed once (Point_cloud_object) and posed by rigid transforms per query.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Intersection/Interpolation_search.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/Randomized_sampling.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Intersection/refinement.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/internal/timing.h>
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/concepts/LeafIntersector.h>

namespace PCCD {
namespace internal {

/// False when no verified contact can exist, decided on the hierarchies alone (no f evaluation): a
/// verified contact x lies within contact_core D_p of its nearest point p of A and within
/// contact_core D_q of its nearest point q of B, and within the kernel's support of both, so A and
/// B must have points p, q with |p - q| <= min(c D_p, R_A) + min(c D_q, R_B). Only the boxes are
/// compared here (the walk stops at the first leaf pair whose grown boxes overlap: comparing points
/// measured slower than leaving them to the traversal), so false is exact and true is "maybe".
/// Without verification, or for the flat traversal or hierarchies without reaches, true.
template <class A, class B>
bool surfaces_may_touch(const Posed_object<A>& pa, const Posed_object<B>& pb, const Intersection_options& options,
                        Intersection_counters& counters)
{
    const Point_cloud_hierarchy& ha = pa.object->hierarchy();
    const Point_cloud_hierarchy& hb = pb.object->hierarchy();
    if (options.traversal == Traversal::flat || !options.verify_contacts || !ha.has_reach() || !hb.has_reach())
        return true;
    Reach_counters c;
    const bool meet = reaches_meet(ha, hb, pb.from_world * pa.to_world,
                                   Reach_rule{.scale = options.contact_core, .cap = pa.support_radius()},
                                   Reach_rule{.scale = options.contact_core, .cap = pb.support_radius()}, c,
                                   0, Visitor_pairs{options.visitor});
    counters.node_pairs += c.node_pairs;
    counters.leaf_pairs += c.leaf_pairs;
    return meet;
}

/// "Separate" is earned (Intersection_options::certify_separation): called when a query found no
/// verified contact and its budget holds. Unless the policy's own search was already the complete
/// interpolation search (intersection_points() with Interpolation_search), the interpolation search
/// samples the whole region from the query's seed; then the first crossing the verification
/// rejected that passed Query_state::crossing_check becomes the answer's point.
template <class A, class B, class Policy>
void certify_separation(const Posed_object<A>& pa, const Posed_object<B>& pb, const Intersection_options& options,
                        const Policy& policy, double r_min, Query_state& state)
{
    constexpr bool isearch = std::is_same_v<Policy, Interpolation_search>;
    if (!state.region_searched && (!isearch || state.sink.first_hit())) {
        const Interpolation_search search = [&] {
            if constexpr (isearch) return policy;
            else return Interpolation_search{};
        }();
        const double epsilon = isearch ? options.epsilon.value_or(search.default_epsilon(r_min))
                                       : search.default_epsilon(r_min);
        state.engine = Random_engine(state.seed);
        state.search_all = true;
        state.rejected_crossing.reset();
        ++state.counters.certification_passes;
        search.run_roles(pa, pb, options, epsilon, state);
    }
    if (state.sink.size() == 0 && state.rejected_crossing && !state.out_of_budget()) {
        state.sink.add(*state.rejected_crossing);
        ++state.counters.unverified_crossings;
    }
}

template <class A, class B, class Policy>
Intersection_result run_query(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                              const Rigid_transform_3<double>& pose_b, const Intersection_options& options,
                              const Policy& policy, bool first_hit, const char* function)
{
    check_options(options, function);
    policy.check();
    const Posed_object<A> pa(a, pose_a);
    const Posed_object<B> pb(b, pose_b);
    const double r_min = std::min(pa.sampling_radius(), pb.sampling_radius());
    const double epsilon = options.epsilon.value_or(policy.default_epsilon(r_min));
    const double spacing = options.point_spacing.value_or(std::max(pa.sampling_radius(), pb.sampling_radius()));
    if (!(std::isfinite(epsilon) && epsilon > 0.0))
        throw Invalid_input(concat(function, ": the automatic epsilon ", epsilon, " is not positive"));

    Intersection_result result;
    const auto start = Steady_clock::now();
    // The separation test first: a "no" it proves needs no query state at all.
    if (!surfaces_may_touch(pa, pb, options, result.counters)) {
        result.status = Intersection_status::separate;
        result.closest_estimate = std::numeric_limits<double>::infinity(); // no point lies in both domains
        return result;
    }
    Query_state state(options.seed, options.max_f_evaluations, first_hit, spacing, result.points);
    state.counters = result.counters;
    state.visitor = options.visitor;
    state.posed_a = &pa;
    if (options.max_time_us)
        state.deadline = start + std::chrono::nanoseconds(std::int64_t(*options.max_time_us * 1e3));
    if (options.verify_contacts) {
        const double tolerance = options.contact_tolerance.value_or(0.05 * r_min);
        const double reach = 2.0 * std::max(pa.sampling_radius(), pb.sampling_radius());
        const double core = options.contact_core;
        state.verifier = [&pa, &pb, &state, tolerance, reach, core](const Intersection_point& candidate) {
            return refine_by_projection(pa, pb, candidate.position, reach, tolerance, state, core);
        };
        if (options.certify_separation)
            state.crossing_check = [&pa, &pb, &state, core](const Eigen::Vector3d& x) -> std::optional<Intersection_point> {
                if (state.out_of_budget()) return std::nullopt; // never overdraw the budget
                ++state.counters.refinement_samples; // a step of the verification: two evaluations at most
                const auto both = evaluate_both(pa, pb, x, state);
                if (!both || !(std::max(both->first.domain_fraction, both->second.domain_fraction) <= core))
                    return std::nullopt;
                // Both clouds hold a point within their sampling radius of it (no crossing through a
                // lone outlier's wide domain).
                const auto near = [&x](const auto& posed, const Surface_evaluation& e) {
                    return (posed.from_world.transform_point(x) - posed.position(e.nearest)).norm() <= posed.sampling_radius();
                };
                if (!near(pa, both->first) || !near(pb, both->second)) return std::nullopt;
                return Intersection_point{x, both->first.value, both->second.value, Intersection_point_kind::approximate};
            };
    }
    policy.run(pa, pb, options, epsilon, state, result.closest_estimate);
    if (options.verify_contacts && options.certify_separation && state.sink.size() == 0 && !state.out_of_budget())
        certify_separation(pa, pb, options, policy, r_min, state);

    if (!first_hit && !options.verify_contacts && options.refinement != Refinement::none) {
        // Refine every approximate point; a point that does not converge stays an AIP.
        for (Intersection_point& p : result.points) {
            if (p.kind != Intersection_point_kind::approximate || state.out_of_budget()) continue;
            const double radius = 2.0 * spacing;
            const std::optional<Intersection_point> refined =
                options.refinement == Refinement::projection
                    ? refine_by_projection(pa, pb, p.position, radius, epsilon, state)
                    : refine_by_sampling(pa, pb, p.position, 0.5 * spacing, epsilon, options.refinement_samples, state);
            if (refined) p = *refined;
        }
    }
    result.intersects = !result.points.empty();
    result.status = result.intersects  ? Intersection_status::intersecting
                    : state.budget_hit ? Intersection_status::undecided
                                       : Intersection_status::separate;
    result.counters = state.counters;
    return result;
}

} // namespace internal

/// Whether the surfaces of `a` posed by `pose_a` and `b` posed by `pose_b` intersect: stops at the
/// first intersection point found, which the result carries (an AIP for Interpolation_search, a
/// sample for Randomized_sampling), with the query's counters.
///
/// \tparam A, B models of CollisionObject (Point_cloud_object<K>).
/// \tparam Policy a model of LeafIntersector for A and B: Interpolation_search (default) or
///         Randomized_sampling.
/// \param pose_a, pose_b rigid motions from each object's local frame to the world
///        (Rigid_transform_3 rejects non-rigid matrices when it is built).
/// \throws Invalid_input for invalid options or policy parameters (message names the field).
/// Thread safety: the objects are only read; any number of queries may run concurrently on the same
/// objects. The answer, points and counters depend only on the arguments (seed included).
/// Complexity: see Interpolation_search / Randomized_sampling; O(1) allocations per query besides
/// the candidate lists.
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
Intersection_result do_intersect(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                                 const Rigid_transform_3<double>& pose_b, const Intersection_options& options = {},
                                 const Policy& policy = Policy())
{
    return internal::run_query(a, pose_a, b, pose_b, options, policy, true, "do_intersect");
}

/// Points on the intersection curves of the two posed surfaces, no two closer than
/// options.point_spacing, refined as options.refinement says (world coordinates). The whole sample
/// the policy asks for is searched (no early stop). Same parameters, guarantees and exceptions as
/// do_intersect(); in particular any number may run concurrently on the same objects, and the
/// result (points bit for bit, counters) depends only on the arguments.
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
Intersection_result intersection_points(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                                        const Rigid_transform_3<double>& pose_b,
                                        const Intersection_options& options = {}, const Policy& policy = Policy())
{
    return internal::run_query(a, pose_a, b, pose_b, options, policy, false, "intersection_points");
}

/// do_intersect() for two objects already in one frame (both at the identity pose).
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
Intersection_result do_intersect(const A& a, const B& b, const Intersection_options& options = {},
                                 const Policy& policy = Policy())
{
    const Rigid_transform_3<double> identity;
    return internal::run_query(a, identity, b, identity, options, policy, true, "do_intersect");
}

/// intersection_points() for two objects already in one frame (both at the identity pose).
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
Intersection_result intersection_points(const A& a, const B& b, const Intersection_options& options = {},
                                        const Policy& policy = Policy())
{
    const Rigid_transform_3<double> identity;
    return internal::run_query(a, identity, b, identity, options, policy, false, "intersection_points");
}

} // namespace PCCD
