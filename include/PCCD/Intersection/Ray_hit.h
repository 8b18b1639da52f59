// PCCD/Intersection/Ray_hit.h -- what ray_intersection() returns (doc/manual/intersection.md "Ray
// queries"): whether and where the ray meets the implicit surface, the surface normal there, and
// counters of the work done. Plain data.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include <Eigen/Core>

namespace PCCD {

/// The answer of a ray query.
enum class Ray_status : std::uint8_t {
    /// The ray meets the surface within [0, t_max]: Ray_hit::t, point and normal are set.
    hit = 0,
    /// The ray does not meet the surface within [0, t_max] (up to the step of the march,
    /// Ray_options::step_fraction).
    miss = 1,
    /// The budget (Ray_options::max_f_evaluations) ran out before a hit was found: the query
    /// cannot say "miss".
    undecided = 2,
};

/// "hit", "miss" or "undecided".
inline const char* to_string(Ray_status status)
{
    switch (status) {
    case Ray_status::hit: return "hit";
    case Ray_status::miss: return "miss";
    case Ray_status::undecided: return "undecided";
    }
    return "unknown";
}

/// The work of one ray query.
struct Ray_counters {
    /// Hierarchy nodes whose volume, grown by the node's reach, was tested against the ray.
    std::size_t node_visits = 0;
    /// Leaves whose points' reach balls were intersected with the ray.
    std::size_t leaf_visits = 0;
    /// Evaluations of f.
    std::size_t f_evaluations = 0;
    /// Evaluations spent narrowing a sign change down to |f| <= epsilon.
    std::size_t refinement_steps = 0;
    /// Sign changes of f that were not crossings of f = 0: f undefined between the two sides, or a
    /// jump of f (f is discontinuous where its neighbourhood changes) with |f| > epsilon on both
    /// sides of it. The march went on past them.
    std::size_t rejected_sign_changes = 0;
};

/// The first point where a ray meets an object's implicit surface f = 0. World frame throughout.
struct Ray_hit {
    Ray_status status = Ray_status::miss;
    /// status == Ray_status::hit.
    bool hit = false;
    /// The ray parameter of the hit: point = origin + t * direction / |direction| (the direction is
    /// normalized, so t is the distance from the origin), 0 <= t <= t_max; +infinity without a hit.
    double t = std::numeric_limits<double>::infinity();
    /// The hit point; NaN without a hit.
    Eigen::Vector3d point = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    /// The unit normal of the surface at the hit, oriented outwards (towards f > 0, the side the
    /// object's oriented normals point to), whichever side the ray came from; NaN without a hit.
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    /// f at the hit point, |f| <= epsilon; NaN without a hit and for an approximate one.
    double f = std::numeric_limits<double>::quiet_NaN();
    /// False for a hit where |f| <= epsilon (the usual case). True when the ray crosses the surface
    /// where f is undefined over a short stretch (less than the march's step: a pocket of the domain
    /// around a noisy cluster of points) or jumps across 0 by at most 4 epsilon: the hit is then the
    /// linear interpolation between the last point outside and the first inside (its error at most
    /// that stretch), the normal the blend of their normals, and f NaN.
    bool approximate = false;
    /// Which way the ray passes the surface: true from outside (f > 0) to inside (f < 0), false when
    /// it leaves the object (a ray starting inside it). For a hit at a point of the march that was
    /// already within epsilon of the surface: whether the ray heads into the object there
    /// (normal . direction < 0).
    bool entering = false;
    /// The cloud point nearest to the hit (an index of the object's cloud()), for per-point data
    /// such as colours or materials; Surface_evaluation::no_point's value without a hit.
    std::uint32_t nearest_point = std::numeric_limits<std::uint32_t>::max();
    Ray_counters counters;

    explicit operator bool() const { return hit; }
};

} // namespace PCCD
