// PCCD/Surface/estimate_normals.h -- the unoriented WLS normal n(p_i) at every point of a cloud
// (doc/algorithms.md, "The implicit surface"), the raw material of normal orientation: the same fit
// as WLS_surface, evaluated at the cloud points themselves.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Surface/internal/wls_fit.h>
#include <PCCD/concepts/SurfaceDistance.h>
#include <PCCD/concepts/SurfaceWeight.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// Iterations of the robust refit of refit_normals() after its first fit: the number every figure
/// of doc/manual/surface.md ("Sharp features") was measured with; other counts were not measured.
inline constexpr int robust_refit_iterations = 4;

namespace internal {

/// The WLS sums of cloud point i's weighted neighbours within `support` (offsets from p_i).
template <class Distance, class Weight>
Wls_sums sums_at_point(const Distance& distance, const Weight& weight, double support, std::size_t i)
{
    const auto index = static_cast<std::uint32_t>(i);
    const Eigen::Vector3d x = distance.position(index);
    Wls_sums sums;
    distance.for_each_neighbor_of_point(index, support, [&](std::uint32_t j, double d) {
        sums.add(distance.position(j) - x, double(weight(d)));
    });
    return sums;
}

/// The robust refit of refit_normals() at cloud point x from its neighbours (offsets from x and
/// weights) and their plain fit `fit` with total weight `weight_sum`: each neighbour's weight times
/// exp(-(r / sigma_r)^2), r its distance from the last plane, robust_refit_iterations times (fewer
/// when a refit keeps less than a tenth of the weight or is undetermined).
inline Wls_fit robust_refit(const Eigen::Vector3d& x, const std::vector<std::pair<Eigen::Vector3d, double>>& neighbors,
                            double weight_sum, double sigma_r, Wls_fit fit)
{
    const double inv = 1.0 / (sigma_r * sigma_r);
    for (int iteration = 0; iteration < robust_refit_iterations; ++iteration) {
        const Eigen::Vector3d centre = fit.centroid - x;
        Wls_sums again;
        for (const auto& [offset, w] : neighbors) {
            const double r = fit.normal.dot(offset - centre);
            again.add(offset, w * std::exp(-r * r * inv));
        }
        if (!(again.weight >= 0.1 * weight_sum)) break;
        const Wls_fit next = finish_fit(x, again);
        if (!next.determined) break;
        fit = next;
    }
    return fit;
}

} // namespace internal

/// Unoriented normals of a cloud.
struct Normal_estimate {
    /// 3 x N: column i is the unit eigenvector of the smallest eigenvalue of B(p_i), with the
    /// eigen-solver's arbitrary sign, or zero where the fit does not determine it.
    Eigen::Matrix3Xd normals;
    /// Number of points whose normal is undetermined (zero columns): isolated points or points whose
    /// weighted neighbours are collinear.
    std::size_t undetermined = 0;
    /// Leave-one-out residual of every point: the signed distance n_i' . (p_i - a_i') of p_i from
    /// the plane fitted to its weighted neighbours without p_i itself; NaN where that fit is
    /// undetermined. Its spread measures the noise of the cloud (plus the curvature the plane
    /// cannot follow inside the kernel), see noise_estimate().
    Eigen::VectorXd residuals;
};

/// A robust estimate of the cloud's noise level sigma (standard deviation of the points' offsets
/// from the surface): median |residual| / 0.6745 over the points with a residual (for Gaussian
/// offsets the median absolute value is 0.6745 sigma). On a clean sample it is not 0 but the
/// curvature the kernel's plane cannot follow (0.1-0.15 mean spacings on the 30k-point scans of
/// doc/benchmarks.md, more on coarse samples of curved shapes); 0 when no point has a residual.
inline double noise_estimate(const Normal_estimate& estimate)
{
    std::vector<double> r;
    r.reserve(std::size_t(estimate.residuals.size()));
    for (Eigen::Index i = 0; i < estimate.residuals.size(); ++i)
        if (std::isfinite(estimate.residuals(i))) r.push_back(std::abs(estimate.residuals(i)));
    if (r.empty()) return 0.0;
    const auto middle = r.begin() + std::ptrdiff_t(r.size() / 2);
    std::nth_element(r.begin(), middle, r.end());
    return *middle / 0.6745;
}

/// The WLS normal n(p_i) of every cloud point, before orientation.
///
/// \tparam Distance a model of SurfaceDistance.
/// \tparam Weight a model of SurfaceWeight.
/// \param threads worker threads, >= 1 (unset: all available); ignored without TBB. The result does not
///        depend on it.
/// \throws Invalid_input if the weight's support radius exceeds `distance.max_radius()` (beyond a
///         relative 1e-12 of rounding).
/// Complexity: N neighbour enumerations (O(N k) with a CPSP map). Thread safety: reads its
/// arguments only.
template <SurfaceDistance Distance, SurfaceWeight Weight>
Normal_estimate estimate_normals(const Distance& distance, const Weight& weight,
                                 std::optional<unsigned> threads = std::nullopt)
{
    const double support = double(weight.support_radius());
    if (support > double(distance.max_radius()) * (1.0 + 1e-12))
        throw Invalid_input(internal::concat("estimate_normals: the kernel's support radius ", support,
                                             " exceeds the largest radius the distance policy answers (",
                                             double(distance.max_radius()), ")"));
    const std::size_t n = distance.size();
    Normal_estimate result{Eigen::Matrix3Xd::Zero(3, Eigen::Index(n)), 0,
                           Eigen::VectorXd::Constant(Eigen::Index(n), std::numeric_limits<double>::quiet_NaN())};
    internal::with_threads(threads, [&] {
        internal::parallel_for_ranges(n, 256, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Eigen::Vector3d x = distance.position(static_cast<std::uint32_t>(i));
                const internal::Wls_sums sums = internal::sums_at_point(distance, weight, support, i);
                if (sums.count == 0 || !(sums.weight > 0.0)) continue;
                const internal::Wls_fit fit = internal::finish_fit(x, sums);
                if (fit.determined) result.normals.col(Eigen::Index(i)) = fit.normal;
                // p_i itself sits at offset 0: without it only the weight sum and the count change.
                internal::Wls_sums others = sums;
                others.weight -= double(weight(0.0));
                others.count -= 1;
                if (others.count == 0 || !(others.weight > 0.0)) continue;
                const internal::Wls_fit loo = internal::finish_fit(x, others);
                if (loo.determined) result.residuals(Eigen::Index(i)) = loo.normal.dot(x - loo.centroid);
            }
        });
    });
    for (Eigen::Index i = 0; i < result.normals.cols(); ++i)
        if (result.normals.col(i).isZero(0.0)) ++result.undetermined;
    return result;
}

