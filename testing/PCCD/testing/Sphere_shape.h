// PCCD/testing/Sphere_shape.h -- a sphere with its exact signed distance, closest point and
// normal, and a uniform-by-area sampler: reference geometry for the tests and benchmarks of
// doc/algorithms.md, "Benchmark procedure" (and the analytic truth of the exact checks).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Surface_sample.h>

namespace PCCD::testing {

/// The sphere |x - centre| = radius. Signed distance |x - centre| - radius: positive outside.
/// Immutable; all member functions are const, O(1) (sample: O(n)), and safe to call concurrently
/// (each caller passes its own engine).
class Sphere_shape {
public:
    /// \throws Invalid_input if `centre` is not finite or `radius` is not finite and > 0.
    Sphere_shape(const Eigen::Vector3d& centre, double radius) : m_centre(centre), m_radius(radius)
    {
        detail::check_finite(centre, "sphere centre");
        if (!(std::isfinite(radius) && radius > 0.0))
            throw Invalid_input(internal::concat("sphere radius is ", radius, "; it must be finite and > 0"));
    }

    const Eigen::Vector3d& centre() const { return m_centre; }
    double radius() const { return m_radius; }

    /// |x - centre| - radius.
    double signed_distance(const Eigen::Vector3d& x) const { return (x - m_centre).norm() - m_radius; }

    /// The point of the sphere nearest to `x`. At the centre, where every point is nearest, it is
    /// centre + (0, 0, radius).
    Eigen::Vector3d closest_point(const Eigen::Vector3d& x) const { return m_centre + m_radius * normal(x); }

    /// The outward unit normal at closest_point(x).
    Eigen::Vector3d normal(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d d = x - m_centre;
        const double length = d.norm();
        return length > 0.0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::UnitZ();
    }

    /// 4 pi radius^2.
    double area() const { return 4.0 * std::numbers::pi * m_radius * m_radius; }

    /// One point uniformly distributed on the sphere (Archimedes: z uniform in [-r, r], azimuth
    /// uniform), with its normal. Draws two uniforms.
    Surface_point random_point(Random_engine& engine) const
    {
        const double z = uniform_real(engine, -1.0, 1.0);
        const double phi = 2.0 * std::numbers::pi * uniform_01(engine);
        const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d n(rho * std::cos(phi), rho * std::sin(phi), z);
        return {m_centre + m_radius * n, n};
    }

    /// `n` points uniformly distributed by area with their exact normals, plus the Gaussian noise of
    /// `options` (see Sample_options). Deterministic for a given engine state. O(n).
    /// \throws Invalid_input if the options are invalid.
    Surface_sample sample(std::size_t n, Random_engine& engine, const Sample_options& options = {}) const
    {
        return detail::sample_shape(*this, n, engine, options);
    }

private:
    Eigen::Vector3d m_centre;
    double m_radius;
};

} // namespace PCCD::testing
