// PCCD/concepts/LeafIntersector.h -- concept of the leaf intersector policies that search the
// overlap region of two objects for a common zero of their surfaces (doc/manual/intersection.md,
// "Leaf intersectors"; archetype in test/concepts/archetypes_test.cpp). The public types it names
// (Posed_object, Query_state, Intersection_options) are declared here and defined in
// PCCD/Intersection/; a policy is checked where they are complete (do_intersect.h).
#pragma once

#include <concepts>

namespace PCCD {

template <class Object>
struct Posed_object;       // PCCD/Intersection/Posed_object.h
struct Query_state;        // PCCD/Intersection/Query_state.h
struct Intersection_options; // PCCD/Intersection/Intersection_options.h

/// \concept LeafIntersector
/// A policy deciding, inside the overlap region of two objects of types A and B, whether and where
/// their surfaces intersect (doc/manual/intersection.md). For `const P& p` and a double r:
/// - `P::name()`: a short name ("isearch", "rst"), convertible to const char*;
/// - `p.check()`: throws PCCD::Invalid_input for invalid parameters;
/// - `p.default_epsilon(r)`: the tolerance used when the options leave epsilon unset, given the
///   smaller sampling radius r, convertible to double;
/// - `p.run(a, b, options, epsilon, state, closest)`, called by do_intersect() and
///   intersection_points() with the two posed objects (PCCD::Posed_object<A>,
///   PCCD::Posed_object<B>), the Intersection_options, epsilon, the query's PCCD::Query_state
///   (counters, budget, engine, the sink that verifies and collects candidates:
///   `state.offer(point)`) and a double that receives the closest-distance estimate (NaN when the
///   policy makes none).
///
/// Models: PCCD::Interpolation_search, PCCD::Randomized_sampling, for every pair of
/// CollisionObject types.
template <class P, class A, class B>
concept LeafIntersector = requires(const P& p, double r, const Posed_object<A>& a,
                                   const Posed_object<B>& b, const Intersection_options& options,
                                   Query_state& state, double& closest) {
    { P::name() } -> std::convertible_to<const char*>;
    p.check();
    { p.default_epsilon(r) } -> std::convertible_to<double>;
    p.run(a, b, options, r, state, closest);
};

} // namespace PCCD
