// PCCD/Continuous/time_of_contact.h -- time_of_contact(), continuous collision detection between
// two point-cloud objects moving rigidly over t in [0, 1]: conservative advancement on a certified
// lower bound of the surfaces' distance (point pairs minus their reaches,
// Proximity/internal/surface_gap.h), contact checks at short sub-steps where that bound cannot
// exclude contact, and bisection of the first contact time (doc/algorithms.md, "Continuous
// collision"; doc/manual/continuous.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <PCCD/Continuous/Contact_time_options.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Proximity/internal/surface_gap.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/concepts/RigidMotion.h>

namespace PCCD {

namespace internal {

/// One contact check of time_of_contact: whether the surfaces are within the tolerance at a time,
/// with a contact point and normal when they are.
struct Contact_check {
    bool contact = false;
    Eigen::Vector3d point = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

template <class A, class MA, class B, class MB>
class Contact_time_query {
public:
    Contact_time_query(const A& a, const MA& motion_a, const B& b, const MB& motion_b, const Contact_time_options& options,
                       Contact_time_counters& counters)
        : m_a(a), m_b(b), m_motion_a(motion_a), m_motion_b(motion_b), m_options(options), m_counters(counters)
    {
        const auto& ra = a.hierarchy().root().box;
        const auto& rb = b.hierarchy().root().box;
        m_speed = double(motion_a.max_point_speed(ra.center(), 0.5 * ra.diagonal().norm())) +
                  double(motion_b.max_point_speed(rb.center(), 0.5 * rb.diagonal().norm()));
        if (!(std::isfinite(m_speed) && m_speed >= 0.0))
            throw Invalid_input(concat("time_of_contact: the motions' speed bound ", m_speed, " is not finite"));
        m_reach_a = internal::surface_reach(a.hierarchy(), double(a.surface().support_radius()));
        m_reach_b = internal::surface_reach(b.hierarchy(), double(b.surface().support_radius()));
        // A motion that changes its object's reaches (Deforming_motion) scales them to bound every frame's.
        if constexpr (requires { motion_a.reach_scale(); }) m_reach_a.rule.scale *= double(motion_a.reach_scale());
        if constexpr (requires { motion_b.reach_scale(); }) m_reach_b.rule.scale *= double(motion_b.reach_scale());
        const double r_a = double(a.sampling_radius()), r_b = double(b.sampling_radius());
        const double r_min = std::min(r_a, r_b);
        m_accuracy = options.time_accuracy.value_or(0.25 * r_min);
        m_near = options.near_step * r_min;
    }

    /// Node pairs of an advancement step's walk (see lower_bound()).
    /// (Measured on the bunny: budgets of 16, 64 and 256 cost within 20 % of each other, an unlimited
    /// walk 20 % more.)
    static constexpr std::size_t walk_budget = 64;

    double speed() const { return m_speed; }
    double accuracy() const { return m_accuracy; }
    double near() const { return m_near; }

    /// A lower bound of the distance between the surfaces at time t, certified whatever the fit:
    /// every point of a surface lies within the reach of its nearest cloud point (the domain radius,
    /// capped by the support radius; surface_gap.h), so the smallest |p - q| - reach(p) - reach(q)
    /// over the point pairs bounds the distance from below. A value >= `limit` when nothing is closer
    /// than `limit`. The walk enters walk_budget node pairs at most: far from contact a rough bound
    /// is enough (the pairs left count with their node bounds, and the advancement then steps a
    /// little shorter). It stops at the first point pair whose gap is below `band` (the caller's
    /// near band: that pair alone decides) and returns that gap.
    double lower_bound(double t, double limit, double band)
    {
        ++m_counters.advancement_steps;
        frame(t);
        const Rigid_transform_3<double> a_to_b = m_motion_b.pose(t).inverse() * m_motion_a.pose(t);
        const std::size_t budget = std::min<std::size_t>(m_options.distance.max_node_pairs.value_or(walk_budget), walk_budget);
        const internal::Surface_gap_bound g =
            internal::surface_gap_lower_bound(m_a.hierarchy(), m_b.hierarchy(), a_to_b, m_reach_a, m_reach_b, limit, band, budget);
        m_counters.node_pairs += g.node_pairs;
        return g.lower;
    }

    /// Brings the objects of motions that change them (Deforming_motion: advance_object()) to time
    /// t, once per time.
    void frame(double t)
    {
        if (m_frame_at == t) return;
        m_frame_at.reset(); // a frame that throws leaves no claim
        if constexpr (requires { m_motion_a.advance_object(t); }) m_motion_a.advance_object(t);
        if constexpr (requires { m_motion_b.advance_object(t); }) m_motion_b.advance_object(t);
        m_frame_at = t;
    }

