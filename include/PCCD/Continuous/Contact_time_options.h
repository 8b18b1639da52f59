// PCCD/Continuous/Contact_time_options.h -- the options and the result of time_of_contact()
// (doc/manual/continuous.md, "Options" and "Result"): the distance that counts as contact, the
// accuracy of the time, the step of the near band, the budget; status, time, bracket, contact
// point and normal, counters.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Proximity/Distance_options.h>

namespace PCCD {

/// Options of time_of_contact(). Every field has a documented default.
struct Contact_time_options {
    /// Surfaces closer than this (world units) are in contact. Default 0: contact means the
    /// implicit surfaces intersect (do_intersect()). Finite and >= 0.
    double tolerance = 0.0;
    /// The bracket [t_low, t_high] of a contact is narrowed by bisection until no point moves
    /// farther than this between t_low and t_high (world units). Unset (default): 0.25 times the
    /// smaller sampling radius of the two objects (about half a mean spacing on area-sampled
    /// clouds). When set: finite and > 0.
    std::optional<double> time_accuracy = std::nullopt;
    /// Where the certified lower bound cannot exclude contact (the surfaces are within their sampling
    /// radii of each other), the motion is checked at sub-steps across which no point moves farther
    /// than near_step times the smaller sampling radius. Default 0.5; in (0, 4].
    double near_step = 0.5;
    /// Budget on the steps (conservative advancement steps, near-band checks and bisection steps
    /// together); once spent the answer is undecided with the bracket so far. Default 100000; >= 1.
    std::size_t max_steps = 100000;
    /// The options of the distance walks and the contact checks (their intersection options decide
    /// contact; seed included).
    Distance_options distance = {};
};

/// What time_of_contact() found.
enum class Contact_time_status : std::uint8_t {
    /// The surfaces come within the tolerance at time t (first contact found).
    contact = 0,
    /// They stay farther apart than the tolerance over [0, 1] (see the guarantee of time_of_contact).
    no_contact = 1,
    /// The step budget ran out first: no contact before t_low; after it, unknown.
    undecided = 2,
};

/// Counters of one time_of_contact() call.
struct Contact_time_counters {
    /// Walks of the two hierarchies for a lower bound: one per advancement step, and one per
    /// near-band step that could have left the band (time_of_contact() skips the others).
    std::size_t advancement_steps = 0;
    /// Contact checks at sub-steps of the near band, and bisection steps.
    std::size_t near_checks = 0;
    std::size_t bisection_steps = 0;
    /// Node pairs of all walks and f evaluations of all checks.
    std::size_t node_pairs = 0;
    std::size_t f_evaluations = 0;

    friend bool operator==(const Contact_time_counters&, const Contact_time_counters&) = default;
};

/// The result of time_of_contact().
struct Contact_time_result {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    Contact_time_status status = Contact_time_status::undecided;
    /// contact: the first time found in contact (= t_high). NaN otherwise.
    double t = nan;
    /// The bracket. contact: t_low <= t = t_high; no check and no bound found contact before t_low
    /// (the last time known free of contact; t_low = t_high = 0 for a contact at the start), a
    /// check found contact at t_high. no_contact: t_low = 1, t_high NaN. undecided: t_low is how far
    /// the query got, t_high NaN.
    double t_low = 0.0;
    double t_high = nan;
    /// contact: a point of the contact (world frame, at time t) and the contact normal there (unit,
    /// the direction in which B must move to leave A). NaN otherwise.
    Eigen::Vector3d point = Eigen::Vector3d::Constant(nan);
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(nan);
    Contact_time_counters counters;

    explicit operator bool() const { return status == Contact_time_status::contact; }
};

namespace internal {

inline void check_options(const Contact_time_options& o, const char* function)
{
    if (!(std::isfinite(o.tolerance) && o.tolerance >= 0.0))
        throw Invalid_input(concat(function, ": tolerance ", o.tolerance, " must be finite and >= 0"));
    if (o.time_accuracy && !(std::isfinite(*o.time_accuracy) && *o.time_accuracy > 0.0))
        throw Invalid_input(concat(function, ": time_accuracy ", *o.time_accuracy,
                                   " must be finite and > 0 (leave it unset for the automatic value)"));
    if (!(std::isfinite(o.near_step) && o.near_step > 0.0 && o.near_step <= 4.0))
        throw Invalid_input(concat(function, ": near_step ", o.near_step, " must be in (0, 4]"));
    if (o.max_steps == 0) throw Invalid_input(concat(function, ": max_steps must be >= 1"));
    check_options(o.distance, function);
}

} // namespace internal
} // namespace PCCD
