// Tests of clearance() along a path (doc/manual/proximity.md "Clearance along a path") against
// analytic truth: a sampled unit sphere moved along a line past another one (surface distance
// |c| - 2 in closed form) and down onto a sampled plane patch (distance h - 1). The tolerance is
// the accuracy of distance() on these clouds stated by its own tests (test/Proximity/distance_test.cpp:
// every error at most 0.5 mean spacings): a pose farther than that from the margin must be placed
// on its analytic side, so the first pose below the margin is the analytic one when the path steps
// over the margin by more than that, and lies in the analytic band of width 2 x 0.5 spacings when it
// steps finely. Also: thread-count independence, the seeds of distance_many(), the cap, budgets
// that never mislabel a pose, and bad input.
// Also covers Proximity/Clearance_options.h and Proximity/Clearance_profile.h.
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Proximity/Clearance_options.h>
#include <PCCD/Proximity/Clearance_profile.h>
#include <PCCD/Proximity/clearance.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/testing/Plane_patch_shape.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "proximity_test_helpers.h"

namespace {

using PCCD::Clearance_status;
using PCCD::Rigid_transform_3;
using namespace pccd_test;

/// The accuracy of distance() on the sampled spheres, in mean spacings (distance_test.cpp).
constexpr double accuracy = 0.5;

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

bool same(const PCCD::Clearance_sample& x, const PCCD::Clearance_sample& y)
{
    bool ok = x.status == y.status && same_bits(x.clearance, y.clearance) && same_bits(x.lower_bound, y.lower_bound) &&
              same_bits(x.upper_bound, y.upper_bound) && same_bits(x.depth, y.depth) && x.counters == y.counters;
    for (int d = 0; d < 3; ++d)
        ok = ok && same_bits(x.point_object(d), y.point_object(d)) && same_bits(x.point_scene(d), y.point_scene(d));
    return ok;
}

/// A straight path of the sphere's centre along `dir`, at surface gaps gaps[i] from the sphere at
/// the origin (centre (2 + gap) dir), each pose with its own random rotation.
std::vector<Rigid_transform_3<double>> sphere_path(const std::vector<double>& gaps, const Eigen::Vector3d& dir)
{
    std::vector<Rigid_transform_3<double>> poses;
    for (std::size_t i = 0; i < gaps.size(); ++i) poses.push_back(centred_at((2.0 + gaps[i]) * dir, 700 + i));
    return poses;
}

/// The analytic first index whose gap is below `limit`, if any.
std::optional<std::size_t> first_below(const std::vector<double>& gaps, double limit)
{
    for (std::size_t i = 0; i < gaps.size(); ++i)
        if (gaps[i] < limit) return i;
    return std::nullopt;
}

/// Every sample on its analytic side of the margin, up to the accuracy; the interval holds the gap.
void check_against_gaps(const PCCD::Clearance_profile& p, const std::vector<double>& gaps, double margin, double spacing)
{
    REQUIRE(p.samples.size() == gaps.size());
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        const PCCD::Clearance_sample& s = p.samples[i];
        const double g = gaps[i];
        INFO("pose " << i << " gap " << g / spacing << " spacings, status " << PCCD::to_string(s.status) << ", clearance "
                     << s.clearance / spacing << " spacings");
        if (g >= margin + accuracy * spacing) CHECK((s.status == Clearance_status::clear || s.status == Clearance_status::beyond_cap));
        if (g < margin - accuracy * spacing && g > accuracy * spacing) CHECK(s.status == Clearance_status::below_margin);
        if (g < -3.0 * spacing) CHECK(s.status == Clearance_status::intersecting);
        if (s.status == Clearance_status::clear || s.status == Clearance_status::below_margin) {
            CHECK(std::abs(s.clearance - std::max(g, 0.0)) <= accuracy * spacing);
            CHECK(s.lower_bound <= g + accuracy * spacing);
            CHECK(s.upper_bound >= g - accuracy * spacing);
            CHECK((s.point_object - s.point_scene).norm() == Approx(s.clearance).epsilon(1e-12));
        }
        if (s.status == Clearance_status::intersecting) {
            CHECK(s.clearance == 0.0);
            CHECK(g < accuracy * spacing);
        }
        CHECK(s.status != Clearance_status::undecided); // no budget
    }
}

} // namespace

