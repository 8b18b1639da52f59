// Tests of time_of_contact() and the rigid motions (doc/manual/continuous.md) against analytic
// truth: spheres meeting along a line and along a screw (first contact time in closed form), a small
// sphere shot through a thin plate faster than discrete steps can see, near misses; and, on random
// motions of torus and sphere clouds (fixed seeds), against dense discrete do_intersect checks: no
// contact that the dense checks find comes before t_low, and no_contact only where they find none,
// for the default fit, the IMLS fit of the sharp-feature options and the lean (Euclidean) object.
// The advancement's lower bound (surface_gap.h) against brute force over all point pairs, and
// against the distances between points of the two zero sets found by projection (it must stay below
// every one of them).
#include <PCCD/Continuous/Contact_time_options.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>

#include <catch2/catch.hpp>

#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/internal/surface_gap.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/sharp_feature_options.h>

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

// The same clouds as torus() and sphere(1.0), with the IMLS fit of the sharp-feature options.
const Object& imls_torus()
{
    static const Object t = [] {
        const auto s = pccd_test::sample_shape(pccd_test::test_torus(), 3000, 0.0, 44);
        return Object(pccd_test::columns(s.points), PCCD::sharp_feature_options());
    }();
    return t;
}

const Object& imls_sphere()
{
    static const Object u = [] {
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 41);
        return Object(pccd_test::columns(s.points), PCCD::sharp_feature_options());
    }();
    return u;
}

// A cloud without a surface domain: its surface can reach as far as the kernel's support.
const Object& domainless_sphere()
{
    static const Object u = [] {
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 1500, 0.0, 45);
        PCCD::Point_cloud_object_options o;
        o.domain.enabled = false;
        return Object(pccd_test::columns(s.points), o);
    }();
    return u;
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

namespace {

/// 30 random motions of `a` and `b` (seed 2024) against 1,000 discrete checks each.
template <class A, class B>
void check_against_dense_checks(const A& a, const B& b)
{
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

} // namespace

TEST_CASE("time_of_contact: against dense discrete checks on random motions", "[continuous]")
{
    SECTION("default fit") { check_against_dense_checks(torus(), sphere(1.0)); }
    SECTION("IMLS fit (sharp-feature options)") { check_against_dense_checks(imls_torus(), imls_sphere()); }
    SECTION("lean objects (Euclidean kernel)")
    {
        const auto t = pccd_test::sample_shape(pccd_test::test_torus(), 3000, 0.0, 44);
        const auto u = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 41);
        const PCCD::Euclidean_point_cloud_object<> lean_torus(pccd_test::columns(t.points));
        const PCCD::Euclidean_point_cloud_object<> lean_sphere(pccd_test::columns(u.points));
        check_against_dense_checks(lean_torus, lean_sphere);
    }
}

namespace {

/// min over point pairs of |T p - q| - reach(p) - reach(q), straight from the clouds' positions and
/// domain radii (reach: the domain radius capped by the support radius; without a domain, the
/// support radius).
double brute_force_gap(const Object& a, const Rigid_transform_3<double>& a_to_b, const Object& b)
{
    const auto reach = [](const Object& o, std::size_t i) {
        const double h = o.surface().support_radius();
        return o.domain_radii().size() == 0 ? h : std::min(o.domain_radii()(Eigen::Index(i)), h);
    };
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Eigen::Vector3d p = a_to_b.transform_point(Eigen::Vector3d(a.cloud().position(i)));
        const double ra = reach(a, i);
        for (std::size_t j = 0; j < b.size(); ++j)
            gap = std::min(gap, (p - Eigen::Vector3d(b.cloud().position(j))).norm() - ra - reach(b, j));
    }
    return gap;
}

