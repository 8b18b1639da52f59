// Tests of the proximity queries (doc/manual/proximity.md) against analytic truth: two sampled unit
// spheres, whose surface distance, penetration depths, witness points and normals are known in
// closed form, and brute force over the point pairs for the closest-pair walk.
// Also covers Proximity/Distance_options.h, Proximity/Distance_result.h and
// concepts/ProximityObject.h: the cases below exercise what they declare.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/Distance_options.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Proximity/internal/surface_reach.h>
#include <PCCD/Random.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/pose_generator.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "proximity_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using namespace pccd_test;

static_assert(PCCD::ProximityObject<PCCD::Point_cloud_object<>>);

} // namespace

TEST_CASE("distance: separate spheres, against the analytic gap", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> pose_a;
    PCCD::Random_engine engine(5);
    std::vector<double> errors;
    for (int k = 0; k < 24; ++k) {
        // gaps from one to twenty spacings, in random directions
        const double gap = s.spacing * (1.0 + 19.0 * PCCD::uniform_01(engine));
        const Eigen::Vector3d dir = random_direction(engine);
        const Eigen::Vector3d centre = (2.0 + gap) * dir;
        const PCCD::Distance_result r = PCCD::distance(s.a, pose_a, s.b, centred_at(centre, 100 + k));
        INFO("gap " << gap << " spacing " << s.spacing);
        REQUIRE(r.status == PCCD::Intersection_status::separate);
        REQUIRE(std::isfinite(r.distance));
        errors.push_back(std::abs(r.distance - gap) / s.spacing);
        // the interval holds the truth (the sampled sphere's radius differs from 1 by the fit's bias only)
        CHECK(r.lower_bound <= gap + 0.5 * s.spacing);
        CHECK(r.upper_bound >= gap - 0.5 * s.spacing);
        CHECK(r.lower_bound <= r.distance);
        CHECK(r.distance <= r.upper_bound);
        // witnesses on the spheres, facing each other, their distance the distance
        CHECK(std::abs(r.point_a.norm() - 1.0) <= 0.25 * s.spacing);
        CHECK(std::abs((r.point_b - centre).norm() - 1.0) <= 0.25 * s.spacing);
        CHECK((r.point_a - r.point_b).norm() == Approx(r.distance).epsilon(1e-12));
        CHECK(degrees(r.point_a, dir) <= 5.0);
        CHECK(degrees(r.point_b - centre, -dir) <= 5.0);
        CHECK(degrees(r.normal_a, dir) <= 10.0);
        CHECK(degrees(r.normal_b, -dir) <= 10.0);
        CHECK(degrees(r.contact_normal, dir) <= 5.0);
        // the surfaces are there: |f| small at the witnesses
        CHECK(std::abs(*s.a.surface().value(r.point_a)) <= 0.05 * s.spacing);
        CHECK(std::abs(*s.b.surface().value(centred_at(centre, 100 + k).inverse().transform_point(r.point_b))) <= 0.05 * s.spacing);
    }
    INFO("median error " << median(errors) << " spacings");
    CHECK(median(errors) <= 0.1);
    CHECK(*std::max_element(errors.begin(), errors.end()) <= 0.5);
}

TEST_CASE("distance: status agrees with do_intersect, penetration depth of overlapping spheres", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> pose_a;
    PCCD::Random_engine engine(6);
    std::vector<double> depth_errors, angles;
    for (int k = 0; k < 12; ++k) {
        // overlaps of 3 to 12 spacings: the deepest point of each sphere inside the other lies
        // at depth = the overlap, on the line of centres
        const double overlap = s.spacing * (3.0 + 9.0 * PCCD::uniform_01(engine));
        const Eigen::Vector3d dir = random_direction(engine);
        const Eigen::Vector3d centre = (2.0 - overlap) * dir;
        const auto pose_b = centred_at(centre, 200 + k);
        const PCCD::Distance_result r = PCCD::distance(s.a, pose_a, s.b, pose_b, {.penetration = true});
        const PCCD::Intersection_result i = PCCD::do_intersect(s.a, pose_a, s.b, pose_b);
        REQUIRE(r.status == i.status);
        REQUIRE(r.status == PCCD::Intersection_status::intersecting);
        CHECK(r.distance == 0.0);
        REQUIRE(std::isfinite(r.depth));
        CHECK(r.depth == std::max(r.depth_a, r.depth_b));
        depth_errors.push_back(std::abs(r.depth - overlap) / s.spacing);
        angles.push_back(degrees(r.contact_normal, dir));
        // the deeper witness lies on its own sphere inside the other one
        CHECK(std::abs(r.point_a.norm() - 1.0) <= 0.25 * s.spacing);
        CHECK(std::abs((r.point_b - centre).norm() - 1.0) <= 0.25 * s.spacing);
        CHECK((r.point_a - r.point_b).norm() == Approx(r.depth).margin(1e-9));
    }
    INFO("median depth error " << median(depth_errors) << " spacings, median normal angle " << median(angles));
    CHECK(median(depth_errors) <= 0.25);
    CHECK(median(angles) <= 15.0);
}

