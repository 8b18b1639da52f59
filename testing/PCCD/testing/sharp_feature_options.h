// The sharp-feature options of the surface (doc/manual/surface.md, "Sharp features: the IMLS fit"),
// as the accuracy test and the tunnel benchmark measure them: the IMLS fit, a Gaussian of 2/3 the
// default bandwidth within the same support (theta_eps 3e-5), and the oriented normals refitted with
// 3/4 of it (half the default bandwidth). Not library code (testing/, never installed).
#pragma once

#include <PCCD/Point_cloud_object_options.h>

namespace PCCD::testing {

/// `base` with the sharp-feature surface options set (its other fields kept).
inline Point_cloud_object_options sharp_feature_options(Point_cloud_object_options base = {})
{
    base.surface_fit = Surface_fit::imls;
    base.bandwidth.theta_eps = 3e-5;
    base.normal_bandwidth = 0.75;
    return base;
}

} // namespace PCCD::testing
