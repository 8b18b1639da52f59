// Tests of the hierarchy traversals of PCCD/Intersection (Intersection_options::traversal, the
// separation test of do_intersect.h and the time budget) against analytic truth: two unit spheres
// whose centres are d apart intersect exactly when d < 2. The traversals must agree with the flat
// traversal (the published method), never answer "separate" for an undecided query, and never lose
// a contact when the budget grows.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "../surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;

struct Spheres {
    PCCD::Point_cloud_object<> a, b;
    double r; // the larger sampling radius
};

const Spheres& spheres()
{
    static const Spheres s = [] {
        const auto sa = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 21);
        const auto sb = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 22);
        PCCD::Point_cloud_object<> a(pccd_test::columns(sa.points));
        PCCD::Point_cloud_object<> b(pccd_test::columns(sb.points));
        const double r = std::max(a.sampling_radius(), b.sampling_radius());
        return Spheres{std::move(a), std::move(b), r};
    }();
    return s;
}

struct Pose {
    Rigid_transform_3<double> a, b;
    double d;
};

/// Random rotations about each centre, centres d apart along a random direction, d uniform in [0, 2.6].
std::vector<Pose> poses(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    std::vector<Pose> out;
    for (std::size_t k = 0; k < n; ++k) {
        const double d = PCCD::uniform_real(engine, 0.0, 2.6);
        const Eigen::Matrix3d ra = PCCD::testing::uniform_random_rotation(engine);
        const Eigen::Matrix3d rb = PCCD::testing::uniform_random_rotation(engine);
        const Eigen::Vector3d direction = PCCD::testing::uniform_random_rotation(engine).col(0);
        out.push_back({Rigid_transform_3<double>(ra, Eigen::Vector3d::Zero()), Rigid_transform_3<double>(rb, d * direction), d});
    }
    return out;
}

} // namespace

TEST_CASE("Hierarchy traversals agree with the flat traversal and the analytic truth", "[hierarchy]")
{
    const Spheres& s = spheres();
    const std::vector<Pose> ps = poses(240, 5);
    for (const PCCD::Traversal traversal : {PCCD::Traversal::depth_first, PCCD::Traversal::likelihood}) {
        std::size_t agree = 0, wrong = 0, counted = 0, cheaper = 0;
        for (std::size_t k = 0; k < ps.size(); ++k) {
            const Pose& p = ps[k];
            const auto flat = PCCD::do_intersect(s.a, p.a, s.b, p.b, {.seed = k, .traversal = PCCD::Traversal::flat});
            const auto walked = PCCD::do_intersect(s.a, p.a, s.b, p.b, {.seed = k, .traversal = traversal});
            CHECK(walked.status != PCCD::Intersection_status::undecided);
            agree += flat.intersects == walked.intersects ? 1 : 0;
            cheaper += walked.counters.f_evaluations <= flat.counters.f_evaluations ? 1 : 0;
            // Grazing band: the spheres' gap or overlap is below two sampling radii.
            if (std::abs(p.d - 2.0) < 2.0 * s.r) continue;
            ++counted;
            wrong += walked.intersects != (p.d < 2.0) ? 1 : 0;
            if (walked.intersects != (p.d < 2.0) || flat.intersects != (p.d < 2.0)) std::printf("pose %zu d %.4f (2 r %.4f): flat %d walked %d\n", k, p.d, 2 * s.r, int(flat.intersects), int(walked.intersects));
        }
        std::printf("traversal %d: agrees with flat on %zu / %zu poses, %zu wrong of %zu outside the grazing band, "
                    "%zu with no more f evaluations than flat\n",
                    int(traversal), agree, ps.size(), wrong, counted, cheaper);
        CHECK(double(agree) >= 0.99 * double(ps.size()));
        CHECK(wrong == 0);
        CHECK(counted >= 200);
    }
}

