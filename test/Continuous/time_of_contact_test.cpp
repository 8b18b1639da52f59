// Tests of time_of_contact() and the rigid motions (doc/manual/continuous.md) against analytic
// truth: spheres meeting along a line and along a screw (first contact time in closed form), a small
// sphere shot through a thin plate faster than discrete steps can see, near misses; and, on random
// motions of torus and sphere clouds (fixed seeds), against dense discrete do_intersect checks: no
// contact that the dense checks find comes before t_low, and no_contact only where they find none.
#include <PCCD/Continuous/Contact_time_options.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>

#include <catch2/catch.hpp>

#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using Object = PCCD::Point_cloud_object<>;

const Object& sphere(double radius)
{
    static const Object unit = [] {
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 41);
        return Object(pccd_test::columns(s.points));
    }();
    static const Object small = [] {
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 800, 0.0, 42);
        return Object(pccd_test::columns(0.2 * s.points));
    }();
    return radius == 1.0 ? unit : small;
}

const Object& plate()
{
    static const Object p = [] {
        const auto s = pccd_test::sample_shape(pccd_test::test_plane(), 3000, 0.0, 43);
        return Object(pccd_test::columns(s.points));
    }();
    return p;
}

const Object& torus()
{
    static const Object t = [] {
        const auto s = pccd_test::sample_shape(pccd_test::test_torus(), 3000, 0.0, 44);
        return Object(pccd_test::columns(s.points));
    }();
    return t;
}

Rigid_transform_3<double> at(const Eigen::Vector3d& t) { return Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), t); }

double spacing(const Object& a, const Object& b) { return std::max(a.cloud().mean_spacing(), b.cloud().mean_spacing()); }

} // namespace

TEST_CASE("Rigid motions: end poses, and no point moves faster than the speed bound", "[continuous]")
{
    PCCD::Random_engine engine(3);
    for (int k = 0; k < 50; ++k) {
        const Rigid_transform_3<double> p0(PCCD::testing::uniform_random_rotation(engine),
                                           Eigen::Vector3d(PCCD::standard_normal(engine), PCCD::standard_normal(engine), 0.0));
        const Rigid_transform_3<double> p1(PCCD::testing::uniform_random_rotation(engine),
                                           Eigen::Vector3d(3.0 * PCCD::standard_normal(engine), 1.0, 2.0));
        const PCCD::Linear_motion linear(p0, p1, Eigen::Vector3d(0.3, -0.2, 0.1));
        const PCCD::Screw_motion screw(p0, p1);
        for (const double t : {0.0, 1.0}) {
            const Rigid_transform_3<double> expected = t == 0.0 ? p0 : p1;
            CHECK((linear.pose(t).matrix() - expected.matrix()).norm() < 1e-12);
            CHECK((screw.pose(t).matrix() - expected.matrix()).norm() < 1e-12);
        }
        // The screw's end pose is reached by the screw itself too (t just below 1).
        CHECK((screw.pose(1.0 - 1e-9).matrix() - p1.matrix()).norm() < 1e-6);
        CHECK((linear.pose(1.0 - 1e-9).matrix() - p1.matrix()).norm() < 1e-6);
        // Finite differences of random points of a ball never beat the bound.
        const Eigen::Vector3d c(0.5, 0.5, -0.5);
        const double radius = 1.5;
        const double v_linear = linear.max_point_speed(c, radius), v_screw = screw.max_point_speed(c, radius);
        for (int j = 0; j < 20; ++j) {
            Eigen::Vector3d x(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
            x = c + radius * PCCD::uniform_01(engine) * x.normalized();
            const double t = PCCD::uniform_real(engine, 0.0, 0.999);
            const double h = 1e-3;
            CHECK((linear.pose(t + h).transform_point(x) - linear.pose(t).transform_point(x)).norm() / h <= v_linear * (1 + 1e-9));
            CHECK((screw.pose(t + h).transform_point(x) - screw.pose(t).transform_point(x)).norm() / h <= v_screw * (1 + 1e-9));
        }
    }
    // A screw about the z axis: every point keeps its distance from the axis and its height.
    const PCCD::Screw_motion turn(at(Eigen::Vector3d(3, 0, 0)),
                                  Rigid_transform_3<double>(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                                                            Eigen::Vector3d(0, 3, 0)));
    const Eigen::Vector3d mid = turn.pose(0.5).transform_point(Eigen::Vector3d::Zero());
    CHECK(std::abs(mid.head<2>().norm() - 3.0) < 1e-12);
    CHECK(std::abs(mid.z()) < 1e-12);
    CHECK(std::abs(std::atan2(mid.y(), mid.x()) - std::numbers::pi / 4) < 1e-12);
    // Bad times and centres.
    const PCCD::Linear_motion still(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()));
    CHECK_THROWS_AS(still.pose(-0.1), PCCD::Invalid_input);
    CHECK_THROWS_AS(still.pose(1.5), PCCD::Invalid_input);
    CHECK_THROWS_AS(still.pose(std::numeric_limits<double>::quiet_NaN()), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::Linear_motion(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()),
                                        Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0)),
                    PCCD::Invalid_input);
    CHECK_THROWS_AS(still.max_point_speed(Eigen::Vector3d::Zero(), -1.0), PCCD::Invalid_input);
}

