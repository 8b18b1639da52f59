// PCCD/sampling_radius.h -- the sampling radius r(P) of a point cloud and its uses
// (doc/algorithms.md, "Sampling radius and sphere coverings", WSCG05 §4.2): a Monte-Carlo estimate
// of the radius at which spheres around P (or around a subset P') cover the surface, the subsample
// rule r(P') ~ sqrt(|P| / |P'|) r(P), and the surfel count estimate of the root bracketing.
//
// Random points "on the surface" without a surface: the implicit surface f needs r(P) for its
// bandwidth, so it cannot be used here. Instead, a Monte-Carlo point is drawn on the tangent disk of
// a random cloud point p_i: x = p_i + t, t uniform in the disk of radius R in the plane fitted (PCA)
// to the k nearest neighbours of p_i, with R = disk_factor * (median nearest-neighbour distance).
// Disks overlap more where the cloud is dense, so x is weighted by 1 / c(x), c(x) the number of cloud
// points within R of x; the weighted sample is then uniform over the union of the disks, which
// approximates the surface (the disks overhang its boundaries by at most R). r(P') is the weighted
// `quantile` of the distance from x to the nearest point of P'.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <PCCD/Error.h>
#include <PCCD/Kd_tree.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Random.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/internal/parallel.h>
#include <PCCD/sampling_radius_options.h>

namespace PCCD {

namespace internal {

inline void check(const Sampling_radius_options& o)
{
    if (o.samples == 0) throw Invalid_input("sampling radius: samples must be >= 1");
    if (!(std::isgreater(o.quantile, 0.0) && std::islessequal(o.quantile, 1.0)))
        throw Invalid_input(concat("sampling radius: quantile must be in (0, 1], got ", o.quantile));
    if (o.neighbors < 2) throw Invalid_input(concat("sampling radius: neighbors must be >= 2, got ", o.neighbors));
    if (!(std::isfinite(o.disk_factor) && o.disk_factor > 0.0))
        throw Invalid_input(concat("sampling radius: disk_factor must be finite and > 0, got ", o.disk_factor));
}

/// The Monte-Carlo estimate over the surface sampled by `surface`, distances measured to `centres`.
template <PointCloudKernel K>
double sampling_radius_to(const Point_cloud<K>& surface, const Kd_tree<typename K::FT>& centres,
                          const Sampling_radius_options& o)
{
    using FT = typename K::FT;
    using Vector_3 = Eigen::Matrix<FT, 3, 1>;
    check(o);
    if (surface.size() < 2) throw Invalid_input("sampling radius needs at least two points");
    const std::size_t m = o.samples;
    // All random numbers are drawn up front, in order, so the result does not depend on threads.
    struct Draw {
        std::uint32_t base;
        double radius_fraction, angle;
    };
    std::vector<Draw> draws(m);
    Random_engine rng(o.seed);
    for (Draw& d : draws) {
        d.base = std::uint32_t(uniform_index(rng, surface.size()));
        d.radius_fraction = std::sqrt(uniform_01(rng));
        d.angle = 2.0 * std::numbers::pi * uniform_01(rng);
    }
    std::vector<double> nearest(m);
    std::vector<Eigen::Vector3d> axis_u(m), axis_v(m);
    std::vector<std::pair<double, double>> distance_weight(m);
    internal::with_threads(o.threads, [&] {
        // Tangent planes and nearest-neighbour distances of the base points.
        internal::parallel_for_ranges(m, 256, [&](std::size_t begin, std::size_t end) {
            std::vector<Neighbor<FT>> nn;
            for (std::size_t s = begin; s < end; ++s) {
                const Vector_3 p = surface.position(draws[s].base);
                surface.k_nearest(p, std::size_t(o.neighbors) + 1, nn);
                Eigen::Vector3d mean = Eigen::Vector3d::Zero();
                for (const auto& q : nn) mean += surface.position(q.index).template cast<double>();
                mean /= double(nn.size());
                Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
                double nn_distance = 0.0;
                for (const auto& q : nn) {
                    const Eigen::Vector3d d = surface.position(q.index).template cast<double>() - mean;
                    cov += d * d.transpose();
                    if (q.index != draws[s].base && nn_distance == 0.0)
                        nn_distance = std::sqrt(double(q.squared_distance));
                }
                const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(cov);
                axis_u[s] = eigen.eigenvectors().col(2);
                axis_v[s] = eigen.eigenvectors().col(1);
                nearest[s] = nn_distance;
            }
        });
        std::vector<double> sorted = nearest;
        std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(m / 2), sorted.end());
        const double disk = o.disk_factor * sorted[m / 2];
        // The Monte-Carlo points, their distance to the nearest centre and their weight 1 / c(x).
        internal::parallel_for_ranges(m, 256, [&](std::size_t begin, std::size_t end) {
            std::vector<Neighbor<FT>> near;
            for (std::size_t s = begin; s < end; ++s) {
                const Draw& d = draws[s];
                const Eigen::Vector3d x =
                    surface.position(d.base).template cast<double>() +
                    disk * d.radius_fraction * (std::cos(d.angle) * axis_u[s] + std::sin(d.angle) * axis_v[s]);
                const Vector_3 xf = x.cast<FT>();
                surface.within_radius(xf, FT(disk), near);
                const double weight = 1.0 / double(std::max<std::size_t>(near.size(), 1));
                distance_weight[s] = {std::sqrt(double(centres.nearest(xf).squared_distance)), weight};
            }
        });
    });
    std::sort(distance_weight.begin(), distance_weight.end());
    double total = 0.0;
    for (const auto& [distance, weight] : distance_weight) total += weight;
    const double target = o.quantile * total;
    double cumulative = 0.0;
    for (const auto& [distance, weight] : distance_weight) {
        cumulative += weight;
        if (cumulative >= target * (1.0 - 1e-12)) return distance;
    }
    return distance_weight.back().first;
}

} // namespace internal

