// PCCD/concepts/RigidMotion.h -- concept of the motions continuous collision detection takes
// (doc/manual/continuous.md; proven by the archetype in test/concepts/archetypes_test.cpp). It
// includes only the pose type, Rigid_transform_3, of the ground stage.
#pragma once

#include <concepts>

#include <Eigen/Core>

#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// \concept RigidMotion
/// A rigid motion of an object over the time interval [0, 1]. For `const M& m`, a time `double t`
/// in [0, 1], a local point `Eigen::Vector3d c` and a radius `double r >= 0`:
/// - `m.pose(t)`: the pose (local to world) at time t, a Rigid_transform_3<double>; pose(0) and
///   pose(1) are the start and end poses;
/// - `m.max_point_speed(c, r)`: an upper bound, convertible to double, of |d/dt pose(t) x| over
///   t in [0, 1] and every local point x with |x - c| <= r. Conservative advancement relies on it:
///   no point of the ball moves farther than max_point_speed(c, r) * |t1 - t0| between t0 and t1.
/// Both must be const and safe to call concurrently.
///
/// Models: PCCD::Linear_motion (translation of a centre with the rotation interpolated about it)
/// and PCCD::Screw_motion (constant rotation about and translation along one axis).
template <class M>
concept RigidMotion = requires(const M& m, double t, const Eigen::Vector3d& c, double r) {
    { m.pose(t) } -> std::convertible_to<Rigid_transform_3<double>>;
    { m.max_point_speed(c, r) } -> std::convertible_to<double>;
};

} // namespace PCCD
