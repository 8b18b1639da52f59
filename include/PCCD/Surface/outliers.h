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

namespace PCCD {

/// Options of find_outliers() and of Point_cloud_object's outlier removal.
struct Outlier_options {
    /// Remove the outliers before building the surface (Point_cloud_object). Default true.
    bool remove = true;
    /// k of the local spacing l_i (distance to the k-th nearest other point). Default 6. >= 1.
    unsigned neighbors = 6;
    /// Point i is an outlier when l_i > ratio * median of l_j over its k nearest neighbours j (the
    /// upper median for even k). Default 4: measured on uniform samples of a sphere, a torus and a
    /// plane patch, l_i / median(l_j) stays at 1.6-2.2, and at 2.3-3.1 across a 16-fold step in
    /// density. A single stray point is caught by this test once it is about 12 spacings off a
    /// plane; stray points closer to the surface stay and act as noise, which the fit and the
    /// verified contacts absorb. Must be finite and > 1.
    double ratio = 4.0;
    /// Point i is also an outlier when l_i > global_ratio * the median of l over the whole cloud:
    /// the local test alone misses stray points whose nearest neighbours are other stray points (a
    /// scatter of outliers away from the surface). Default 8: a local spacing 8 times the typical
    /// one. Measured on a plane patch with one half sparser: 8 times fewer points there flag nothing,
    /// 16 times fewer flag 1-2 legitimate points of the sparse half on some seeds; set it higher, or
    /// to 0 to disable this test, for scans whose density varies more than 8-fold. Must be finite and
    /// 0 or > 1.
    double global_ratio = 8.0;
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

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
