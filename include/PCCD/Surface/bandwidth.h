// PCCD/Surface/bandwidth.h -- the kernel bandwidth of the implicit surface (doc/algorithms.md,
// "Weights, support and bandwidth", from the talk): h(P) = eta r(P) / sqrt(-ln theta_eps), r(P) the
// sampling radius of the cloud, so that the kernel's support radius h sqrt(-ln theta_eps) is eta
// r(P) whatever theta_eps; or a bandwidth the user gives.
#pragma once

#include <cmath>
#include <optional>

#include <PCCD/Error.h>
#include <PCCD/Surface/Gaussian_weight.h>

namespace PCCD {

/// How the Gaussian kernel of the surface is chosen. Defaults measured in doc/manual/surface.md
/// ("Choosing eta and theta_eps").
struct Bandwidth_options {
    /// eta: the support radius in units of the sampling radius r(P), independent of the sampling
    /// density. Default 3. Must be finite and > 0.
    double eta = 3.0;
    /// theta_eps: weights below it are ignored. Default 1e-2. Must lie in (0, 1).
    double theta_eps = 1e-2;
    /// A bandwidth h given by the user (length unit of the cloud), used as it is: eta, r(P) and
    /// noise_factor are then ignored. Unset (default): automatic, eta r(P) / sqrt(-ln theta_eps).
    /// When set: finite and > 0.
    std::optional<double> bandwidth = std::nullopt;
    /// Noise-aware support (automatic bandwidth only): the support radius is at least
    /// noise_factor * sigma, sigma the cloud's noise estimate (noise_estimate()), so that the fit
    /// keeps averaging over enough points when the noise is heavy. Default 15, measured with the
    /// sphere fit (Surface_fit::sphere, Point_cloud_object's default) on noisy area samples of the
    /// bunny and the elephant (doc/benchmarks.md "Accuracy on scans"): with sigma = 0.6 mean spacings
    /// it widens the support from eta r(P) (8 spacings) to about 10 spacings and brings the curves'
    /// median distance from 0.32 to 0.28 spacings and their p95 from 1.15 to 0.98 (bunny); 20 is
    /// worse again (the sphere no longer follows the shape). Up to sigma = 0.3 spacings the rule
    /// leaves eta r(P) alone. With the plane fit, whose shrinkage on curved parts grows with the
    /// kernel, 10 is the better value. At sigma = 1 spacing eta r(P) leaves about 3 % of the surface
    /// with flipped normals, a support of about 4 r(P) 0.1 %. 0 disables it. Must be finite and >= 0.
    double noise_factor = 15.0;
};

namespace internal {

inline void check_noise_factor(const Bandwidth_options& options)
{
    if (!(std::isfinite(options.noise_factor) && options.noise_factor >= 0.0))
        throw Invalid_input(concat("bandwidth: noise_factor is ", options.noise_factor, "; it must be finite and >= 0"));
}

} // namespace internal

/// h = eta r / sqrt(-ln theta_eps), or options.bandwidth when it is set.
/// \throws Invalid_input if an option is out of range or `sampling_radius` is not finite and > 0
///         (when it is needed).
inline double kernel_bandwidth(double sampling_radius, const Bandwidth_options& options = {})
{
    if (!(std::isgreater(options.theta_eps, 0.0) && std::isless(options.theta_eps, 1.0)))
        throw Invalid_input(internal::concat("bandwidth: theta_eps is ", options.theta_eps, "; it must lie in (0, 1)"));
    if (options.bandwidth) {
        if (!(std::isfinite(*options.bandwidth) && *options.bandwidth > 0.0))
            throw Invalid_input(internal::concat("bandwidth: the given bandwidth is ", *options.bandwidth,
                                                 "; it must be finite and > 0 (leave it unset for the automatic value)"));
        return *options.bandwidth;
    }
    if (!(std::isfinite(options.eta) && options.eta > 0.0))
        throw Invalid_input(internal::concat("bandwidth: eta is ", options.eta, "; it must be finite and > 0"));
    if (sampling_radius == 0.0)
        throw Invalid_input("bandwidth: the sampling radius is 0; it must be finite and > 0. It is 0 when at least "
                            "half of the points coincide with another point (the median distance to the nearest "
                            "other point is 0): the points have no spacing to size the surface's kernel by; remove "
                            "the duplicate points");
    if (!(std::isfinite(sampling_radius) && sampling_radius > 0.0))
        throw Invalid_input(internal::concat("bandwidth: the sampling radius is ", sampling_radius,
                                             "; it must be finite and > 0"));
    return options.eta * sampling_radius / std::sqrt(-std::log(options.theta_eps));
}

/// The wider weight the noise asks for: a Gaussian weight of support radius noise_factor * sigma
/// (same theta_eps) when that exceeds `weight`'s support and the bandwidth is automatic; nullopt
/// otherwise (keep `weight`). \throws Invalid_input if noise_factor is invalid.
inline std::optional<Gaussian_weight> noise_aware_weight(const Gaussian_weight& weight, double sigma,
                                                         const Bandwidth_options& options = {})
{
    internal::check_noise_factor(options);
    if (options.bandwidth || !(std::isfinite(sigma) && sigma > 0.0)) return std::nullopt;
    const double support = options.noise_factor * sigma;
    if (!(support > double(weight.support_radius()))) return std::nullopt;
    return Gaussian_weight(support / std::sqrt(-std::log(double(weight.threshold()))), weight.threshold());
}

/// The Gaussian weight of kernel_bandwidth() with threshold options.theta_eps.
inline Gaussian_weight gaussian_weight(double sampling_radius, const Bandwidth_options& options = {})
{
    return Gaussian_weight(kernel_bandwidth(sampling_radius, options), options.theta_eps);
}

} // namespace PCCD
