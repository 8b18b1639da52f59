// PCCD/testing/statistics.h -- the summary statistics of the benchmarks, the pccd tool and the
// accuracy tests: mean, median (mean of the two middle values for an even count), upper median and
// upper quantile (an element of the sorted values, no interpolation). Part of no manual chapter:
// the figures they summarize are in doc/benchmarks.md and doc/reliability.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace PCCD::testing {

/// The arithmetic mean of `values`; NaN when empty.
inline double mean(const std::vector<double>& values)
{
    if (values.empty()) return std::nan("");
    return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

/// The median of `values`: the middle value, or the mean of the two middle values for an even
/// count; NaN when empty. O(n).
inline double median(std::vector<double> values)
{
    if (values.empty()) return std::nan("");
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (values.size() % 2 == 1) return *middle;
    return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

/// Element min(n - 1, n * percent / 100) (integer division) of the ascending `sorted` values: the
/// upper `percent` % quantile without interpolation. `sorted` must be sorted and not empty.
inline double sorted_quantile(const std::vector<double>& sorted, std::size_t percent)
{
    return sorted[std::min(sorted.size() - 1, sorted.size() * percent / 100)];
}

/// The upper median of `values`: element n / 2 of the sorted values (the upper middle value for an
/// even count). `values` must not be empty. O(n).
inline double upper_median(std::vector<double> values)
{
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

} // namespace PCCD::testing
