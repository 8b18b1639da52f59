// PCCD/Kinetic/flightplan_speed.h -- max_speed(flightplan, t0, t1): an upper bound of a
// flightplan's speed over a time interval, read off its pieces (the cubics of Linear_flightplan,
// Piecewise_linear_flightplan and Polynomial_flightplan). Continuous collision detection of a
// deforming cloud advances by it (doc/algorithms.md "Continuous collision"; doc/manual/continuous.md
// "Deforming clouds").
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/concepts/Flightplan.h>

namespace PCCD {

/// \concept PiecewiseCubicFlightplan
/// A Flightplan made of pieces, each a cubic per axis, as the shipped flightplans are. For
/// `const F& f`, a time `double t`, a piece `std::size_t k` and `int axis` in {0, 1, 2}:
/// - `f.piece_at(t)`: the piece holding time t (piece_begin(k) <= t < piece_end(k));
/// - `f.piece_begin(k)`, `f.piece_end(k)`: its time interval (-infinity and +infinity at the ends);
/// - `f.piece_origin(k)`: the time u = 0 of its cubics;
/// - `f.piece_cubic(k, axis)`: coordinate `axis` on the piece as a Cubic in u = t - piece_origin(k).
template <class F>
concept PiecewiseCubicFlightplan = Flightplan<F> && requires(const F& f, double t, std::size_t k, int axis) {
    { f.piece_at(t) } -> std::convertible_to<std::size_t>;
    { f.piece_begin(k) } -> std::convertible_to<double>;
    { f.piece_end(k) } -> std::convertible_to<double>;
    { f.piece_origin(k) } -> std::convertible_to<double>;
    { f.piece_cubic(k, axis) } -> std::same_as<Cubic>;
};

namespace internal {

/// max |c'(u)| over u in [lo, hi] for a cubic c: at the ends and at the derivative's extremum.
inline double max_abs_derivative(const Cubic& c, double lo, double hi)
{
    const auto d = [&](double u) { return (3.0 * c.c[3] * u + 2.0 * c.c[2]) * u + c.c[1]; };
    double m = std::max(std::abs(d(lo)), std::abs(d(hi)));
    if (c.c[3] != 0.0) {
        const double u = -c.c[2] / (3.0 * c.c[3]);
        if (u > lo && u < hi) m = std::max(m, std::abs(d(u)));
    }
    return m;
}

} // namespace internal

/// An upper bound of the speed |p'(t)| of flightplan `f` over [t0, t1]: on every piece that meets
/// the interval, the largest derivative of each coordinate's cubic there, combined as the length of
/// the vector of the three maxima (so the bound is exact for straight motions along an axis and at
/// most sqrt(3) times too large otherwise). Up to rounding in the last bits.
/// \throws Invalid_input unless t0 and t1 are finite and t0 <= t1.
/// Complexity: O(log pieces + pieces within [t0, t1]).
template <PiecewiseCubicFlightplan F>
double max_speed(const F& f, double t0, double t1)
{
    if (!(std::isfinite(t0) && std::isfinite(t1) && t0 <= t1))
        throw Invalid_input(internal::concat("max_speed: the interval [", t0, ", ", t1, "] must be finite with t0 <= t1"));
    double best = 0.0;
    for (std::size_t k = f.piece_at(t0);; ++k) {
        const double lo = std::max(t0, double(f.piece_begin(k))), hi = std::min(t1, double(f.piece_end(k)));
        if (lo <= hi) {
            const double origin = f.piece_origin(k);
            double squared = 0.0;
            for (int axis = 0; axis < 3; ++axis) {
                const double m = internal::max_abs_derivative(f.piece_cubic(k, axis), lo - origin, hi - origin);
                squared += m * m;
            }
            best = std::max(best, std::sqrt(squared));
        }
        if (!(double(f.piece_end(k)) < t1)) break;
    }
    return best;
}

} // namespace PCCD