TEST_CASE("time_of_contact: spheres meeting along a line and along a screw", "[continuous]")
{
    const Object& a = sphere(1.0);
    const double s = spacing(a, a);
    const PCCD::Linear_motion still(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()));
    // B from x = 4 to x = -4: first contact when the centres are 2 apart, t = 0.25 (path length 8).
    const PCCD::Linear_motion through(at(Eigen::Vector3d(4, 0, 0)), at(Eigen::Vector3d(-4, 0, 0)));
    const PCCD::Contact_time_result r = PCCD::time_of_contact(a, still, a, through);
    REQUIRE(r.status == PCCD::Contact_time_status::contact);
    CHECK(std::abs(r.t - 0.25) * 8.0 <= s);
    CHECK(r.t_low <= r.t_high);
    CHECK((r.t_high - r.t_low) * 8.0 <= 0.25 * a.sampling_radius() + 1e-12);
    CHECK(std::abs(r.point.x() - 1.0) <= s);
    CHECK(r.normal.x() > std::cos(20.0 * std::numbers::pi / 180.0)); // B leaves A towards +x
    CHECK(PCCD::do_intersect(a, still.pose(r.t), a, through.pose(r.t)).intersects);
    INFO("steps " << r.counters.advancement_steps << ", near checks " << r.counters.near_checks << ", bisection "
                  << r.counters.bisection_steps);
    CHECK(r.counters.advancement_steps < 60);
    // A positive tolerance: contact earlier, when the gap closes to the tolerance.
    const PCCD::Contact_time_result near = PCCD::time_of_contact(a, still, a, through, {.tolerance = 0.4});
    REQUIRE(near.status == PCCD::Contact_time_status::contact);
    CHECK(std::abs(near.t - (4.0 - 2.4) / 8.0) * 8.0 <= s);
    // Passing at a gap of 0.5 (5 spacings or so): no contact; with tolerance 0.6: contact.
    const PCCD::Linear_motion past(at(Eigen::Vector3d(4, 2.5, 0)), at(Eigen::Vector3d(-4, 2.5, 0)));
    CHECK(PCCD::time_of_contact(a, still, a, past).status == PCCD::Contact_time_status::no_contact);
    const auto grazing = PCCD::time_of_contact(a, still, a, past, {.tolerance = 0.6});
    CHECK(grazing.status == PCCD::Contact_time_status::contact);
    // The gap reaches 0.6 at x = sqrt(2.6^2 - 2.5^2); there the time moves 2.6 / 0.71 = 3.6 times
    // faster along the path than the gap changes, so a surface error of e shifts it by 3.6 e.
    const double x_graze = std::sqrt(2.6 * 2.6 - 2.5 * 2.5);
    CHECK(std::abs(grazing.t - (4.0 - x_graze) / 8.0) * 8.0 <= 2.0 * s);
    // Starting in contact: t = 0.
    const PCCD::Linear_motion overlapping(at(Eigen::Vector3d(1.5, 0, 0)), at(Eigen::Vector3d(5, 0, 0)));
    const auto start = PCCD::time_of_contact(a, still, a, overlapping);
    CHECK(start.status == PCCD::Contact_time_status::contact);
    CHECK(start.t == 0.0);
    // A screw about the z axis from (3, 0, 0) to (0, 3, 0) against a sphere at (0, 3, 0): contact
    // when the centre distance is 2, at angle asin(7/9).
    const PCCD::Linear_motion fixed(at(Eigen::Vector3d(0, 3, 0)), at(Eigen::Vector3d(0, 3, 0)));
    const PCCD::Screw_motion turn(at(Eigen::Vector3d(3, 0, 0)),
                                  Rigid_transform_3<double>(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                                                            Eigen::Vector3d(0, 3, 0)));
    const auto screwed = PCCD::time_of_contact(a, fixed, a, turn);
    REQUIRE(screwed.status == PCCD::Contact_time_status::contact);
    const double t_exact = std::asin(7.0 / 9.0) / (std::numbers::pi / 2);
    CHECK(std::abs(screwed.t - t_exact) * (3.0 * std::numbers::pi / 2) <= s);
}

