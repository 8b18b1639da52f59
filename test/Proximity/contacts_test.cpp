// Tests of contacts() (doc/manual/proximity.md "Contacts") against analytic truth: a unit sphere
// touched by a cloud of two small spheres at two places (two regions, each with a known depth and
// normal), one overlapping pair of unit spheres (one region), and separate poses (none).
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Proximity/contacts.h>
#include <PCCD/testing/Sphere_shape.h>

#include <catch2/catch.hpp>

#include "proximity_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using namespace pccd_test;

/// Two spheres of radius 0.5 centred at (+-c, 0, 0), sampled as one cloud at the unit spheres'
/// density.
const PCCD::Point_cloud_object<>& two_balls(double c)
{
    static const PCCD::Point_cloud_object<> object = [c] {
        const PCCD::testing::Sphere_shape left(Eigen::Vector3d(-c, 0, 0), 0.5), right(Eigen::Vector3d(c, 0, 0), 0.5);
        const auto l = pccd_test::sample_shape(left, 1500, 0.0, 31);
        const auto r = pccd_test::sample_shape(right, 1500, 0.0, 32);
        std::vector<Eigen::Vector3d> points = pccd_test::columns(l.points);
        const std::vector<Eigen::Vector3d> more = pccd_test::columns(r.points);
        points.insert(points.end(), more.begin(), more.end());
        return PCCD::Point_cloud_object<>(points);
    }();
    return object;
}

} // namespace

TEST_CASE("contacts: two regions, each with its depth and normal", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const double overlap = 0.15; // each small ball reaches 0.15 into the unit sphere
    const double c = 1.5 - overlap;
    const PCCD::Contact_result r = PCCD::contacts(s.a, Rigid_transform_3<double>(), two_balls(c), Rigid_transform_3<double>());
    REQUIRE(r.status == PCCD::Intersection_status::intersecting);
    REQUIRE(r.regions == 2);
    REQUIRE(r.contacts.size() == 2);
    bool seen[2] = {false, false};
    for (const PCCD::Contact& k : r.contacts) {
        const int side = k.position.x() > 0.0 ? 1 : 0;
        seen[side] = true;
        const Eigen::Vector3d dir(side ? 1.0 : -1.0, 0.0, 0.0);
        INFO("contact at " << k.position.transpose() << " depth " << k.depth << " normal " << k.normal.transpose());
        CHECK(std::abs(k.depth - overlap) <= 0.5 * s.spacing);
        CHECK(degrees(k.normal, dir) <= 15.0);
        CHECK(degrees(k.position, dir) <= 10.0);
        CHECK(k.points_inside > 0);
        CHECK((k.point_a - k.point_b).norm() == Approx(k.depth).margin(1e-9));
    }
    CHECK((seen[0] && seen[1]));
    CHECK(r.contacts[0].depth >= r.contacts[1].depth);

    const PCCD::Contact_result one = PCCD::contacts(s.a, Rigid_transform_3<double>(), two_balls(c), Rigid_transform_3<double>(),
                                                   {.max_contacts = 1});
    CHECK(one.regions == 2);
    CHECK(one.contacts.size() == 1);
}

TEST_CASE("contacts: one region for overlapping spheres, none when separate", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const double overlap = 8.0 * s.spacing;
    const auto pose_b = centred_at(Eigen::Vector3d(0.0, 2.0 - overlap, 0.0), 41);
    const PCCD::Contact_result r = PCCD::contacts(s.a, Rigid_transform_3<double>(), s.b, pose_b);
    REQUIRE(r.status == PCCD::Intersection_status::intersecting);
    REQUIRE(r.contacts.size() == 1);
    CHECK(std::abs(r.contacts[0].depth - overlap) <= 0.5 * s.spacing);
    CHECK(degrees(r.contacts[0].normal, Eigen::Vector3d::UnitY()) <= 15.0);

    const auto apart = centred_at(Eigen::Vector3d(0.0, 2.0 + 4.0 * s.spacing, 0.0), 42);
    const PCCD::Contact_result none = PCCD::contacts(s.a, Rigid_transform_3<double>(), s.b, apart);
    CHECK(none.status == PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, apart).status);
    CHECK(none.status == PCCD::Intersection_status::separate);
    CHECK(none.contacts.empty());
    CHECK_THROWS_WITH(PCCD::contacts(s.a, Rigid_transform_3<double>(), s.b, apart, {.max_contacts = 0}),
                      Catch::Matchers::Contains("max_contacts"));
}
