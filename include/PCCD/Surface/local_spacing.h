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

namespace PCCD {

/// The local spacing of a cloud: l_i = distance from p_i to its k-th nearest other point (k capped
/// at N - 1), and, when requested, the indices of those k neighbours (row-major, k per point,
/// nearest first; the point itself is never among them, its duplicates may be).
struct Local_spacing {
    unsigned k = 0;
    Eigen::VectorXd spacing;
    std::vector<std::uint32_t> neighbors;
};

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
            for (std::size_t i = begin; i < end; ++i) {
                cloud.k_nearest(cloud.position(std::uint32_t(i)), result.k + 1, nn);
                // The point itself is among the k + 1 nearest (at distance 0, maybe tied with
                // duplicates of it): drop it, or the farthest entry if ties pushed it out.
                std::size_t written = 0;
                bool skipped_self = false;
                for (const auto& entry : nn) {
                    if (!skipped_self && entry.index == i) {
                        skipped_self = true;
                        continue;
                    }
                    if (written == result.k) break;
                    if (keep_neighbors) result.neighbors[i * result.k + written] = entry.index;
                    ++written;
                }
                result.spacing(Eigen::Index(i)) = std::sqrt(double(nn.back().squared_distance));
            }
        });
    });
    return result;
}

} // namespace PCCD
