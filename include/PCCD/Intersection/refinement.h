// PCCD/Intersection/refinement.h -- refinement of an approximate intersection point
// (doc/manual/intersection.md, "Refinement"): WSCG05's random sampling in the intersection sphere around the AIP, and a
// Gauss-Newton projection onto f_A = f_B = 0. Both work on world points and count every evaluation.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>

#include <Eigen/Core>
#include <Eigen/LU>

#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Random.h>

namespace PCCD::internal {

/// Both surfaces at the world point x: nullopt unless both are defined, and when the budget runs
/// out after the first evaluation (so a refinement step never overdraws it).
template <class OA, class OB>
std::optional<std::pair<Surface_evaluation, Surface_evaluation>> evaluate_both(const Posed_object<OA>& a,
                                                                            const Posed_object<OB>& b,
                                                                            const Eigen::Vector3d& x,
                                                                            Query_state& state)
{
    Surface_evaluation ea = state.evaluate_world(a, x);
    if (!ea.defined() || state.out_of_budget()) return std::nullopt;
    Surface_evaluation eb = state.evaluate_world(b, x);
    if (!eb.defined()) return std::nullopt;
    return std::make_pair(std::move(ea), std::move(eb));
}

/// Sampling refinement (WSCG05 section 4.3): the sphere of centre x and radius `radius` is covered
/// by s = ceil(sqrt(3) radius / epsilon)^3 cells; s ln s + 3.5 s uniform samples (at most
/// `max_samples`) are drawn in it, and the one with the smallest max(|f_A|, |f_B|) is returned if
/// that value is <= epsilon. \pre radius > 0, epsilon > 0
template <class OA, class OB>
std::optional<Intersection_point> refine_by_sampling(const Posed_object<OA>& a, const Posed_object<OB>& b,
                                                     const Eigen::Vector3d& x, double radius, double epsilon,
                                                     std::size_t max_samples, Query_state& state)
{
    const double cells_per_side = std::ceil(std::sqrt(3.0) * radius / epsilon);
    const double s = std::max(1.0, cells_per_side * cells_per_side * cells_per_side);
    const double wanted = s * std::log(s) + 3.5 * s;
    const std::size_t n = std::size_t(std::min(double(max_samples), std::max(1.0, wanted)));
    std::optional<Intersection_point> best;
    double best_value = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n && !state.out_of_budget(); ++k) {
        // Uniform in the ball: a normal direction and a radius with density r^2.
        Eigen::Vector3d d(standard_normal(state.engine), standard_normal(state.engine), standard_normal(state.engine));
        const double norm = d.norm();
        if (!(norm > 0.0)) continue;
        const double rho = radius * std::cbrt(uniform_01(state.engine));
        const Eigen::Vector3d y = x + (rho / norm) * d;
        ++state.counters.refinement_samples;
        const auto both = evaluate_both(a, b, y, state);
        if (!both) continue;
        const double value = std::max(std::abs(both->first.value), std::abs(both->second.value));
        if (value < best_value) {
            best_value = value;
            best = Intersection_point{y, both->first.value, both->second.value, Intersection_point_kind::refined};
        }
    }
    if (best && best_value <= epsilon) return best;
    return std::nullopt;
}

/// Projection refinement and contact verification: damped Gauss-Newton (Levenberg-Marquardt) steps
/// on (f_A, f_B)(x) = 0, dx = -J^T (J J^T + lambda I)^-1 f with J = [n_A^T; n_B^T] (the gradients
/// of the two WLS surfaces are their normals to first order) and lambda = `damping`. The damping
/// keeps the step finite where the normals are (nearly) parallel: coincident surfaces converge onto
/// their common zero set, parallel surfaces a gap g apart stop at the middle with max(|f_A|, |f_B|)
/// = g / 2. Stops when max(|f_A|, |f_B|) <= epsilon (returns the point), after `max_steps` steps,
/// when a step shrinks max(|f_A|, |f_B|) by less than a tenth (stagnation),
/// when a surface is undefined at the start (outside its support or domain, or degenerate), or
/// when a step leaves the ball of `radius` around the start. A step that lands where a surface is
/// undefined is halved back towards the previous point (twice at most per projection). A point
/// reached farther than `core` times the domain radius from either cloud (Surface_evaluation::
/// domain_fraction) is not accepted.
template <class OA, class OB>
std::optional<Intersection_point> refine_by_projection(const Posed_object<OA>& a, const Posed_object<OB>& b,
                                                       const Eigen::Vector3d& start, double radius, double epsilon,
                                                       Query_state& state, double core = 1.0, int max_steps = 8,
                                                       double damping = 1e-3)
{
    Eigen::Vector3d x = start;
    Eigen::Vector3d previous = start;
    int backtracks = 0;
    double last_residual = std::numeric_limits<double>::infinity();
    for (int step = 0; step <= max_steps && !state.out_of_budget(); ++step) {
        ++state.counters.refinement_samples;
        const auto both = evaluate_both(a, b, x, state);
        if (!both) {
            // A step that left a surface's support or domain is halved (at most twice in all);
            // the start itself must be defined.
            if (step == 0 || backtracks == 2) return std::nullopt;
            ++backtracks;
            x = 0.5 * (x + previous);
            continue;
        }
        const auto& [ea, eb] = *both;
        const double residual = std::max(std::abs(ea.value), std::abs(eb.value));
        if (residual <= epsilon) {
            if (!(std::max(ea.domain_fraction, eb.domain_fraction) <= core)) return std::nullopt;
            return Intersection_point{x, ea.value, eb.value, Intersection_point_kind::refined};
        }
        // Stagnation: a Gauss-Newton step that does not shrink the residual by a tenth will not reach
        // epsilon (parallel surfaces a gap apart stop at their middle after one or two steps).
        if (step == max_steps || residual > 0.9 * last_residual) break;
        last_residual = residual;
        // Normals in world coordinates.
        const Eigen::Vector3d na = a.to_world.transform_vector(ea.normal);
        const Eigen::Vector3d nb = b.to_world.transform_vector(eb.normal);
        Eigen::Matrix<double, 2, 3> j;
        j.row(0) = na.transpose();
        j.row(1) = nb.transpose();
        const Eigen::Matrix2d jjt = j * j.transpose() + damping * Eigen::Matrix2d::Identity();
        const Eigen::Vector2d f(ea.value, eb.value);
        previous = x;
        x -= j.transpose() * jjt.inverse() * f;
        if ((x - start).squaredNorm() > radius * radius) return std::nullopt;
    }
    return std::nullopt;
}

} // namespace PCCD::internal
