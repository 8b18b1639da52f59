// PCCD/Surface/surface_domain.h -- where the implicit surface of a point cloud is defined
// (doc/manual/surface.md, "Scans: where the surface is defined"): the zero set of a weighted
// least-squares fit is meaningful only near the data; far from it (at the edge of the kernel's
// support, where a handful of points decide the fit) it has spurious sheets. After Amenta and Kil's
// domain of a point-set surface, f is defined at x only when x lies within a local,
// spacing-relative distance D_{p*} of its nearest cloud point p*. This header computes the radii
// D_i; WLS_surface applies them.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Surface/local_spacing.h>
#include <PCCD/Surface/surface_options.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

namespace internal {

inline void check_domain_options(const Surface_domain_options& o)
{
    if (o.neighbors == 0) throw Invalid_input("surface domain: neighbors must be >= 1");
    if (!(std::isfinite(o.factor) && o.factor > 0.0))
        throw Invalid_input(concat("surface domain: factor ", o.factor, " must be finite and > 0"));
}

} // namespace internal

/// The domain radii D_i = factor * l_i from a local spacing (see local_spacing()), or empty when
/// `options.enabled` is false. Points that coincide with k others (l_i = 0) get the smallest
/// positive radius of the cloud (never 0, which would leave no domain at all).
/// \throws Invalid_input for invalid options.
inline Eigen::VectorXd surface_domain_radii(const Local_spacing& spacing, const Surface_domain_options& options = {})
{
    internal::check_domain_options(options);
    if (!options.enabled) return {};
    Eigen::VectorXd radii = options.factor * spacing.spacing;
    double smallest = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < radii.size(); ++i)
        if (radii(i) > 0.0) smallest = std::min(smallest, radii(i));
    if (!std::isfinite(smallest)) smallest = std::numeric_limits<double>::min(); // all points coincide
    for (Eigen::Index i = 0; i < radii.size(); ++i)
        if (!(radii(i) > 0.0)) radii(i) = smallest;
    return radii;
}

/// The domain radii of a cloud: D_i = factor * (distance from p_i to its k-th nearest other
/// point), k = options.neighbors. Empty when `options.enabled` is false.
/// \throws Invalid_input for invalid options or a cloud of fewer than two points.
/// Complexity: that of local_spacing(). Thread safety: reads the cloud only.
template <PointCloudKernel K>
Eigen::VectorXd surface_domain_radii(const Point_cloud<K>& cloud, const Surface_domain_options& options = {})
{
    internal::check_domain_options(options);
    if (!options.enabled) return {};
    return surface_domain_radii(local_spacing(cloud, options.neighbors, false, options.threads), options);
}

} // namespace PCCD