TEST_CASE("distance: max_distance reports only farther-than, cheaply", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> pose_a;
    const auto pose_b = centred_at(Eigen::Vector3d(3.0, 0.0, 0.0), 7); // gap 1
    const PCCD::Distance_result near = PCCD::distance(s.a, pose_a, s.b, pose_b, {.max_distance = 2.0});
    CHECK(near.distance == Approx(1.0).margin(0.5 * s.spacing));
    const PCCD::Distance_result far = PCCD::distance(s.a, pose_a, s.b, pose_b, {.max_distance = 0.5});
    CHECK(far.status == PCCD::Intersection_status::separate);
    CHECK(far.distance == std::numeric_limits<double>::infinity());
    CHECK(far.lower_bound >= 0.5);
    CHECK(far.counters.f_evaluations == 0);
    CHECK(std::isnan(far.point_a.x()));
}

TEST_CASE("distance: the interval holds the truth and narrows as the node-pair budget grows", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> pose_a;
    const double gap = 10.0 * s.spacing;
    const auto pose_b = centred_at(Eigen::Vector3d(0.3, -0.8, 0.52).normalized() * (2.0 + gap), 8);
    double previous_width = std::numeric_limits<double>::infinity();
    double previous_lower = -1.0;
    double previous_upper = std::numeric_limits<double>::infinity();
    for (std::size_t budget : {1u, 4u, 16u, 64u, 256u, 100000u}) {
        const PCCD::Distance_result r = PCCD::distance(s.a, pose_a, s.b, pose_b, {.max_node_pairs = budget});
        INFO("budget " << budget << ": [" << r.lower_bound << ", " << r.upper_bound << "]");
        REQUIRE(r.status == PCCD::Intersection_status::separate);
        CHECK(r.lower_bound <= gap + 0.5 * s.spacing);
        CHECK(r.upper_bound >= gap - 0.5 * s.spacing);
        // the lower bound only rises; the upper bound (the refined witnesses of the best pair so
        // far) may differ by the refinement's tolerance between two candidates
        CHECK(r.lower_bound >= previous_lower - 1e-12);
        CHECK(r.upper_bound <= previous_upper + 0.05 * s.spacing);
        previous_width = r.upper_bound - r.lower_bound;
        previous_lower = r.lower_bound;
        previous_upper = r.upper_bound;
    }
    // the full walk: the interval is about the two surfaces' radii wide (sampling radius 2.4
    // mean spacings each here, and the noise estimate of the curved fit)
    CHECK(previous_width <= 7.0 * s.spacing);
    CHECK(std::isfinite(previous_width));
}

TEST_CASE("within_distance: the clearance test agrees with the distance", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> pose_a;
    PCCD::Random_engine engine(9);
    for (int k = 0; k < 10; ++k) {
        const double gap = s.spacing * (2.0 + 10.0 * PCCD::uniform_01(engine));
        const auto pose_b = centred_at((2.0 + gap) * random_direction(engine), 300 + k);
        CHECK(PCCD::within_distance(s.a, pose_a, s.b, pose_b, gap + s.spacing).within);
        CHECK_FALSE(PCCD::within_distance(s.a, pose_a, s.b, pose_b, gap - s.spacing).within);
    }
    const auto touching = centred_at(Eigen::Vector3d(1.5, 0, 0), 10);
    const PCCD::Clearance_result c = PCCD::within_distance(s.a, pose_a, s.b, touching, 0.0);
    CHECK(c.within);
    CHECK(c.status == PCCD::Intersection_status::intersecting);
}

