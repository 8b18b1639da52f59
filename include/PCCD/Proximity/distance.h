// PCCD/Proximity/distance.h -- the distance between the implicit surfaces of two posed point clouds,
// with honest bounds, witness points and normals, the penetration depths of intersecting poses, and
// the clearance test within_distance() (doc/algorithms.md "Proximity queries"; doc/manual/proximity.md).
// Whether the surfaces touch is decided by do_intersect() (so the two never disagree); the
// distance comes from the closest point pairs of the clouds (a branch and bound walk of the two
// hierarchies) refined onto both surfaces.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Proximity/Distance_options.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Proximity/internal/closest_pairs.h>
#include <PCCD/Proximity/internal/penetration.h>
#include <PCCD/Proximity/internal/surface_projection.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/internal/finite.h>
#include <PCCD/internal/timing.h>

namespace PCCD {
namespace internal {

/// How far a sampled surface can lie from its samples: the sampling radius (every surface point
/// within it of a sample) plus twice the estimated noise (samples displaced off the surface).
template <class O>
double surface_radius(const Posed_object<O>& o)
{
    return o.sampling_radius() + 2.0 * o.noise_estimate();
}

inline void check_pose(const Rigid_transform_3<double>& pose, const char* which, const char* function)
{
    if (!all_finite(pose.rotation()) || !all_finite(pose.translation()))
        throw Invalid_input(concat(function, ": ", which, " is not finite (NaN or infinity in the pose)"));
}

/// The closest-pair walk prunes node pairs whose lower bound is within this fraction of the smaller
/// sampling radius of the best pair so far: measured on the benchmark poses of the 30,000-point
/// bunny (doc/benchmarks.md "Proximity queries"), 0.5 visits 0.65 times the node pairs of an exact
/// walk, and the refined distance differs from that of the exact walk by no more than 0.6 mean
/// spacings (95 % of the poses: 0.25), i.e. less than the refinement's own variation between
/// candidates; 1.0 saves another third but doubles that difference.
inline constexpr double walk_slack_factor = 0.5;

/// The pieces one proximity query shares: posed objects, tolerances, budgets.
template <class A, class B>
struct Proximity_query {
    Posed_object<A> pa;
    Posed_object<B> pb;
    const Distance_options& options;
    double tolerance;  // on |f| of a witness, and the refinement's stopping step
    double max_step;   // the longest projection step (stays within the surfaces' domains)
    double walk_slack; // the closest-pair walk's slack (closest_pairs_traits)
    Steady_clock::time_point start;
    Proximity_state state;

    Proximity_query(const A& a, const Rigid_transform_3<double>& pose_a, const B& b, const Rigid_transform_3<double>& pose_b,
                    const Distance_options& o, Distance_counters& counters)
        : pa(a, pose_a), pb(b, pose_b), options(o),
          tolerance(o.absolute_tolerance.value_or(0.01 * std::min(pa.sampling_radius(), pb.sampling_radius()))),
          max_step(2.0 * std::max(pa.sampling_radius(), pb.sampling_radius())),
          walk_slack(walk_slack_factor * std::min(pa.sampling_radius(), pb.sampling_radius())), start(Steady_clock::now()),
          state{counters, o.max_f_evaluations, std::nullopt}
    {
        if (o.max_time_us) state.deadline = start + std::chrono::nanoseconds(std::int64_t(*o.max_time_us * 1e3));
    }

    /// do_intersect() with what remains of the budgets.
    Intersection_result decide()
    {
        Intersection_options io = options.intersection;
        if (options.max_f_evaluations)
            io.max_f_evaluations = std::max<std::size_t>(1, *options.max_f_evaluations - std::min(*options.max_f_evaluations, state.counters.f_evaluations));
        if (options.max_time_us)
            io.max_time_us = std::max(1e-3, *options.max_time_us - ms_since(start) * 1e3);
        Intersection_result r = do_intersect(*pa.object, pa.to_world, *pb.object, pb.to_world, io);
        state.counters.intersection = r.counters;
        return r;
    }

