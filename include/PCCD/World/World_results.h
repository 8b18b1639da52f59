// PCCD/World/World_results.h -- what the queries of a Collision_world report: World_pair (two
// instances whose surfaces touch), World_hit (an instance touched by a query object),
// World_proximity (an instance within a distance), World_ray_hit (an instance a ray meets)
// (doc/manual/world.md, "Queries").
#pragma once

#include <limits>

#include <Eigen/Core>

#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/Ray_hit.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/World/World_handle.h>

namespace PCCD {

/// Two instances of a world whose surfaces intersect (status intersecting) or might (status
/// undecided: a budget of World_options::intersection ran out; reported so that no contact is
/// missed). a.index < b.index.
struct World_pair {
    World_handle a;
    World_handle b;
    Intersection_status status = Intersection_status::intersecting;
    /// The intersection point do_intersect() found (world frame); NaN when undecided.
    Eigen::Vector3d point = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());

    friend bool operator==(const World_pair&, const World_pair&) = default;
};

/// An instance of the world that a query object touches (or might: status undecided).
struct World_hit {
    World_handle handle;
    Intersection_status status = Intersection_status::intersecting;
    /// The intersection point found (world frame); NaN when undecided.
    Eigen::Vector3d point = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// An instance of the world a ray meets: the first hit of the ray on its surface
/// (PCCD::ray_intersection), world frame.
struct World_ray_hit {
    World_handle handle;
    Ray_hit hit;
};

/// An instance of the world within the asked distance of a query object: the clearance answer of
/// PCCD::within_distance() (query object as a, the instance as b).
struct World_proximity {
    World_handle handle;
    Clearance_result clearance;
};

} // namespace PCCD
