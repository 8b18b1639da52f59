// PCCD/sampling_radius_options.h -- what the Monte-Carlo estimate of the sampling radius r(P) can
// be told (doc/algorithms.md "Sampling radius"; computed by PCCD/sampling_radius.h). Options only:
// it includes no implementation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace PCCD {

/// Options of sampling_radius().
struct Sampling_radius_options {
    /// Number of Monte-Carlo points. Default 10,000 (relative spread of the 0.99-quantile estimate
    /// about 3 %; 20 ms per 10^4 points). Must be >= 1.
    std::size_t samples = 10000;
    /// Which quantile of the distances to the nearest centre is r: 1 gives the maximum, i.e. full
    /// coverage of the sampled surface, at the price of a noisy estimate that grows like sqrt(log N)
    /// for random samples. Default 0.99: spheres of radius r cover 99 % of the surface. Must be in
    /// (0, 1].
    double quantile = 0.99;
    /// Neighbours fitted by PCA for the tangent plane of a point. Default 10. Must be >= 2.
    unsigned neighbors = 10;
    /// The tangent disks' radius R in units of the median nearest-neighbour distance (measured on
    /// the sampled points). Default 3: for a random (Poisson) sample fewer than 0.2 % of the
    /// surface is farther than that from every point, so the 0.99 quantile is unaffected. Must be > 0.
    double disk_factor = 3.0;
    /// Seed of the Monte-Carlo points. Default 1.
    std::uint64_t seed = 1;
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

} // namespace PCCD
