// PCCD/concepts/SurfaceWeight.h -- concept of the weight policies of the implicit surface
// (doc/algorithms.md, "Weights, support and bandwidth"): a kernel theta(d) of a distance with a
// bounded support.
#pragma once

#include <concepts>

namespace PCCD {

/// \concept SurfaceWeight
/// A weight function theta(d) >= 0 of a distance d >= 0, with a bounded support: the WLS surface
/// visits only the points at distance d <= `w.support_radius()` and gives them weight `w(d)`.
///
/// Requirements, for `const W& w` and `double d`:
/// - `W` is copy constructible (the surface stores it by value);
/// - `w(d)` returns the weight as a double: positive for 0 <= d <= support_radius(), nonincreasing
///   in d (the surface relies on it to stop walking a distance-sorted neighbour list early);
/// - `w.support_radius()` returns the support radius as a double, finite and > 0.
///
/// Models shipped by PCCD: Gaussian_weight (theta(d) = exp(-d^2 / h^2), cut where theta drops
/// below the threshold theta_eps).
template <class W>
concept SurfaceWeight = std::copy_constructible<W> && requires(const W& w, double d) {
    { w(d) } -> std::convertible_to<double>;
    { w.support_radius() } -> std::convertible_to<double>;
};

} // namespace PCCD
