// PCCD/Kinetic/internal/Piecewise_cubic.h -- robust crossing times of one piece of the difference
// of two piecewise polynomial trajectories of degree <= 3, the numerical core of next_crossing
// (next_crossing.h) and so of every shipped Flightplan model (doc/manual/kinetic.md, "Flightplans":
// "Crossings are isolated robustly").
//
// The difference d = a - b of two coordinate trajectories is cut at the union of both key-frame
// boundaries. On each merged segment d is a polynomial, expanded around the segment start (a point
// that does not depend on the query time). Its critical points split the segment into monotone
// pieces; a piece whose end values have strictly opposite signs holds exactly one crossing, found
// by bisection, and the sign of every piece is read off its end values. A segment start is
// evaluated from the key-frame data of the segment itself, so a crossing at or near a key-frame
// boundary is found exactly once: either as a root inside the earlier segment or as a negative
// start of the later one, never both and never neither.
//
// Why d and -d cannot ping-pong: every step (coefficients, quadratic formula, bisection, Horner) is
// symmetric under negation in IEEE arithmetic, so the crossings of b - a are bit for bit those of
// a - b, and local times are converted to absolute times by the same rounding. After a drops below
// b at T, the interval on which b is below a ends exactly at T, so the new certificate fails
// strictly after T.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include <PCCD/Kinetic/Cubic.h>

namespace PCCD::internal {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

/// Sign of a polynomial of degree `deg` >= 1 towards +infinity (`toward_plus`) or -infinity.
inline int sign_at_infinity(const Cubic& p, int deg, bool toward_plus)
{
    const int s = p.c[std::size_t(deg)] > 0.0 ? 1 : -1;
    return (toward_plus || deg % 2 == 0) ? s : -s;
}

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

/// Bisection on [l, r] where p(l) and p(r) are nonzero with opposite signs: the last double at
/// which p still has the sign of p(l) (or a point where p evaluates to exactly 0).
inline double bisect_root(const Cubic& p, double l, double r)
{
    const int sl = sign_of(p(l));
    for (;;) {
        const double m = l + 0.5 * (r - l);
        if (!(m > l && m < r)) return l;
        const double vm = p(m);
        if (vm == 0.0) return m;
        if (sign_of(vm) == sl)
            l = m;
        else
            r = m;
    }
}

/// The first time s > t, s in the segment (origin + lo, origin + hi), at which p(s - origin) < 0;
/// +infinity if none. `lo` may be -infinity and `hi` +infinity; origin + lo <= t.
/// Returns t itself when p is negative just after t.
inline double first_negative_time(const Cubic& p, double lo, double hi, double origin, double t)
{
    // A negative open interval (a, b) of local times, mapped to absolute times by one rounding.
    auto report = [&](double a, double b) -> double {
        const double b_abs = origin + b;
        if (!(b_abs > t)) return infinity;
        return std::max(origin + a, t);
    };

    const int deg = p.degree();
    if (deg <= 0) return (deg == 0 && p.c[0] < 0.0) ? report(lo, hi) : infinity;
    if (deg == 1) {
        const double r = std::clamp(-p.c[0] / p.c[1], lo, hi);
        return p.c[1] > 0.0 ? (r > lo ? report(lo, r) : infinity) : (r < hi ? report(r, hi) : infinity);
    }

    // Monotone pieces: segment ends, critical points strictly inside, and the Cauchy bound for
    // unbounded ends (all real roots and, by Gauss-Lucas, all critical points lie inside it).
    std::array<double, 6> x{};
    std::size_t n = 0;
    const double lead = std::abs(p.c[std::size_t(deg)]);
    double bound = 0.0;
    for (int i = 0; i < deg; ++i) bound = std::max(bound, std::abs(p.c[std::size_t(i)]) / lead);
    bound = std::min(1.0 + bound, 1e300);

    x[n++] = lo;
    if (lo == -infinity && -bound < hi) x[n++] = -bound;
    {
        // p'(u) = 3 c3 u^2 + 2 c2 u + c1, solved with the cancellation-free form of the formula.
        const double qa = 3.0 * p.c[3], qb = 2.0 * p.c[2], qc = p.c[1];
        std::array<double, 2> crit{};
        std::size_t m = 0;
        if (qa == 0.0) {
            crit[m++] = -qc / qb;
        } else {
            const double disc = qb * qb - 4.0 * qa * qc;
            if (disc > 0.0) {
                const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
                crit[m++] = q / qa;
                if (q != 0.0) crit[m++] = qc / q;
            }
        }
        if (m == 2 && crit[1] < crit[0]) std::swap(crit[0], crit[1]);
        for (std::size_t i = 0; i < m; ++i)
            if (crit[i] > x[n - 1] && crit[i] < hi && (hi != infinity || crit[i] < bound)) x[n++] = crit[i];
    }
    if (hi == infinity && bound > x[n - 1]) x[n++] = bound;
    x[n++] = hi;

    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double a = x[i], b = x[i + 1];
        if (b != infinity && !(origin + b > t)) continue;
        const int sa = std::isfinite(a) ? sign_of(p(a)) : sign_at_infinity(p, deg, false);
        const int sb = std::isfinite(b) ? sign_of(p(b)) : sign_at_infinity(p, deg, true);
        if (sa <= 0 && sb <= 0) {
            if (sa == 0 && sb == 0) continue; // identically zero between two zeros: a tie, not a crossing
            const double at = report(a, b);
            if (at != infinity) return at;
        } else if (sa > 0 && sb < 0) {
            const double at = report(bisect_root(p, a, b), b);
            if (at != infinity) return at;
        } else if (sa < 0 && sb > 0) {
            const double at = report(a, bisect_root(p, a, b));
            if (at != infinity) return at;
        }
    }
    return infinity;
}

} // namespace PCCD::internal