TEST_CASE("clearance: a sphere passing a sphere, the first pose below the margin is the analytic one", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Eigen::Vector3d dir = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
    const double margin = 7.0 * s.spacing;

    SECTION("coarse steps: two spacings, the margin one spacing from either neighbour")
    {
        std::vector<double> gaps; // 16, 14, ..., -6 spacings
        for (int k = 0; k <= 11; ++k) gaps.push_back((16.0 - 2.0 * k) * s.spacing);
        const auto poses = sphere_path(gaps, dir);
        const PCCD::Clearance_profile p = PCCD::clearance(s.b, s.a, poses, margin);
        check_against_gaps(p, gaps, margin, s.spacing);
        REQUIRE(p.first_below_margin);
        CHECK(*p.first_below_margin == *first_below(gaps, margin)); // exactly: 1 spacing > the accuracy
        CHECK(*p.first_below_margin == 5);                          // gap 6 spacings
        // its witnesses: on the scene sphere facing the object, on the object facing the scene
        const Eigen::Vector3d centre = (2.0 + gaps[5]) * dir;
        CHECK(p.first_point_object.allFinite());
        CHECK(std::abs(p.first_point_scene.norm() - 1.0) <= 0.25 * s.spacing);
        CHECK(std::abs((p.first_point_object - centre).norm() - 1.0) <= 0.25 * s.spacing);
        CHECK(degrees(p.first_point_scene, dir) <= 5.0);
        CHECK(degrees(p.first_point_object - centre, -dir) <= 5.0);
        CHECK(p.first_point_object == p.samples[5].point_object);
        // the minimum: an intersecting pose (clearance 0), the first of them
        REQUIRE(p.minimum);
        CHECK(p.minimum_clearance == 0.0);
        CHECK(p.samples[*p.minimum].status == Clearance_status::intersecting);
        CHECK(gaps[*p.minimum] < accuracy * s.spacing);
        // counters: every pose counted once, the work summed
        const auto& c = p.counters;
        CHECK(c.clear + c.below_margin + c.intersecting + c.beyond_cap + c.undecided == gaps.size());
        CHECK(c.clear >= 4); // gaps 16..10
        CHECK(c.intersecting >= 2); // gaps -4, -6
        std::size_t node_pairs = 0, f = 0;
        for (const auto& sample : p.samples) {
            node_pairs += sample.counters.node_pairs;
            f += sample.counters.intersection.f_evaluations;
        }
        CHECK(c.work.node_pairs == node_pairs);
        CHECK(c.work.intersection.f_evaluations == f);
        CHECK(!p.all_clear());
        CHECK(p.margin == margin);
    }

    SECTION("fine steps: a tenth of a spacing, the first pose within the stated band")
    {
        std::vector<double> gaps; // 10 down to 4 spacings
        for (int k = 0; k <= 60; ++k) gaps.push_back((10.0 - 0.1 * k) * s.spacing);
        const auto poses = sphere_path(gaps, dir);
        const PCCD::Clearance_profile p = PCCD::clearance(s.b, s.a, poses, margin, {.batch = {.threads = 2}});
        check_against_gaps(p, gaps, margin, s.spacing);
        REQUIRE(p.first_below_margin);
        const std::size_t earliest = *first_below(gaps, margin + accuracy * s.spacing);
        const std::size_t latest = *first_below(gaps, margin - accuracy * s.spacing);
        INFO("analytic first " << *first_below(gaps, margin) << ", found " << *p.first_below_margin);
        CHECK(*p.first_below_margin >= earliest);
        CHECK(*p.first_below_margin <= latest);
        // the minimum clearance: the last pose's gap, within the accuracy; its pose within one
        // accuracy of the analytic minimum on either side
        REQUIRE(p.minimum);
        CHECK(std::abs(p.minimum_clearance - gaps.back()) <= accuracy * s.spacing);
        CHECK(gaps[*p.minimum] <= gaps.back() + 2.0 * accuracy * s.spacing);
    }

    SECTION("there and back: the minimum at the turning point")
    {
        std::vector<double> gaps;
        for (int k = -10; k <= 10; ++k) gaps.push_back((3.0 + 0.8 * std::abs(k)) * s.spacing); // closest 3 spacings
        const auto poses = sphere_path(gaps, dir);
        const PCCD::Clearance_profile p = PCCD::clearance(s.b, s.a, poses, 2.0 * s.spacing);
        check_against_gaps(p, gaps, 2.0 * s.spacing, s.spacing);
        CHECK(!p.first_below_margin);
        CHECK(p.all_clear());
        REQUIRE(p.minimum);
        CHECK(std::abs(p.minimum_clearance - 3.0 * s.spacing) <= accuracy * s.spacing);
        CHECK(gaps[*p.minimum] <= 3.0 * s.spacing + 2.0 * accuracy * s.spacing);
    }
}

