// PCCD/Proximity/internal/surface_projection.h -- points on the implicit surfaces for the proximity
// queries (doc/algorithms.md "Proximity queries"): Newton steps x <- x - f(x) n(x) onto f = 0, the
// closest point of a surface to a point (tangent-plane steps from a surface point nearby), and the
// alternating refinement of a witness pair towards the closest points of two surfaces. Every
// evaluation is counted and checked against the query's budget.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/internal/timing.h>

namespace PCCD::internal {

/// Counters and budgets of one proximity query.
struct Proximity_state {
    Distance_counters& counters;
    std::optional<std::size_t> max_f;
    std::optional<Steady_clock::time_point> deadline;
    bool budget_hit = false;

    /// True (and remembered) once a budget is spent (the intersection query's evaluations count).
    bool out_of_budget()
    {
        if (max_f && counters.f_evaluations + counters.intersection.f_evaluations >= *max_f) budget_hit = true;
        if (deadline && !budget_hit && Steady_clock::now() >= *deadline) budget_hit = true;
        return budget_hit;
    }
    template <class Object>
    Surface_evaluation evaluate(const Posed_object<Object>& o, const Eigen::Vector3d& world)
    {
        ++counters.f_evaluations;
        return o.object->surface().evaluate(o.from_world.transform_point(world));
    }
};

/// A point of a surface (world frame) with f and the unit normal there (pointing out of the object).
struct Surface_point {
    Eigen::Vector3d x;
    Eigen::Vector3d normal;
    double f;
    /// |x - p*| / D_{p*} at x (Surface_evaluation::domain_fraction): 0 at a cloud point, 1 at the
    /// edge of the surface's domain.
    double domain_fraction = 0.0;
};

/// Newton steps x <- x - f(x) n(x) from the world point x onto the surface of `o` until |f| <=
/// tolerance (at most `steps` steps, none longer than `max_step`). nullopt when f is undefined at
/// a step, a step would be longer than max_step, the budget runs out, or the steps do not reach the
/// tolerance.
template <class Object>
std::optional<Surface_point> project_onto_surface(const Posed_object<Object>& o, Eigen::Vector3d x, double tolerance,
                                                  double max_step, Proximity_state& state, int steps = 4)
{
    for (int k = 0; k <= steps; ++k) {
        if (state.out_of_budget()) return std::nullopt;
        const Surface_evaluation e = state.evaluate(o, x);
        if (!e.defined()) return std::nullopt;
        const Eigen::Vector3d n = o.to_world.rotation() * e.normal;
        if (std::abs(e.value) <= tolerance) return Surface_point{x, n, e.value, e.domain_fraction};
        if (k == steps || std::abs(e.value) > max_step) return std::nullopt;
        x -= e.value * n;
        ++state.counters.refinement_steps;
    }
    return std::nullopt;
}

/// How far from its samples a witness may go: the refinement accepts a surface point only where
/// Surface_evaluation::domain_fraction <= this, i.e. within 0.3 times the domain radius D_{p*}
/// (about 0.8 mean spacings on a uniform sample) of its nearest cloud point. The zero set farther
/// out, still inside the domain, holds sheets the fit makes beside sharp edges and noise (seen 1.2
/// spacings outside a sampled bar's edge); doc/benchmarks.md "Witnesses that reach the edges".
inline constexpr double witness_domain_fraction = 0.3;
/// Halvings of a refinement step that overshoots (fails to project, leaves the region above, or
/// does not bring the point closer) before the refinement gives up at that point.
inline constexpr int witness_step_halvings = 4;

/// The point of the surface of `o` closest to the world point z, from the surface point `from`
/// nearby: z projected onto the tangent plane at `from` (a step of at most `max_step` along it),
/// then onto the surface; a step that fails to project, lands farther than
/// witness_domain_fraction of the domain from the samples, or does not bring the point closer to
/// z is halved (at most witness_step_halvings times): on a curved surface, beside an edge, the
/// tangent-plane step overshoots. Repeated while the foot moves by more than `tolerance` (at most
/// `rounds` times). Returns the last surface point reached (`from` itself when no step succeeds).
template <class Object>
Surface_point closest_on_surface(const Posed_object<Object>& o, const Eigen::Vector3d& z, Surface_point from,
                                 double tolerance, double max_step, Proximity_state& state, int rounds = 3)
{
    for (int k = 0; k < rounds; ++k) {
        Eigen::Vector3d step = (z - from.x) - (z - from.x).dot(from.normal) * from.normal;
        const double length = step.norm();
        if (length <= tolerance) break;
        if (length > max_step) step *= max_step / length;
        const double before = (z - from.x).norm();
        std::optional<Surface_point> next;
        for (int h = 0; h <= witness_step_halvings && !next; ++h, step *= 0.5) {
            if (h > 0 && step.norm() <= tolerance) break;
            next = project_onto_surface(o, from.x + step, tolerance, max_step, state);
            if (next && !(next->domain_fraction <= witness_domain_fraction && (z - next->x).norm() < before)) next.reset();
        }
        if (!next) break;
        const bool small = (next->x - from.x).norm() <= tolerance;
        from = *next;
        if (small) break;
    }
    return from;
}

/// A witness pair: points on surface A and on surface B.
struct Witness_pair {
    Surface_point a;
    Surface_point b;
    double distance() const { return (a.x - b.x).norm(); }
};

/// Alternating refinement of the witness pair w towards a local minimum of |x_A - x_B| over the
/// two surfaces: x_B <- the closest point of B to x_A, x_A <- the closest point of A to x_B, while
/// the distance shrinks by more than `tolerance` (at most `rounds` rounds). Returns the best pair met.
template <class OA, class OB>
Witness_pair refine_witnesses(const Posed_object<OA>& a, const Posed_object<OB>& b, Witness_pair w, double tolerance,
                              double max_step, Proximity_state& state, int rounds = 6)
{
    double d = w.distance();
    for (int k = 0; k < rounds && !state.out_of_budget(); ++k) {
        Witness_pair next = w;
        next.b = closest_on_surface(b, next.a.x, next.b, tolerance, max_step, state, 1);
        next.a = closest_on_surface(a, next.b.x, next.a, tolerance, max_step, state, 1);
        const double nd = next.distance();
        if (!(nd < d)) break;
        const bool small = d - nd <= tolerance;
        w = next;
        d = nd;
        if (small) break;
    }
    return w;
}

} // namespace PCCD::internal
