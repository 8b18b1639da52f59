// PCCD/sharp_feature_options.h -- the preprocessing options for parts with sharp edges as one call:
// the IMLS fit, a Gaussian of 2/3 the default bandwidth within the same support (theta_eps 3e-5),
// and the oriented normals refitted robustly (residual scale 0.25 bandwidths), on top of any other
// options. What they change and where they help or hurt is measured in doc/manual/surface.md,
// "Sharp features: the IMLS fit" (doc/algorithms.md, "The implicit surface").
#pragma once

#include <PCCD/Point_cloud_object_options.h>

namespace PCCD {

/// `base` with the sharp-feature surface options set: surface_fit = Surface_fit::imls,
/// bandwidth.theta_eps = 3e-5 and normal_residual_scale = 0.25; every other field of `base` is
/// kept. For CAD and mechanical parts (clean samples of sharp edges, thin walls); on noisy scans
/// the default sphere fit is the better choice (doc/manual/surface.md, "Sharp features").
inline Point_cloud_object_options sharp_feature_options(Point_cloud_object_options base = {})
{
    base.surface_fit = Surface_fit::imls;
    base.bandwidth.theta_eps = 3e-5;
    base.normal_residual_scale = 0.25;
    return base;
}

} // namespace PCCD