TEST_CASE("The predicted covering takes fewer samples and keeps the verdicts", "[hierarchy]")
{
    // Interpolation_search::walk_predicted_cover: annulus points predicted on a sample's side of
    // the other surface are covered as if sampled. Against the walk without it (+infinity) and the
    // analytic truth: the same verdicts outside the grazing band, and fewer samples on misses, where
    // the walk samples everything within reach.
    const Spheres& s = spheres();
    const PCCD::Interpolation_search off{.walk_predicted_cover = std::numeric_limits<double>::infinity()};
    const PCCD::Interpolation_search on{};
    REQUIRE(on.walk_predicted_cover == 0.5);
    const std::vector<Pose> ps = poses(240, 7);
    std::size_t wrong_on = 0, wrong_off = 0, samples_on = 0, samples_off = 0, near = 0, differ = 0;
    for (std::size_t k = 0; k < ps.size(); ++k) {
        const Pose& p = ps[k];
        // The walk's own samples: without the certification pass of a "separate", which is the
        // same complete search for both.
        const auto with = PCCD::do_intersect(s.a, p.a, s.b, p.b, {.seed = k, .certify_separation = false}, on);
        const auto without = PCCD::do_intersect(s.a, p.a, s.b, p.b, {.seed = k, .certify_separation = false}, off);
        differ += with.intersects != without.intersects ? 1 : 0;
        if (p.d > 2.0 && !with.intersects && !without.intersects) { // misses: all within reach is sampled
            ++near;
            samples_on += with.counters.samples;
            samples_off += without.counters.samples;
        }
        if (std::abs(p.d - 2.0) < 2.0 * s.r) continue; // grazing band
        wrong_on += with.intersects != (p.d < 2.0) ? 1 : 0;
        wrong_off += without.intersects != (p.d < 2.0) ? 1 : 0;
    }
    // Near misses head on, gaps of 0.2 to 1.2 sampling radii: separate with either walk (the gap is
    // known, and f_B is about the distance to sphere B).
    const Rigid_transform_3<double> identity(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    for (const double g : {0.2, 0.5, 0.8, 1.2}) {
        const Rigid_transform_3<double> apart(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0 + g * s.r, 0, 0));
        const auto with = PCCD::do_intersect(s.a, identity, s.b, apart, {.certify_separation = false}, on);
        const auto without = PCCD::do_intersect(s.a, identity, s.b, apart, {.certify_separation = false}, off);
        CHECK_FALSE(with.intersects);
        CHECK_FALSE(without.intersects);
        ++near;
        samples_on += with.counters.samples;
        samples_off += without.counters.samples;
    }
    std::printf("predicted covering: %zu / %zu verdicts differ; wrong outside the grazing band %zu (off: %zu); "
                "samples on %zu misses %zu (off: %zu)\n",
                differ, ps.size(), wrong_on, wrong_off, near, samples_on, samples_off);
    CHECK(wrong_on == 0);
    CHECK(wrong_off == 0);
    CHECK(double(differ) <= 0.01 * double(ps.size()));
    REQUIRE(near >= 10);
    CHECK(samples_off > 0);
    CHECK(double(samples_on) <= 0.8 * double(samples_off));
}

