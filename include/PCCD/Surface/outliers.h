// PCCD/Surface/outliers.h -- isolated points of a scan (doc/manual/surface.md, "Scans":
// outliers): a point whose local spacing is far above that of its own neighbours lies off
// the sampled surface (a stray return of the scanner), and is left out of the surface. The test is
// local, so uneven sampling density is not mistaken for outliers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Surface/local_spacing.h>
#include <PCCD/Surface/surface_options.h>

namespace PCCD {

namespace internal {

inline void check_outlier_options(const Outlier_options& o)
{
    if (o.neighbors == 0) throw Invalid_input("outliers: neighbors must be >= 1");
    if (!(std::isfinite(o.ratio) && o.ratio > 1.0))
        throw Invalid_input(concat("outliers: ratio ", o.ratio, " must be finite and > 1"));
    if (!(std::isfinite(o.global_ratio) && (o.global_ratio == 0.0 || o.global_ratio > 1.0)))
        throw Invalid_input(concat("outliers: global_ratio ", o.global_ratio, " must be finite and 0 or > 1"));
}

} // namespace internal

/// The outliers of a cloud, given its local spacing with neighbour lists (local_spacing(cloud, k,
/// true)): indices i, ascending, with l_i > ratio * median_{j in kNN(i)} l_j or (when global_ratio
/// > 0) l_i > global_ratio * median_j l_j.
/// \throws Invalid_input for invalid options or a spacing without neighbour lists.
/// Complexity: O(N k). Deterministic.
inline std::vector<std::uint32_t> find_outliers(const Local_spacing& spacing, const Outlier_options& options = {})
{
    internal::check_outlier_options(options);
    const std::size_t n = std::size_t(spacing.spacing.size());
    if (spacing.neighbors.size() != n * spacing.k)
        throw Invalid_input("outliers: the local spacing carries no neighbour lists");
    std::vector<std::uint32_t> outliers;
    double global_limit = std::numeric_limits<double>::infinity();
    if (options.global_ratio > 0.0 && n > 0) {
        std::vector<double> all(spacing.spacing.data(), spacing.spacing.data() + n);
        const auto middle = all.begin() + std::ptrdiff_t(n / 2);
        std::nth_element(all.begin(), middle, all.end());
        if (*middle > 0.0) global_limit = options.global_ratio * *middle;
    }
    std::vector<double> around(spacing.k);
    for (std::size_t i = 0; i < n; ++i) {
        for (unsigned m = 0; m < spacing.k; ++m) around[m] = spacing.spacing(Eigen::Index(spacing.neighbors[i * spacing.k + m]));
        const auto middle = around.begin() + std::ptrdiff_t(around.size() / 2);
        std::nth_element(around.begin(), middle, around.end());
        const double l = spacing.spacing(Eigen::Index(i));
        // A zero median (neighbours with k duplicates of themselves) is no evidence of isolation.
        if ((*middle > 0.0 && l > options.ratio * *middle) || l > global_limit) outliers.push_back(std::uint32_t(i));
    }
    return outliers;
}

/// The outliers of a cloud (see above), computing its local spacing with options.neighbors.
template <PointCloudKernel K>
std::vector<std::uint32_t> find_outliers(const Point_cloud<K>& cloud, const Outlier_options& options = {})
{
    internal::check_outlier_options(options);
    return find_outliers(local_spacing(cloud, options.neighbors, true, options.threads), options);
}

} // namespace PCCD
