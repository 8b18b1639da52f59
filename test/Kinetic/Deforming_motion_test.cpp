// Tests of Deforming_motion (PCCD/Kinetic/Deforming_motion.h) with time_of_contact(): a sphere
// cloud that moves rigidly by its flightplans and one that grows while it moves, each against a
// rigid sphere, first contact in closed form; a twisting, swaying cloud on key frames against dense
// discrete checks (no contact they find lies before t_low); bad motions.
#include <PCCD/Kinetic/Deforming_motion.h>

#include <catch2/catch.hpp>

#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/Kinetic/Polynomial_flightplan.h>
#include <PCCD/Point_cloud_object.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include "surface_test_helpers.h"

static_assert(PCCD::RigidMotion<PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Linear_flightplan>>);
static_assert(PCCD::RigidMotion<PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Polynomial_flightplan>>);

namespace {

using Deforming = PCCD::Deforming_point_cloud_object<>;
using Rigid = PCCD::Point_cloud_object<>;

Eigen::Matrix3Xd sphere_points(std::size_t n, std::uint64_t seed) { return pccd_test::sample_shape(pccd_test::unit_sphere(), n, 0.0, seed).points; }

const Rigid& rigid_sphere()
{
    static const Rigid o(pccd_test::columns(sphere_points(2000, 51)));
    return o;
}

const PCCD::Rigid_transform_3<double> rest;
const PCCD::Linear_motion still(rest, rest);

} // namespace

TEST_CASE("Deforming_motion: a cloud moved by its flightplans meets a rigid sphere when the closed form says", "[continuous]")
{
    const Eigen::Matrix3Xd p = sphere_points(2000, 52);
    Deforming cloud(p);
    const double s = cloud.cloud().mean_spacing();
    SECTION("rigid translation by flightplans")
    {
        // Centre from x = 4 at t = 0 to x = -4 at t = 2: the spheres touch at t = 0.5, s = 0.25 (path 8).
        std::vector<PCCD::Linear_flightplan> plans;
        for (Eigen::Index i = 0; i < p.cols(); ++i)
            plans.emplace_back(Eigen::Vector3d(p.col(i)) + Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(-4, 0, 0));
        const PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Linear_flightplan> motion(
            cloud, std::span<const PCCD::Linear_flightplan>(plans), 0.0, 2.0);
        CHECK(motion.max_point_speed(Eigen::Vector3d::Zero(), 1.0) == Approx(8.0).epsilon(1e-12));
        const PCCD::Contact_time_result r = PCCD::time_of_contact(cloud, motion, rigid_sphere(), still);
        REQUIRE(r.status == PCCD::Contact_time_status::contact);
        CHECK(std::abs(r.t - 0.25) * 8.0 <= s);
        CHECK(r.t_low <= r.t_high);
        CHECK(std::abs(r.point.x() - 1.0) <= 2.0 * s); // where the rigid sphere faces +x
        // The object is left at a frame the query looked at; the contact is there at t.
        cloud.advance_to(motion.time(r.t), std::span<const PCCD::Linear_flightplan>(plans));
        CHECK(PCCD::do_intersect(cloud, rest, rigid_sphere(), rest).intersects);
        // Passing at a gap of 0.5: no contact.
        std::vector<PCCD::Linear_flightplan> past;
        for (Eigen::Index i = 0; i < p.cols(); ++i)
            past.emplace_back(Eigen::Vector3d(p.col(i)) + Eigen::Vector3d(4, 2.5, 0), Eigen::Vector3d(-4, 0, 0));
        const PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Linear_flightplan> by(
            cloud, std::span<const PCCD::Linear_flightplan>(past), 0.0, 2.0);
        CHECK(PCCD::time_of_contact(cloud, by, rigid_sphere(), still).status == PCCD::Contact_time_status::no_contact);
    }
    SECTION("growing while it moves")
    {
        // p_i(t) = (1 + 0.15 t) p_i + (3.5 - 3 t, 0, 0) over t in [0, 1] (every edge stretched by at
        // most 1.15, within the stretch bound): the surfaces touch when 3.5 - 3 t = 2 + 0.15 t.
        std::vector<PCCD::Linear_flightplan> plans;
        for (Eigen::Index i = 0; i < p.cols(); ++i)
            plans.emplace_back(Eigen::Vector3d(p.col(i)) + Eigen::Vector3d(3.5, 0, 0),
                               0.15 * Eigen::Vector3d(p.col(i)) + Eigen::Vector3d(-3, 0, 0));
        const PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Linear_flightplan> motion(
            cloud, std::span<const PCCD::Linear_flightplan>(plans), 0.0, 1.0);
        const PCCD::Contact_time_result r = PCCD::time_of_contact(cloud, motion, rigid_sphere(), still);
        REQUIRE(r.status == PCCD::Contact_time_status::contact);
        const double exact = 1.5 / 3.15;
        INFO("t " << r.t << ", exact " << exact);
        CHECK(std::abs(r.t - exact) * 3.0 <= 1.5 * s); // the centre moves 3 per unit time
    }
}