TEST_CASE("clearance: a sphere lowered onto a plane patch", "[proximity]")
{
    const PCCD::testing::Plane_patch_shape patch(Eigen::Vector3d(-3, -3, 0), Eigen::Vector3d(6, 0, 0), Eigen::Vector3d(0, 6, 0));
    const auto sample = sample_shape(patch, 20000, 0.0, 31);
    const PCCD::Point_cloud_object<> plane(columns(sample.points));
    const Sphere_pair& s = spheres();
    const double spacing = std::max(s.spacing, plane.cloud().mean_spacing());
    std::vector<double> gaps; // height of the sphere's bottom over the plane: 12 down to 1 spacings
    std::vector<Rigid_transform_3<double>> poses;
    for (int k = 0; k <= 22; ++k) {
        gaps.push_back((12.0 - 0.5 * k) * spacing);
        poses.push_back(centred_at(Eigen::Vector3d(0.2, -0.1, 1.0 + gaps.back()), 900 + k));
    }
    const double margin = 4.25 * spacing; // a quarter spacing off the path's steps
    const PCCD::Clearance_profile p = PCCD::clearance(s.b, plane, poses, margin);
    check_against_gaps(p, gaps, margin, spacing);
    REQUIRE(p.first_below_margin);
    const std::size_t earliest = *first_below(gaps, margin + accuracy * spacing);
    const std::size_t latest = *first_below(gaps, margin - accuracy * spacing);
    INFO("analytic first " << *first_below(gaps, margin) << ", found " << *p.first_below_margin);
    CHECK(*p.first_below_margin >= earliest);
    CHECK(*p.first_below_margin <= latest);
    // the witness on the plane lies under the sphere's centre, the object's at its bottom
    const Eigen::Vector3d under(0.2, -0.1, 0.0);
    CHECK((p.first_point_scene - under).norm() <= 0.1);
    CHECK(std::abs(p.first_point_scene.z()) <= 0.25 * spacing);
    CHECK(std::abs(p.first_point_object.z() - gaps[*p.first_below_margin]) <= accuracy * spacing);
}

