// PCCD/Kinetic/Linear_flightplan.h -- the simplest Flightplan model (doc/manual/kinetic.md,
// "Flightplans"): constant velocity, p(t) = p0 + v (t - t0) for all t. Two linear flightplans cross
// at most once per axis, which is the setting of the O(n log n) event bound.
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/Kinetic/internal/Piecewise_cubic.h>
#include <PCCD/Kinetic/next_crossing.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// Motion at constant velocity: p(t) = p0 + v (t - t0), for every t.
/// A model of Flightplan. Immutable; every member function is const and thread-safe.
class Linear_flightplan {
public:
    /// A vertex at rest at the origin.
    Linear_flightplan() = default;

    /// \param start position p0 at time `t0`; \param velocity v (units per time unit).
    /// \throws Invalid_input if a coordinate, a velocity component or t0 is not finite.
    Linear_flightplan(const Eigen::Vector3d& start, const Eigen::Vector3d& velocity, double t0 = 0.0)
        : m_start(start), m_velocity(velocity), m_t0(t0)
    {
        if (!internal::all_finite(start) || !internal::all_finite(velocity) || !std::isfinite(t0))
            throw Invalid_input(internal::concat("Linear_flightplan: non-finite start (", start.transpose(),
                                                 "), velocity (", velocity.transpose(), ") or t0 ", t0));
    }

    /// Coordinate `axis` (0, 1, 2) at time t. O(1).
    double coordinate(int axis, double t) const
    {
        return m_velocity[axis] * (t - m_t0) + m_start[axis];
    }
    /// Position at time t. O(1).
    Eigen::Vector3d position(double t) const { return {coordinate(0, t), coordinate(1, t), coordinate(2, t)}; }

    /// inf{ s > t : coordinate(axis, s) < other.coordinate(axis, s) } or +infinity. O(1).
    double next_crossing(const Linear_flightplan& other, int axis, double t) const
    {
        return PCCD::next_crossing(*this, other, axis, t);
    }

    const Eigen::Vector3d& start() const { return m_start; }
    const Eigen::Vector3d& velocity() const { return m_velocity; }
    double t0() const { return m_t0; }

    /// \cond PIECES -- the piece interface read by PCCD::next_crossing: one piece, all times.
    std::size_t piece_count() const { return 1; }
    std::size_t piece_at(double) const { return 0; }
    double piece_begin(std::size_t) const { return -internal::infinity; }
    double piece_end(std::size_t) const { return internal::infinity; }
    double piece_origin(std::size_t) const { return m_t0; }
    Cubic piece_cubic(std::size_t, int axis) const
    {
        return Cubic{{m_start[axis], m_velocity[axis], 0.0, 0.0}};
    }
    /// \endcond

private:
    Eigen::Vector3d m_start = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_velocity = Eigen::Vector3d::Zero();
    double m_t0 = 0.0;
};

} // namespace PCCD
