// PCCD/Intersection/ray_intersection.h -- the first point where a ray meets the implicit surface of
// one posed point-cloud object (doc/algorithms.md "Ray queries"; doc/manual/intersection.md "Ray
// queries"): the ray is taken into the object's frame, the point cloud hierarchy is walked
// best-first for the stretches of the ray within the reach of some point (the only places where f
// can be defined, internal/ray_cover.h), f is marched along those stretches in increasing t with
// steps no longer than a fraction of the sampling radius (shorter where f and its gradient predict
// the surface), and the first crossing of f = 0 is narrowed down to |f| <= epsilon by a safeguarded
// regula falsi. The narrow phase of a ray cast against point clouds.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Intersection/Ray_hit.h>
#include <PCCD/Intersection/Ray_options.h>
#include <PCCD/Intersection/internal/ray_cover.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/internal/finite.h>

namespace PCCD {
namespace internal {

/// One evaluation of f on the ray.
struct Ray_sample {
    double t = 0.0;
    Surface_evaluation e;
    bool defined() const { return e.defined(); }
    bool inside() const { return e.value < 0.0; }
};

/// The march of ray_intersection() over one object (local frame): evaluations, the budget, and the
/// answer once found.
template <class O>
class Ray_march {
public:
    /// `step` the march's longest step h, `max_gap` the widest stretch without f bridged by a
    /// crossing (the kernel's support radius).
    Ray_march(const O& object, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double epsilon,
              double step, double max_gap, std::optional<std::size_t> budget, Ray_counters& counters)
        : m_object(object), m_origin(origin), m_direction(direction), m_epsilon(epsilon), m_step(step),
          m_max_gap(max_gap), m_budget(budget), m_counters(counters)
    {
    }

    /// f at t; nullopt when the budget is spent.
    std::optional<Ray_sample> sample(double t)
    {
        if (m_budget && m_counters.f_evaluations >= *m_budget) return std::nullopt;
        ++m_counters.f_evaluations;
        return Ray_sample{t, m_object.surface().evaluate(Eigen::Vector3d(m_origin + t * m_direction))};
    }
    bool on_surface(const Ray_sample& s) const { return s.defined() && std::abs(s.e.value) <= m_epsilon; }

    enum class Outcome : unsigned char { found, approximate, none, budget };

    /// Narrows the sign change between a and b (a.t < b.t, both defined, |f| > epsilon, opposite
    /// signs; f may be undefined between them) to a point with |f| <= epsilon (`found`): regula falsi
    /// with the Illinois rule, a bisection whenever a step did not halve the bracket; where f is
    /// undefined at a step, the middles of the two halves are tried instead. When neither gets
    /// there -- f undefined across the rest of the bracket (a pocket of the domain, where a noisy
    /// cluster of points has a small domain radius) or the bracket shrunk to 0.1 epsilon (a jump of
    /// f, where its neighbourhood changes) -- the sign change still counts as a crossing,
    /// `approximate`, if it is one surface seen from both sides: the bracket at most `max_gap` (the
    /// kernel's support radius) wide, the normals at its ends on the same side (n_a . n_b > 0),
    /// and |f_a| + |f_b| at most the bracket's width plus two steps 2h (f changes no faster than a
    /// distance, or jumps by less than 2h, the sampling radius at the default step, as it does
    /// near sharp edges); `found` is then the secant point, with the normals' blend and f NaN.
    /// Otherwise `none`: not a crossing.
    Outcome refine(Ray_sample a, Ray_sample b, Ray_sample& found)
    {
        double fa = a.e.value, fb = b.e.value; // Illinois: scaled copies, signs kept
        int kept = 0;                          // which end the last step kept (-1 a, +1 b)
        bool bisect = false;
        const double smallest = 0.1 * m_epsilon; // f changes by > 2 epsilon over it: a jump
        for (int step = 0; step < 200; ++step) {
            const double width = b.t - a.t;
            if (!(width > smallest)) break;
            double t = bisect ? a.t + 0.5 * width : a.t + width * (fa / (fa - fb));
            t = std::clamp(t, a.t + 1e-3 * width, b.t - 1e-3 * width);
            std::optional<Ray_sample> m = sample(t);
            if (!m) return Outcome::budget;
            ++m_counters.refinement_steps;
            for (const double other : {0.5 * (a.t + t), 0.5 * (t + b.t)}) {
                if (m->defined()) break;
                m = sample(other);
                if (!m) return Outcome::budget;
                ++m_counters.refinement_steps;
            }
            if (!m->defined()) break;
            if (on_surface(*m)) {
                found = *m;
                return Outcome::found;
            }
            if (m->inside() == a.inside()) {
                a = *m, fa = m->e.value;
                if (kept == -1) fb *= 0.5;
                kept = -1;
            } else {
                b = *m, fb = m->e.value;
                if (kept == +1) fa *= 0.5;
                kept = +1;
            }
            bisect = !(b.t - a.t <= 0.5 * width);
        }
        const double width = b.t - a.t, fa_abs = std::abs(a.e.value), fb_abs = std::abs(b.e.value);
        if (width <= m_max_gap && a.e.normal.dot(b.e.normal) > 0.0 && fa_abs + fb_abs <= width + 2.0 * m_step) {
            const double wa = fb_abs / (fa_abs + fb_abs); // the weight of a: 1 at a zero at a
            found = wa >= 0.5 ? a : b;
            found.t = a.t + width * (1.0 - wa);
            found.e.normal = (wa * a.e.normal + (1.0 - wa) * b.e.normal).normalized();
            found.e.value = std::numeric_limits<double>::quiet_NaN();
            return Outcome::approximate;
        }
        ++m_counters.rejected_sign_changes;
        return Outcome::none;
    }

