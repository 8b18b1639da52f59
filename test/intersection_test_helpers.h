// Shared helper of the intersection tests and the do_intersect fuzz target: bit-for-bit comparison
// of two intersection results. Needs no test framework.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>

#include <PCCD/Intersection/Intersection_result.h>

namespace pccd_test {

/// The first field in which `x` and `y` differ bit for bit (NaN fields included: equal NaNs of the
/// same bits are equal), or an empty string when they are identical.
inline std::string result_difference(const PCCD::Intersection_result& x, const PCCD::Intersection_result& y)
{
    const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
    if (x.intersects != y.intersects) return "intersects";
    if (x.status != y.status) return "status";
    if (!(x.counters == y.counters)) return "counters";
    if (bits(x.closest_estimate) != bits(y.closest_estimate)) return "closest_estimate";
    if (x.points.size() != y.points.size()) return "number of points";
    for (std::size_t k = 0; k < x.points.size(); ++k) {
        const auto& p = x.points[k];
        const auto& q = y.points[k];
        for (int d = 0; d < 3; ++d)
            if (bits(p.position(d)) != bits(q.position(d))) return "point " + std::to_string(k) + " position";
        if (bits(p.f_a) != bits(q.f_a) || bits(p.f_b) != bits(q.f_b)) return "point " + std::to_string(k) + " f values";
        if (p.kind != q.kind) return "point " + std::to_string(k) + " kind";
    }
    return {};
}

} // namespace pccd_test
