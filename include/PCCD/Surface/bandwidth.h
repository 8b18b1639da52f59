// PCCD/Surface/bandwidth.h -- the kernel bandwidth of the implicit surface (doc/algorithms.md,
// "Weights, support and bandwidth", from the talk): h(P) = eta r(P) / sqrt(-ln theta_eps), r(P) the
// sampling radius of the cloud, so that the kernel's support radius h sqrt(-ln theta_eps) is eta
// r(P) whatever theta_eps; or a bandwidth the user gives.
#pragma once

#include <cmath>
#include <optional>

#include <PCCD/Error.h>
#include <PCCD/Surface/Gaussian_weight.h>
#include <PCCD/Surface/surface_options.h>

namespace PCCD {

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
