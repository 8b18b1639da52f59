// PCCD/Proximity/Distance_options.h -- the run-time knobs of the proximity queries
// (doc/manual/proximity.md "Options"): tolerances, the distance beyond which only "farther than" is
// reported, budgets, penetration, the number of contacts, and the options of the intersection
// query that decides whether the surfaces touch.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>

#include <PCCD/Error.h>
#include <PCCD/Intersection/Intersection_options.h>

namespace PCCD {

/// Options of distance(), within_distance() and contacts(). Every field has a documented default;
/// use designated initializers: `{.max_distance = 0.5, .penetration = true}`. A plain value: one
/// instance may be shared by any number of concurrent queries.
struct Distance_options {
    /// The refinement of the witness points stops when a step shortens their distance by less than
    /// max(absolute_tolerance, relative_tolerance * distance). Unset (default): 0.01 times the
    /// smaller sampling radius of the two objects. When set: finite and > 0.
    std::optional<double> absolute_tolerance = std::nullopt;
    /// See absolute_tolerance. Default 0. Must be finite and >= 0.
    double relative_tolerance = 0.0;
    /// Farther than this (world units), report only that: status separate, distance +infinity,
    /// lower_bound >= max_distance, no witnesses, when no point pair of the clouds comes within it
    /// plus how far the surfaces may lie from their samples (the surface radii, or the reaches with
    /// certified_lower_bound). A pair that does is refined as usual, and its distance is reported
    /// even where it ends above max_distance. Cheap: the hierarchy walk prunes every node pair
    /// beyond that. Unset (default): no limit. When set: finite and >= 0.
    std::optional<double> max_distance = std::nullopt;
    /// Budget on the evaluations of f (both surfaces, the intersection query included). Unset
    /// (default): none. When set: >= 1. A query that runs out answers with what it has: status
    /// undecided when the intersection query could not decide, else the best witnesses so far and
    /// an honest interval [lower_bound, upper_bound].
    std::optional<std::size_t> max_f_evaluations = std::nullopt;
    /// Time budget in microseconds (steady clock), as max_f_evaluations; the answer then depends on
    /// the machine's speed. Unset (default): none. When set: finite and > 0.
    std::optional<double> max_time_us = std::nullopt;
    /// Budget on the node pairs of the closest-pair walk (a deterministic time-critical budget, as
    /// the ADB-trees of Klein and Zachmann bound the work of a traversal): once spent, the walk
    /// descends no further and the lower bound is that of the pairs it left, so the interval
    /// [lower_bound, upper_bound] narrows as the budget grows. Unset (default): none. When set: >= 1.
    std::optional<std::size_t> max_node_pairs = std::nullopt;
    /// For intersecting poses, also measure the penetration: the deepest point of each surface
    /// inside the other object and its distance to the other surface (Distance_result::depth,
    /// depth_a, depth_b, contact_normal and the witnesses). Default false.
    bool penetration = false;
    /// contacts(): the largest number of contact regions returned (the deepest first). Default 8;
    /// must be >= 1.
    std::size_t max_contacts = 8;
    /// The closest point pairs of the two clouds (in distinct leaf pairs) whose witnesses are
    /// refined onto the surfaces; the distance is the smallest found. More candidates guard
    /// against a noisy or outlying closest pair at a few more evaluations each. Default 2; >= 1.
    std::size_t candidates = 2;
    /// Certify lower_bound: bound the surfaces' distance from below by the smallest |p - q| -
    /// reach(p) - reach(q) over the point pairs, reach(p) the domain radius of p capped by the
    /// support radius (f is defined nowhere else, so this holds whatever the fit; the walk finds it
    /// to within half a sampling radius), instead of the closest pair's distance minus the surface
    /// radii r(P) + 2 sigma (a premise that fails on a few tenths of a percent of the zero set).
    /// max_distance and a clearance margin then prune by the same reaches. Costs 13-27 % more time
    /// (doc/benchmarks.md "A certified lower bound"). Default false.
    bool certified_lower_bound = false;
    /// The query that decides whether the surfaces touch (do_intersect() with these options; its
    /// seed makes the whole query deterministic). Its budgets are replaced by what remains of the
    /// budgets above.
    Intersection_options intersection = {};
};

namespace internal {

inline void check_options(const Distance_options& o, const char* function)
{
    if (o.absolute_tolerance && !(std::isfinite(*o.absolute_tolerance) && *o.absolute_tolerance > 0.0))
        throw Invalid_input(concat(function, ": absolute_tolerance ", *o.absolute_tolerance,
                                   " must be finite and > 0 (leave it unset for the automatic value)"));
    if (!(std::isfinite(o.relative_tolerance) && o.relative_tolerance >= 0.0))
        throw Invalid_input(concat(function, ": relative_tolerance ", o.relative_tolerance, " must be finite and >= 0"));
    if (o.max_distance && !(std::isfinite(*o.max_distance) && *o.max_distance >= 0.0))
        throw Invalid_input(concat(function, ": max_distance ", *o.max_distance,
                                   " must be finite and >= 0 (leave it unset for no limit)"));
    if (o.max_f_evaluations && *o.max_f_evaluations == 0)
        throw Invalid_input(concat(function, ": a budget of zero f evaluations (max_f_evaluations = 0) cannot answer; leave it unset for no budget"));
    if (o.max_time_us && !(std::isfinite(*o.max_time_us) && *o.max_time_us > 0.0))
        throw Invalid_input(concat(function, ": max_time_us ", *o.max_time_us, " must be finite and > 0 (leave it unset for no time limit)"));
    if (o.max_node_pairs && *o.max_node_pairs == 0)
        throw Invalid_input(concat(function, ": max_node_pairs = 0 leaves the walk nothing to visit; leave it unset for no budget"));
    if (o.max_contacts == 0) throw Invalid_input(concat(function, ": max_contacts must be >= 1"));
    if (o.candidates == 0) throw Invalid_input(concat(function, ": candidates must be >= 1"));
    check_options(o.intersection, function);
}

} // namespace internal
} // namespace PCCD