    /// Whether the near band holds at t without a new bound: the last bound, L at time t_b, put
    /// t_b in the band, and L + v (t - t_b) is still below tolerance + near_step r_min (a bound rises
    /// no faster than the objects move). Staying in the band is always safe, since it only checks
    /// more often; what this saves is the walks of a deep band, where the bound lies several
    /// near-band steps below its edge.
    bool still_in_band(double t) const
    {
        return m_band_time && m_band_lower + m_speed * (t - *m_band_time) < m_options.tolerance + m_near;
    }
    /// Records the bound that put time t in the near band (see still_in_band()).
    void entered_band(double t, double lower)
    {
        m_band_time = t;
        m_band_lower = lower;
    }
    /// The advancement left the near band.
    void left_band() { m_band_time.reset(); }

    /// Whether the surfaces are within the tolerance at time t.
    Contact_check check(double t)
    {
        frame(t);
        const Rigid_transform_3<double> pa = m_motion_a.pose(t), pb = m_motion_b.pose(t);
        Contact_check c;
        if (m_options.tolerance == 0.0) {
            const Intersection_result r = do_intersect(m_a, pa, m_b, pb, m_options.distance.intersection);
            m_counters.f_evaluations += r.counters.f_evaluations;
            // An undecided answer (a budget of the intersection options ran out) counts as contact:
            // a missed contact is the worse error.
            c.contact = r.status != Intersection_status::separate;
            if (!r.points.empty()) {
                c.point = r.points.front().position;
                c.normal = crossing_normal(pa, pb, c.point);
            }
            return c;
        }
        const Clearance_result r = within_distance(m_a, pa, m_b, pb, m_options.tolerance, m_options.distance);
        m_counters.f_evaluations += r.counters.f_evaluations;
        m_counters.node_pairs += r.counters.node_pairs;
        c.contact = r.within || r.status == Intersection_status::undecided;
        if (r.within && r.status == Intersection_status::separate) {
            c.point = 0.5 * (r.point_a + r.point_b);
            const Eigen::Vector3d d = r.point_b - r.point_a;
            c.normal = d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : crossing_normal(pa, pb, c.point);
        } else if (r.within) {
            const Intersection_result i = do_intersect(m_a, pa, m_b, pb, m_options.distance.intersection);
            if (!i.points.empty()) {
                c.point = i.points.front().position;
                c.normal = crossing_normal(pa, pb, c.point);
            }
        }
        return c;
    }

private:
    /// n_A - n_B at a crossing point, normalized: the direction in which B must move to leave A.
    Eigen::Vector3d crossing_normal(const Rigid_transform_3<double>& pa, const Rigid_transform_3<double>& pb,
                                    const Eigen::Vector3d& x) const
    {
        const Surface_evaluation ea = m_a.surface().evaluate(pa.inverse().transform_point(x));
        const Surface_evaluation eb = m_b.surface().evaluate(pb.inverse().transform_point(x));
        if (ea.defined() && eb.defined()) {
            const Eigen::Vector3d n = pa.rotation() * ea.normal - pb.rotation() * eb.normal;
            if (n.norm() > 0.0) return n.normalized();
        }
        return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    }

