// PCCD/Intersection/Ray_options.h -- the run-time knobs of ray_intersection() (doc/manual/intersection.md
// "Ray queries"; doc/algorithms.md "Ray queries"): the tolerance on |f|, the marching step and an
// evaluation budget, with the check that rejects bad values.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>

#include <PCCD/Error.h>

namespace PCCD {

/// Options of ray_intersection(). Every field has a documented default; use designated
/// initializers: `{.epsilon = 1e-3, .max_f_evaluations = 64}`. A plain value: one instance may be
/// shared by any number of concurrent queries.
struct Ray_options {
    /// The tolerance on |f| (world units, which are the object's: poses are rigid): a hit is a point
    /// of the ray with |f| <= epsilon. Unset (default): 0.05 r, r the object's sampling radius (as
    /// Intersection_options::epsilon). When set: finite and > 0.
    std::optional<double> epsilon = std::nullopt;
    /// The longest step of the march along the ray, as a fraction of the sampling radius r:
    /// h = step_fraction * r. Two crossings of f = 0 less than h apart along the ray (a wall thinner
    /// than h, a graze whose chord inside the object is shorter than h) may both be missed; any
    /// other crossing where f is defined is found. Default 0.5; in (0, 1].
    double step_fraction = 0.5;
    /// Budget: the query stops once it has evaluated f this many times; if no hit was found by
    /// then, the answer is Ray_status::undecided (never a miss). Unset (default): no budget. When
    /// set: >= 1.
    std::optional<std::size_t> max_f_evaluations = std::nullopt;
};

namespace internal {

/// Throws Invalid_input naming the field of `o` that is out of range.
inline void check_ray_options(const Ray_options& o)
{
    if (o.epsilon && !(std::isfinite(*o.epsilon) && *o.epsilon > 0.0))
        throw Invalid_input(concat("ray_intersection: epsilon ", *o.epsilon,
                                   " must be finite and > 0 (leave it unset for the automatic value)"));
    if (!(std::isfinite(o.step_fraction) && o.step_fraction > 0.0 && o.step_fraction <= 1.0))
        throw Invalid_input(concat("ray_intersection: step_fraction ", o.step_fraction, " must be in (0, 1]"));
    if (o.max_f_evaluations && *o.max_f_evaluations == 0)
        throw Invalid_input("ray_intersection: max_f_evaluations must be >= 1 when set (leave it unset for no budget)");
}

} // namespace internal
} // namespace PCCD
