// Tests of PCCD/Exact/mesh_contact_time.h: exact_time_of_contact against analytic truth on boxes
// (a cube sliding into a cube face first: first contact when the gap closes, also with a positive
// tolerance; a cube passing at a known gap: no contact and the smallest distance; a cube turning
// into another about a screw axis) and bad arguments.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_contact_time.h>
#include <PCCD/Rigid_transform_3.h>
#include "exact_test_helpers.h"

namespace {

using Pose = PCCD::Rigid_transform_3<double>;
Pose at(const Eigen::Vector3d& t) { return Pose(Eigen::Matrix3d::Identity(), t); }

} // namespace

TEST_CASE("exact_time_of_contact: a cube sliding into a cube", "[exact][continuous]")
{
    const PCCD::Exact_mesh cube(pccd_test::box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.5)));
    const PCCD::Linear_motion still(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()));
    // B from x = 5 to x = -5: the faces meet when x = 1, t = 0.4 (path length 10).
    const PCCD::Linear_motion slide(at(Eigen::Vector3d(5, 0.2, 0.1)), at(Eigen::Vector3d(-5, 0.2, 0.1)));
    const double accuracy = 1e-3;
    const PCCD::Exact_contact_time r = PCCD::exact_time_of_contact(cube, still, cube, slide, 0.0, accuracy);
    REQUIRE(r.contact);
    // The gap is 10 (0.4 - t): within accuracy at t, positive before.
    CHECK(r.t <= 0.4);
    CHECK(10.0 * (0.4 - r.t) <= accuracy * (1 + 1e-9));
    CHECK(r.min_distance <= accuracy);
    // Tolerance 0.5: when the gap is 0.5, t = 0.35.
    const auto near = PCCD::exact_time_of_contact(cube, still, cube, slide, 0.5, accuracy);
    REQUIRE(near.contact);
    CHECK(near.t <= 0.35 + 1e-12);
    CHECK(10.0 * (0.35 - near.t) <= accuracy * (1 + 1e-9));
    // Passing at y = 2: the gap never drops below 1.
    const PCCD::Linear_motion past(at(Eigen::Vector3d(5, 2, 0)), at(Eigen::Vector3d(-5, 2, 0)));
    const auto miss = PCCD::exact_time_of_contact(cube, still, cube, past, 0.0, accuracy);
    CHECK_FALSE(miss.contact);
    CHECK(miss.t == 1.0);
    CHECK(miss.min_distance >= 1.0 - 1e-12);
    CHECK(miss.min_distance <= 1.0 + 0.05); // the advancement gets near the closest time
    CHECK(PCCD::exact_time_of_contact(cube, still, cube, past, 0.9, accuracy).contact == false);
    CHECK(PCCD::exact_time_of_contact(cube, still, cube, past, 1.1, accuracy).contact == true);
    // Starting in contact.
    const PCCD::Linear_motion overlapping(at(Eigen::Vector3d(0.5, 0, 0)), at(Eigen::Vector3d(5, 0, 0)));
    const auto start = PCCD::exact_time_of_contact(cube, still, cube, overlapping, 0.0, accuracy);
    CHECK(start.contact);
    CHECK(start.t == 0.0);
}

TEST_CASE("exact_time_of_contact: a cube turning about a screw axis into a cube", "[exact][continuous]")
{
    const PCCD::Exact_mesh cube(pccd_test::box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.5)));
    // A at (0, 3, 0); B turns about the z axis from (3, 0, 0) to (0, 3, 0) keeping its orientation
    // relative to the radius: its face towards A is the one facing +y at the end. Contact when the
    // cubes' faces meet; the truth is found by dense exact tests (independent of the advancement).
    const PCCD::Linear_motion fixed(at(Eigen::Vector3d(0, 3, 0)), at(Eigen::Vector3d(0, 3, 0)));
    const PCCD::Screw_motion turn(at(Eigen::Vector3d(3, 0, 0)),
                                  Pose(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                                       Eigen::Vector3d(0, 3, 0)));
    const double accuracy = 1e-3;
    const auto r = PCCD::exact_time_of_contact(cube, fixed, cube, turn, 0.0, accuracy);
    REQUIRE(r.contact);
    double first = 1.0;
    for (int i = 0; i <= 20000; ++i)
        if (PCCD::exact_do_intersect(cube, fixed.pose(0.0), cube, turn.pose(i / 20000.0))) {
            first = i / 20000.0;
            break;
        }
    CHECK(r.t <= first + 1e-12);
    // Within the accuracy of the dense grid plus what the bracket allows (arc length 3 pi / 2).
    CHECK((first - r.t) * 3.0 * std::numbers::pi / 2.0 <= 0.01);
}

TEST_CASE("exact_time_of_contact: bad arguments", "[exact][continuous]")
{
    const PCCD::Exact_mesh cube(pccd_test::box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.5)));
    const PCCD::Linear_motion still(at(Eigen::Vector3d::Zero()), at(Eigen::Vector3d::Zero()));
    CHECK_THROWS_AS(PCCD::exact_time_of_contact(cube, still, cube, still, -1.0, 1e-3), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::exact_time_of_contact(cube, still, cube, still, 0.0, 0.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::exact_time_of_contact(cube, still, cube, still, std::numeric_limits<double>::quiet_NaN(), 1e-3),
                    PCCD::Invalid_input);
}