TEST_CASE("Deforming_motion: a twisting, swaying cloud against dense discrete checks", "[continuous]")
{
    // Key frames every 0.25: the sphere twists about z (angle 0.3 z t, within the stretch bound) and
    // sways along x towards the rigid sphere and back.
    const Eigen::Matrix3Xd p = sphere_points(1500, 53);
    Deforming cloud(p);
    const std::vector<double> key_times{0.0, 0.25, 0.5, 0.75, 1.0};
    const auto times = std::make_shared<const std::vector<double>>(key_times);
    const double offsets[] = {3.2, 2.6, 1.9, 2.4, 3.0};
    int contacts = 0;
    for (const double lift : {0.0, 0.6, 1.2}) {
        std::vector<PCCD::Piecewise_linear_flightplan> plans;
        for (Eigen::Index i = 0; i < p.cols(); ++i) {
            std::vector<Eigen::Vector3d> keys;
            for (std::size_t k = 0; k < key_times.size(); ++k) {
                const double angle = 0.3 * p(2, i) * key_times[k];
                const Eigen::Vector3d q = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d(p.col(i));
                keys.push_back(q + Eigen::Vector3d(offsets[k], lift, 0));
            }
            plans.emplace_back(times, keys);
        }
        const std::span<const PCCD::Piecewise_linear_flightplan> span(plans);
        const PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Piecewise_linear_flightplan> motion(cloud, span, 0.0, 1.0);
        const PCCD::Contact_time_result r = PCCD::time_of_contact(cloud, motion, rigid_sphere(), still);
        double first = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= 400 && !std::isfinite(first); ++i) {
            cloud.advance_to(i / 400.0, span);
            if (PCCD::do_intersect(cloud, rest, rigid_sphere(), rest).intersects) first = i / 400.0;
        }
        INFO("lift " << lift << ": status " << int(r.status) << " t " << r.t << " t_low " << r.t_low << ", dense first " << first);
        if (std::isfinite(first)) {
            ++contacts;
            CHECK(r.status == PCCD::Contact_time_status::contact);
            CHECK(r.t_low <= first + 1e-12);
        } else if (r.status == PCCD::Contact_time_status::contact) {
            cloud.advance_to(r.t, span);
            CHECK(PCCD::do_intersect(cloud, rest, rigid_sphere(), rest).intersects);
        }
    }
    CHECK(contacts >= 2); // lifts 0 and 0.6 come within reach; 1.2 grazes or passes
}

TEST_CASE("Deforming_motion: bad motions", "[continuous]")
{
    const Eigen::Matrix3Xd p = sphere_points(500, 54);
    Deforming cloud(p);
    std::vector<PCCD::Linear_flightplan> plans;
    for (Eigen::Index i = 0; i < p.cols(); ++i) plans.emplace_back(Eigen::Vector3d(p.col(i)), Eigen::Vector3d(1, 0, 0));
    const std::span<const PCCD::Linear_flightplan> span(plans);
    using Motion = PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Linear_flightplan>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(Motion(cloud, span, 1.0, 0.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(Motion(cloud, span, nan, 1.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(Motion(cloud, span.first(10), 0.0, 1.0), PCCD::Invalid_input);
    const Motion ok(cloud, span, 0.0, 1.0);
    CHECK(ok.reach_scale() == Approx(1.25 * 1.25)); // the default stretch bound 0.25
    CHECK_THROWS_AS(ok.pose(1.5), PCCD::Invalid_input);
    CHECK_THROWS_AS(ok.advance_object(nan), PCCD::Invalid_input);
    CHECK_THROWS_AS(ok.max_point_speed(Eigen::Vector3d::Zero(), -1.0), PCCD::Invalid_input);
    // A deformation that breaks the stretch rule ends the query with its error.
    std::vector<PCCD::Linear_flightplan> blow_up;
    for (Eigen::Index i = 0; i < p.cols(); ++i) blow_up.emplace_back(Eigen::Vector3d(p.col(i)) * 3.0, Eigen::Vector3d(p.col(i)));
    const Motion bad(cloud, std::span<const PCCD::Linear_flightplan>(blow_up), 0.0, 1.0);
    CHECK_THROWS_AS(PCCD::time_of_contact(cloud, bad, rigid_sphere(), still), PCCD::Invalid_input);
}
