// The sharp-feature options of the surface (doc/manual/surface.md, "Sharp features: the IMLS fit"),
// as the accuracy test and the tunnel benchmark measure them: the IMLS fit, a Gaussian of 2/3 the
// default bandwidth within the same support (theta_eps 3e-5), and the oriented normals refitted
// robustly with that kernel (residual scale 0.25 bandwidths). Not library code (testing/, never
// installed).
#pragma once

#include <PCCD/Point_cloud_object_options.h>

namespace PCCD::testing {

/// `base` with the sharp-feature surface options set (its other fields kept).
inline Point_cloud_object_options sharp_feature_options(Point_cloud_object_options base = {})
{
    base.surface_fit = Surface_fit::imls;
    base.bandwidth.theta_eps = 3e-5;
    base.normal_residual_scale = 0.25;
    return base;
}

} // namespace PCCD::testing
