// PCCD/Surface/internal/wls_fit.h -- the weighted least-squares fit behind every evaluation of the
// implicit surface (doc/algorithms.md, "The implicit surface"): one pass over the weighted
// neighbours gives a(x) and the weighted covariance B(x); the eigenvector of B's smallest
// eigenvalue is the unoriented n(x).
#pragma once

#include <cstdint>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <PCCD/internal/finite.h>

namespace PCCD::internal {

/// Sums of one WLS fit, accumulated relative to the query point x so that the covariance does not
/// lose digits to coordinates far from the origin: W = sum theta_i, s = sum theta_i (p_i - x),
/// S = sum theta_i (p_i - x)(p_i - x)^T. Then a(x) = x + s / W and B / W = S / W - (s / W)(s / W)^T.
struct Wls_sums {
    double weight = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    std::uint32_t count = 0;

    void add(const Eigen::Vector3d& offset, double theta)
    {
        weight += theta;
        first += theta * offset;
        // Only the lower triangle is read by the eigen-solver.
        second(0, 0) += theta * offset.x() * offset.x();
        second(1, 0) += theta * offset.y() * offset.x();
        second(2, 0) += theta * offset.z() * offset.x();
        second(1, 1) += theta * offset.y() * offset.y();
        second(2, 1) += theta * offset.z() * offset.y();
        second(2, 2) += theta * offset.z() * offset.z();
        ++count;
    }
};

/// The unoriented fit: a(x), and n(x) when the covariance determines it.
struct Wls_fit {
    Eigen::Vector3d centroid;
    /// Unit eigenvector of the smallest eigenvalue; valid only when `determined`.
    Eigen::Vector3d normal;
    /// False when fewer than three points carry weight, when they lie along a line (lambda_1 <
    /// wls_min_aspect lambda_2), or when the smallest eigenvalue of B ties with the middle one (an
    /// isotropic neighbourhood): n(x) is then arbitrary.
    bool determined = false;
};

/// Relative gap (lambda_1 - lambda_0) / lambda_2 below which the smallest eigenvector of B counts as
/// undetermined. Far above the closed-form solver's rounding (~1e-13 relative), far below the gap of
/// any neighbourhood that spans a surface patch.
inline constexpr double wls_degenerate_gap = 1e-9;

/// Smallest ratio lambda_1 / lambda_2 of a neighbourhood that determines a normal: below it the
/// weighted points lie along a line (a few points at the edge of the support, a sampled curve) and
/// the smallest eigenvector turns freely about that line, so any noise decides n(x).
inline constexpr double wls_min_aspect = 0.05;

/// Finishes the fit for query point x. \pre sums.weight > 0.
inline Wls_fit finish_fit(const Eigen::Vector3d& x, const Wls_sums& sums)
{
    Wls_fit fit;
    const Eigen::Vector3d mean_offset = sums.first / sums.weight;
    fit.centroid = x + mean_offset;
    // B / W; its strict upper triangle holds garbage that the solver does not read.
    const Eigen::Matrix3d covariance = sums.second / sums.weight - mean_offset * mean_offset.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance, Eigen::ComputeEigenvectors);
    const Eigen::Vector3d lambda = solver.eigenvalues(); // ascending
    // B / W is a difference of second moments about x, so its eigenvalues carry an absolute rounding
    // error of a few ulps of trace(S / W): a gap below that is no gap (one or two points, or collinear
    // points seen from afar, would otherwise pass as "determined" on rounding noise).
    const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * (sums.second.trace() / sums.weight);
    const double gap = lambda(1) - lambda(0);
    fit.determined = sums.count >= 3 && gap > wls_degenerate_gap * lambda(2) &&
                     gap > rounding && lambda(1) >= wls_min_aspect * lambda(2) &&
                     internal::all_finite(solver.eigenvectors().col(0));
    fit.normal = solver.eigenvectors().col(0).normalized();
    return fit;
}

} // namespace PCCD::internal
