// PCCD/Sampling/Surface_sample.h -- the types shared by PCCD's surface samplers (analytic shapes
// and triangle meshes): the sampling options, one sampled point with its normal, and a sample of
// many points as 3 x N matrices ready for Point_cloud. Test data for doc/algorithms.md, "Benchmark
// procedure".
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// Options of every surface sampler.
struct Sample_options {
    /// Standard deviation of the isotropic Gaussian noise added to each sampled point: every
    /// coordinate gets an independent N(0, noise_sigma^2) offset (length unit of the shape).
    /// Normals are not perturbed: they stay the exact normals at the noise-free point.
    /// Default 0 (points exactly on the surface). Must be finite and >= 0.
    double noise_sigma = 0.0;
};

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

namespace internal {

inline void check_sample_options(const Sample_options& options)
{
    if (!(std::isfinite(options.noise_sigma) && options.noise_sigma >= 0.0))
        throw Invalid_input(concat("sample options: noise_sigma is ", options.noise_sigma,
                                   "; it must be finite and >= 0"));
}

/// Adds N(0, sigma^2) to every coordinate, column after column. Draws nothing when sigma is 0, so the
/// noise-free positions of a sample do not depend on sigma for a given seed.
inline void add_gaussian_noise(Eigen::Matrix3Xd& points, double sigma, Random_engine& engine)
{
    if (sigma == 0.0) return;
    for (Eigen::Index i = 0; i < points.cols(); ++i)
        for (int k = 0; k < 3; ++k) points(k, i) += sigma * standard_normal(engine);
}

/// `n` independent draws of `shape.random_point(engine)`, then the noise of `options`.
template <class Shape>
Surface_sample sample_shape(const Shape& shape, std::size_t n, Random_engine& engine, const Sample_options& options)
{
    check_sample_options(options);
    Surface_sample sample{Eigen::Matrix3Xd(3, Eigen::Index(n)), Eigen::Matrix3Xd(3, Eigen::Index(n))};
    for (Eigen::Index i = 0; i < Eigen::Index(n); ++i) {
        const Surface_point p = shape.random_point(engine);
        sample.points.col(i) = p.position;
        sample.normals.col(i) = p.normal;
    }
    add_gaussian_noise(sample.points, options.noise_sigma, engine);
    return sample;
}

/// Throws unless every coordinate of `v` is finite; `what` names the argument.
inline void check_finite(const Eigen::Vector3d& v, const char* what)
{
    if (!internal::all_finite(v))
        throw Invalid_input(concat(what, " (", v.x(), ", ", v.y(), ", ", v.z(), ") is not finite"));
}

} // namespace internal
} // namespace PCCD
