// PCCD/Intersection/Intersection_options.h -- the run-time knobs shared by every intersection query
// (doc/manual/intersection.md "Options"): seed, tolerance, region, traversal, refinement, output
// density, budgets.
// The leaf intersector policies (Interpolation_search.h, Randomized_sampling.h) carry their own.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include <PCCD/Error.h>

namespace PCCD {

struct Intersection_visitor; // Intersection_visitor.h

/// Where a query looks for the intersection.
enum class Overlap_region : std::uint8_t {
    /// Pairs of hierarchy leaves whose boxes may overlap (the default): the work follows the contact
    /// region.
    leaf_boxes = 0,
    /// Box(A) intersected with Box(B), as WSCG05 section 5.2 did ("no BV hierarchies were used"):
    /// every point of A inside B's box (grown by B's kernel support), and vice versa.
    object_boxes = 1,
};

/// How a query walks the two objects' point cloud hierarchies (doc/manual/hierarchy.md).
enum class Traversal : std::uint8_t {
    /// The published method: the region is what Overlap_region says (boxes grown by the kernel's
    /// support), drawn uniformly; no separation test before f is evaluated. Kept for comparison.
    flat = 0,
    /// The hierarchies are walked depth-first with each point's reach (where its surface can be
    /// defined): a pair of objects whose points are nowhere within the sum of their reaches
    /// (scaled by contact_core for verified contacts) is `separate` with no f evaluation, and each
    /// role samples only the points where the other surface can be defined.
    depth_first = 1,
    /// As depth_first, but of the two children of a node, the one whose box centre lies nearer the
    /// other node's box centre is walked first: the estimated likelihood of a contact is the
    /// closeness of the two boxes, so that a first-hit query reaches the touching parts early.
    /// Measured fastest (doc/benchmarks.md "Point cloud hierarchy"). Default.
    likelihood = 2,
};

/// How the points of intersection_points() are refined (doc/manual/intersection.md, "Refinement").
enum class Refinement : std::uint8_t {
    /// Return the approximate intersection points (AIPs) as found.
    none = 0,
    /// WSCG05 section 4.3: random samples in the intersection sphere around the AIP; the sample with
    /// the smallest max(|f_A|, |f_B|) replaces the AIP when both values are below the threshold.
    sampling = 1,
    /// Gauss-Newton on the two equations f_A = f_B = 0 (minimum-norm steps, two evaluations per step)
    /// starting at the AIP; measured more precise and cheaper than sampling (doc/benchmarks.md).
    projection = 2,
};

/// Options of do_intersect() and intersection_points(). Every field has a documented default; use
/// designated initializers: `{.seed = 7, .refinement = Refinement::none}`.
/// A plain value: one instance may be shared by any number of concurrent queries (they only read it).
struct Intersection_options {
    /// Seed of every random choice of the query. The same seed gives the same answer, points and
    /// counters on every platform and for any number of concurrent queries.
    std::uint64_t seed = 0x5eed;
    /// The tolerance epsilon on |f| (world units): the interpolation search stops at a path point
    /// with |f| <= epsilon; the refinement accepts points with max(|f_A|, |f_B|) <= epsilon; the
    /// randomized sampling reports samples with both |f| < epsilon. Unset (default): automatic, a
    /// fraction of the smaller sampling radius r (Interpolation_search and the refinement: 0.05 r;
    /// Randomized_sampling: its own default, see there). When set: finite and > 0.
    std::optional<double> epsilon = std::nullopt;
    /// The region searched by the flat traversal (default: overlapping hierarchy leaves).
    Overlap_region region = Overlap_region::leaf_boxes;
    /// How the hierarchies are walked (default: likelihood; flat is the published method). Objects
    /// whose hierarchy was built without reaches are always walked flat.
    Traversal traversal = Traversal::likelihood;
    /// Refinement of the points of intersection_points() when contacts are not verified
    /// (verify_contacts = false; verified points are already projected onto both surfaces).
    /// do_intersect() never refines: it answers at the first candidate. Default: projection.
    Refinement refinement = Refinement::projection;
    /// intersection_points(): the smallest distance between two returned points (world units); the
    /// caller's density along the curves. Unset (default): the larger mean spacing of the two clouds.
    /// When set: finite and > 0.
    std::optional<double> point_spacing = std::nullopt;
    /// Largest number of refinement samples per point with Refinement::sampling (default 64).
    std::size_t refinement_samples = 64;
    /// Budget: the query stops once it has evaluated f this many times, with
    /// Intersection_status::undecided if nothing was found. Unset (default): no budget. When
    /// set: >= 1.
    std::optional<std::size_t> max_f_evaluations = std::nullopt;
    /// Time budget in microseconds (time-critical queries): the query stops once this much wall
    /// time (steady clock) has passed since it started, with Intersection_status::undecided if
    /// nothing was found; an answer found in time stands. Checked at every leaf pair and f
    /// evaluation, so a query may overrun by about one leaf pair's work. Unlike the other options,
    /// the answer then depends on the machine's speed. Unset (default): no limit. When set: finite
    /// and > 0.
    std::optional<double> max_time_us = std::nullopt;
    /// Events of the query (node pairs, leaf pairs, brackets, evaluations of f) reported to this
    /// visitor (Intersection_visitor.h), which must outlive the query; the visitor's members run on
    /// the query's thread. Default nullptr: no events. Not owned.
    Intersection_visitor* visitor = nullptr;
    /// Sample both roles (points of A tested against f_B, then points of B against f_A). Default
    /// true; false samples only the object with fewer candidate points.
    bool symmetric = true;
    /// Verified contacts (default true): a candidate the policy finds (an AIP of the interpolation
    /// search, a cloud point with |f| <= epsilon, an RST sample) is only a candidate. It becomes a
    /// result point only if damped Gauss-Newton steps from it reach a common zero of f_A and f_B,
    /// max(|f_A|, |f_B|) <= contact_tolerance, inside both surfaces' domains and within
    /// 2 max(r_A, r_B) of the candidate; the result point is that projected point (kind refined).
    /// Rejected candidates are counted (Intersection_counters::candidates_rejected) and the search
    /// goes on. false: the published methods as they are (a sample of A with |f_B| <= epsilon is a
    /// contact), with intersection_points() refined as `refinement` says.
    bool verify_contacts = true;
    /// The verification's tolerance on max(|f_A|, |f_B|) (world units). Unset (default): 0.05 times
    /// the smaller sampling radius, for both policies. When set: finite and > 0.
    std::optional<double> contact_tolerance = std::nullopt;
    /// A verified contact must also lie within this fraction of both surfaces' domain radii from
    /// their nearest cloud points (Surface_evaluation::domain_fraction), in (0, 1]. Default 0.6,
    /// measured on scan-like clouds (doc/benchmarks.md "Accuracy on scans"): the zeros the
    /// surfaces share near the edge of a domain, where a fit rests on few points, were the false
    /// contacts left; true contacts of non-grazing poses lie deeper (their first hits: median 0.41),
    /// and the search goes on past the few it rejects. With the sphere fit, 0.6 leaves no false
    /// contact in 13,000 poses for either policy; it costs about 1 % of curve coverage against 0.7.
    double contact_core = 0.6;
    /// "Separate" is earned (default true; with verify_contacts only; doc/manual/intersection.md,
    /// "When PCCD says separate"). Before a query answers separate, whatever its policy and
    /// traversal: (1) every point of the region within reach is sampled in each role — the walk of
    /// the likelihood and depth-first traversals samples afterwards the points its covering skipped,
    /// and where that is not possible (a sample cap reached, random partners, the flat traversal,
    /// RST) the interpolation search samples the region from the query's seed as
    /// intersection_points() does — so do_intersect() says intersecting whenever
    /// intersection_points() with the same options finds a point; (2) if that search found
    /// a crossing, i.e. two points of one cloud on a path of its graph on opposite sides of the
    /// other surface, with both surfaces defined at the AIP between them, which the verification
    /// rejected (no common zero within contact_tolerance
    /// where the surfaces bend faster than the kernel resolves, at sharp edges, thin walls and in
    /// sparse clouds), the answer is intersecting with that crossing as its point (kind
    /// approximate; Intersection_counters::unverified_crossings = 1). false: the policy's own
    /// search decides (faster near misses; misses contacts of sparse clouds and sharp parts).
    bool certify_separation = true;
};

namespace internal {

inline void check_options(const Intersection_options& o, const char* function)
{
    if (o.epsilon && !(std::isfinite(*o.epsilon) && *o.epsilon > 0.0))
        throw Invalid_input(concat(function, ": epsilon ", *o.epsilon, " must be finite and > 0 (leave it unset for the automatic value)"));
    if (o.point_spacing && !(std::isfinite(*o.point_spacing) && *o.point_spacing > 0.0))
        throw Invalid_input(concat(function, ": point_spacing ", *o.point_spacing,
                                   " must be finite and > 0 (leave it unset for the automatic value)"));
    if (o.contact_tolerance && !(std::isfinite(*o.contact_tolerance) && *o.contact_tolerance > 0.0))
        throw Invalid_input(concat(function, ": contact_tolerance ", *o.contact_tolerance,
                                   " must be finite and > 0 (leave it unset for the automatic value)"));
    if (!(std::isgreater(o.contact_core, 0.0) && std::islessequal(o.contact_core, 1.0)))
        throw Invalid_input(concat(function, ": contact_core ", o.contact_core, " must lie in (0, 1]"));
    if (o.max_f_evaluations && *o.max_f_evaluations == 0)
        throw Invalid_input(concat(function, ": a budget of zero f evaluations (max_f_evaluations = 0) cannot answer; leave it unset for no budget"));
    if (o.max_time_us && !(std::isfinite(*o.max_time_us) && *o.max_time_us > 0.0))
        throw Invalid_input(concat(function, ": max_time_us ", *o.max_time_us, " must be finite and > 0 (leave it unset for no time limit)"));
    if (o.refinement == Refinement::sampling && o.refinement_samples == 0)
        throw Invalid_input(concat(function, ": refinement_samples must be >= 1 with Refinement::sampling"));
    if (o.region != Overlap_region::leaf_boxes && o.region != Overlap_region::object_boxes)
        throw Invalid_input(concat(function, ": unknown overlap region"));
    if (o.traversal != Traversal::flat && o.traversal != Traversal::depth_first && o.traversal != Traversal::likelihood)
        throw Invalid_input(concat(function, ": unknown traversal"));
    if (o.refinement != Refinement::none && o.refinement != Refinement::sampling &&
        o.refinement != Refinement::projection)
        throw Invalid_input(concat(function, ": unknown refinement"));
}

} // namespace internal
} // namespace PCCD