TEST_CASE("Objects whose reaches cannot meet are separate without an f evaluation", "[hierarchy]")
{
    const Spheres& s = spheres();
    const double largest_reach = std::max(s.a.hierarchy().root().reach, s.b.hierarchy().root().reach);
    const Rigid_transform_3<double> identity(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    // Just beyond where two points could lie within contact_core times the sum of their reaches.
    const PCCD::Intersection_options options{};
    const double d = 2.0 + 2.0 * options.contact_core * largest_reach + 0.01;
    const Rigid_transform_3<double> apart(Eigen::Matrix3d::Identity(), Eigen::Vector3d(d, 0, 0));
    const auto result = PCCD::do_intersect(s.a, identity, s.b, apart, options);
    CHECK(result.status == PCCD::Intersection_status::separate);
    CHECK(result.counters.f_evaluations == 0);
    CHECK(result.counters.node_pairs > 0);
    // The same pose answered by the flat traversal: the same verdict.
    CHECK_FALSE(PCCD::do_intersect(s.a, identity, s.b, apart, {.traversal = PCCD::Traversal::flat}).intersects);
}

TEST_CASE("Growing budgets never lose a contact, and a spent budget is undecided, never separate", "[hierarchy]")
{
    const Spheres& s = spheres();
    const std::vector<Pose> ps = poses(40, 9);
    std::size_t undecided = 0;
    for (std::size_t k = 0; k < ps.size(); ++k) {
        const Pose& p = ps[k];
        const auto full = PCCD::do_intersect(s.a, p.a, s.b, p.b, {.seed = k});
        bool found = false;
        for (std::size_t budget = 1; budget <= 1024; budget *= 2) {
            const auto limited = PCCD::do_intersect(s.a, p.a, s.b, p.b, {.seed = k, .max_f_evaluations = budget});
            if (found) CHECK(limited.intersects);
            found = found || limited.intersects;
            if (limited.counters.f_evaluations >= budget) {
                CHECK(limited.status != PCCD::Intersection_status::separate);
                undecided += limited.status == PCCD::Intersection_status::undecided ? 1 : 0;
            }
            if (limited.intersects) CHECK(full.intersects); // a budget only cuts the same walk short
        }
        CHECK(found == full.intersects);
    }
    CHECK(undecided > 0);
}

TEST_CASE("A time budget that runs out first gives undecided", "[hierarchy]")
{
    const Spheres& s = spheres();
    const Rigid_transform_3<double> identity(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    // A near miss: the reaches meet, so the query has work to do.
    const Rigid_transform_3<double> near(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0 + 0.5 * s.r, 0, 0));
    const auto result = PCCD::do_intersect(s.a, identity, s.b, near, {.max_time_us = 1e-3});
    CHECK(result.status == PCCD::Intersection_status::undecided);
    CHECK_FALSE(result.intersects);
    CHECK(std::string(PCCD::to_string(result.status)) == "undecided");
    // Invalid time budgets and traversals are rejected with a message naming the field.
    CHECK_THROWS_WITH(PCCD::do_intersect(s.a, identity, s.b, near, {.max_time_us = 0.0}),
                      Catch::Matchers::Contains("max_time_us"));
    CHECK_THROWS_WITH(PCCD::do_intersect(s.a, identity, s.b, near, {.max_time_us = std::nan("")}),
                      Catch::Matchers::Contains("max_time_us"));
    CHECK_THROWS_WITH(PCCD::do_intersect(s.a, identity, s.b, near, {.traversal = PCCD::Traversal(9)}),
                      Catch::Matchers::Contains("unknown traversal"));
}

TEST_CASE("Objects already in one frame need no poses", "[intersection]")
{
    const Spheres& s = spheres();
    const Rigid_transform_3<double> identity(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    // Two unit spheres at the same centre: coincident surfaces, reported intersecting.
    const auto posed = PCCD::do_intersect(s.a, identity, s.b, identity, {.seed = 3});
    const auto plain = PCCD::do_intersect(s.a, s.b, {.seed = 3});
    CHECK(plain.intersects == posed.intersects);
    CHECK(plain.counters == posed.counters);
    const auto curve = PCCD::intersection_points(s.a, s.b, {.seed = 3});
    CHECK(curve.counters == PCCD::intersection_points(s.a, identity, s.b, identity, {.seed = 3}).counters);
}

TEST_CASE("The interpolation search's closest estimate measures the gap of a near miss", "[hierarchy]")
{
    // Two unit spheres whose centres are 2 + g apart: every point of A is at least g from sphere B,
    // and f_B is the signed distance to B up to the surface's error (a small fraction of r on a
    // clean sphere), so the smallest |f_B| over points of A cannot fall much below g.
    const Spheres& s = spheres();
    const Rigid_transform_3<double> identity(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    std::size_t estimated = 0;
    for (const double g : {0.2, 0.5, 0.8, 1.2}) {
        const Rigid_transform_3<double> pose_b(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0 + g * s.r, 0, 0));
        for (const PCCD::Traversal traversal : {PCCD::Traversal::flat, PCCD::Traversal::likelihood}) {
            const auto result = PCCD::do_intersect(s.a, identity, s.b, pose_b, {.seed = 4, .traversal = traversal});
            INFO("gap " << g << " r, traversal " << int(traversal) << ": estimate " << result.closest_estimate / s.r
                        << " r, " << result.counters.f_evaluations << " f evaluations");
            REQUIRE_FALSE(std::isnan(result.closest_estimate));
            REQUIRE(result.status == PCCD::Intersection_status::separate);
            CHECK(result.counters.pending_node_pairs == 0); // a "separate" walk ran to its end
            if (std::isinf(result.closest_estimate)) continue; // no sample had f_B defined
            ++estimated;
            CHECK(result.closest_estimate >= g * s.r - 0.2 * s.r);
            // Samples cover the region within reach: the nearest sampled point is not far off.
            CHECK(result.closest_estimate <= g * s.r + 1.5 * s.r);
        }
    }
    CHECK(estimated >= 4);
    // A spent budget still reports what it saw: finite or +infinity, never NaN.
    const Rigid_transform_3<double> near(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0 + 0.3 * s.r, 0, 0));
    const auto cut = PCCD::do_intersect(s.a, identity, s.b, near, {.max_f_evaluations = 3});
    CHECK(cut.status == PCCD::Intersection_status::undecided);
    CHECK_FALSE(std::isnan(cut.closest_estimate));
    // Cut inside the walk (no probes first): it says how many node pairs it left.
    const auto walked = PCCD::do_intersect(s.a, identity, s.b, near, {.max_f_evaluations = 5},
                                           PCCD::Interpolation_search{.probe_draws = 0});
    CHECK(walked.status == PCCD::Intersection_status::undecided);
    CHECK(walked.counters.pending_node_pairs > 0);
}
