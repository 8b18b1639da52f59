// PCCD/testing/Torus_shape.h -- a ring torus around the z axis with its exact signed distance,
// closest point and normal, and a sampler with the correct area density: reference geometry for the
// tests and benchmarks of doc/algorithms.md, "Benchmark procedure" (a genus-1 surface with
// curvature of both signs).
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Surface_sample.h>

namespace PCCD::testing {

/// The ring torus of major radius R and minor radius r (R > r > 0) with axis parallel to z through
/// `centre`. With (x, y, z) relative to the centre and rho = sqrt(x^2 + y^2), the surface is
/// (rho - R)^2 + z^2 = r^2 and the signed distance is sqrt((rho - R)^2 + z^2) - r (positive outside
/// the tube). Parametrization: ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), v the poloidal
/// angle; the area element is r (R + r cos v) du dv and the area 4 pi^2 R r.
///
/// Immutable; all member functions are const, O(1) (sample: O(n) expected), and safe to call
/// concurrently (each caller passes its own engine).
class Torus_shape {
public:
    /// \throws Invalid_input unless R and r are finite with R > r > 0 and `centre` is finite.
    Torus_shape(double major_radius, double minor_radius, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero())
        : m_major(major_radius), m_minor(minor_radius), m_centre(centre)
    {
        detail::check_finite(centre, "torus centre");
        if (!(std::isfinite(major_radius) && std::isfinite(minor_radius) && minor_radius > 0.0 &&
              major_radius > minor_radius))
            throw Invalid_input(internal::concat("torus radii R = ", major_radius, ", r = ", minor_radius,
                                                 ": a ring torus needs finite R > r > 0"));
    }

    double major_radius() const { return m_major; }
    double minor_radius() const { return m_minor; }
    const Eigen::Vector3d& centre() const { return m_centre; }

    /// sqrt((rho - R)^2 + z^2) - r.
    double signed_distance(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d d = x - m_centre;
        return std::hypot(std::hypot(d.x(), d.y()) - m_major, d.z()) - m_minor;
    }

    /// The point of the torus nearest to `x`: the nearest point of the tube circle in the meridian
    /// half-plane through `x`. Where the nearest point is not unique, the conventions are: on the
    /// axis (rho = 0) the meridian half-plane of +x is used; on the core circle (the tube's centre
    /// line) the outer equator point (v = 0) is used.
    Eigen::Vector3d closest_point(const Eigen::Vector3d& x) const
    {
        const Meridian_frame f = frame(x);
        return m_centre + m_major * f.radial + m_minor * f.normal;
    }

    /// The outward unit normal at closest_point(x) (same conventions).
    Eigen::Vector3d normal(const Eigen::Vector3d& x) const { return frame(x).normal; }

    /// 4 pi^2 R r.
    double area() const { return 4.0 * std::numbers::pi * std::numbers::pi * m_major * m_minor; }

    /// One point uniformly distributed by area, with its normal: u uniform, v drawn with density
    /// proportional to R + r cos v by rejection (acceptance rate R / (R + r) >= 1/2).
    Surface_point random_point(Random_engine& engine) const
    {
        const double u = 2.0 * std::numbers::pi * uniform_01(engine);
        double v = 0.0;
        do {
            v = 2.0 * std::numbers::pi * uniform_01(engine);
        } while (uniform_01(engine) * (m_major + m_minor) >= m_major + m_minor * std::cos(v));
        const Eigen::Vector3d n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
        const double ring = m_major + m_minor * std::cos(v);
        return {m_centre + Eigen::Vector3d(ring * std::cos(u), ring * std::sin(u), m_minor * std::sin(v)), n};
    }

    /// `n` points uniformly distributed by area with their exact normals, plus the Gaussian noise of
    /// `options` (see Sample_options). Deterministic for a given engine state. O(n) expected.
    /// \throws Invalid_input if the options are invalid.
    Surface_sample sample(std::size_t n, Random_engine& engine, const Sample_options& options = {}) const
    {
        return detail::sample_shape(*this, n, engine, options);
    }

private:
    struct Meridian_frame {
        Eigen::Vector3d radial; // unit vector from the axis towards x, horizontal
        Eigen::Vector3d normal; // unit vector from the core circle towards x, in the meridian plane
    };

    // Computed from the in-plane coordinates (rho - R, z), so that the normal lies exactly in the
    // meridian plane even when x is within rounding of the core circle.
    Meridian_frame frame(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d d = x - m_centre;
        const double rho = std::hypot(d.x(), d.y());
        const Eigen::Vector3d radial =
            rho > 0.0 ? Eigen::Vector3d(d.x() / rho, d.y() / rho, 0.0) : Eigen::Vector3d::UnitX();
        const double a = rho - m_major, b = d.z(), length = std::hypot(a, b);
        if (!(length > 0.0)) return {radial, radial};
        return {radial, Eigen::Vector3d((a / length) * radial + (b / length) * Eigen::Vector3d::UnitZ())};
    }

    double m_major;
    double m_minor;
    Eigen::Vector3d m_centre;
};

} // namespace PCCD::testing