TEST_CASE("clearance: the same samples whatever the thread count, each that of distance() with its seed", "[proximity]")
{
    const Sphere_pair& s = spheres();
    PCCD::Random_engine engine(41);
    std::vector<double> gaps;
    std::vector<Rigid_transform_3<double>> poses;
    for (int k = 0; k < 20; ++k) {
        gaps.push_back(s.spacing * (-8.0 + 24.0 * PCCD::uniform_01(engine)));
        poses.push_back(centred_at((2.0 + gaps.back()) * random_direction(engine), 800 + k));
    }
    const double margin = 4.0 * s.spacing;
    const PCCD::Clearance_options options{.max_distance = 12.0 * s.spacing,
                                          .distance = {.penetration = true},
                                          .batch = {.first_index = 5}};
    PCCD::Clearance_options one = options, two = options;
    one.batch.threads = 1;
    two.batch.threads = 2;
    const PCCD::Clearance_profile p1 = PCCD::clearance(s.b, s.a, poses, margin, one);
    const PCCD::Clearance_profile p2 = PCCD::clearance(s.b, s.a, poses, margin, two);
    REQUIRE(p1.samples.size() == poses.size());
    REQUIRE(p2.samples.size() == poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        CHECK(same(p1.samples[i], p2.samples[i]));
        PCCD::Distance_options single{.max_distance = options.max_distance, .penetration = true};
        single.intersection.seed = PCCD::pair_seed(single.intersection.seed, 5 + i);
        const PCCD::Distance_result d = PCCD::distance(s.b, poses[i], s.a, Rigid_transform_3<double>(), single);
        if (p1.samples[i].status == Clearance_status::beyond_cap) // reported as "farther than the cap"
            CHECK((d.distance > *options.max_distance && p1.samples[i].clearance == std::numeric_limits<double>::infinity()));
        else
            CHECK(same_bits(p1.samples[i].clearance, d.distance));
        CHECK(same_bits(p1.samples[i].lower_bound, d.lower_bound));
        CHECK(same_bits(p1.samples[i].upper_bound, d.upper_bound));
        CHECK(p1.samples[i].counters == d.counters);
        if (d.intersecting()) CHECK(same_bits(p1.samples[i].depth, d.depth));
    }
    CHECK(p1.first_below_margin == p2.first_below_margin);
    CHECK(p1.minimum == p2.minimum);
    CHECK(same_bits(p1.minimum_clearance, p2.minimum_clearance));
    CHECK(p1.counters.work == p2.counters.work);
    // intersecting poses with penetration carry the depth: the overlap -gap, within the accuracy
    for (std::size_t i = 0; i < poses.size(); ++i)
        if (p1.samples[i].status == Clearance_status::intersecting && gaps[i] < -3.0 * s.spacing)
            CHECK(std::abs(p1.samples[i].depth + gaps[i]) <= 2.0 * accuracy * s.spacing);
}

TEST_CASE("clearance: the cap", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Eigen::Vector3d dir(0.0, 0.0, 1.0);
    std::vector<double> gaps;
    for (int k = 0; k <= 10; ++k) gaps.push_back((20.0 - 2.0 * k) * s.spacing); // 20 .. 0
    const auto poses = sphere_path(gaps, dir);
    const double cap = 9.0 * s.spacing, margin = 3.0 * s.spacing;
    const PCCD::Clearance_profile p = PCCD::clearance(s.b, s.a, poses, margin, {.max_distance = cap});
    CHECK(p.max_distance == cap);
    // the walk prunes beyond the cap plus both surface radii: farther than that nothing is measured
    const double radii = s.a.sampling_radius() + 2.0 * s.a.noise_estimate() + s.b.sampling_radius() + 2.0 * s.b.noise_estimate();
    std::size_t pruned = 0;
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        const PCCD::Clearance_sample& x = p.samples[i];
        INFO("pose " << i << " gap " << gaps[i] / s.spacing << " spacings: " << PCCD::to_string(x.status));
        if (gaps[i] > cap + accuracy * s.spacing) {
            CHECK(x.status == Clearance_status::beyond_cap);
            CHECK(x.clearance == std::numeric_limits<double>::infinity());
        }
        if (gaps[i] > cap + radii + accuracy * s.spacing) {
            CHECK(x.lower_bound >= cap);
            CHECK(x.counters.f_evaluations == 0);
            CHECK(!x.point_object.allFinite());
            ++pruned;
        }
        if (gaps[i] < cap - accuracy * s.spacing) CHECK(x.status != Clearance_status::beyond_cap);
    }
    CHECK(pruned >= 2);
    CHECK(p.counters.beyond_cap >= 5);
    // every pose beyond the cap: no minimum, nothing below the margin, all clear
    const std::vector<Rigid_transform_3<double>> far(poses.begin(), poses.begin() + 4);
    const PCCD::Clearance_profile q = PCCD::clearance(s.b, s.a, far, margin, {.max_distance = cap});
    CHECK(q.counters.beyond_cap == 4);
    CHECK(!q.minimum);
    CHECK(q.minimum_clearance == std::numeric_limits<double>::infinity());
    CHECK(q.all_clear());
}

