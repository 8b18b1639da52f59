// PCCD/concepts/Flightplan.h -- concept of the vertex trajectories ("flightplans") that drive the
// kinetic AABB tree (doc/algorithms.md, "Kinetic AABB tree"): a position at any time and, for two
// flightplans of the same type, the next time at which one coordinate of the first drops below the
// other's.
#pragma once

#include <concepts>

#include <Eigen/Core>

namespace PCCD {

/// \concept Flightplan
/// A known, continuous trajectory t -> p(t) in R^3 (double precision, t in seconds or any unit).
///
/// Requirements, for `const F& a, b`, `double t` and `int axis` in {0, 1, 2}:
/// - `F` is copyable: copy constructible and copy assignable (the tree stores one flightplan per
///   vertex and set_flightplan() replaces one in place); a default constructor is not needed;
/// - `a.position(t)` returns the position at time t as an `Eigen::Vector3d` (the trees add and
///   compare the positions as vectors);
/// - `a.coordinate(axis, t)` returns `a.position(t)[axis]` as a double, bit for bit;
/// - `a.next_crossing(b, axis, t)` returns the first time from which coordinate `axis` of `a` drops
///   below that of `b`: inf{ s > t : a_axis(s) < b_axis(s) }, or +infinity when that never happens.
///   It returns `t` itself when `a` is below `b` immediately after `t`. Touching without crossing
///   (a double root) and running tied over an interval are not crossings.
///
/// Determinism contract (what makes the kinetic tree terminate and treat ties the same way on every
/// run): for the same `a, b, axis`, the sets of times at which `a.next_crossing(b, ...)` and
/// `b.next_crossing(a, ...)` switch are computed from the same numbers, so after `a` drops below `b`
/// at time T, `b.next_crossing(a, axis, T)` is strictly greater than T.
///
/// Trajectories must be continuous in t: a crossing hidden inside a jump cannot be detected. To
/// change a motion abruptly, replace the flightplan (Kinetic_AABB_tree::set_flightplan), which
/// repairs the tree at the current time.
///
/// Models shipped by PCCD: Linear_flightplan, Piecewise_linear_flightplan (key frames),
/// Polynomial_flightplan (piecewise polynomials of degree <= 3: one cubic for all times, or cubic
/// Hermite key frames). Polynomial_flightplan can represent the other two, so use it when one tree
/// mixes kinds of motion.
template <class F>
concept Flightplan = std::copyable<F> && requires(const F& a, const F& b, double t, int axis) {
    { a.position(t) } -> std::same_as<Eigen::Vector3d>;
    { a.coordinate(axis, t) } -> std::same_as<double>;
    { a.next_crossing(b, axis, t) } -> std::same_as<double>;
};

} // namespace PCCD