    /// The k closest point pairs of the clouds within `bound` (their local positions in hierarchy
    /// order), with the smallest lower bound of what a budget left unvisited; `certificate`, when
    /// given, is brought to the certified lower bound of the surfaces' distance in the same walk.
    auto closest_pairs(std::size_t k, double bound, Gap_certificate* certificate = nullptr)
    {
        const Point_cloud_hierarchy& ha = pa.object->hierarchy();
        const Point_cloud_hierarchy& hb = pb.object->hierarchy();
        auto stop = [this, visited = std::size_t(0)]() mutable {
            return (options.max_node_pairs && ++visited > *options.max_node_pairs) || state.out_of_budget();
        };
        const Rigid_transform_3<double> a_to_b = pb.from_world * pa.to_world;
        Closest_pairs_traits<decltype(stop)> traits(ha, hb, a_to_b, k, bound, walk_slack, stop);
        traits.certificate = certificate;
        // The local search's first pair tightens the pruning of an unbounded walk; under a finite
        // bound (max_distance, a clearance margin) the bound already prunes, and the search would
        // cost more than it saves (measured: within_distance 1.3-1.5x -> 1.1-1.3x do_intersect).
        if (!ha.empty() && !hb.empty() && !std::isfinite(bound)) {
            const Point_pair seed = local_closest_pair(ha, hb, a_to_b);
            if (seed.distance < bound) traits.seed(seed);
        }
        const Walk_counters w = traverse(ha, Point_cloud_hierarchy::Index(0), hb, Point_cloud_hierarchy::Index(0), traits);
        state.counters.node_pairs += w.tested;
        state.counters.leaf_pairs += traits.leaf_pairs;
        state.counters.point_pairs += traits.point_pairs;
        return traits;
    }

    /// The witness pair refined from the cloud point pair c, or nullopt when a projection fails.
    std::optional<Witness_pair> refine(const Point_pair& c)
    {
        const Point_cloud_hierarchy& ha = pa.object->hierarchy();
        const Point_cloud_hierarchy& hb = pb.object->hierarchy();
        const Eigen::Vector3d p = pa.to_world.transform_point(Eigen::Vector3d(ha.ordered_points().col(c.first).head<3>()));
        const Eigen::Vector3d q = pb.to_world.transform_point(Eigen::Vector3d(hb.ordered_points().col(c.second).head<3>()));
        ++state.counters.candidates_refined;
        const std::optional<Surface_point> x = project_onto_surface(pa, p, tolerance, max_step, state);
        if (!x) return std::nullopt;
        const std::optional<Surface_point> y = project_onto_surface(pb, q, tolerance, max_step, state);
        if (!y) return std::nullopt;
        const double step = options.relative_tolerance > 0.0 ? std::max(tolerance, options.relative_tolerance * (x->x - y->x).norm())
                                                             : tolerance;
        return refine_witnesses(pa, pb, Witness_pair{*x, *y}, step, max_step, state);
    }

    /// Penetration depths of an intersecting pose, written into r.
    void penetration(Distance_result& r)
    {
        const std::size_t tries = 4;
        const std::optional<Local_depth> da = deepest(pa, pb, points_inside(pa, pb, state), tries, tolerance, max_step, state);
        const std::optional<Local_depth> db = deepest(pb, pa, points_inside(pb, pa, state), tries, tolerance, max_step, state);
        r.depth_a = da ? da->depth : 0.0;
        r.depth_b = db ? db->depth : 0.0;
        r.depth = std::max(r.depth_a, r.depth_b);
        if (da && (!db || da->depth >= db->depth)) {
            r.point_a = da->deep.x;
            r.normal_a = da->deep.normal;
            r.point_b = da->surface.x;
            r.normal_b = da->surface.normal;
            r.contact_normal = -da->surface.normal;
        } else if (db) {
            r.point_b = db->deep.x;
            r.normal_b = db->deep.normal;
            r.point_a = db->surface.x;
            r.normal_a = db->surface.normal;
            r.contact_normal = db->surface.normal;
        } else if (!r.intersection_points.empty()) {
            // No sample lies inside the other object: the surfaces cross by less than the sampling
            // resolution; the contact normal is that of the crossing.
            const Eigen::Vector3d x = r.intersection_points.front().position;
            r.contact_normal = crossing_normal(x);
            r.point_a = r.point_b = x;
        }
    }

