// PCCD/concepts/CollisionObject.h -- concept of the preprocessed objects the intersection queries
// take (doc/manual/intersection.md; the requirements are proven by archetypes in
// test/concepts/archetypes_test.cpp). Like every concept header it includes no stage of the
// library: the PCCD types it names are declared here and defined by their stages (a model is
// checked where they are complete).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>


namespace PCCD {

class Close_pairs_shortest_paths; // PCCD/Geodesic/Close_pairs_shortest_paths.h
class Point_cloud_hierarchy;      // PCCD/Hierarchy/Point_cloud_hierarchy.h
class Proximity_graph;            // PCCD/Proximity_graph/Proximity_graph.h
struct Surface_evaluation;        // PCCD/Surface/WLS_surface.h

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
/// The interpolation search (the default leaf intersector) also needs the partners of a sample and
/// the paths between them: a GeodesicCollisionObject gives them from its CPSP map, a
/// EuclideanCollisionObject from its kd-tree. Randomized_sampling needs neither, but do_intersect()
/// and the queries built on it certify a "separate" with the interpolation search whatever the
/// policy (Intersection_options::certify_separation), so their objects must model one of the two
/// (a static assertion says so otherwise).
///
/// Models: PCCD::Point_cloud_object<K> and PCCD::Deforming_point_cloud_object<K> (its current
/// frame), both GeodesicCollisionObject, and PCCD::Euclidean_point_cloud_object<K>, a
/// EuclideanCollisionObject, for every kernel K. Archetype and near-misses:
/// test/concepts/archetypes_test.cpp.
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
    { o.hierarchy() } -> std::convertible_to<const Point_cloud_hierarchy&>;
    { o.sampling_radius() } -> std::convertible_to<double>;
    { o.noise_estimate() } -> std::convertible_to<double>;
};

/// \concept GeodesicCollisionObject
/// A CollisionObject that keeps its geodesic map: for `const O& o`,
/// - `o.graph()`: its PCCD::Proximity_graph (read by Path_choice::on_the_fly);
/// - `o.cpsp()`: the PCCD::Close_pairs_shortest_paths map of that graph (annulus, targets,
///   distances, bound and, through Stored_paths, the stored paths), which the interpolation search
///   takes its partners and paths from.
/// Models: PCCD::Point_cloud_object<K>, PCCD::Deforming_point_cloud_object<K>.
template <class O>
concept GeodesicCollisionObject = CollisionObject<O> && requires(const O& o) {
    { o.graph() } -> std::convertible_to<const Proximity_graph&>;
    { o.cpsp() } -> std::convertible_to<const Close_pairs_shortest_paths&>;
};

/// \concept EuclideanCollisionObject
/// A CollisionObject whose cloud answers nearest-point and radius queries, from which the
/// interpolation search takes the partners of a sample (the points of its Euclidean annulus) and
/// the paths of a bracket (the points nearest to the chord). With `C` the type of `o.cloud()` (for
/// `const O& o`): the types `C::FT` (float or double), `C::Vector_3` (an Eigen 3-vector of FT) and
/// `C::Neighbor` (with `index`, a point index, and `squared_distance`), and for a `C::Vector_3 v`, an
/// `FT r` and a `std::vector<C::Neighbor>& out`: `o.cloud().position(i)` convertible to
/// `C::Vector_3`, `o.cloud().nearest(v).index` (the nearest point) and
/// `o.cloud().within_radius(v, r, out)` (every point within r, nearest first).
/// Models: PCCD::Euclidean_point_cloud_object<K>, and every PCCD::Point_cloud_object<K> too (the
/// interpolation search prefers the CPSP map where there is one).
namespace internal {
/// The type of `o.cloud()` for a `const O& o`.
template <class O>
using cloud_type = std::remove_cvref_t<decltype(std::declval<const O&>().cloud())>;
} // namespace internal

template <class O>
concept EuclideanCollisionObject =
    CollisionObject<O> &&
    requires(const O& o, std::uint32_t i, const typename internal::cloud_type<O>::Vector_3& v,
             typename internal::cloud_type<O>::FT r, std::vector<typename internal::cloud_type<O>::Neighbor>& out) {
        { o.cloud().position(i) } -> std::convertible_to<typename internal::cloud_type<O>::Vector_3>;
        { o.cloud().nearest(v).index } -> std::convertible_to<std::uint32_t>;
        { o.cloud().nearest(v).squared_distance } -> std::convertible_to<double>;
        o.cloud().within_radius(v, r, out);
    };

} // namespace PCCD
