// PCCD/Kinetic/Kinetic_ray.h -- the ray of the kinetic trees' ray queries and the hit they report
// (doc/manual/kinetic.md, "Queries": first_hit and first_hits of Kinetic_AABB_tree and
// Refit_AABB_tree, on Kinetic_triangle primitives). Plain data; intersect_ray_triangle.h computes
// one hit.
#pragma once

#include <cstdint>
#include <limits>

#include <Eigen/Core>

namespace PCCD {

/// A ray origin + s * direction, s in [s_min, s_max].
struct Kinetic_ray {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
    double s_min = 0.0;
    double s_max = std::numeric_limits<double>::infinity();
};

/// The first hit of a ray: the primitive, the ray parameter s and the barycentric coordinates
/// (u, v) of the hit point p = (1 - u - v) a + u b + v c on triangle (a, b, c).
struct Kinetic_ray_hit {
    std::uint32_t primitive = 0;
    double s = 0.0;
    double u = 0.0;
    double v = 0.0;
};

} // namespace PCCD