/// Fits every normal of `normals` again with the kernel `weight` (narrower than the one they were
/// estimated with, typically) and keeps each one's sign: column i becomes the new fit at p_i, turned
/// to agree with the old column i (a positive dot product). Where the new fit is undetermined, or
/// the old column is zero (no normal), column i stays as it was. A narrow kernel bends the normals
/// less across sharp edges, which the IMLS fit reads (doc/manual/surface.md, "Sharp features");
/// the orientation, done on the wider kernel's smoother normals, carries over.
///
/// With `residual_scale` (a length sigma_r), the fit is made robust (an M-estimator, iteratively
/// reweighted): after the plane is fitted, each neighbour's weight is multiplied by
/// exp(-(r_j / sigma_r)^2), r_j its distance from that plane, and the plane fitted again,
/// robust_refit_iterations times. Near a sharp edge the points of the other face lie off the plane
/// of the face p_i is on, lose their weight, and the normal turns to that face's instead of the
/// average of the two; a refit that would keep less than a tenth of the weight keeps the last plane.
///
/// \tparam Distance a model of SurfaceDistance. \tparam Weight a model of SurfaceWeight.
/// \param normals 3 x N, oriented (N = distance.size()); refitted in place.
/// \param threads as estimate_normals(); the result does not depend on it.
/// \param residual_scale sigma_r of the robust fit (same unit as the points); unset: the plain fit.
/// \throws Invalid_input as estimate_normals(), if `normals` does not have N columns, or if
///         `residual_scale` is set and not finite and > 0.
/// Returns the number of normals refitted. Complexity: N neighbour enumerations within the new
/// support (times 1 + robust_refit_iterations passes over the neighbours with `residual_scale`).
/// Thread safety: reads its arguments only, writes `normals`.
template <SurfaceDistance Distance, SurfaceWeight Weight>
std::size_t refit_normals(const Distance& distance, const Weight& weight, Eigen::Matrix3Xd& normals,
                          std::optional<unsigned> threads = std::nullopt,
                          std::optional<double> residual_scale = std::nullopt)
{
    // A quiet comparison: a NaN is refused, never trapped.
    if (residual_scale && !(std::isfinite(*residual_scale) && std::isgreater(*residual_scale, 0.0)))
        throw Invalid_input(internal::concat("refit_normals: residual_scale is ", *residual_scale,
                                             "; it must be finite and > 0"));
    const double support = double(weight.support_radius());
    if (support > double(distance.max_radius()) * (1.0 + 1e-12))
        throw Invalid_input(internal::concat("refit_normals: the kernel's support radius ", support,
                                             " exceeds the largest radius the distance policy answers (",
                                             double(distance.max_radius()), ")"));
    if (std::size_t(normals.cols()) != distance.size())
        throw Invalid_input(internal::concat("refit_normals: ", normals.cols(), " normals given for ", distance.size(),
                                             " points"));
    const std::size_t n = distance.size();
    std::vector<std::uint8_t> refitted(n, 0);
    // The robust refit reads each point's neighbours again: read them once into this buffer (one per
    // thread, reused) and sum them from it, in the same order as sums_at_point().
    thread_local std::vector<std::pair<Eigen::Vector3d, double>> neighbors;
    internal::with_threads(threads, [&] {
        internal::parallel_for_ranges(n, 256, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const auto old = normals.col(Eigen::Index(i));
                if (old.isZero(0.0)) continue;
                const auto index = static_cast<std::uint32_t>(i);
                const Eigen::Vector3d x = distance.position(index);
                internal::Wls_sums sums;
                if (residual_scale) {
                    neighbors.clear();
                    distance.for_each_neighbor_of_point(index, support, [&](std::uint32_t j, double d) {
                        neighbors.emplace_back(distance.position(j) - x, double(weight(d)));
                        sums.add(neighbors.back().first, neighbors.back().second);
                    });
                } else {
                    sums = internal::sums_at_point(distance, weight, support, i);
                }
                if (sums.count == 0 || !(sums.weight > 0.0)) continue;
                internal::Wls_fit fit = internal::finish_fit(x, sums);
                if (!fit.determined) continue;
                if (residual_scale) fit = internal::robust_refit(x, neighbors, sums.weight, *residual_scale, fit);
                normals.col(Eigen::Index(i)) = fit.normal.dot(old) < 0.0 ? Eigen::Vector3d(-fit.normal) : fit.normal;
                refitted[i] = 1;
            }
        });
    });
    return std::size_t(std::count(refitted.begin(), refitted.end(), std::uint8_t(1)));
}

} // namespace PCCD
