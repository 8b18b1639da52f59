// PCCD/Point_traits.h -- the customization point through which PCCD reads the x, y, z coordinates
// of any 3D point type, and the concept `Point3` that checks it.
//
// Shipped: every type with x(), y(), z() members returning numbers (CGAL's Point_3 and Vector_3,
// Eigen's 3-vectors) and std::array<T, 3>. Specialize PCCD::Point_traits for any other type:
//
//     template <> struct PCCD::Point_traits<My_point> {
//         static double x(const My_point& p) { return p.v[0]; }   // likewise y, z
//     };
#pragma once

#include <array>
#include <concepts>
#include <type_traits>

namespace PCCD {

/// Coordinate access for a point type `P`: static functions `x(p)`, `y(p)`, `z(p)`.
/// The primary template is empty: a type without a specialization is not a `Point3`.
template <class P>
struct Point_traits {};

/// Types with `x()`, `y()`, `z()` members (CGAL points and vectors, Eigen 3-vectors).
template <class P>
    requires requires(const P& p) {
        { p.x() } -> std::convertible_to<double>;
        { p.y() } -> std::convertible_to<double>;
        { p.z() } -> std::convertible_to<double>;
    }
struct Point_traits<P> {
    static auto x(const P& p) { return p.x(); }
    static auto y(const P& p) { return p.y(); }
    static auto z(const P& p) { return p.z(); }
};

/// `std::array<T, 3>` of numbers.
template <class T>
    requires std::is_arithmetic_v<T>
struct Point_traits<std::array<T, 3>> {
    static T x(const std::array<T, 3>& p) { return p[0]; }
    static T y(const std::array<T, 3>& p) { return p[1]; }
    static T z(const std::array<T, 3>& p) { return p[2]; }
};

/// \concept Point3
/// A 3D point type whose coordinates PCCD can read: `Point_traits<P>::x(p)`, `y(p)`, `z(p)` are
/// valid and convertible to double. Models: CGAL::Point_3<K>, CGAL::Vector_3<K>,
/// Eigen::Matrix<T,3,1>, std::array<T,3>, and any type with a Point_traits specialization.
template <class P>
concept Point3 = requires(const P& p) {
    { Point_traits<P>::x(p) } -> std::convertible_to<double>;
    { Point_traits<P>::y(p) } -> std::convertible_to<double>;
    { Point_traits<P>::z(p) } -> std::convertible_to<double>;
};

} // namespace PCCD
