// PCCD/Surface/local_spacing.h -- the local spacing of a point cloud (doc/manual/surface.md,
// "Scans"): for every point, its distance to its k-th nearest other point, and optionally
// those k neighbours. The surface's domain (surface_domain.h) and the outlier test (outliers.h)
// are both made of it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/internal/parallel.h>
#include <PCCD/internal/removal.h>

namespace PCCD {

/// The local spacing of a cloud: l_i = distance from p_i to its k-th nearest other point (k capped
/// at N - 1), and, when requested, the indices of those k neighbours (row-major, k per point,
/// nearest first; the point itself is never among them, its duplicates may be).
struct Local_spacing {
    unsigned k = 0;
    Eigen::VectorXd spacing;
    std::vector<std::uint32_t> neighbors;
};

namespace internal {

/// Point i's entry of `result` (its spacing, and its list when `result` keeps lists), from its
/// k + 1 nearest points in `cloud` (k = result.k; `nn` is scratch).
template <class K>
void spacing_of_point(const Point_cloud<K>& cloud, std::uint32_t i, Local_spacing& result,
                      std::vector<typename Point_cloud<K>::Neighbor>& nn)
{
    cloud.k_nearest(cloud.position(i), result.k + 1, nn);
    const bool keep_neighbors = !result.neighbors.empty();
    // The point itself is among the k + 1 nearest (at distance 0, maybe tied with duplicates of
    // it): drop it, or the farthest entry if ties pushed it out.
    std::size_t written = 0;
    bool skipped_self = false;
    for (const auto& entry : nn) {
        if (!skipped_self && entry.index == i) {
            skipped_self = true;
            continue;
        }
        if (written == result.k) break;
        if (keep_neighbors) result.neighbors[std::size_t(i) * result.k + written] = entry.index;
        ++written;
    }
    result.spacing(Eigen::Index(i)) = std::sqrt(double(nn.back().squared_distance));
}

} // namespace internal

/// Computes the local spacing with k neighbours (`keep_neighbors`: also the neighbour lists).
/// \throws Invalid_input if k == 0 or the cloud has fewer than two points.
/// Complexity: N (k + 1)-nearest queries, O(N k log N) expected; deterministic whatever `threads`.
template <PointCloudKernel K>
Local_spacing local_spacing(const Point_cloud<K>& cloud, unsigned k, bool keep_neighbors = false,
                            std::optional<unsigned> threads = std::nullopt)
{
    if (k == 0) throw Invalid_input("local spacing: k must be >= 1");
    const std::size_t n = cloud.size();
    if (n < 2) throw Invalid_input("local spacing: a cloud of fewer than two points has no spacing");
    Local_spacing result;
    result.k = unsigned(std::min<std::size_t>(k, n - 1));
    result.spacing.resize(Eigen::Index(n));
    if (keep_neighbors) result.neighbors.resize(n * result.k);
    internal::with_threads(threads, [&] {
        internal::parallel_for_ranges(n, 512, [&](std::size_t begin, std::size_t end) {
            std::vector<typename Point_cloud<K>::Neighbor> nn;
            for (std::size_t i = begin; i < end; ++i) internal::spacing_of_point(cloud, std::uint32_t(i), result, nn);
        });
    });
    return result;
}

/// The local spacing, with neighbour lists, of the cloud `remaining` that is left when the points
/// `removed` (indices into the cloud `spacing` was computed on, sorted, each at most once) are
/// taken out of it, the others keeping their order. A point none of whose k neighbours was removed
/// keeps its spacing and its list (renumbered): the k nearest by (distance, index), which the
/// queries find exactly, are then still its k nearest. The points that lost a neighbour are queried
/// again on `remaining`. The result equals local_spacing(remaining, spacing.k, true, threads), at
/// the cost of those queries only (after removing the few outliers of a scan, a few per million).
/// \throws Invalid_input if `spacing` has no neighbour lists, or `removed` and `remaining` do not
/// fit it.
template <PointCloudKernel K>
Local_spacing local_spacing_without(const Local_spacing& spacing, const std::vector<std::uint32_t>& removed,
                                    const Point_cloud<K>& remaining, std::optional<unsigned> threads = std::nullopt)
{
    const std::size_t old_n = std::size_t(spacing.spacing.size());
    const std::size_t k = spacing.k;
    if (k == 0 || spacing.neighbors.size() != old_n * k)
        throw Invalid_input("local spacing: removing points needs the spacing's neighbour lists");
    if (removed.size() > old_n || remaining.size() != old_n - removed.size())
        throw Invalid_input(internal::concat("local spacing: ", removed.size(), " points removed from ", old_n,
                                             " leave ", old_n - std::min(removed.size(), old_n), ", not ",
                                             remaining.size()));
    // renumbered[i]: the index in `remaining` of point i, or `gone`.
    const std::vector<std::uint32_t> renumbered = internal::renumber_without(old_n, removed, "local spacing");
    constexpr std::uint32_t gone = internal::removed_point;
    const std::size_t n = remaining.size();
    if (n < 2) throw Invalid_input("local spacing: a cloud of fewer than two points has no spacing");
    Local_spacing result;
    result.k = unsigned(std::min<std::size_t>(k, n - 1));
    result.spacing.resize(Eigen::Index(n));
    result.neighbors.resize(n * result.k);
    std::vector<std::uint32_t> again; // indices in `remaining` of the points to query again
    for (std::size_t i = 0; i < old_n; ++i) {
        const std::uint32_t at = renumbered[i];
        if (at == gone) continue;
        const std::uint32_t* list = spacing.neighbors.data() + i * k;
        // (A point whose list is intact keeps its spacing even when ties at distance 0 had pushed
        // it out of its own k + 1 nearest: it and its k listed copies still lie at 0.)
        bool intact = result.k == k;
        for (std::size_t m = 0; m < k && intact; ++m) intact = renumbered[list[m]] != gone;
        if (!intact) {
            again.push_back(at);
            continue;
        }
        result.spacing(Eigen::Index(at)) = spacing.spacing(Eigen::Index(i));
        for (std::size_t m = 0; m < k; ++m) result.neighbors[at * k + m] = renumbered[list[m]];
    }
    internal::with_threads(threads, [&] {
        internal::parallel_for_ranges(again.size(), 64, [&](std::size_t begin, std::size_t end) {
            std::vector<typename Point_cloud<K>::Neighbor> nn;
            for (std::size_t j = begin; j < end; ++j)
                internal::spacing_of_point(remaining, again[j], result, nn);
        });
    });
    return result;
}

} // namespace PCCD
