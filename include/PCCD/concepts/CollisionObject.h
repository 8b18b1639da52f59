// PCCD/concepts/CollisionObject.h -- concept of the preprocessed objects the intersection queries
// take (ALGORITHMS.md sections 4-6), and of the leaf intersector policies.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

namespace PCCD {

/// \concept CollisionObject
/// A preprocessed point cloud an intersection query can work on. For `const O& o`, an index
/// `std::uint32_t i` and an `Eigen::Vector3d x` (local coordinates of the object):
/// - `o.size()`: number of points;
/// - `o.cloud().position(i)`: the local position of point i (an Eigen 3-vector of any scalar);
/// - `o.surface().evaluate(x)`: a PCCD::Surface_evaluation of the implicit surface at x, and
///   `o.surface().support_radius()`: the distance beyond which the surface is undefined;
/// - `o.cpsp()`: the Close_pairs_shortest_paths map of its proximity graph (annulus, targets, path,
///   bound);
/// - `o.hierarchy()`: a Point_cloud_hierarchy over its points;
/// - `o.sampling_radius()`: r(P);
/// - `o.noise_estimate()`: the estimated noise level sigma of its points (0 for a clean cloud is
///   fine), which widens the band of candidate contacts of the interpolation search.
/// All of these must be const and safe to call concurrently.
///
/// Model: PCCD::Point_cloud_object<K> for every kernel K.
template <class O>
concept CollisionObject = requires(const O& o, std::uint32_t i, const Eigen::Vector3d& x) {
    { o.size() } -> std::convertible_to<std::size_t>;
    o.cloud().position(i);
    o.surface().evaluate(x);
    { o.surface().support_radius() } -> std::convertible_to<double>;
    o.cpsp().annulus(i, 0.0, 1.0);
    o.cpsp().bound();
    o.hierarchy().root();
    { o.sampling_radius() } -> std::convertible_to<double>;
    { o.noise_estimate() } -> std::convertible_to<double>;
};

/// \concept LeafIntersector
/// A policy deciding, inside the overlap region of two objects, whether and where their surfaces
/// intersect (ALGORITHMS.md sections 5 and 6). For `const P& p` and a double r:
/// - `P::name()`: a short name ("isearch", "rst");
/// - `p.check()`: throws PCCD::Invalid_input for invalid parameters;
/// - `p.default_epsilon(r)`: the tolerance used when the options leave epsilon unset, given the
///   smaller sampling radius r;
/// - a member template `run(a, b, options, epsilon, state, closest)` called by do_intersect() with
///   the two posed objects (internal interface, see Interpolation_search.h).
///
/// Models: PCCD::Interpolation_search, PCCD::Randomized_sampling.
template <class P>
concept LeafIntersector = requires(const P& p, double r) {
    { P::name() } -> std::convertible_to<const char*>;
    p.check();
    { p.default_epsilon(r) } -> std::convertible_to<double>;
};

} // namespace PCCD
