// PCCD/Proximity/Distance_result.h -- what the proximity queries return (doc/manual/proximity.md
// "The result"): the status, the distance between the two implicit surfaces with an honest interval
// around it and the witness points, the penetration depths with the contact normal, the contact
// regions of contacts(), and the counters of the work done.
#pragma once

#include <concepts>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Intersection/Intersection_result.h>

namespace PCCD {

/// Work counters of one proximity query. Deterministic for given objects, poses and options
/// (seed included), whatever the number of threads.
struct Distance_counters {
    /// Node pairs tested and leaf pairs compared point by point by the closest-pair walk.
    std::size_t node_pairs = 0;
    std::size_t leaf_pairs = 0;
    /// Point pairs whose distance was computed at the leaves.
    std::size_t point_pairs = 0;
    /// Evaluations of f_A or f_B by the distance, penetration and contact steps (the intersection
    /// query's own are in `intersection`).
    std::size_t f_evaluations = 0;
    /// Steps of the witness refinement (each a projection onto one surface).
    std::size_t refinement_steps = 0;
    /// Closest point pairs whose witnesses were refined.
    std::size_t candidates_refined = 0;
    /// Points tested for lying inside the other object (penetration and contacts).
    std::size_t inside_tests = 0;
    /// The counters of the intersection query that decided the status (zero when the hierarchies
    /// alone proved the surfaces apart).
    Intersection_counters intersection;

    friend bool operator==(const Distance_counters&, const Distance_counters&) = default;
};

/// Calls `f(name, value)` for each counter of `counters` but the intersection query's, in a fixed
/// order, with the names the tools and the Python module use. The intersection query's counters
/// are listed by for_each_counter(counters.intersection, f); the tools and the Python module print
/// them with their names prefixed "intersection_".
template <class Counters, class F>
    requires std::same_as<std::remove_cvref_t<Counters>, Distance_counters>
void for_each_counter(Counters&& counters, F&& f)
{
    f("node_pairs", counters.node_pairs);
    f("leaf_pairs", counters.leaf_pairs);
    f("point_pairs", counters.point_pairs);
    f("f_evaluations", counters.f_evaluations);
    f("refinement_steps", counters.refinement_steps);
    f("candidates_refined", counters.candidates_refined);
    f("inside_tests", counters.inside_tests);
}

/// The result of distance() and within_distance(). Points and normals are in world coordinates;
/// fields a query did not compute are NaN (never a fabricated 0).
struct Distance_result {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// intersecting, separate, or undecided (a budget ran out before the intersection query
    /// could decide). Always the status do_intersect() gives with Distance_options::intersection.
    Intersection_status status = Intersection_status::undecided;
    /// Separate: the distance between the two implicit surfaces, |point_a - point_b| (+infinity
    /// when the objects are farther apart than Distance_options::max_distance). Intersecting: 0.
    /// Undecided: NaN.
    double distance = nan;
    /// An honest interval around the distance between the sampled surfaces: lower_bound <= true
    /// distance <= upper_bound. By default the lower bound is that of the clouds' closest point
    /// pair found so far minus both objects' surface radii (sampling radius plus twice the noise:
    /// a premise, every point of a sampled surface lies about that close to a sample), so its gap
    /// to the distance is about the two sampling radii once the walk has ended, and wider when a
    /// budget stopped it. With Distance_options::certified_lower_bound it is certified: the
    /// smallest point pair distance minus both points' domain radii (capped by the support
    /// radius; f is defined nowhere else). The upper bound is the distance of the witness points
    /// (on the surfaces) plus their |f| plus twice both objects' estimated noise (a noisy sample's
    /// implicit surface may bulge towards the other object by about that much). 0 and 0 for
    /// intersecting poses; 0 and +infinity before anything is known.
    double lower_bound = 0.0;
    double upper_bound = std::numeric_limits<double>::infinity();
    /// Separate: the closest points found on surface A and surface B, and the surfaces' unit
    /// normals there (pointing out of each object). Intersecting with penetration: the witnesses of
    /// the deeper of the two depths (the deepest point of one surface inside the other object, and
    /// its closest point on the other surface). NaN otherwise.
    Eigen::Vector3d point_a = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d point_b = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d normal_a = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d normal_b = Eigen::Vector3d::Constant(nan);
    /// Penetration (Distance_options::penetration, intersecting poses): depth_a is the largest
    /// distance from a point of surface A inside object B to surface B, depth_b the same with the
    /// roles swapped, depth the larger of the two (0 when no point of either surface lies inside the
    /// other object deeper than the surfaces' tolerance). NaN when not measured.
    double depth = nan;
    double depth_a = nan;
    double depth_b = nan;
    /// Intersecting with penetration: the unit direction in which B must move to leave A at the
    /// deepest point (the outward normal of B at its witness reversed when the deeper point is A's,
    /// the outward normal of A at its witness when it is B's); moving B by depth * contact_normal
    /// undoes that local penetration. Separate: the unit vector from point_a to point_b. NaN
    /// otherwise.
    Eigen::Vector3d contact_normal = Eigen::Vector3d::Constant(nan);
    Distance_counters counters;
    /// The point of the intersection query when the surfaces intersect (on both surfaces).
    std::vector<Intersection_point> intersection_points;

    /// True when the surfaces intersect.
    bool intersecting() const { return status == Intersection_status::intersecting; }
};

/// The result of within_distance(): whether the surfaces come closer than the margin.
struct Clearance_result {
    /// True when the surfaces intersect or come closer than the margin (status intersecting, or
    /// separate with a pair of witness points closer than the margin).
    bool within = false;
    /// As Distance_result::status; undecided (within false) when a budget ran out before the answer.
    Intersection_status status = Intersection_status::undecided;
    /// The margin asked for.
    double margin = Distance_result::nan;
    /// As in Distance_result, as far as the query had to look (a "no" may stop at a lower bound
    /// above the margin, with upper_bound +infinity).
    double lower_bound = 0.0;
    double upper_bound = std::numeric_limits<double>::infinity();
    /// Separate and within: witnesses on surface A and B closer than the margin. NaN otherwise.
    Eigen::Vector3d point_a = Eigen::Vector3d::Constant(Distance_result::nan);
    Eigen::Vector3d point_b = Eigen::Vector3d::Constant(Distance_result::nan);
    Distance_counters counters;

    explicit operator bool() const { return within; }
};

/// One contact region of an intersecting pose, as a physics engine consumes it.
struct Contact {
    /// The representative point: the middle of the region's deepest witness pair (or, for a region
    /// with no sample inside the other object, a point of the intersection curve).
    Eigen::Vector3d position = Eigen::Vector3d::Constant(Distance_result::nan);
    /// Unit direction in which B must move to leave A here (as Distance_result::contact_normal).
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(Distance_result::nan);
    /// The region's largest local depth (>= 0).
    double depth = 0.0;
    /// The deepest witness pair: on surface A and on surface B.
    Eigen::Vector3d point_a = Eigen::Vector3d::Constant(Distance_result::nan);
    Eigen::Vector3d point_b = Eigen::Vector3d::Constant(Distance_result::nan);
    /// The number of cloud points of both objects found inside the other object in this region.
    std::size_t points_inside = 0;
};

/// The result of contacts().
struct Contact_result {
    /// As Distance_result::status.
    Intersection_status status = Intersection_status::undecided;
    /// The contact regions, deepest first, at most Distance_options::max_contacts.
    std::vector<Contact> contacts;
    /// Regions found in all (may exceed contacts.size()).
    std::size_t regions = 0;
    Distance_counters counters;
};

} // namespace PCCD
