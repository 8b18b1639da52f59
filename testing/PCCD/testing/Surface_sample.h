// PCCD/testing/Surface_sample.h -- the types shared by the analytic test shapes (Sphere_shape,
// Torus_shape, Plane_patch_shape, Parallel_sheets_shape): one sampled point with its normal, and a
// sample of many points as 3 x N matrices ready for Point_cloud. Their options are the public
// Sample_options of <PCCD/sample_triangle_mesh.h>. Test data for doc/algorithms.md, "Benchmark
// procedure"; not installed (testing/, see doc/design.md).
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/internal/finite.h>
#include <PCCD/sample_triangle_mesh.h>

namespace PCCD::testing {

/// One point on a surface with its unit normal there.
struct Surface_point {
    Eigen::Vector3d position;
    Eigen::Vector3d normal;
};

/// A sample of N points: column i of `points` is point i, column i of `normals` its unit normal.
/// `Point_cloud<> cloud(sample.points);` builds a cloud from it.
struct Surface_sample {
    Eigen::Matrix3Xd points;
    Eigen::Matrix3Xd normals;
};

namespace detail {

/// `n` independent draws of `shape.random_point(engine)`, then the noise of `options`.
template <class Shape>
Surface_sample sample_shape(const Shape& shape, std::size_t n, Random_engine& engine, const Sample_options& options)
{
    internal::check_sample_options(options);
    Surface_sample sample{Eigen::Matrix3Xd(3, Eigen::Index(n)), Eigen::Matrix3Xd(3, Eigen::Index(n))};
    for (Eigen::Index i = 0; i < Eigen::Index(n); ++i) {
        const Surface_point p = shape.random_point(engine);
        sample.points.col(i) = p.position;
        sample.normals.col(i) = p.normal;
    }
    internal::add_gaussian_noise(sample.points, options.noise_sigma, engine);
    return sample;
}

/// Throws unless every coordinate of `v` is finite; `what` names the argument.
inline void check_finite(const Eigen::Vector3d& v, const char* what)
{
    if (!internal::all_finite(v))
        throw Invalid_input(internal::concat(what, " (", v.x(), ", ", v.y(), ", ", v.z(), ") is not finite"));
}

} // namespace detail
} // namespace PCCD::testing
