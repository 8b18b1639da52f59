// Shared helpers of the surface tests: analytic test shapes at a given density and noise, the
// Point_cloud_object built over their samples, and query points near the surface with their exact
// signed distance.
#pragma once

#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Plane_patch_shape.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pccd_test {

inline std::vector<Eigen::Vector3d> columns(const Eigen::Matrix3Xd& m)
{
    std::vector<Eigen::Vector3d> out(std::size_t(m.cols()));
    for (Eigen::Index i = 0; i < m.cols(); ++i) out[std::size_t(i)] = m.col(i);
    return out;
}

/// A point near a shape with the shape's exact signed distance there.
struct Query {
    Eigen::Vector3d x;
    double signed_distance;
    Eigen::Vector3d surface_point;
    Eigen::Vector3d normal;
};

/// `count` points at signed offsets t uniform in [-band, band] along the exact normal of uniformly
/// drawn surface points (so the exact signed distance is t, also for the plane patch).
template <class Shape>
std::vector<Query> queries_near(const Shape& shape, std::size_t count, double band, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    std::vector<Query> out;
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const PCCD::testing::Surface_point p = shape.random_point(engine);
        const double t = PCCD::uniform_real(engine, -band, band);
        const Eigen::Vector3d x = p.position + t * p.normal;
        out.push_back({x, shape.signed_distance(x), p.position, p.normal});
    }
    return out;
}

/// The analytic shapes of the surface tests. `curvature_radius` is the smallest principal radius of
/// curvature (infinite for the plane), which bounds the WLS bias.
struct Test_shape {
    std::string name;
    double curvature_radius;
    bool closed;
};

inline const PCCD::testing::Sphere_shape& unit_sphere()
{
    static const PCCD::testing::Sphere_shape shape(Eigen::Vector3d::Zero(), 1.0);
    return shape;
}
inline const PCCD::testing::Torus_shape& test_torus()
{
    static const PCCD::testing::Torus_shape shape(1.0, 0.4);
    return shape;
}
inline const PCCD::testing::Plane_patch_shape& test_plane()
{
    static const PCCD::testing::Plane_patch_shape shape(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, 0, 0),
                                               Eigen::Vector3d(0, 2, 0));
    return shape;
}

/// Calls `body(shape_info, shape)` for the sphere, the torus and the plane patch.
template <class Body>
void for_each_test_shape(const Body& body)
{
    body(Test_shape{"sphere", 1.0, true}, unit_sphere());
    body(Test_shape{"torus", 0.4, true}, test_torus());
    body(Test_shape{"plane", std::numeric_limits<double>::infinity(), false}, test_plane());
}

/// The sampled cloud: n points with Gaussian noise of sigma = noise * 0.5 sqrt(area / n) (about
/// `noise` mean spacings).
template <class Shape>
PCCD::testing::Surface_sample sample_shape(const Shape& shape, std::size_t n, double noise, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    const double sigma = noise * 0.5 * std::sqrt(shape.area() / double(n));
    return shape.sample(n, engine, {.noise_sigma = sigma});
}

} // namespace pccd_test
