// PCCD/concepts/CollisionObject.h -- concept of the preprocessed objects the intersection queries
// take, and of the leaf intersector policies that search them (doc/manual/intersection.md; the
// requirements are proven by archetypes in test/concepts/archetypes_test.cpp).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <Eigen/Core>

#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/internal/Query_state.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Surface/WLS_surface.h>

namespace PCCD {

/// \concept CollisionObject
/// A preprocessed point cloud an intersection query can work on. For `const O& o`, an index
/// `std::uint32_t i` and an `Eigen::Vector3d x` (local coordinates of the object):
/// - `o.size()`: number of points N, convertible to std::size_t;
/// - `o.cloud().position(i)`: the local position of point i, an Eigen 3-vector of any floating
///   scalar (read through `.template cast<double>()`);
/// - `o.cloud().coordinates()`: all positions, a reference to an `Eigen::Matrix<FT, 3, Eigen::Dynamic>`
///   held by the object, FT float or double (the paths the interpolation search computes on the fly,
///   Path_choice::on_the_fly, walk over it);
/// - `o.surface().evaluate(x)`: the PCCD::Surface_evaluation of the implicit surface at x, and
///   `o.surface().support_radius()`: the distance beyond which the surface is undefined;
/// - `o.graph()`: its PCCD::Proximity_graph (read by Path_choice::on_the_fly);
/// - `o.cpsp()`: the PCCD::Close_pairs_shortest_paths map of that graph (annulus, targets,
///   distances, bound and, through Stored_paths, the stored paths);
/// - `o.hierarchy()`: a PCCD::Point_cloud_hierarchy over its points; when it has reaches
///   (Point_cloud_hierarchy::has_reach), the reach of each point must be its domain radius: f must
///   be undefined (or outside_domain) at every x farther than reach_i from its nearest point p_i.
///   The hierarchy traversals rely on it to declare objects separate without evaluating f; a
///   hierarchy without reaches is walked flat;
/// - `o.sampling_radius()`: r(P), convertible to double;
/// - `o.noise_estimate()`: the estimated noise level sigma of its points, convertible to double (0
///   for a clean cloud is fine), which widens the band of candidate contacts of the interpolation
///   search.
/// All of these must be const and safe to call concurrently; the references must stay valid while
/// the object lives.
///
/// Models: PCCD::Point_cloud_object<K> and PCCD::Deforming_point_cloud_object<K> (its current
/// frame) for every kernel K. Archetype and near-misses: test/concepts/archetypes_test.cpp.
namespace internal {

/// A 3 x N Eigen matrix of float or double held by the object (an lvalue, not a temporary).
template <class M>
concept Point_matrix_reference =
    std::is_lvalue_reference_v<M> && (std::same_as<std::remove_cvref_t<M>, Eigen::Matrix<float, 3, Eigen::Dynamic>> ||
                                      std::same_as<std::remove_cvref_t<M>, Eigen::Matrix<double, 3, Eigen::Dynamic>>);

} // namespace internal

template <class O>
concept CollisionObject = requires(const O& o, std::uint32_t i, const Eigen::Vector3d& x) {
    { o.size() } -> std::convertible_to<std::size_t>;
    { o.cloud().position(i).template cast<double>() } -> std::convertible_to<Eigen::Vector3d>;
    { o.cloud().coordinates() } -> internal::Point_matrix_reference;
    { o.surface().evaluate(x) } -> std::same_as<Surface_evaluation>;
    { o.surface().support_radius() } -> std::convertible_to<double>;
    { o.graph() } -> std::convertible_to<const Proximity_graph&>;
    { o.cpsp() } -> std::convertible_to<const Close_pairs_shortest_paths&>;
    { o.hierarchy() } -> std::convertible_to<const Point_cloud_hierarchy&>;
    { o.sampling_radius() } -> std::convertible_to<double>;
    { o.noise_estimate() } -> std::convertible_to<double>;
};

/// \concept LeafIntersector
/// A policy deciding, inside the overlap region of two objects of types A and B, whether and where
/// their surfaces intersect (doc/manual/intersection.md). For `const P& p` and a double r:
/// - `P::name()`: a short name ("isearch", "rst"), convertible to const char*;
/// - `p.check()`: throws PCCD::Invalid_input for invalid parameters;
/// - `p.default_epsilon(r)`: the tolerance used when the options leave epsilon unset, given the
///   smaller sampling radius r, convertible to double;
/// - `p.run(a, b, options, epsilon, state, closest)`, called by do_intersect() and
///   intersection_points() with the two posed objects (internal::Posed_object<A>,
///   internal::Posed_object<B>), the Intersection_options, epsilon, the query's
///   internal::Query_state (counters, budget, engine, the sink that collects and verifies
///   candidates: `state.offer(point)`) and a double that receives the closest-distance estimate
///   (NaN when the policy makes none).
///
/// Models: PCCD::Interpolation_search, PCCD::Randomized_sampling, for every pair of
/// CollisionObject types.
template <class P, class A, class B>
concept LeafIntersector = requires(const P& p, double r, const internal::Posed_object<A>& a,
                                   const internal::Posed_object<B>& b, const Intersection_options& options,
                                   internal::Query_state& state, double& closest) {
    { P::name() } -> std::convertible_to<const char*>;
    p.check();
    { p.default_epsilon(r) } -> std::convertible_to<double>;
    p.run(a, b, options, r, state, closest);
};

} // namespace PCCD