    /// Where f became defined at `b` already inside (no defined sample before it in this part of
    /// the ray), `a` the last sample before it (f undefined there). The ray came from outside if
    /// the point at `a` lies on the outer side of the surface's tangent plane at b's nearest cloud
    /// point p* ((x_a - p*) . n(b) > 0), or if f decreases clearly along the ray at b (n(b) . u <=
    /// -0.25: f becomes defined getting deeper, which a ray coming from deep inside, where f is
    /// undefined, cannot do: it meets the band where f is defined while f grows towards 0). If
    /// so, or if a zero can lie between a and b (|f(b)| below
    /// the gap, f being an approximate signed distance), [a, b] is bisected down to epsilon for a
    /// defined point outside (a crossing the step stepped over, then refined; `found` is the first
    /// point with |f| <= epsilon met). If there is none and the ray came from outside, it entered
    /// where f is undefined (at a sharp edge the fit may bulge out past its domain):
    /// `approximate` at the first defined point, located within epsilon.
    Outcome search_back(double a, Ray_sample b, Ray_sample& found)
    {
        const Eigen::Vector3d nearest = m_object.cloud().position(b.e.nearest).template cast<double>();
        const bool heading_in = (m_origin + a * m_direction - nearest).dot(b.e.normal) > 0.0 ||
                                b.e.normal.dot(m_direction) <= -0.25;
        if (!heading_in && !(std::abs(b.e.value) < b.t - a)) return Outcome::none;
        while (b.t - a > m_epsilon) {
            const std::optional<Ray_sample> m = sample(a + 0.5 * (b.t - a));
            if (!m) return Outcome::budget;
            ++m_counters.refinement_steps;
            if (!m->defined()) {
                a = m->t;
            } else if (on_surface(*m)) {
                found = *m;
                return Outcome::found;
            } else if (m->inside()) {
                b = *m;
            } else {
                return refine(*m, b, found);
            }
        }
        if (!heading_in) return Outcome::none;
        found = b;
        found.e.value = std::numeric_limits<double>::quiet_NaN();
        return Outcome::approximate;
    }

