// PCCD/concepts/SurfaceDistance.h -- concept of the distance policies of the implicit surface
// (doc/algorithms.md, "Euclidean and geodesic distance"): which cloud points lie within a distance
// of a query, and how far.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

namespace PCCD {
namespace internal {

/// The visitor a SurfaceDistance is checked with: called as `visitor(index, distance)`.
struct Neighbor_visitor_archetype {
    void operator()(std::uint32_t, double) const {}
};

} // namespace internal

/// \concept SurfaceDistance
/// A distance d(x, p_i) from a query to the points of a cloud, with the neighbour enumeration the
/// WLS surface needs. The query is either a point of the cloud (by index) or any point of space.
///
/// Requirements, for `const D& d`, `std::uint32_t i < d.size()`, `const Eigen::Vector3d& x`,
/// `double radius >= 0` and a callable `visitor(std::uint32_t index, double distance)`:
/// - `D` is copy constructible (the surface stores it by value; copies should be cheap views);
/// - `d.size()`: the number of cloud points;
/// - `d.position(i)`: the coordinates of point i, convertible to `Eigen::Vector3d`;
/// - `d.max_radius()`: the largest `radius` the two enumerations below answer exactly (+infinity
///   when unbounded); the surface refuses a weight whose support exceeds it;
/// - `d.for_each_neighbor_of_point(i, radius, visitor)` calls `visitor(j, d(p_i, p_j))` once for
///   every point j with d(p_i, p_j) <= radius (i itself included, at distance 0);
/// - `d.for_each_neighbor(x, radius, visitor)` calls `visitor(j, d(x, p_j))` once for every point
///   j with d(x, p_j) <= radius and returns the index of the cloud point nearest to x (Euclidean,
///   smallest index among equally near ones) as a `std::optional<std::uint32_t>`; it returns
///   `std::nullopt`, without calling the visitor, when no point lies within `radius`.
/// Both enumerations must be const and safe to call from several threads at once.
///
/// Models shipped by PCCD: Euclidean_distance (kd-tree radius queries) and Geodesic_distance
/// (d(x, p) = |x - p*| + g(p*, p) read from a close-pairs shortest-path map, no kd-tree query at
/// cloud points).
template <class D>
concept SurfaceDistance =
    std::copy_constructible<D> &&
    requires(const D& d, std::uint32_t i, const Eigen::Vector3d& x, double radius,
             const internal::Neighbor_visitor_archetype& visitor) {
        { d.size() } -> std::convertible_to<std::size_t>;
        { d.position(i) } -> std::convertible_to<Eigen::Vector3d>;
        { d.max_radius() } -> std::convertible_to<double>;
        d.for_each_neighbor_of_point(i, radius, visitor);
        { d.for_each_neighbor(x, radius, visitor) } -> std::same_as<std::optional<std::uint32_t>>;
    };

} // namespace PCCD
