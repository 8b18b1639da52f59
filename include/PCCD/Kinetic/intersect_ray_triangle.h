// PCCD/Kinetic/intersect_ray_triangle.h -- the ray-triangle test at the leaves of the kinetic trees'
// ray queries (doc/manual/kinetic.md, "Queries": first_hit, first_hits), exposed so that callers
// can check the trees' answers against brute force over all triangles.
#pragma once

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Kinetic/Kinetic_ray.h>

namespace PCCD {

/// Ray-triangle intersection (Moeller-Trumbore), the leaf test of every ray query. Returns the hit
/// parameter s within [ray.s_min, ray.s_max] and the barycentrics (the hit's primitive is 0); nothing
/// for a miss or a ray parallel to the plane.
inline std::optional<Kinetic_ray_hit> intersect_ray_triangle(const Kinetic_ray& ray, const Eigen::Vector3d& a,
                                                             const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
    const Eigen::Vector3d e1 = b - a, e2 = c - a;
    const Eigen::Vector3d p = ray.direction.cross(e2);
    const double det = e1.dot(p);
    if (det == 0.0) return std::nullopt;
    const double inv = 1.0 / det;
    const Eigen::Vector3d tv = ray.origin - a;
    const double u = tv.dot(p) * inv;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const Eigen::Vector3d q = tv.cross(e1);
    const double v = ray.direction.dot(q) * inv;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double s = e2.dot(q) * inv;
    if (!(s >= ray.s_min && s <= ray.s_max)) return std::nullopt;
    return Kinetic_ray_hit{0, s, u, v};
}

} // namespace PCCD