    /// The direction in which B must move to leave A at a point x where the surfaces cross: n_A - n_B
    /// normalized (NaN where a surface is undefined or the normals cancel).
    Eigen::Vector3d crossing_normal(const Eigen::Vector3d& x)
    {
        const Surface_evaluation ea = state.evaluate(pa, x), eb = state.evaluate(pb, x);
        if (ea.defined() && eb.defined()) {
            const Eigen::Vector3d n = pa.to_world.rotation() * ea.normal - pb.to_world.rotation() * eb.normal;
            if (n.norm() > 0.0) return n.normalized();
        }
        return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    }
};

template <class A, class B>
Distance_result run_distance(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                             const Rigid_transform_3<double>& pose_b, const Distance_options& options,
                             std::optional<double> margin, const char* function)
{
    check_options(options, function);
    check_pose(pose_a, "pose_a", function);
    check_pose(pose_b, "pose_b", function);
    Distance_result r;
    Proximity_query<A, B> q(a, pose_a, b, pose_b, options, r.counters);
    const double rho = surface_radius(q.pa) + surface_radius(q.pb);

    Intersection_result decided = q.decide();
    r.status = decided.status;
    if (decided.status == Intersection_status::intersecting) {
        r.distance = 0.0;
        r.lower_bound = r.upper_bound = 0.0;
        r.intersection_points = std::move(decided.points);
        if (options.penetration && !margin) q.penetration(r);
        return r;
    }
    if (decided.status == Intersection_status::undecided) return r;

    // Separate: the closest point pairs, pruned beyond max_distance (or the margin) plus how far a
    // surface can lie from its samples, refined onto the surfaces. By default that is the surface
    // radii r(P) + 2 sigma, and the lower bound is the closest pair's distance minus them (a premise
    // about the fit). With certified_lower_bound it is the points' reaches (domain radii capped by
    // the support radius, surface_reach.h: f is defined nowhere else), and the same walk certifies
    // the lower bound: the smallest gap |p - q| - reach(p) - reach(q) over the point pairs.
    const std::optional<double> limit = margin ? margin : options.max_distance;
    const Point_cloud_hierarchy& ha = a.hierarchy();
    const Point_cloud_hierarchy& hb = b.hierarchy();
    Gap_certificate certificate{surface_reach(ha, double(a.surface().support_radius())),
                                surface_reach(hb, double(b.surface().support_radius())),
                                limit ? *limit : std::numeric_limits<double>::infinity()};
    const bool certify = options.certified_lower_bound;
    const double beyond_samples = !certify ? rho
                                  : ha.empty() || hb.empty()
                                      ? 0.0
                                      : certificate.reach_s(ha.root().reach) + certificate.reach_t(hb.root().reach);
    const double bound = limit ? *limit + beyond_samples : std::numeric_limits<double>::infinity();
    const auto walk = q.closest_pairs(options.candidates, bound, certify ? &certificate : nullptr);
    const double walk_lower = std::min(walk.best.empty() ? bound : walk.best.front().distance, walk.pending_lower);
    r.lower_bound = std::max(0.0, certify ? certificate.lower() : walk_lower - rho);
    if (walk.best.empty()) {
        if (!walk.stopped && limit) { // nothing within the limit
            r.distance = std::numeric_limits<double>::infinity();
            r.lower_bound = std::max(r.lower_bound, *limit);
        }
        return r;
    }
    std::optional<Witness_pair> best;
    for (const Point_pair& c : walk.best) {
        if (q.state.out_of_budget()) break;
        if (best && c.distance - rho >= best->distance()) break; // cannot beat it
        const std::optional<Witness_pair> w = q.refine(c);
        if (w && (!best || w->distance() < best->distance())) best = w;
        if (margin && best && best->distance() <= *margin) break; // the clearance question is answered
    }
    if (!best) { // every projection failed (or the budget ran out): the cloud points as they are
        const Point_pair& c = walk.best.front();
        r.point_a = pose_a.transform_point(Eigen::Vector3d(a.hierarchy().ordered_points().col(c.first).template head<3>()));
        r.point_b = pose_b.transform_point(Eigen::Vector3d(b.hierarchy().ordered_points().col(c.second).template head<3>()));
        r.distance = c.distance;
        r.upper_bound = c.distance + rho;
    } else {
        r.point_a = best->a.x;
        r.point_b = best->b.x;
        r.normal_a = best->a.normal;
        r.normal_b = best->b.normal;
        r.distance = best->distance();
        // The witnesses lie within |f| of their surfaces; a noisy sample's surface may bulge towards
        // the other object by up to about twice the noise, so the sampled surfaces may lie that
        // much farther apart.
        r.upper_bound = r.distance + std::abs(best->a.f) + std::abs(best->b.f) +
                        2.0 * (q.pa.noise_estimate() + q.pb.noise_estimate());
    }
    r.lower_bound = std::min(r.lower_bound, r.distance);
    if (r.distance > 0.0) r.contact_normal = (r.point_b - r.point_a) / r.distance;
    return r;
}

} // namespace internal

/// The distance between the implicit surfaces of `a` posed by `pose_a` and `b` posed by `pose_b`,
/// with witness points, normals and an honest interval; with options.penetration, the local
/// penetration depths of intersecting poses (see Distance_result for every field).
///
/// The status is do_intersect()'s with options.intersection (run first). Separate poses: a branch
/// and bound walk of the two hierarchies finds the options.candidates closest point pairs of the
/// clouds in distinct leaf pairs; each is projected onto both surfaces and refined by alternating
/// closest-point steps; the smallest distance is the answer.
///
/// \tparam A, B models of ProximityObject (Point_cloud_object<K>, Deforming_point_cloud_object<K>).
/// \throws Invalid_input for invalid options (the message names the field) or a pose with NaN or
///         infinite entries.
/// Thread safety: the objects are only read; any number of queries may run concurrently. The result
/// depends only on the arguments (seed included) unless a time budget is set.
/// Complexity: that of do_intersect(), plus O(height) node pairs for the closest pairs of
/// well-separated objects and a few tens of f evaluations for the refinement; penetration adds one
/// nearest-point query per point of each cloud inside the other's box.
template <ProximityObject A, ProximityObject B>
Distance_result distance(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                         const Rigid_transform_3<double>& pose_b, const Distance_options& options = {})
{
    return internal::run_distance(a, pose_a, b, pose_b, options, std::nullopt, "distance");
}

/// distance() for two objects already in one frame.
template <ProximityObject A, ProximityObject B>
Distance_result distance(const A& a, const B& b, const Distance_options& options = {})
{
    const Rigid_transform_3<double> identity;
    return internal::run_distance(a, identity, b, identity, options, std::nullopt, "distance");
}

/// Clearance: whether the surfaces of the posed objects intersect or come closer than `margin`
/// (world units). The same answer as distance() compared with the margin, but a "no" stops as soon
/// as the walk proves every point pair farther than margin plus the surfaces' radii, and a "yes" at
/// the first witness pair within the margin.
/// \throws Invalid_input if margin is negative or not finite, and as distance().
template <ProximityObject A, ProximityObject B>
Clearance_result within_distance(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                                 const Rigid_transform_3<double>& pose_b, double margin,
                                 const Distance_options& options = {})
{
    if (!(std::isfinite(margin) && margin >= 0.0))
        throw Invalid_input(internal::concat("within_distance: margin ", margin, " must be finite and >= 0"));
    const Distance_result d = internal::run_distance(a, pose_a, b, pose_b, options, margin, "within_distance");
    Clearance_result c;
    c.status = d.status;
    c.margin = margin;
    c.lower_bound = d.lower_bound;
    c.upper_bound = d.upper_bound;
    c.counters = d.counters;
    c.within = d.status == Intersection_status::intersecting ||
               (d.status == Intersection_status::separate && std::islessequal(d.distance, margin)); // NaN: not known
    if (c.within && d.status == Intersection_status::separate) {
        c.point_a = d.point_a;
        c.point_b = d.point_b;
    }
    return c;
}

} // namespace PCCD