    const A& m_a;
    const B& m_b;
    const MA& m_motion_a;
    const MB& m_motion_b;
    const Contact_time_options& m_options;
    Contact_time_counters& m_counters;
    double m_speed = 0.0;
    internal::Surface_reach m_reach_a, m_reach_b;
    std::optional<double> m_band_time; // the time of the bound that put the walk in the near band
    double m_band_lower = 0.0;         // and that bound
    std::optional<double> m_frame_at;  // the time of the objects' frames (motions that change them)
    double m_accuracy = 0.0;
    double m_near = 0.0;
};

} // namespace internal

/// The first time in [0, 1] at which the implicit surfaces of `a` moving by `motion_a` and `b`
/// moving by `motion_b` come within options.tolerance of each other (intersect, for the default
/// tolerance 0).
///
/// Method: conservative advancement. At time t a walk of the two hierarchies bounds the surfaces'
/// distance from below by L (the smallest |p - q| - reach(p) - reach(q) over the point pairs, where
/// a point's reach is its domain radius capped by the support radius: every zero of f lies within
/// the reach of its nearest cloud point, so L holds whatever the fit); no point moves faster than v
/// (the motions' max_point_speed over the clouds' bounding balls, both objects summed), so the
/// surfaces stay farther apart than the tolerance until t + (L - tolerance) / v, and t advances by
/// that much. Where L - tolerance is below near_step r_min (the bound cannot exclude contact), the
/// surfaces are checked for contact (do_intersect, or within_distance for a positive tolerance) at
/// sub-steps of near_step r_min / v until a check finds contact or L rises again (the walk is not
/// repeated while L + v (t - t_L) stays in the band). A contact found is bracketed by bisection
/// until no point moves farther than time_accuracy within the bracket.
///
/// Guarantee: (1) `no_contact` means the surfaces stayed farther apart than the tolerance over
/// [0, 1] except possibly for contacts that begin and end between two sub-steps of the near band,
/// which move no point farther than near_step r_min relative to the other object: such a contact
/// is shallower than that (half a sampling radius by default); (2) `contact` at t means a check
/// found the surfaces within the tolerance at t, and no check and no bound found contact before
/// t_low; the bracket satisfies v (t_high - t_low) <= time_accuracy. The time is that of the first
/// contact found: with the exception of (1), the first contact.
///
/// \tparam A, B models of ProximityObject (Point_cloud_object<K>).
/// \tparam MA, MB models of RigidMotion (Linear_motion, Screw_motion, or Deforming_motion for a
///         Deforming_point_cloud_object following flightplans: then each time is looked at on the
///         frame advance_object() makes, and the reaches are scaled by reach_scale()).
/// \throws Invalid_input for invalid options (the message names the field), or motions whose speed
///         bound is not finite.
/// Thread safety: the objects and motions are only read; any number of calls may run concurrently.
/// The result depends only on the arguments (seeds included) unless a time budget is set in
/// options.distance.
/// Complexity: one hierarchy walk per advancement step (O(height) node pairs for well separated
/// objects; the steps grow like log(1 / gap) on approach), one contact check per near sub-step and
/// per bisection step (about log2(near_step r_min / time_accuracy)); 64 node pairs at most per
/// advancement walk.
template <ProximityObject A, RigidMotion MA, ProximityObject B, RigidMotion MB>
Contact_time_result time_of_contact(const A& a, const MA& motion_a, const B& b, const MB& motion_b,
                                    const Contact_time_options& options = {})
{
    internal::check_options(options, "time_of_contact");
    Contact_time_result r;
    internal::Contact_time_query<A, MA, B, MB> q(a, motion_a, b, motion_b, options, r.counters);
    const double v = q.speed();
    const double tol = options.tolerance;
    std::size_t steps = 0;
    double t = 0.0;
    double clear = -1.0; // the last time known free of contact (-1: none yet)
    std::optional<internal::Contact_check> found;
    while (true) {
        if (++steps > options.max_steps) {
            r.status = Contact_time_status::undecided;
            r.t_low = std::max(0.0, clear);
            return r;
        }
        if (!q.still_in_band(t)) {
            const double remaining = v * (1.0 - t); // the farthest any point can still move relative to the other object
            const double lower = q.lower_bound(t, tol + remaining + q.near(), tol + q.near());
            if (lower > tol + remaining) { // nothing can come within the tolerance before t = 1
                r.status = Contact_time_status::no_contact;
                r.t_low = 1.0;
                return r;
            }
            if (lower - tol >= q.near()) { // advance: certified free of contact until t + (lower - tol) / v
                q.left_band();
                clear = t;
                t = std::min(1.0, t + (lower - tol) / v);
                continue;
            }
            q.entered_band(t, lower);
        }
        // The near band: check this time, then a sub-step of near_step r_min of motion.
        ++r.counters.near_checks;
        internal::Contact_check c = q.check(t);
        if (c.contact) {
            found = c;
            break;
        }
        clear = t;
        if (t >= 1.0 || v == 0.0) {
            r.status = Contact_time_status::no_contact;
            r.t_low = 1.0;
            return r;
        }
        t = std::min(1.0, t + q.near() / v);
    }
    // Contact at t; bisect between the last clear time and t.
    double low = clear < 0.0 ? t : clear;
    double high = t;
    while (v * (high - low) > q.accuracy()) {
        if (++steps > options.max_steps) break;
        ++r.counters.bisection_steps;
        const double mid = 0.5 * (low + high);
        internal::Contact_check c = q.check(mid);
        if (c.contact) {
            high = mid;
            found = c;
        } else {
            low = mid;
        }
    }
    r.status = Contact_time_status::contact;
    r.t = r.t_high = high;
    r.t_low = low;
    r.point = found->point;
    r.normal = found->normal;
    return r;
}

} // namespace PCCD