/// \name Sampling radius
/// @{

/// Monte-Carlo estimate of r(P), the sampling radius of `cloud`: the radius such that spheres of
/// that radius around all points cover the `options.quantile` part of the surface they sample (see
/// the header comment for how surface points are drawn without a surface).
///
/// \tparam K a model of PointCloudKernel.
/// \throws Invalid_input for invalid options or a cloud of fewer than two points.
/// Complexity: O(samples * (k + c) log N), c the points within the disk radius: about 20 ms for
/// the default 10^4 samples, independent of N but for the log. Deterministic for a given seed.
/// Thread safety: reads `cloud` only.
template <PointCloudKernel K>
double sampling_radius(const Point_cloud<K>& cloud, const Sampling_radius_options& options = {})
{
    return internal::sampling_radius_to(cloud, cloud.kd_tree(), options);
}

/// Monte-Carlo estimate of r(P') for the subset P' of `cloud` given by point indices `subset`:
/// the covering radius of spheres around P' over the surface sampled by the whole cloud.
/// \throws Invalid_input if `subset` is empty or holds an index out of range, or as above.
/// Complexity: O(|P'| log |P'|) for a kd-tree over P', plus the cost above.
template <PointCloudKernel K>
double sampling_radius(const Point_cloud<K>& cloud, std::span<const std::uint32_t> subset,
                       const Sampling_radius_options& options = {})
{
    if (subset.empty()) throw Invalid_input("sampling radius of an empty subset");
    typename Kd_tree<typename K::FT>::Coordinates c(3, Eigen::Index(subset.size()));
    for (std::size_t i = 0; i < subset.size(); ++i) {
        if (subset[i] >= cloud.size())
            throw Invalid_input(internal::concat("sampling radius: subset index ", subset[i], " is out of range (",
                                                 cloud.size(), " points)"));
        c.col(Eigen::Index(i)) = cloud.position(subset[i]);
    }
    const Kd_tree<typename K::FT> tree(std::move(c));
    return internal::sampling_radius_to(cloud, tree, options);
}

/// The subsample rule of doc/algorithms.md, "Sampling radius and sphere coverings": r(P') ~
/// sqrt(|P| / |P'|) r(P) for a subset P' of `subset_size` points drawn evenly from a cloud of
/// `size` points with sampling radius `radius`.
/// \throws Invalid_input unless 0 < subset_size <= size.
inline double subsample_sampling_radius(double radius, std::size_t size, std::size_t subset_size)
{
    if (subset_size == 0 || subset_size > size)
        throw Invalid_input(internal::concat("subsample of ", subset_size, " points out of ", size));
    return std::sqrt(double(size) / double(subset_size)) * radius;
}

/// Surface area estimate F ~ |A| pi r(A)^2 of a cloud part A of `points` points with sampling
/// radius `radius` (doc/algorithms.md, "Sampling radius and sphere coverings"; the covering spheres
/// overlap, so it errs on the large side, which makes the surfel count below conservative).
inline double estimated_surface_area(std::size_t points, double radius)
{
    return double(points) * std::numbers::pi * radius * radius;
}

/// Number of conceptual surfels of radius `surfel_radius` on the surface of a cloud part of
/// `points` points with sampling radius `radius`: a ~ F / (pi r^2) = |A| r(A)^2 / r^2 (the `a` of
/// the root bracketing, doc/algorithms.md, "Root bracketing").
/// \throws Invalid_input unless surfel_radius > 0.
inline double estimated_surfel_count(std::size_t points, double radius, double surfel_radius)
{
    if (!std::isgreater(surfel_radius, 0.0))
        throw Invalid_input(internal::concat("surfel radius must be > 0, got ", surfel_radius));
    return estimated_surface_area(points, radius) / (std::numbers::pi * surfel_radius * surfel_radius);
}

/// @}

} // namespace PCCD