    /// Where f was defined at `a`, approaching 0 (f n(a) . u < 0) with its zero predicted by
    /// a + |f(a)| / |n(a) . u| before `b`, and is undefined at b: the domain may end at the surface
    /// there (a noisy cluster of points has small domain radii). [a, b] is bisected down to epsilon
    /// for a crossing (refined as above); if there is none, the last defined point lies within half
    /// a step of the surface (|f| <= h / 2) and the zero predicted from it lies within a step of
    /// where f stops being defined, the ray crosses the surface there: `approximate` at that
    /// predicted zero, with that point's normal.
    Outcome search_forward(Ray_sample a, double b, Ray_sample& found)
    {
        while (b - a.t > m_epsilon) {
            const std::optional<Ray_sample> m = sample(a.t + 0.5 * (b - a.t));
            if (!m) return Outcome::budget;
            ++m_counters.refinement_steps;
            if (!m->defined()) {
                b = m->t;
            } else if (on_surface(*m)) {
                found = *m;
                return Outcome::found;
            } else if (m->inside() != a.inside()) {
                return refine(a, *m, found);
            } else {
                a = *m;
            }
        }
        const double slope = a.e.normal.dot(m_direction);
        if (!((a.e.value > 0.0) != (slope > 0.0) && std::abs(slope) > 1e-3)) return Outcome::none;
        const double zero = a.t - a.e.value / slope;
        if (!(std::abs(a.e.value) <= 0.5 * m_step && zero <= b + m_step)) return Outcome::none;
        found = a;
        found.t = std::max(a.t, zero);
        found.e.value = std::numeric_limits<double>::quiet_NaN();
        return Outcome::approximate;
    }

private:
    const O& m_object;
    Eigen::Vector3d m_origin;
    Eigen::Vector3d m_direction;
    double m_epsilon;
    double m_step;
    double m_max_gap;
    std::optional<std::size_t> m_budget;
    Ray_counters& m_counters;
};

inline void check_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_max)
{
    if (!all_finite(origin))
        throw Invalid_input(concat("ray_intersection: the ray origin (", origin.x(), ", ", origin.y(), ", ", origin.z(),
                                   ") is not finite"));
    if (!all_finite(direction))
        throw Invalid_input(concat("ray_intersection: the ray direction (", direction.x(), ", ", direction.y(), ", ",
                                   direction.z(), ") is not finite"));
    if (direction.isZero(0.0)) throw Invalid_input("ray_intersection: the ray direction is zero");
    if (std::isnan(t_max) || t_max < 0.0)
        throw Invalid_input(concat("ray_intersection: t_max ", t_max, " must be >= 0 (+infinity for an unbounded ray)"));
}

} // namespace internal

