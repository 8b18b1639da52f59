// Shared fixtures of the proximity tests: two sampled unit spheres (analytic truth: surface
// distance, penetration depth, witnesses and normals in closed form) and small geometric helpers.
#pragma once

#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/testing/pose_generator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "surface_test_helpers.h"

namespace pccd_test {

using PCCD::Rigid_transform_3;

/// Two unit spheres sampled with n points each (different seeds), with their mean spacing.
struct Sphere_pair {
    PCCD::Point_cloud_object<> a;
    PCCD::Point_cloud_object<> b;
    double spacing;
};

inline const Sphere_pair& spheres()
{
    static const Sphere_pair pair = [] {
        const auto sa = pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 21);
        const auto sb = pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 22);
        PCCD::Point_cloud_object<> a(pccd_test::columns(sa.points));
        PCCD::Point_cloud_object<> b(pccd_test::columns(sb.points));
        const double spacing = std::max(a.cloud().mean_spacing(), b.cloud().mean_spacing());
        return Sphere_pair{std::move(a), std::move(b), spacing};
    }();
    return pair;
}

/// B's pose: a random rotation (the sphere does not care) and its centre at `c`.
inline Rigid_transform_3<double> centred_at(const Eigen::Vector3d& c, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    return Rigid_transform_3<double>(PCCD::testing::uniform_random_rotation(engine), c);
}

inline Eigen::Vector3d random_direction(PCCD::Random_engine& engine)
{
    Eigen::Vector3d d(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
    return d.normalized();
}

inline double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? std::numeric_limits<double>::quiet_NaN() : v[v.size() / 2];
}

inline double degrees(const Eigen::Vector3d& u, const Eigen::Vector3d& v)
{
    return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

} // namespace pccd_test
