// PCCD/Kinetic/Deforming_motion.h -- Deforming_motion, the motion of a deforming point cloud
// (Deforming_point_cloud_object) whose points follow flightplans over a time interval, in the form
// time_of_contact() takes: its frames over s in [0, 1] and a bound of every point's speed, so that
// continuous collision detection finds the first contact of a deforming cloud with a rigid or
// another moving one (doc/algorithms.md "Continuous collision"; doc/manual/continuous.md
// "Deforming clouds").
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include <Eigen/Core>

#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Error.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Kinetic/flightplan_speed.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

/// The deformation of a Deforming_point_cloud_object whose point i follows flightplans[i], from
/// flightplan time t0 to t1, seen by time_of_contact() as a motion over s in [0, 1]: at s the object
/// is the frame at time t0 + s (t1 - t0) (advance_to()), in world coordinates (pose(s) is the
/// identity), and no point moves faster than max_point_speed() = (t1 - t0) times the largest
/// max_speed() of the flightplans over [t0, t1]. Since a frame's domain radii follow the stretch
/// of its edges, the advancement's lower bound uses the reaches scaled by reach_scale().
///
/// It models RigidMotion and adds advance_object(s), which time_of_contact() calls before it looks
/// at the object at s, and reach_scale(). The motion holds the object and the flightplans by
/// reference: both must outlive it, and the object's frame changes during the query (afterwards it
/// is at the last time the query looked at; call advance_to() to set another). A frame that breaks the object's stretch
/// rule ends the query with its Deformation_error (under Stretch_action::fail).
///
/// \tparam K the object's kernel. \tparam F a model of PiecewiseCubicFlightplan.
/// Thread safety: advance_object() changes the object: one query at a time per object, and no other
/// use of the object meanwhile.
template <PointCloudKernel K, PiecewiseCubicFlightplan F>
class Deforming_motion {
public:
    /// \throws Invalid_input if t0 or t1 is not finite or t1 < t0, or flightplans.size() differs
    ///         from object.size().
    /// Complexity: O(N log pieces) for the speed bound.
    Deforming_motion(Deforming_point_cloud_object<K>& object, std::span<const F> flightplans, double t0, double t1)
        : m_object(&object), m_flightplans(flightplans), m_t0(t0), m_t1(t1)
    {
        if (!(std::isfinite(t0) && std::isfinite(t1) && t0 <= t1))
            throw Invalid_input(internal::concat("Deforming_motion: the interval [", t0, ", ", t1,
                                                 "] must be finite with t0 <= t1"));
        if (flightplans.size() != object.size())
            throw Invalid_input(internal::concat("Deforming_motion: ", flightplans.size(), " flightplans for ", object.size(),
                                                 " points (need one per point)"));
        double fastest = 0.0;
        for (const F& f : flightplans) fastest = std::max(fastest, max_speed(f, t0, t1));
        m_speed = fastest * (t1 - t0);
    }

    /// The identity: the flightplans are in world coordinates. \throws Invalid_input for s outside [0, 1].
    Rigid_transform_3<double> pose(double s) const
    {
        internal::check_motion_time(s, "Deforming_motion");
        return {};
    }
    /// The bound of every point's speed per unit of s (whatever c and r).
    double max_point_speed(const Eigen::Vector3d& c, double r) const
    {
        internal::check_local_point(c, r, "Deforming_motion");
        return m_speed;
    }
    /// How much the reaches of the object's current frame must be scaled to bound its reaches at
    /// every other frame of the motion: (1 + stretch_bound)^2. A frame's domain radii are the rest
    /// pose's times each point's mean edge stretch, which the stretch rule keeps within
    /// [1 / (1 + b), 1 + b]; so any frame's radius is at most the rest radius times 1 + b, and that
    /// is at most the current radius times (1 + b)^2. time_of_contact() scales the reaches of its
    /// lower bound by it, so that the bound's rate of change stays within max_point_speed().
    /// (Under Stretch_action::rebuild a frame may replace the rest pose, and this bound with it.)
    double reach_scale() const
    {
        const double high = 1.0 + m_object->options().stretch_bound;
        return high * high;
    }
    /// The flightplan time of s.
    double time(double s) const { return s >= 1.0 ? m_t1 : m_t0 + s * (m_t1 - m_t0); }
    /// Moves the object to the frame at time(s) (advance_to()).
    /// \throws Invalid_input for s outside [0, 1]; as Deforming_point_cloud_object::advance_to().
    /// Complexity: that of advance_to(), O(N k).
    void advance_object(double s) const
    {
        internal::check_motion_time(s, "Deforming_motion");
        m_object->advance_to(time(s), m_flightplans);
    }

private:
    Deforming_point_cloud_object<K>* m_object;
    std::span<const F> m_flightplans;
    double m_t0, m_t1;
    double m_speed = 0.0;
};

} // namespace PCCD
