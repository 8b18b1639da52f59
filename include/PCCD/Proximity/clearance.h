// PCCD/Proximity/clearance.h -- clearance() along a path: an object moved through a scene by a list
// of poses (a wagon scan through a tunnel scan), and at every pose the distance between the two
// implicit surfaces placed against a safety margin, with the first pose below the margin and the
// minimum clearance (doc/manual/proximity.md "Clearance along a path"). Each pose is one distance()
// query, answered in parallel by the batch machinery of distance_many() and bit for bit the
// sequential answer whatever the number of threads.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Proximity/Clearance_options.h>
#include <PCCD/Proximity/Clearance_profile.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/ProximityObject.h>

namespace PCCD {
namespace internal {

/// Adds the counters of `b` to those of `a`, field by field (those of the intersection query too).
inline void add_counters(Distance_counters& a, const Distance_counters& b)
{
    std::vector<std::size_t> values;
    for_each_counter(b, [&](const char*, std::size_t v) { values.push_back(v); });
    std::size_t k = 0;
    for_each_counter(a, [&](const char*, std::size_t& v) { v += values[k++]; });
    values.clear();
    for_each_counter(b.intersection, [&](const char*, std::size_t v) { values.push_back(v); });
    k = 0;
    for_each_counter(a.intersection, [&](const char*, std::size_t& v) { v += values[k++]; });
}

/// The sample of one pose from its distance() answer, placed against the margin: below it when the
/// clearance is (strictly) smaller; beyond the cap when distance() found nothing within it or
/// measured more than it (the walk prunes at the cap plus the surfaces' radii, so a pose just
/// beyond the cap may still be measured); a pose whose walk a budget stopped without a witness is
/// still clear when its lower bound reaches the margin.
inline Clearance_sample clearance_sample(const Distance_result& d, double margin, std::optional<double> cap)
{
    Clearance_sample s;
    s.clearance = d.distance;
    s.lower_bound = d.lower_bound;
    s.upper_bound = d.upper_bound;
    s.counters = d.counters;
    s.depth = d.depth;
    if (d.point_a.allFinite() && d.point_b.allFinite()) {
        s.point_object = d.point_a;
        s.point_scene = d.point_b;
    }
    switch (d.status) {
    case Intersection_status::intersecting: s.status = Clearance_status::intersecting; break;
    case Intersection_status::undecided: s.status = Clearance_status::undecided; break;
    case Intersection_status::separate:
        if (d.distance == std::numeric_limits<double>::infinity() || (cap && std::isgreater(d.distance, *cap))) {
            s.status = Clearance_status::beyond_cap;
            s.clearance = std::numeric_limits<double>::infinity();
        } else if (std::isless(d.distance, margin))
            s.status = Clearance_status::below_margin;
        else if (std::isgreaterequal(d.distance, margin) || d.lower_bound >= margin)
            s.status = Clearance_status::clear;
        else
            s.status = Clearance_status::undecided; // NaN distance: a budget stopped the walk below the margin
        break;
    }
    return s;
}

/// The summary of the path from its samples: first pose below the margin, minimum, counters.
inline void summarize(Clearance_profile& p)
{
    for (std::size_t i = 0; i < p.samples.size(); ++i) {
        const Clearance_sample& s = p.samples[i];
        switch (s.status) {
        case Clearance_status::clear: ++p.counters.clear; break;
        case Clearance_status::below_margin: ++p.counters.below_margin; break;
        case Clearance_status::intersecting: ++p.counters.intersecting; break;
        case Clearance_status::beyond_cap: ++p.counters.beyond_cap; break;
        case Clearance_status::undecided: ++p.counters.undecided; break;
        }
        add_counters(p.counters.work, s.counters);
        const bool below = s.status == Clearance_status::below_margin || s.status == Clearance_status::intersecting;
        if (below && !p.first_below_margin) {
            p.first_below_margin = i;
            p.first_point_object = s.point_object;
            p.first_point_scene = s.point_scene;
        }
        if (s.status == Clearance_status::undecided && !p.first_undecided) p.first_undecided = i;
        if (s.status != Clearance_status::beyond_cap && std::isfinite(s.clearance) && s.clearance < p.minimum_clearance) {
            p.minimum = i;
            p.minimum_clearance = s.clearance;
        }
    }
}

} // namespace internal

/// The clearance of `object` moved along `poses` through `scene`: poses[i] places the object in the
/// scene's frame (the scene stays at the identity). Pose i is answered by distance() with
/// options.distance, the cap options.max_distance as its max_distance and the seed
/// pair_seed(options.distance.intersection.seed, options.batch.first_index + i), and placed against
/// `margin` (see Clearance_status: below_margin when the clearance is strictly smaller than the
/// margin). Sample i is that query's answer whatever options.batch.threads (bit for bit, without a
/// time budget). An empty path gives an empty profile.
///
/// \tparam A, B models of ProximityObject (Point_cloud_object<K>, Deforming_point_cloud_object<K>).
/// \throws Invalid_input for a negative, NaN or infinite margin, invalid options (naming the field),
///         or a pose with NaN or infinite entries (naming its index), before any query runs; an
///         exception of a pose's query after the others are done (that of the lowest index).
/// Thread safety: the objects are only read. Complexity: one distance() per pose, divided among
/// the threads; poses beyond the cap cost a pruned walk and no evaluation of f.
template <ProximityObject A, ProximityObject B>
Clearance_profile clearance(const A& object, const B& scene, std::span<const Rigid_transform_3<double>> poses,
                            double margin, const Clearance_options& options = {})
{
    const char* function = "clearance";
    internal::check_options(options, margin, function);
    for (std::size_t i = 0; i < poses.size(); ++i)
        if (!internal::all_finite(poses[i].rotation()) || !internal::all_finite(poses[i].translation()))
            throw Invalid_input(internal::concat(function, ": pose ", i, " is not finite (NaN or infinity in the pose)"));
    std::vector<Posed_pair<A, B>> pairs;
    pairs.reserve(poses.size());
    for (const Rigid_transform_3<double>& pose : poses) pairs.push_back({&object, pose, &scene, Rigid_transform_3<double>()});
    Distance_options distance_options = options.distance;
    distance_options.max_distance = options.max_distance;

    Clearance_profile p;
    p.margin = margin;
    p.max_distance = options.max_distance;
    p.samples = internal::run_batch<Clearance_sample>(
        std::span<const Posed_pair<A, B>>(pairs), options.batch, function, [&](const Posed_pair<A, B>& pair, std::uint64_t index) {
            Distance_options pose_options = distance_options;
            pose_options.intersection.seed = pair_seed(distance_options.intersection.seed, index);
            return internal::clearance_sample(
                internal::run_distance(*pair.a, pair.pose_a, *pair.b, pair.pose_b, pose_options, std::nullopt, function), margin,
                options.max_distance);
        });
    internal::summarize(p);
    return p;
}

/// The same for a vector of poses.
template <ProximityObject A, ProximityObject B>
Clearance_profile clearance(const A& object, const B& scene, const std::vector<Rigid_transform_3<double>>& poses,
                            double margin, const Clearance_options& options = {})
{
    return clearance(object, scene, std::span<const Rigid_transform_3<double>>(poses), margin, options);
}

} // namespace PCCD
