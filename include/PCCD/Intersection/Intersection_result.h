// PCCD/Intersection/Intersection_result.h -- what an intersection query returns
// (doc/manual/intersection.md, "The result"): answers carry their evidence: the answer, the intersection points found, and the counters the papers'
// evaluation figures are made of (doc/benchmarks.md).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

namespace PCCD {

/// How a point of an intersection result was obtained.
enum class Intersection_point_kind : std::uint8_t {
    /// An approximate intersection point (AIP, doc/manual/intersection.md): on the graph edge of one
    /// cloud where the other surface's f changes sign, linearly interpolated between its two ends.
    approximate = 0,
    /// Refined (doc/algorithms.md, "Refinement") or verified: a point where both |f_A| and |f_B| are below the refinement
    /// (or verification) tolerance, inside both surfaces' domains.
    refined = 1,
    /// Randomized sampling (doc/algorithms.md, "Randomized sampling"): a sample where both |f_A| and |f_B| are below epsilon.
    sampled = 2,
};

/// One point on (near) the intersection curves of the two surfaces, in world coordinates.
struct Intersection_point {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    /// f_A and f_B at `position`; NaN where they were not evaluated (approximate points: the AIP is
    /// interpolated, f is not re-evaluated there).
    double f_a = std::numeric_limits<double>::quiet_NaN();
    double f_b = std::numeric_limits<double>::quiet_NaN();
    Intersection_point_kind kind = Intersection_point_kind::approximate;
};

/// Why a query stopped.
enum class Intersection_status : std::uint8_t {
    /// The surfaces intersect (at least one point found).
    intersecting = 0,
    /// No intersection found after the whole sampling the options ask for.
    separate = 1,
    /// A budget (f evaluations or time, Intersection_options::max_f_evaluations / max_time_us) ran
    /// out before an intersection was found: the query cannot say "no"; the counters tell how far it
    /// got. Never reported as separate.
    undecided = 2,
    /// The former name of `undecided`.
    budget_exhausted = undecided,
};

inline const char* to_string(Intersection_status status)
{
    switch (status) {
    case Intersection_status::intersecting: return "intersecting";
    case Intersection_status::separate: return "separate";
    case Intersection_status::undecided: return "undecided";
    }
    return "unknown";
}

/// Work counters of one query. Deterministic for a given seed, objects, poses and options (whatever
/// the number of threads running queries and their order). A plain value, owned by its result.
struct Intersection_counters {
    /// Evaluations of f_A or f_B, defined or not (the figure of WSCG05 Fig. 11).
    std::size_t f_evaluations = 0;
    /// Root bracketing: sample points that had a partner search (f of the other surface defined
    /// and small enough for a sign change within reach), and partner candidates evaluated.
    std::size_t brackets_tried = 0;
    std::size_t partner_candidates = 0;
    /// Brackets found: pairs with opposite signs of f.
    std::size_t brackets_found = 0;
    /// Steps of the interpolation search (each one f evaluation).
    std::size_t search_steps = 0;
    /// Steps that fell back to bisection.
    std::size_t bisection_steps = 0;
    /// Sample points drawn: cloud points (interpolation search) or points in space (RST).
    std::size_t samples = 0;
    /// Points of the two clouds inside the overlap region (the sets sampled from).
    std::size_t candidate_points = 0;
    /// Samples drawn by the refinement, and Gauss-Newton steps of the refinement and of the contact
    /// verification (two f evaluations each).
    std::size_t refinement_samples = 0;
    /// Candidate points (AIPs, points with |f| <= epsilon, RST samples) that the contact
    /// verification rejected: no common zero of f_A and f_B inside both surfaces' domains within
    /// reach (Intersection_options::verify_contacts).
    std::size_t candidates_rejected = 0;
    /// Hierarchy traversal: node pairs tested and leaf pairs found overlapping. The interpolation
    /// search traverses only when it enumerates its region (after its rejection phase found the
    /// region small): a first hit in a deep overlap reports 0 leaf pairs.
    std::size_t node_pairs = 0;
    std::size_t leaf_pairs = 0;
    /// Walked first-hit traversals: node pairs left unvisited when the walk stopped (at a contact,
    /// or when a budget ran out: with an `undecided` answer, how much was left to look at).
    std::size_t pending_node_pairs = 0;
    /// "Separate" is earned (Intersection_options::certify_separation): 1 when the query searched the
    /// rest of the region within reach before it could answer separate (the walk's completion by
    /// the points its covering skipped, or the complete interpolation search), else 0; and whether
    /// the answer rests on a crossing the verification rejected (0 or 1: the result's point is that
    /// crossing, kind approximate).
    std::size_t certification_passes = 0;
    std::size_t unverified_crossings = 0;