/// The first point where the ray origin + t * u, u = direction / |direction| (so t is a distance),
/// t in [0, t_max], meets the implicit surface f = 0 of `object` placed in the world by `pose`
/// (local to world). World frame in and out.
///
/// A hit is a point of the ray where f is defined and |f| <= epsilon (Ray_options::epsilon, default
/// 0.05 r): the first sample of the march that lies there, or the point a sign change of f between
/// two consecutive samples is narrowed down to. f is marched in increasing t over the parts of the
/// ray within some point's reach (its domain radius, capped by the kernel's support: elsewhere f is
/// undefined), with steps of at most h = step_fraction * r (default 0.5 r, r the sampling radius),
/// shorter where f and its normal predict the surface sooner. Guaranteed: a crossing of f = 0 is
/// found unless another crossing lies less than h from it along the ray (a wall thinner than h, a
/// graze whose chord through the object is shorter than h); the first one found is the first
/// one, up to that resolution. f is discontinuous where its neighbourhood changes and undefined in
/// pockets of its domain (small domain radii around noisy clusters of points; at sharp edges the
/// fit bulges past its domain): a crossing that ends at such a jump or pocket is still a hit,
/// marked Ray_hit::approximate, when the two sides are one surface (Ray_march::refine,
/// search_back, search_forward say when); a sign change across a hole of the cloud wider than the
/// kernel's support, or between inconsistent sides, is no hit (Ray_counters::rejected_sign_changes
/// counts them) and the march goes on.
///
/// Surface semantics: a ray starting inside the object (f < 0 at the origin) hits where it leaves
/// it (Ray_hit::entering false); a ray starting on the surface (|f| <= epsilon at the origin) hits
/// at t = 0. The normal is the surface's outward unit normal at the hit (world frame).
///
/// \tparam O a model of CollisionObject (Point_cloud_object, Deforming_point_cloud_object).
/// \throws Invalid_input if the origin or direction is not finite, the direction is zero, t_max is
///         NaN or negative, or an option is out of range (Ray_options).
/// Complexity: O(log N) nodes to reach the first stretch near the surface, then a few evaluations
/// of f per stretch crossed (each a kd-tree query and the neighbours' sums): about 5 for a ray
/// hitting the surface, up to 2 D / h + 1 for a ray passing a domain of radius D; measured 10-20 us
/// per hitting ray on 30,000 points (doc/manual/intersection.md "Ray queries").
/// Thread safety: reads the object only; any number of queries may run concurrently.
template <CollisionObject O>
Ray_hit ray_intersection(const O& object, const Rigid_transform_3<double>& pose, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& direction, double t_max = std::numeric_limits<double>::infinity(),
                         const Ray_options& options = {})
{
    internal::check_ray(origin, direction, t_max);
    internal::check_ray_options(options);
    const double r = double(object.sampling_radius());
    if (!(std::isfinite(r) && r > 0.0))
        throw Invalid_input(internal::concat("ray_intersection: the object's sampling radius ", r,
                                             " must be finite and > 0"));
    const double epsilon = options.epsilon ? *options.epsilon : 0.05 * r;
    const double h = options.step_fraction * r;
    // Scaled before the norm: a direction of huge or tiny entries normalizes without overflow.
    const Eigen::Vector3d scaled = direction / direction.cwiseAbs().maxCoeff();
    const Eigen::Vector3d u = scaled / scaled.norm();

    Ray_hit result;
    const Rigid_transform_3<double> from_world = pose.inverse();
    const Eigen::Vector3d o = from_world.transform_point(origin);
    const Eigen::Vector3d d = from_world.transform_vector(u);
    const double support = double(object.surface().support_radius());
    internal::Ray_march<O> march(object, o, d, epsilon, h, support, options.max_f_evaluations, result.counters);
    internal::Ray_reach_cover cover(object.hierarchy(), support, o, d, t_max, result.counters);
    using Outcome = typename internal::Ray_march<O>::Outcome;

    const auto answer = [&](const internal::Ray_sample& s, bool entering, bool approximate) {
        result.status = Ray_status::hit;
        result.hit = true;
        result.t = s.t;
        result.point = origin + s.t * u;
        result.normal = pose.transform_vector(s.e.normal).normalized();
        result.f = s.e.value;
        result.entering = entering;
        result.approximate = approximate;
        result.nearest_point = s.e.nearest;
        return result;
    };
    const auto undecided = [&] {
        result.status = Ray_status::undecided;
        return result;
    };

    double t = 0.0;
    if (!cover.seek(t)) return result;
    // The last sample of the current stretch, and its last sample where f is defined.
    std::optional<internal::Ray_sample> previous, last_defined;
    for (;;) {
        const std::optional<internal::Ray_sample> current = march.sample(t);
        if (!current) return undecided();
        if (march.on_surface(*current)) // entering: from the side of the last defined sample, else by the normal
            return answer(*current, last_defined ? !last_defined->inside() : current->e.normal.dot(d) < 0.0, false);
        if (current->defined()) {
            internal::Ray_sample found;
            Outcome outcome = Outcome::none;
            if (last_defined && last_defined->inside() != current->inside())
                outcome = march.refine(*last_defined, *current, found);
            else if (!last_defined && previous && current->inside())
                outcome = march.search_back(previous->t, *current, found);
            if (outcome == Outcome::budget) return undecided();
            if (outcome == Outcome::found || outcome == Outcome::approximate)
                return answer(found, current->inside(), outcome == Outcome::approximate);
            last_defined = current;
        } else if (previous && previous->defined()) {
            // f stops being defined right after a sample that predicts the surface before here
            const double f = previous->e.value, slope = previous->e.normal.dot(d);
            if ((f > 0.0) != (slope > 0.0) && std::abs(slope) > 1e-3 && previous->t - f / slope <= t) {
                internal::Ray_sample found;
                const Outcome outcome = march.search_forward(*previous, t, found);
                if (outcome == Outcome::budget) return undecided();
                if (outcome == Outcome::found || outcome == Outcome::approximate)
                    return answer(found, !previous->inside(), outcome == Outcome::approximate);
            }
        }
        // The next step: h, or shorter where f and its slope along the ray predict the surface.
        double step = h;
        if (current->defined()) {
            const double f = current->e.value, slope = current->e.normal.dot(d);
            if ((f > 0.0) != (slope > 0.0) && std::abs(slope) > 1e-3) {
                const double predicted = -f / slope + 0.5 * epsilon / std::abs(slope);
                step = std::clamp(predicted, std::min(h, 0.5 * epsilon), h);
            }
        }
        const double end = cover.stretch_end(t, t + step);
        double next = std::min(t + step, end);
        if (!(next > t) && end > t) next = end; // t + step rounded to t
        if (next > t) {
            previous = current;
            t = next;
            continue;
        }
        // The stretch ends here (or the step vanished against t): on to the next one.
        next = cover.next_start();
        if (std::isinf(next)) return result; // no ball left before t_max
        // A gap narrower than the kernel's support (a pocket between reach balls, near a noisy spot)
        // does not separate the samples on its two sides; a wider one (a hole of the cloud) does.
        if (next - t > support) previous.reset(), last_defined.reset();
        t = std::max(next, std::nextafter(t, std::numeric_limits<double>::infinity()));
        if (!cover.seek(t)) return result;
    }
}

} // namespace PCCD
