// PCCD/concepts/PointCloudKernel.h -- concept of the geometric kernels PCCD is generic over.
// PCCD reads a kernel only at its boundary (constructing and reading points); the hot loops work on
// a flat coordinate store of the kernel's number type (doc/design.md, "Generic types").
#pragma once

#include <concepts>

namespace PCCD {

/// \concept PointCloudKernel
/// A geometric kernel in CGAL's style, with a floating-point number type.
///
/// Requirements, for `const K& k`, `typename K::FT c` and `const typename K::Point_3& p`:
/// - types `K::FT` (a `std::floating_point`), `K::Point_3`, `K::Vector_3`;
/// - `k.construct_point_3_object()(c, c, c)` returns a `K::Point_3`;
/// - `k.compute_x_3_object()(p)`, `compute_y_3_object()`, `compute_z_3_object()` return the
///   coordinates, convertible to `K::FT`;
/// - `k.compute_squared_distance_3_object()(p, p)` is convertible to `K::FT`.
///
/// Models: PCCD::Eigen_kernel<double>, PCCD::Eigen_kernel<float>, CGAL::Simple_cartesian<double>,
/// CGAL::Simple_cartesian<float>, CGAL::Exact_predicates_inexact_constructions_kernel (Epick).
/// Not models: kernels with exact number types (CGAL::Epeck), whose FT is not a floating-point type;
/// convert their points to an Epick point first.
template <class K>
concept PointCloudKernel = requires(const K& k, typename K::FT c, const typename K::Point_3& p) {
    typename K::FT;
    typename K::Point_3;
    typename K::Vector_3;
    requires std::floating_point<typename K::FT>;
    { k.construct_point_3_object()(c, c, c) } -> std::convertible_to<typename K::Point_3>;
    { k.compute_x_3_object()(p) } -> std::convertible_to<typename K::FT>;
    { k.compute_y_3_object()(p) } -> std::convertible_to<typename K::FT>;
    { k.compute_z_3_object()(p) } -> std::convertible_to<typename K::FT>;
    { k.compute_squared_distance_3_object()(p, p) } -> std::convertible_to<typename K::FT>;
};

} // namespace PCCD
