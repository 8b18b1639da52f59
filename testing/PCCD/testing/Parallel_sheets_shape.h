// PCCD/testing/Parallel_sheets_shape.h -- two parallel rectangles facing away from each other at a
// given gap, the two faces of a thin plate without its rim: reference geometry for the tests of
// doc/algorithms.md, "Euclidean and geodesic distance" and "Benchmark procedure" (a thin gap across
// which a Euclidean kernel bleeds and a geodesic kernel must not).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Plane_patch_shape.h>
#include <PCCD/testing/Surface_sample.h>

namespace PCCD::testing {

/// Two parallel rectangles a distance `gap` apart, with outward normals: with n = (e1 x e2) / |e1 x e2|,
/// sheet 0 is the rectangle { corner + s e1 + t e2 } facing -n and sheet 1 is sheet 0 moved by
/// gap * n, facing +n.
///
/// Signed distance: that of the nearer sheet (Plane_patch_shape's definition: distance to the
/// rectangle, signed by the side of its plane); sheet 0 wins a tie. Between the sheets it is negative
/// (the plate's inside), beyond them positive. closest_point and normal come from the same sheet.
///
/// Immutable; all member functions are const, O(1) (sample: O(n)), and safe to call concurrently
/// (each caller passes its own engine).
class Parallel_sheets_shape {
public:
    /// \throws Invalid_input if the rectangle is invalid (see Plane_patch_shape) or `gap` is not finite
    ///         and > 0.
    Parallel_sheets_shape(const Eigen::Vector3d& corner, const Eigen::Vector3d& edge1, const Eigen::Vector3d& edge2,
                          double gap)
        : m_sheets(make_sheets(corner, edge1, edge2, gap)), m_gap(gap)
    {
    }

    /// Sheet 0 (facing -n) or sheet 1 (facing +n). \pre i < 2
    const Plane_patch_shape& sheet(std::size_t i) const
    {
        PCCD_precondition_msg(i < 2, "Parallel_sheets_shape has sheets 0 and 1");
        return m_sheets[i];
    }
    double gap() const { return m_gap; }

    /// The signed distance to the nearer sheet.
    double signed_distance(const Eigen::Vector3d& x) const { return nearer_sheet(x).signed_distance(x); }

    /// The point of the nearer sheet nearest to `x`.
    Eigen::Vector3d closest_point(const Eigen::Vector3d& x) const { return nearer_sheet(x).closest_point(x); }

    /// The outward unit normal of the nearer sheet (-n or +n).
    Eigen::Vector3d normal(const Eigen::Vector3d& x) const { return nearer_sheet(x).normal(x); }

    /// Twice the rectangle's area.
    double area() const { return m_sheets[0].area() + m_sheets[1].area(); }

    /// One point uniformly distributed on the two sheets (each chosen with probability 1/2), with its
    /// normal. Draws three 64-bit values.
    Surface_point random_point(Random_engine& engine) const
    {
        return m_sheets[uniform_index(engine, 2)].random_point(engine);
    }

    /// `n` points uniformly distributed by area with their normals, plus the Gaussian noise of
    /// `options` (see Sample_options). Deterministic for a given engine state. O(n).
    /// \throws Invalid_input if the options are invalid.
    Surface_sample sample(std::size_t n, Random_engine& engine, const Sample_options& options = {}) const
    {
        return detail::sample_shape(*this, n, engine, options);
    }

private:
    static std::array<Plane_patch_shape, 2> make_sheets(const Eigen::Vector3d& corner, const Eigen::Vector3d& edge1,
                                                        const Eigen::Vector3d& edge2, double gap)
    {
        const Plane_patch_shape facing_n(corner, edge1, edge2);
        if (!(std::isfinite(gap) && gap > 0.0))
            throw Invalid_input(internal::concat("parallel sheets: gap is ", gap, "; it must be finite and > 0"));
        // Swapping the (already perpendicular) edges flips the normal exactly: a x b == -(b x a).
        return {Plane_patch_shape(corner, facing_n.edge2(), facing_n.edge1()),
                Plane_patch_shape(corner + gap * facing_n.normal(corner), facing_n.edge1(), facing_n.edge2())};
    }

    const Plane_patch_shape& nearer_sheet(const Eigen::Vector3d& x) const
    {
        return std::abs(m_sheets[1].signed_distance(x)) < std::abs(m_sheets[0].signed_distance(x)) ? m_sheets[1]
                                                                                                 : m_sheets[0];
    }

    std::array<Plane_patch_shape, 2> m_sheets;
    double m_gap;
};

} // namespace PCCD::testing
