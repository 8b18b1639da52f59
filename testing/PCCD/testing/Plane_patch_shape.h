// PCCD/testing/Plane_patch_shape.h -- a rectangle in 3-space (a surface with a boundary) with its
// signed distance, closest point and normal, and a uniform sampler: reference geometry for the
// tests of doc/algorithms.md, "Real scans" (boundaries, where the implicit surface over a cloud
// must stop).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Surface_sample.h>

namespace PCCD::testing {

/// The closed rectangle { corner + s e1 + t e2 : s, t in [0, 1] } with unit normal
/// n = (e1 x e2) / |e1 x e2| (right-hand rule from e1 to e2).
///
/// Signed distance of a patch with a boundary: the Euclidean distance from x to the nearest point of
/// the rectangle (its interior, an edge or a corner), with the sign of the side of the rectangle's
/// plane x lies on: + where (x - corner) . n >= 0, - below. It is exact, and |signed_distance(x)| =
/// |x - closest_point(x)| everywhere; it is continuous except across the plane outside the rectangle,
/// where the sign flips (a sheet has no inside).
///
/// Immutable; all member functions are const, O(1) (sample: O(n)), and safe to call concurrently
/// (each caller passes its own engine).
class Plane_patch_shape {
public:
    /// Relative tolerance on |e1 . e2| / (|e1| |e2|) for the edges to count as perpendicular.
    static constexpr double perpendicular_tolerance = 1e-9;

    /// \param corner one corner of the rectangle.
    /// \param edge1, edge2 the two edge vectors leaving `corner`; `edge2` is made exactly
    ///        perpendicular to `edge1` (removing its component along `edge1`, at most
    ///        `perpendicular_tolerance` relative).
    /// \throws Invalid_input if an input is not finite, an edge has zero length, or the edges are not
    ///         perpendicular within `perpendicular_tolerance`.
    Plane_patch_shape(const Eigen::Vector3d& corner, const Eigen::Vector3d& edge1, const Eigen::Vector3d& edge2)
        : m_corner(corner), m_edge1(edge1), m_edge2(edge2)
    {
        detail::check_finite(corner, "plane patch corner");
        detail::check_finite(edge1, "plane patch edge1");
        detail::check_finite(edge2, "plane patch edge2");
        const double l1 = edge1.norm(), l2 = edge2.norm();
        if (!(l1 > 0.0 && l2 > 0.0))
            throw Invalid_input(internal::concat("plane patch: edge", l1 > 0.0 ? 2 : 1, " has zero length"));
        const double cosine = edge1.dot(edge2) / (l1 * l2);
        if (std::abs(cosine) > perpendicular_tolerance)
            throw Invalid_input(internal::concat("plane patch: the edges are not perpendicular (cosine ", cosine,
                                                 ", tolerance ", perpendicular_tolerance, ")"));
        m_edge2 -= (edge1.dot(edge2) / (l1 * l1)) * edge1;
        m_normal = m_edge1.cross(m_edge2).normalized();
    }

    const Eigen::Vector3d& corner() const { return m_corner; }
    const Eigen::Vector3d& edge1() const { return m_edge1; }
    const Eigen::Vector3d& edge2() const { return m_edge2; }

    /// Distance to the rectangle, signed by the side of its plane (see the class documentation).
    double signed_distance(const Eigen::Vector3d& x) const
    {
        const double distance = (x - closest_point(x)).norm();
        return (x - m_corner).dot(m_normal) >= 0.0 ? distance : -distance;
    }

    /// The point of the rectangle nearest to `x` (always unique: the rectangle is convex).
    Eigen::Vector3d closest_point(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d d = x - m_corner;
        const double s = std::clamp(d.dot(m_edge1) / m_edge1.squaredNorm(), 0.0, 1.0);
        const double t = std::clamp(d.dot(m_edge2) / m_edge2.squaredNorm(), 0.0, 1.0);
        return m_corner + s * m_edge1 + t * m_edge2;
    }

    /// The patch's unit normal n (the same for every x).
    Eigen::Vector3d normal(const Eigen::Vector3d&) const { return m_normal; }

    /// |e1| |e2|.
    double area() const { return m_edge1.norm() * m_edge2.norm(); }

    /// 2 (|e1| + |e2|), the length of the boundary.
    double perimeter() const { return 2.0 * (m_edge1.norm() + m_edge2.norm()); }

    /// One point uniformly distributed on the rectangle, with the normal n. Draws two uniforms.
    Surface_point random_point(Random_engine& engine) const
    {
        const double s = uniform_01(engine);
        const double t = uniform_01(engine);
        return {m_corner + s * m_edge1 + t * m_edge2, m_normal};
    }

    /// `n` points uniformly distributed by area with the normal n, plus the Gaussian noise of
    /// `options` (see Sample_options). Deterministic for a given engine state. O(n).
    /// \throws Invalid_input if the options are invalid.
    Surface_sample sample(std::size_t n, Random_engine& engine, const Sample_options& options = {}) const
    {
        return detail::sample_shape(*this, n, engine, options);
    }

private:
    Eigen::Vector3d m_corner;
    Eigen::Vector3d m_edge1;
    Eigen::Vector3d m_edge2;
    Eigen::Vector3d m_normal;
};

} // namespace PCCD::testing
