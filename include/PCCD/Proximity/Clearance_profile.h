// PCCD/Proximity/Clearance_profile.h -- what clearance() returns (doc/manual/proximity.md
// "Clearance along a path"): per pose of the path its status against the margin, the clearance with
// an honest interval and the witness points, and over the path the first pose below the margin, the
// minimum clearance and the counters.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Proximity/Distance_result.h>

namespace PCCD {

/// The answer at one pose of a path, against the margin.
enum class Clearance_status : std::uint8_t {
    /// Separate, the clearance at least the margin (and below the cap, if any).
    clear = 0,
    /// Separate, the clearance below the margin.
    below_margin = 1,
    /// The surfaces intersect (clearance 0).
    intersecting = 2,
    /// Separate and farther apart than Clearance_options::max_distance (clearance +infinity). When
    /// the walk found no point pair within the cap plus the surfaces' radii, lower_bound >= the cap
    /// and nothing else was computed; a pose measured just beyond the cap keeps its interval and
    /// witnesses.
    beyond_cap = 3,
    /// A budget of Clearance_options::distance ran out before the pose could be placed against the
    /// margin.
    undecided = 4,
};

inline const char* to_string(Clearance_status status)
{
    switch (status) {
    case Clearance_status::clear: return "clear";
    case Clearance_status::below_margin: return "below_margin";
    case Clearance_status::intersecting: return "intersecting";
    case Clearance_status::beyond_cap: return "beyond_cap";
    case Clearance_status::undecided: return "undecided";
    }
    return "unknown";
}

/// One pose of the path. Points are in world coordinates (the scene's frame); fields the query did
/// not compute are NaN.
struct Clearance_sample {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    Clearance_status status = Clearance_status::undecided;
    /// The distance between the two implicit surfaces (Distance_result::distance): 0 when
    /// intersecting, +infinity beyond the cap, NaN when undecided or when a budget left no witness.
    double clearance = nan;
    /// The honest interval of Distance_result: lower_bound <= true clearance <= upper_bound.
    double lower_bound = 0.0;
    double upper_bound = std::numeric_limits<double>::infinity();
    /// The closest points found on the object's surface and on the scene's (separate poses whose
    /// distance was measured; intersecting poses with Distance_options::penetration: the deepest
    /// witnesses). NaN otherwise.
    Eigen::Vector3d point_object = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d point_scene = Eigen::Vector3d::Constant(nan);
    /// Intersecting with Distance_options::penetration: Distance_result::depth. NaN otherwise.
    double depth = nan;
    /// The work of this pose's query.
    Distance_counters counters;
};

/// Counters over the whole path: poses by status, and the sum of the poses' work counters.
struct Clearance_counters {
    std::size_t clear = 0;
    std::size_t below_margin = 0;
    std::size_t intersecting = 0;
    std::size_t beyond_cap = 0;
    std::size_t undecided = 0;
    /// The sum over the poses of Clearance_sample::counters.
    Distance_counters work;
};

/// The result of clearance(). Deterministic for given objects, poses and options (seed included),
/// whatever the number of threads, unless a time budget is set.
struct Clearance_profile {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The margin and the cap asked for.
    double margin = nan;
    std::optional<double> max_distance;
    /// One sample per pose, in the order of the poses.
    std::vector<Clearance_sample> samples;
    /// The first pose whose status is below_margin or intersecting (none when every pose keeps the
    /// margin or is undecided), and its witness points (as in its sample).
    std::optional<std::size_t> first_below_margin;
    Eigen::Vector3d first_point_object = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d first_point_scene = Eigen::Vector3d::Constant(nan);
    /// The first pose of the smallest clearance among the poses clear, below the margin or
    /// intersecting (none when there is none: an empty path, or every pose beyond the cap or
    /// undecided) and that clearance (+infinity when none).
    std::optional<std::size_t> minimum;
    double minimum_clearance = std::numeric_limits<double>::infinity();
    /// The first undecided pose, if any: nothing is known about the margin there.
    std::optional<std::size_t> first_undecided;
    Clearance_counters counters;

    /// True when every pose keeps the margin (clear or beyond the cap): no pose below it,
    /// none intersecting, none undecided.
    bool all_clear() const { return !first_below_margin && !first_undecided; }
};

} // namespace PCCD