TEST_CASE("clearance: budgets leave poses undecided but never on the wrong side", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const Eigen::Vector3d dir(1.0, 0.0, 0.0);
    std::vector<double> gaps;
    for (int k = 0; k <= 12; ++k) gaps.push_back((14.0 - 1.5 * k) * s.spacing);
    const auto poses = sphere_path(gaps, dir);
    const double margin = 6.0 * s.spacing;
    for (const std::size_t budget : {std::size_t(1), std::size_t(50), std::size_t(400)}) {
        const PCCD::Clearance_profile p =
            PCCD::clearance(s.b, s.a, poses, margin, {.distance = {.max_f_evaluations = budget}});
        std::size_t undecided = 0;
        for (std::size_t i = 0; i < gaps.size(); ++i) {
            const PCCD::Clearance_sample& x = p.samples[i];
            INFO("budget " << budget << " pose " << i << " gap " << gaps[i] / s.spacing << ": " << PCCD::to_string(x.status));
            if (x.status == Clearance_status::clear) CHECK(gaps[i] >= margin - accuracy * s.spacing);
            if (x.status == Clearance_status::below_margin) CHECK(gaps[i] < margin + accuracy * s.spacing);
            if (x.status == Clearance_status::intersecting) CHECK(gaps[i] < accuracy * s.spacing);
            CHECK(x.lower_bound <= std::max(gaps[i], 0.0) + accuracy * s.spacing);
            undecided += x.status == Clearance_status::undecided;
        }
        CHECK(p.counters.undecided == undecided);
        if (undecided > 0) CHECK(p.first_undecided);
        if (budget == 1) CHECK(undecided > 0);
    }
}

TEST_CASE("clearance: an empty path, bad input", "[proximity]")
{
    const Sphere_pair& s = spheres();
    const std::vector<Rigid_transform_3<double>> none;
    const PCCD::Clearance_profile e = PCCD::clearance(s.b, s.a, none, 0.1);
    CHECK(e.samples.empty());
    CHECK(!e.first_below_margin);
    CHECK(!e.minimum);
    CHECK(e.all_clear());
    CHECK(e.counters.work == PCCD::Distance_counters{});

    const std::vector<Rigid_transform_3<double>> poses{centred_at(Eigen::Vector3d(3, 0, 0), 1)};
    using Catch::Matchers::Contains;
    CHECK_THROWS_AS(PCCD::clearance(s.b, s.a, poses, -0.1), PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, -0.1), Contains("margin"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, std::nan("")), Contains("margin"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, std::numeric_limits<double>::infinity()), Contains("margin"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, none, -1.0), Contains("margin")); // even with no pose
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, 0.5, {.max_distance = 0.25}), Contains("below the margin"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, 0.5, {.max_distance = -1.0}), Contains("max_distance"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, 0.5, {.distance = {.max_distance = 1.0}}),
                      Contains("Clearance_options::max_distance"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, 0.5, {.distance = {.relative_tolerance = -1.0}}),
                      Contains("relative_tolerance"));
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, 0.5, {.batch = {.threads = 0}}), Contains("threads"));
    PCCD::Intersection_visitor visitor;
    PCCD::Clearance_options with_visitor;
    with_visitor.distance.intersection.visitor = &visitor;
    CHECK_THROWS_WITH(PCCD::clearance(s.b, s.a, poses, 0.5, with_visitor), Contains("visitor"));
    // a NaN pose cannot even be built: Rigid_transform_3 refuses it, as a non-rigid matrix
    const double nan = std::nan("");
    CHECK_THROWS_AS(Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(nan, 0, 0)), PCCD::Invalid_input);
    CHECK_THROWS_AS(Rigid_transform_3<double>(2.0 * Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), PCCD::Invalid_input);
}
