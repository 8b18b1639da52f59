// PCCD/Kinetic/next_crossing.h -- the next_crossing of every shipped flightplan, for any trajectory
// made of polynomial pieces of degree <= 3 (doc/manual/kinetic.md, "Flightplans"; the piece
// interface below is in doc/reference/kinetic-concepts.md). A user's Flightplan model that exposes
// the piece interface gets PCCD's robust root isolation by calling it from its own next_crossing.
// The numerical core, and why it needs no tolerance, is internal/Piecewise_cubic.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/Kinetic/internal/Piecewise_cubic.h>

namespace PCCD {

/// The generic `next_crossing` of the shipped flightplans: inf{ s > t : a_axis(s) < b_axis(s) },
/// or +infinity. `F` exposes its trajectory as pieces k = 0 .. piece_count() - 1 covering the time
/// line, piece k on [piece_begin(k), piece_end(k)), the first beginning at -infinity and the last
/// ending at +infinity, each a cubic per axis in u = s - piece_origin(k) (`piece_cubic(k, axis)`,
/// a Cubic), and `piece_at(t)` finding the piece of t.
template <class F>
double next_crossing(const F& a, const F& b, int axis, double t)
{
    using internal::infinity;
    std::size_t ka = a.piece_at(t), kb = b.piece_at(t);
    for (;;) {
        const double a_end = a.piece_end(ka), b_end = b.piece_end(kb);
        const double lo = std::max(a.piece_begin(ka), b.piece_begin(kb));
        const double hi = std::min(a_end, b_end);
        const double origin = std::isfinite(lo)   ? lo
                              : std::isfinite(hi) ? hi
                                                  : std::max(a.piece_origin(ka), b.piece_origin(kb));
        const Cubic d = a.piece_cubic(ka, axis).shifted(origin - a.piece_origin(ka)) -
                        b.piece_cubic(kb, axis).shifted(origin - b.piece_origin(kb));
        const double found = internal::first_negative_time(d, std::isfinite(lo) ? 0.0 : lo,
                                                           std::isfinite(hi) ? hi - origin : hi, origin, t);
        if (found != infinity || hi == infinity) return found;
        if (a_end == hi) ++ka;
        if (b_end == hi) ++kb;
    }
}

} // namespace PCCD