namespace {

/// x moved onto the zero set of `o`'s surface by Newton steps along n(x); nullopt where f is undefined.
template <class O>
std::optional<Eigen::Vector3d> onto_surface(const O& o, Eigen::Vector3d x)
{
    for (int k = 0; k < 30; ++k) {
        const PCCD::Surface_evaluation e = o.surface().evaluate(x);
        if (!e.defined()) return std::nullopt;
        x -= e.value * e.normal;
        if (std::abs(e.value) < 1e-12) break;
    }
    return x;
}

/// The smallest |T p - q| - reach(p) - reach(q) over all point pairs of two objects (T = a_to_b),
/// reach the domain radius capped by the support radius: what certified_lower_bound certifies.
template <class O>
double brute_force_gap(const O& a, const O& b, const Rigid_transform_3<double>& a_to_b)
{
    const auto ra = PCCD::internal::surface_reach(a.hierarchy(), a.surface().support_radius());
    const auto rb = PCCD::internal::surface_reach(b.hierarchy(), b.surface().support_radius());
    const Eigen::Matrix4Xd& pa = a.hierarchy().ordered_points();
    const Eigen::Matrix4Xd& pb = b.hierarchy().ordered_points();
    double gap = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < pa.cols(); ++i) {
        const Eigen::Vector3d p = a_to_b.transform_point(Eigen::Vector3d(pa.col(i).head<3>()));
        const double reach_p = ra(pa(3, i));
        for (Eigen::Index j = 0; j < pb.cols(); ++j)
            gap = std::min(gap, (pb.col(j).head<3>() - p).norm() - reach_p - rb(pb(3, j)));
    }
    return gap;
}

} // namespace

TEST_CASE("distance: certified_lower_bound equals the brute-force gap of the reaches, also under budgets", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> pose_a;
    const double slack = 0.5 * std::min(s.a.sampling_radius(), s.b.sampling_radius());
    PCCD::Random_engine engine(31);
    for (int k = 0; k < 6; ++k) {
        const double gap = s.spacing * (1.0 + 15.0 * PCCD::uniform_01(engine));
        const auto pose_b = centred_at((2.0 + gap) * random_direction(engine), 400 + k);
        const double truth = brute_force_gap(s.a, s.b, pose_b.inverse() * pose_a);
        INFO("pose " << k << ": gap " << gap / s.spacing << " spacings, brute-force reach gap " << truth);
        const PCCD::Distance_result r = PCCD::distance(s.a, pose_a, s.b, pose_b, {.certified_lower_bound = true});
        REQUIRE(r.status == PCCD::Intersection_status::separate);
        // the walk finds the smallest gap to within its slack, and never above it
        CHECK(r.lower_bound <= std::max(0.0, truth) + 1e-12);
        CHECK(r.lower_bound >= truth - slack - 1e-12);
        CHECK(r.lower_bound <= r.distance);
        // the same answer otherwise: the certificate only adds node pairs to the walk. Its closest
        // pairs may differ, and the refinement from another pair can end elsewhere on the sampled
        // surfaces (it keeps to the zero set within 0.3 domain radii of the samples): measured up to
        // 0.11 spacings apart on these poses, both within the analytic test's bounds above
        const PCCD::Distance_result plain = PCCD::distance(s.a, pose_a, s.b, pose_b);
        CHECK(r.distance == Approx(plain.distance).margin(0.15 * s.spacing));
        CHECK(std::abs(r.distance - gap) <= 0.5 * s.spacing);
        CHECK(std::abs(plain.distance - gap) <= 0.5 * s.spacing);
        for (std::size_t budget : {1u, 8u, 64u}) {
            const PCCD::Distance_result b = PCCD::distance(s.a, pose_a, s.b, pose_b, {.max_node_pairs = budget, .certified_lower_bound = true});
            CHECK(b.lower_bound <= std::max(0.0, truth) + 1e-12);
        }
        // max_distance below the certified gap: "farther than" (+inf, the bound at least the cap), or
        // the distance of a pair the walk still met, beyond the cap
        if (truth > 2.0 * s.spacing) {
            const double cap = truth - s.spacing;
            const PCCD::Distance_result far = PCCD::distance(s.a, pose_a, s.b, pose_b, {.max_distance = cap, .certified_lower_bound = true});
            CHECK(far.distance >= cap);
            CHECK(far.lower_bound <= std::max(0.0, truth) + 1e-12);
            if (std::isinf(far.distance)) CHECK(far.lower_bound >= cap);
        }
    }
}