/// Points of the zero set of o's surface (local frame): cloud points pushed off by up to 1.5
/// sampling radii in random directions, then projected by Newton steps x -= f(x) n(x) until |f| <
/// 1e-9; those whose projection leaves the domain are dropped.
std::vector<Eigen::Vector3d> zero_set_points(const Object& o, std::size_t count, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    std::vector<Eigen::Vector3d> out;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t i = std::size_t(PCCD::uniform_real(engine, 0.0, double(o.size()))) % o.size();
        Eigen::Vector3d d(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
        Eigen::Vector3d x = Eigen::Vector3d(o.cloud().position(i)) + PCCD::uniform_real(engine, 0.0, 1.5 * o.sampling_radius()) * d.normalized();
        for (int step = 0; step < 40; ++step) {
            const PCCD::Surface_evaluation e = o.surface().evaluate(x);
            if (!e.defined()) break;
            if (std::abs(e.value) < 1e-9) {
                out.push_back(x);
                break;
            }
            x -= e.value * e.normal;
        }
    }
    return out;
}

} // namespace

TEST_CASE("time_of_contact's lower bound: exact over the point pairs, and below every distance between the surfaces",
          "[continuous]")
{
    struct Pair {
        const char* name;
        const Object& a;
        const Object& b;
    };
    const Pair pairs[] = {{"default fit", torus(), sphere(1.0)},
                          {"IMLS fit", imls_torus(), imls_sphere()},
                          {"no domain", torus(), domainless_sphere()}};
    for (const Pair& pair : pairs) {
        SECTION(pair.name)
        {
            const Object& a = pair.a;
            const Object& b = pair.b;
            const auto reach_a = PCCD::internal::surface_reach(a.hierarchy(), a.surface().support_radius());
            const auto reach_b = PCCD::internal::surface_reach(b.hierarchy(), b.surface().support_radius());
            const std::vector<Eigen::Vector3d> za = zero_set_points(a, 2000, 11), zb = zero_set_points(b, 2000, 12);
            REQUIRE(za.size() > 1300);
            REQUIRE(zb.size() > 1300);
            PCCD::Random_engine engine(77);
            int close = 0;
            for (int k = 0; k < 8; ++k) {
                // B's centre 1.5 to 3.3 from the torus's centre: from deep overlap to a few spacings apart.
                Eigen::Vector3d c(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
                c = PCCD::uniform_real(engine, 1.5, 3.3) * c.normalized();
                const Rigid_transform_3<double> pose_b(PCCD::testing::uniform_random_rotation(engine), c);
                const Rigid_transform_3<double> pose_a(PCCD::testing::uniform_random_rotation(engine), Eigen::Vector3d::Zero());
                const Rigid_transform_3<double> a_to_b = pose_b.inverse() * pose_a;
                const double truth = brute_force_gap(a, a_to_b, b);
                const double inf = std::numeric_limits<double>::infinity();
                // Unlimited walk: exactly the brute-force minimum.
                const auto full = PCCD::internal::surface_gap_lower_bound(a.hierarchy(), b.hierarchy(), a_to_b, reach_a, reach_b,
                                                                          inf, -inf, std::numeric_limits<std::size_t>::max());
                CHECK_FALSE(full.below);
                CHECK(full.lower == Approx(truth).margin(1e-12));
                // Under budgets: a lower bound still.
                for (const std::size_t budget : {std::size_t(1), std::size_t(8), std::size_t(64)}) {
                    const auto cut = PCCD::internal::surface_gap_lower_bound(a.hierarchy(), b.hierarchy(), a_to_b, reach_a, reach_b,
                                                                             inf, -inf, budget);
                    CHECK(cut.lower <= truth + 1e-12);
                }
                // With a threshold above the truth, the walk stops at a pair below it.
                const auto early = PCCD::internal::surface_gap_lower_bound(a.hierarchy(), b.hierarchy(), a_to_b, reach_a, reach_b, inf,
                                                                           truth + 0.1, std::numeric_limits<std::size_t>::max());
                CHECK(early.below);
                CHECK(early.lower < truth + 0.1);
                CHECK(early.lower >= truth - 1e-12);
                // Certified: no two points of the zero sets are closer than the bound.
                double sampled = inf;
                for (const Eigen::Vector3d& x : za) {
                    const Eigen::Vector3d y = a_to_b.transform_point(x);
                    for (const Eigen::Vector3d& z : zb) sampled = std::min(sampled, (y - z).norm());
                }
                INFO("pose " << k << ": bound " << truth << ", closest sampled surface points " << sampled);
                CHECK(truth <= sampled);
                close += sampled < 0.2;
            }
            CHECK(close >= 3); // some poses put the surfaces in or near contact, where the bound matters
        }
    }
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
