// PCCD/Continuous/Rigid_motion.h -- the two rigid motions of continuous collision detection over
// t in [0, 1]: Linear_motion (a stated centre moves on a straight line while the rotation is
// interpolated about it by slerp) and Screw_motion (the constant screw taking the start pose to the
// end pose), each with the speed bound conservative advancement needs (doc/algorithms.md,
// "Continuous collision"; doc/manual/continuous.md).
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/RigidMotion.h>

namespace PCCD {

namespace internal {

inline void check_motion_time(double t, const char* motion)
{
    if (!(std::isfinite(t) && t >= 0.0 && t <= 1.0))
        throw Invalid_input(concat(motion, ": time ", t, " is outside [0, 1]"));
}

inline void check_local_point(const Eigen::Vector3d& c, double r, const char* motion)
{
    if (!c.allFinite() || !std::isfinite(r) || r < 0.0)
        throw Invalid_input(concat(motion, "::max_point_speed: the centre must be finite and the radius finite and >= 0 (got ",
                                   r, ")"));
}

} // namespace internal

/// A local point `centre` of the object moves on the straight segment from its start to its end
/// position (world frame) at constant speed, while the orientation turns from the start rotation to
/// the end rotation by spherical linear interpolation (constant angular speed about a fixed axis,
/// the shorter way): pose(t) x = R(t) (x - centre) + c(t), with c(t) = (1 - t) c0 + t c1 and
/// c_i = pose_i(centre). The centre defaults to the local origin; the object's centre of mass (or
/// its box centre) gives the tightest speed bound and the motion users mostly mean.
class Linear_motion {
public:
    /// \throws Invalid_input if `centre` is not finite. (The poses are rigid and finite by
    ///         construction of Rigid_transform_3.)
    Linear_motion(const Rigid_transform_3<double>& start, const Rigid_transform_3<double>& end,
                  const Eigen::Vector3d& centre = Eigen::Vector3d::Zero())
        : m_start(start), m_end(end), m_centre(centre), m_q0(start.rotation()), m_q1(end.rotation())
    {
        if (!centre.allFinite()) throw Invalid_input("Linear_motion: the centre is not finite");
        m_q0.normalize();
        m_q1.normalize();
        if (m_q0.dot(m_q1) < 0.0) m_q1.coeffs() = -m_q1.coeffs(); // the shorter way
        m_c0 = start.transform_point(centre);
        m_c1 = end.transform_point(centre);
        m_angle = m_q0.angularDistance(m_q1);
    }

    /// The pose at time t in [0, 1] (exactly the start and end poses at 0 and 1).
    /// \throws Invalid_input if t is outside [0, 1] or not finite.
    Rigid_transform_3<double> pose(double t) const
    {
        internal::check_motion_time(t, "Linear_motion");
        if (t == 0.0) return m_start;
        if (t == 1.0) return m_end;
        const Eigen::Matrix3d r = m_q0.slerp(t, m_q1).normalized().toRotationMatrix();
        const Eigen::Vector3d c = (1.0 - t) * m_c0 + t * m_c1;
        return Rigid_transform_3<double>(r, c - r * m_centre);
    }

    /// |c1 - c0| + angle * (|c - centre| + r): the speed of the centre plus the rotation's at the
    /// farthest point of the ball.
    double max_point_speed(const Eigen::Vector3d& c, double r) const
    {
        internal::check_local_point(c, r, "Linear_motion");
        return (m_c1 - m_c0).norm() + m_angle * ((c - m_centre).norm() + r);
    }

    const Rigid_transform_3<double>& start() const { return m_start; }
    const Rigid_transform_3<double>& end() const { return m_end; }
    const Eigen::Vector3d& centre() const { return m_centre; }
    /// The total rotation angle (radians, in [0, pi]).
    double angle() const { return m_angle; }

private:
    Rigid_transform_3<double> m_start, m_end;
    Eigen::Vector3d m_centre;
    Eigen::Quaterniond m_q0, m_q1;
    Eigen::Vector3d m_c0, m_c1;
    double m_angle = 0.0;
};

/// The screw motion from the start pose to the end pose: the relative motion M = end * start^-1 is
/// a rotation by angle theta about an axis (direction u through point q) followed by a translation d
/// along u (Chasles' theorem); pose(t) = M(t) * start, M(t) the rotation by t theta about the axis
/// and the translation t d. Every point turns about the one axis at constant speed: the motion of a
/// part on a rotating table, a nut on a bolt, a door on its hinge.
class Screw_motion {
public:
    Screw_motion(const Rigid_transform_3<double>& start, const Rigid_transform_3<double>& end)
        : m_start(start), m_end(end)
    {
        const Rigid_transform_3<double> m = end * start.inverse();
        const Eigen::AngleAxisd aa(Eigen::Quaterniond(m.rotation()).normalized());
        m_angle = aa.angle();
        const Eigen::Vector3d t = m.translation();
        if (m_angle < 1e-12) { // a pure translation
            m_angle = 0.0;
            m_axis = t.norm() > 0.0 ? Eigen::Vector3d(t.normalized()) : Eigen::Vector3d::UnitZ();
            m_point = Eigen::Vector3d::Zero();
            m_slide = t;
            return;
        }
        m_axis = aa.axis().normalized();
        m_slide = t.dot(m_axis) * m_axis;
        // The axis point q solves (I - R) q = t - d in the plane normal to the axis: with
        // t_perp = t - d, q = (t_perp + cot(theta / 2) u x t_perp) / 2.
        const Eigen::Vector3d t_perp = t - m_slide;
        m_point = 0.5 * (t_perp + m_axis.cross(t_perp) / std::tan(0.5 * m_angle));
    }

    /// The pose at time t in [0, 1] (the start and end poses at 0 and 1).
    /// \throws Invalid_input if t is outside [0, 1] or not finite.
    Rigid_transform_3<double> pose(double t) const
    {
        internal::check_motion_time(t, "Screw_motion");
        if (t == 0.0) return m_start;
        if (t == 1.0) return m_end;
        const Eigen::Matrix3d r = Eigen::AngleAxisd(t * m_angle, m_axis).toRotationMatrix();
        const Eigen::Vector3d shift = m_point - r * m_point + t * m_slide;
        return Rigid_transform_3<double>(r * m_start.rotation(), r * m_start.translation() + shift);
    }

    /// |d| + theta * (distance of the start position of c from the axis + r).
    double max_point_speed(const Eigen::Vector3d& c, double r) const
    {
        internal::check_local_point(c, r, "Screw_motion");
        const Eigen::Vector3d x = m_start.transform_point(c) - m_point;
        const double from_axis = (x - x.dot(m_axis) * m_axis).norm();
        return m_slide.norm() + m_angle * (from_axis + r);
    }

    const Rigid_transform_3<double>& start() const { return m_start; }
    const Rigid_transform_3<double>& end() const { return m_end; }
    /// The screw: angle (radians, [0, pi]), axis direction (unit), a point on the axis, translation along it.
    double angle() const { return m_angle; }
    const Eigen::Vector3d& axis() const { return m_axis; }
    const Eigen::Vector3d& axis_point() const { return m_point; }
    const Eigen::Vector3d& slide() const { return m_slide; }

private:
    Rigid_transform_3<double> m_start, m_end;
    double m_angle = 0.0;
    Eigen::Vector3d m_axis = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d m_point = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_slide = Eigen::Vector3d::Zero();
};

static_assert(RigidMotion<Linear_motion>);
static_assert(RigidMotion<Screw_motion>);

} // namespace PCCD
