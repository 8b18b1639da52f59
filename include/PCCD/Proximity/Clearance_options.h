// PCCD/Proximity/Clearance_options.h -- the run-time knobs of clearance() along a path of poses
// (doc/manual/proximity.md "Clearance along a path"): the cap beyond which a pose's clearance is
// only reported as "at least the cap", the options of the distance query run at every pose, and
// how the poses are spread over threads.
#pragma once

#include <cmath>
#include <optional>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Proximity/Distance_options.h>

namespace PCCD {

/// Options of clearance(). Every field has a documented default; use designated initializers:
/// `{.max_distance = 0.5, .batch = {.threads = 4}}`. A plain value.
struct Clearance_options {
    /// The cap (world units): a pose whose surfaces are farther apart than this is reported as
    /// beyond_cap (clearance +infinity, lower_bound >= max_distance), cheaply: the closest-pair walk
    /// prunes every node pair beyond it and f is not evaluated. Unset (default): no cap, every
    /// separate pose gets its distance, so the profile and the minimum clearance are complete (a
    /// cap derived from the margin would hide the minimum whenever the whole path keeps more than
    /// that clearance, the case a clearance check hopes for). When set: finite and >= the margin
    /// (a cap below the margin could not tell clear poses from poses below the margin).
    std::optional<double> max_distance = std::nullopt;
    /// The options of the distance() query answering each pose (tolerances, budgets, penetration,
    /// candidates, the intersection query's options and seed). Default {}: distance()'s defaults.
    /// Its max_distance must stay unset (set the cap above) and its intersection.visitor too (the
    /// poses run on several threads). Pose i is seeded with
    /// pair_seed(distance.intersection.seed, batch.first_index + i), as pair i of distance_many().
    Distance_options distance = {};
    /// How the poses are spread over threads (Batch_options::threads: default all available;
    /// first_index: the index of pose 0 in a longer path split into chunks, for the seeds). The
    /// results never depend on it (without a time budget).
    Batch_options batch = {};
};

namespace internal {

inline void check_options(const Clearance_options& o, double margin, const char* function)
{
    if (!(std::isfinite(margin) && margin >= 0.0))
        throw Invalid_input(concat(function, ": margin ", margin, " must be finite and >= 0"));
    if (o.max_distance && !(std::isfinite(*o.max_distance) && *o.max_distance >= 0.0))
        throw Invalid_input(concat(function, ": max_distance ", *o.max_distance,
                                   " must be finite and >= 0 (leave it unset for no cap)"));
    if (o.max_distance && *o.max_distance < margin)
        throw Invalid_input(concat(function, ": max_distance ", *o.max_distance, " is below the margin ", margin,
                                   "; a cap below the margin cannot tell clear poses from poses below it"));
    if (o.distance.max_distance)
        throw Invalid_input(concat(function, ": distance.max_distance is set; set the cap as Clearance_options::max_distance"));
    if (o.distance.intersection.visitor)
        throw Invalid_input(concat(function, ": distance.intersection.visitor is set; the poses run on several threads at "
                                             "once, so a visitor is taken by the single queries only"));
    check_options(o.distance, function);
}

} // namespace internal
} // namespace PCCD
