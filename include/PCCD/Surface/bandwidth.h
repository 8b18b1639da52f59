// PCCD/Surface/bandwidth.h -- the kernel bandwidth of the implicit surface (ALGORITHMS.md section 1,
// from the talk): h(P) = eta r(P) / sqrt(-ln theta_eps), r(P) the sampling radius of the cloud, so
// that the kernel's support radius h sqrt(-ln theta_eps) is eta r(P) whatever theta_eps; or a
// bandwidth the user gives.
#pragma once

#include <cmath>

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
    /// A bandwidth h given by the user (length unit of the cloud): when > 0 it is used as it is and
    /// eta and r(P) are ignored. Default 0 (automatic).
    double bandwidth = 0.0;
};

/// h = eta r / sqrt(-ln theta_eps), or options.bandwidth when it is > 0.
/// \throws Invalid_input if an option is out of range or `sampling_radius` is not finite and > 0
///         (when it is needed).
inline double kernel_bandwidth(double sampling_radius, const Bandwidth_options& options = {})
{
    if (!(std::isgreater(options.theta_eps, 0.0) && std::isless(options.theta_eps, 1.0)))
        throw Invalid_input(internal::concat("bandwidth: theta_eps is ", options.theta_eps, "; it must lie in (0, 1)"));
    if (options.bandwidth != 0.0) {
        if (!(std::isfinite(options.bandwidth) && options.bandwidth > 0.0))
            throw Invalid_input(internal::concat("bandwidth: the given bandwidth is ", options.bandwidth,
                                                 "; it must be finite and > 0 (or 0 for automatic)"));
        return options.bandwidth;
    }
    if (!(std::isfinite(options.eta) && options.eta > 0.0))
        throw Invalid_input(internal::concat("bandwidth: eta is ", options.eta, "; it must be finite and > 0"));
    if (!(std::isfinite(sampling_radius) && sampling_radius > 0.0))
        throw Invalid_input(internal::concat("bandwidth: the sampling radius is ", sampling_radius,
                                             "; it must be finite and > 0"));
    return options.eta * sampling_radius / std::sqrt(-std::log(options.theta_eps));
}

/// The Gaussian weight of kernel_bandwidth() with threshold options.theta_eps.
inline Gaussian_weight gaussian_weight(double sampling_radius, const Bandwidth_options& options = {})
{
    return Gaussian_weight(kernel_bandwidth(sampling_radius, options), options.theta_eps);
}

} // namespace PCCD
