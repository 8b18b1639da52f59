// PCCD/Geodesic/internal/interpolation_bound.h -- the search behind the CPSP map's annulus query
// (Close_pairs_shortest_paths::annulus, used by the root bracketing of the interpolation search):
// a lower or upper bound in a sorted float array by interpolation search alternating with
// bisection. Implements the annulus lookup of doc/manual/graphs.md ("The CPSP map") and
// doc/manual/intersection.md ("The leaf intersector policies").
#pragma once

#include <algorithm>
#include <cstddef>

namespace PCCD::internal {

/// First index i in [0, n) with !(a[i] < key) (lower bound) or, if `upper`, with a[i] > key, by
/// interpolation search over the sorted array `a`, alternating with bisection so that the worst
/// case stays O(log n) while uniform-like data take O(log log n) probes.
inline std::size_t interpolation_bound(const float* a, std::size_t n, double key, bool upper)
{
    auto before = [&](float value) { return upper ? double(value) <= key : double(value) < key; };
    std::size_t lo = 0, hi = n;
    for (bool bisect = false; lo < hi; bisect = !bisect) {
        if (!before(a[lo])) return lo;
        if (before(a[hi - 1])) return hi;
        // Now a[lo] is before the key and a[hi - 1] is not, so lo < hi - 1 and a[lo] < a[hi - 1].
        std::size_t probe;
        if (bisect) {
            probe = lo + (hi - 1 - lo) / 2;
        } else {
            const double fraction = (key - double(a[lo])) / (double(a[hi - 1]) - double(a[lo]));
            probe = lo + std::size_t(std::clamp(fraction, 0.0, 1.0) * double(hi - 1 - lo));
        }
        probe = std::clamp(probe, lo + 1, hi - 1);
        if (before(a[probe])) lo = probe + 1;
        else hi = probe;
    }
    return lo;
}

} // namespace PCCD::internal