TEST_CASE("time_of_contact: a small fast sphere through a thin plate does not tunnel", "[continuous]")
{
    const Object& p = plate();
    const Object& ball = sphere(0.2);
    const PCCD::Linear_motion still(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()));
    const double s = spacing(p, ball);
    PCCD::Random_engine engine(17);
    int discrete_misses = 0;
    for (int k = 0; k < 20; ++k) {
        // From z = -10 to z = 10 over a random point of the plate: contact when the ball's bottom
        // reaches the plate (z centre = -0.2), t = 9.8 / 20. Discrete steps of 20 / 29 = 0.69 are
        // longer than the ball (0.4).
        const double x = PCCD::uniform_real(engine, -0.6, 0.6), y = PCCD::uniform_real(engine, -0.6, 0.6);
        const PCCD::Linear_motion shot(at(Eigen::Vector3d(x, y, -10)), at(Eigen::Vector3d(x, y, 10)));
        const auto r = PCCD::time_of_contact(p, still, ball, shot);
        REQUIRE(r.status == PCCD::Contact_time_status::contact);
        CHECK(std::abs(r.t - 0.49) * 20.0 <= s);
        // 30 discrete checks (t = i / 29) see it only when a sample lands within the ball's thickness.
        bool seen = false;
        for (int i = 0; i < 30; ++i) seen = seen || PCCD::do_intersect(p, still.pose(0.0), ball, shot.pose(i / 29.0)).intersects;
        discrete_misses += !seen;
    }
    CHECK(discrete_misses >= 10); // the case really is one discrete checks miss
}

TEST_CASE("time_of_contact: against dense discrete checks on random motions", "[continuous]")
{
    const Object& a = torus();
    const Object& b = sphere(1.0);
    PCCD::Random_engine engine(2024);
    int contacts = 0, misses = 0;
    for (int k = 0; k < 30; ++k) {
        const Rigid_transform_3<double> a0(PCCD::testing::uniform_random_rotation(engine), Eigen::Vector3d::Zero());
        const Rigid_transform_3<double> a1(PCCD::testing::uniform_random_rotation(engine), Eigen::Vector3d(0.2, 0, 0));
        Eigen::Vector3d from(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
        from = 4.0 * from.normalized();
        const Eigen::Vector3d to = -from + Eigen::Vector3d(PCCD::uniform_real(engine, -2.5, 2.5), PCCD::uniform_real(engine, -2.5, 2.5), 0.0);
        const PCCD::Linear_motion ma(a0, a1);
        const PCCD::Rigid_transform_3<double> b0(PCCD::testing::uniform_random_rotation(engine), from);
        const PCCD::Rigid_transform_3<double> b1(PCCD::testing::uniform_random_rotation(engine), to);
        const PCCD::Linear_motion mb(b0, b1);
        const auto r = PCCD::time_of_contact(a, ma, b, mb);
        // Dense checks: 1000 steps, each moving no point farther than 0.02 of the path.
        double first = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= 1000 && !std::isfinite(first); ++i) {
            const double t = i / 1000.0;
            if (PCCD::do_intersect(a, ma.pose(t), b, mb.pose(t)).intersects) first = t;
        }
        if (std::isfinite(first)) {
            ++contacts;
            // No contact the dense checks find comes before t_low.
            CHECK(r.status == PCCD::Contact_time_status::contact);
            CHECK(r.t_low <= first + 1e-12);
            // And the time found is no later than the dense one plus the bracket.
            CHECK(r.t - first <= r.t_high - r.t_low + 1e-12);
            misses += r.status != PCCD::Contact_time_status::contact;
        } else if (r.status == PCCD::Contact_time_status::contact) {
            // A contact the dense checks stepped over: it is real (a check found it at t) and short.
            CHECK(PCCD::do_intersect(a, ma.pose(r.t), b, mb.pose(r.t)).intersects);
        }
    }
    INFO("contacts " << contacts);
    CHECK(contacts >= 8);
    CHECK(misses == 0);
}

TEST_CASE("time_of_contact: bad options", "[continuous]")
{
    const Object& a = sphere(1.0);
    const PCCD::Linear_motion still(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()));
    CHECK_THROWS_AS(PCCD::time_of_contact(a, still, a, still, {.tolerance = -1.0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::time_of_contact(a, still, a, still, {.tolerance = std::numeric_limits<double>::quiet_NaN()}),
                    PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::time_of_contact(a, still, a, still, {.time_accuracy = 0.0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::time_of_contact(a, still, a, still, {.near_step = 0.0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::time_of_contact(a, still, a, still, {.max_steps = 0}), PCCD::Invalid_input);
    // A budget of one step: undecided for a motion that needs more.
    const PCCD::Linear_motion through(at(Eigen::Vector3d(4, 0, 0)), at(Eigen::Vector3d(-4, 0, 0)));
    const auto r = PCCD::time_of_contact(a, still, a, through, {.max_steps = 1});
    CHECK(r.status == PCCD::Contact_time_status::undecided);
    CHECK(std::isnan(r.t));
}
