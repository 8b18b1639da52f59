// PCCD/Surface/Gaussian_weight.h -- the Gaussian kernel with bounded support that weights the
// points of the implicit surface (doc/algorithms.md, "Weights, support and bandwidth"): theta(d) =
// exp(-d^2 / h^2), ignored below the threshold theta_eps, i.e. beyond the support radius h sqrt(-ln
// theta_eps).
#pragma once

#include <cmath>

#include <PCCD/Error.h>

namespace PCCD {

/// The Gaussian weight theta(d) = exp(-d^2 / h^2) of bandwidth h, truncated where it drops below
/// theta_eps: its support radius is R = h sqrt(-ln theta_eps), and theta(R) = theta_eps exactly
/// (up to rounding). Models SurfaceWeight.
///
/// Immutable and trivially copyable; safe to share between threads.
class Gaussian_weight {
public:
    /// \param bandwidth h, finite and > 0 (length unit of the cloud), at most 1e154 and at least 1e-154
    ///        (so that h^2 and 1 / h^2 do not overflow).
    /// \param threshold theta_eps in (0, 1): weights below it are ignored.
    /// \throws Invalid_input naming the bad parameter.
    Gaussian_weight(double bandwidth, double threshold)
        : m_bandwidth(bandwidth), m_threshold(threshold)
    {
        if (!(std::isfinite(bandwidth) && bandwidth > 0.0))
            throw Invalid_input(internal::concat("Gaussian weight: bandwidth h is ", bandwidth,
                                                 "; it must be finite and > 0"));
        if (!(std::isgreater(threshold, 0.0) && std::isless(threshold, 1.0)))
            throw Invalid_input(internal::concat("Gaussian weight: threshold theta_eps is ", threshold,
                                                 "; it must lie in (0, 1)"));
        // Checked before the arithmetic below, which would otherwise overflow (h^2, 1 / h^2) and trap
        // in builds with floating-point exceptions enabled. In [1e-154, 1e154], h^2 and 1 / h^2 are
        // normal doubles and h sqrt(-ln theta_eps) <= 28 h is finite.
        if (!(bandwidth >= 1e-154 && bandwidth <= 1e154))
            throw Invalid_input(internal::concat("Gaussian weight: bandwidth ", bandwidth, " and threshold ", threshold,
                                                 " overflow double precision (h must lie in [1e-154, 1e154])"));
        m_inverse_h2 = 1.0 / (bandwidth * bandwidth);
        m_support = bandwidth * std::sqrt(-std::log(threshold));
    }

    /// theta(d) = exp(-d^2 / h^2). O(1).
    double operator()(double d) const { return std::exp(-d * d * m_inverse_h2); }
    /// h.
    double bandwidth() const { return m_bandwidth; }
    /// theta_eps.
    double threshold() const { return m_threshold; }
    /// R = h sqrt(-ln theta_eps): the largest distance whose weight is >= theta_eps.
    double support_radius() const { return m_support; }

private:
    double m_bandwidth;
    double m_threshold;
    double m_inverse_h2 = 0.0;
    double m_support = 0.0;
};

} // namespace PCCD