    Intersection_counters& operator+=(const Intersection_counters& o)
    {
        f_evaluations += o.f_evaluations;
        brackets_tried += o.brackets_tried;
        partner_candidates += o.partner_candidates;
        brackets_found += o.brackets_found;
        search_steps += o.search_steps;
        bisection_steps += o.bisection_steps;
        samples += o.samples;
        candidate_points += o.candidate_points;
        refinement_samples += o.refinement_samples;
        candidates_rejected += o.candidates_rejected;
        node_pairs += o.node_pairs;
        leaf_pairs += o.leaf_pairs;
        pending_node_pairs += o.pending_node_pairs;
        certification_passes += o.certification_passes;
        unverified_crossings += o.unverified_crossings;
        return *this;
    }
    friend bool operator==(const Intersection_counters&, const Intersection_counters&) = default;
};

/// Calls `f(name, value)` for every counter of `counters`, in a fixed order, with the name the
/// tools and the Python module use for it (`pccd collide --json`, pccd.Result.counters): the one
/// list of the counters' names. `Counters` is Intersection_counters, const or not (then `value` may
/// be assigned).
template <class Counters, class F>
    requires std::same_as<std::remove_cvref_t<Counters>, Intersection_counters>
void for_each_counter(Counters&& counters, F&& f)
{
    f("f_evaluations", counters.f_evaluations);
    f("brackets_tried", counters.brackets_tried);
    f("partner_candidates", counters.partner_candidates);
    f("brackets_found", counters.brackets_found);
    f("search_steps", counters.search_steps);
    f("bisection_steps", counters.bisection_steps);
    f("samples", counters.samples);
    f("candidate_points", counters.candidate_points);
    f("refinement_samples", counters.refinement_samples);
    f("node_pairs", counters.node_pairs);
    f("leaf_pairs", counters.leaf_pairs);
    f("candidates_rejected", counters.candidates_rejected);
    f("pending_node_pairs", counters.pending_node_pairs);
    f("certification_passes", counters.certification_passes);
    f("unverified_crossings", counters.unverified_crossings);
}

/// The result of do_intersect() and intersection_points(). A plain value: each query returns its own,
/// so concurrent queries share nothing through their results.
struct Intersection_result {
    /// True when an intersection was found.
    bool intersects = false;
    Intersection_status status = Intersection_status::separate;
    /// Points on the intersection curves, world coordinates (one for do_intersect(), the first
    /// found; a set with the requested spacing for intersection_points()).
    std::vector<Intersection_point> points;
    Intersection_counters counters;
    /// How far the surfaces are from touching, as far as the query looked (also when it ran out of
    /// budget: the best estimate so far of an `undecided` answer). Randomized sampling: the smallest
    /// max(|f_A|, |f_B|) over its samples, +infinity when no sample had both defined. Interpolation
    /// search: the smallest |f_T(p)| over its samples p (points of one cloud, f_T the other
    /// surface, where defined; f of a cloud at its own points is about 0), +infinity when f_T was
    /// defined at none. Both policies: +infinity when the separation test of the hierarchy
    /// traversals decided (no point can lie within both surfaces' domains; doc/manual/hierarchy.md).
    double closest_estimate = 0.0;

    explicit operator bool() const { return intersects; }
};

} // namespace PCCD