TEST_CASE("distance: certified_lower_bound holds where the surface spans a hole in its samples", "[proximity]")
{
    // A plane sampled with a hole of 2.5 mean spacings' radius: its surface is defined within the
    // hole's rim points' domain radii, so its zero set reaches into the hole farther from every
    // sample than the surface radius r(P) + 2 sigma. A small dense sphere hovers over the hole.
    PCCD::Random_engine engine(5);
    const std::size_t n = 20000;
    const double spacing = std::sqrt(4.0 / double(n));
    const double hole = 2.5 * spacing;
    std::vector<Eigen::Vector3d> plane;
    while (plane.size() < n) {
        const Eigen::Vector3d p(PCCD::uniform_real(engine, -1.0, 1.0), PCCD::uniform_real(engine, -1.0, 1.0), 0.0);
        if (p.head<2>().norm() >= hole) plane.push_back(p);
    }
    std::vector<Eigen::Vector3d> ball;
    const double radius = 0.3 * spacing;
    for (int i = 0; i < 3000; ++i) ball.push_back(radius * random_direction(engine));
    const PCCD::Point_cloud_object<> a(plane);
    const PCCD::Point_cloud_object<> b(ball);
    const Rigid_transform_3<double> pose_a;
    const Rigid_transform_3<double> pose_b(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, radius + 0.3 * spacing));

    // The zero set of the plane inside the hole: the first point of a ray from the centre where f
    // is defined, projected; and the sphere's lowest surface point.
    std::optional<Eigen::Vector3d> za;
    for (double x = 0.0; x < hole && !za; x += 0.01 * spacing) za = onto_surface(a, Eigen::Vector3d(x, 0.0, 0.0));
    REQUIRE(za);
    const std::optional<Eigen::Vector3d> zb = onto_surface(b, Eigen::Vector3d(0.0, 0.0, -radius));
    REQUIRE(zb);
    double nearest_sample = std::numeric_limits<double>::infinity();
    for (const auto& p : plane) nearest_sample = std::min(nearest_sample, (p - *za).norm());
    // the scenario: this zero-set point lies farther from the samples than r(P) + 2 sigma
    REQUIRE(nearest_sample > a.sampling_radius() + 2.0 * a.noise_estimate());
    const double surfaces_apart_at_most = (pose_b.transform_point(*zb) - *za).norm();

    const PCCD::Distance_result r = PCCD::distance(a, pose_a, b, pose_b, {.certified_lower_bound = true});
    INFO("zero set " << nearest_sample / spacing << " spacings from the samples; surfaces at most " << surfaces_apart_at_most
                     << " apart; certified lower bound " << r.lower_bound);
    REQUIRE(r.status == PCCD::Intersection_status::separate);
    CHECK(r.lower_bound <= surfaces_apart_at_most);
    const PCCD::Clearance_result c =
        PCCD::within_distance(a, pose_a, b, pose_b, 2.0 * surfaces_apart_at_most, {.certified_lower_bound = true});
    CHECK(c.lower_bound <= surfaces_apart_at_most);
}

TEST_CASE("distance: bad arguments are refused with a clear message", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Rigid_transform_3<double> id;
    using Catch::Matchers::Contains;
    CHECK_THROWS_WITH(PCCD::within_distance(s.a, id, s.b, id, -1.0), Contains("margin"));
    CHECK_THROWS_WITH(PCCD::distance(s.a, id, s.b, id, {.absolute_tolerance = -1.0}), Contains("absolute_tolerance"));
    CHECK_THROWS_WITH(PCCD::distance(s.a, id, s.b, id, {.relative_tolerance = std::nan("")}), Contains("relative_tolerance"));
    CHECK_THROWS_WITH(PCCD::distance(s.a, id, s.b, id, {.max_distance = -0.1}), Contains("max_distance"));
    CHECK_THROWS_WITH(PCCD::distance(s.a, id, s.b, id, {.max_node_pairs = 0}), Contains("max_node_pairs"));
}
