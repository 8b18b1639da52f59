// Tests of "separate is earned" (Intersection_options::certify_separation, doc/manual/intersection.md
// "When PCCD says separate") against analytic truth: a unit sphere posed around a torus (major
// radius 1, minor 0.4, axis z), with the sphere's centre outside the torus' tube, so the exact gap of
// the two surfaces is (distance from the centre to the torus) - 1. Both are sampled sparsely and
// with noise. Each cause of a missed contact found in the CAD validation has its regression test:
// the walk's shortcuts (one truth for both queries, the walk's completion), the verification
// rejecting true crossings (the crossing rule), and the rule's limits (separated poses stay separate,
// budgets never give "separate").
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../build_helpers.h"
#include "../surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using Object = PCCD::Point_cloud_object<>;

struct Pair {
    Object sphere, torus;
    double r; // the larger sampling radius
};

/// Sparse noisy clouds (noise 0.3 mean spacings): where shortcuts and the verification lose contacts.
const Pair& sparse_pair()
{
    static const Pair p = [] {
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 600, 0.3, 31);
        const auto t = pccd_test::sample_shape(pccd_test::test_torus(), 900, 0.3, 32);
        Object sphere(pccd_test::columns(s.points)), torus(pccd_test::columns(t.points));
        const double r = std::max(sphere.sampling_radius(), torus.sampling_radius());
        return Pair{std::move(sphere), std::move(torus), r};
    }();
    return p;
}

/// Distance from x to the torus surface (major radius 1, minor 0.4, axis z), signed: < 0 inside.
double torus_distance(const Eigen::Vector3d& x)
{
    const double ring = std::hypot(x.x(), x.y()) - 1.0;
    return std::hypot(ring, x.z()) - 0.4;
}

struct Pose {
    Rigid_transform_3<double> sphere; // the torus stays at the identity
    double gap;                       // exact signed gap of the two surfaces: < 0 when they cross
};

/// The sphere's centre uniform in a box around the torus (outside the tube), random rotations.
std::vector<Pose> poses(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    std::vector<Pose> out;
    while (out.size() < n) {
        const Eigen::Vector3d c(PCCD::uniform_real(engine, -2.6, 2.6), PCCD::uniform_real(engine, -2.6, 2.6),
                                PCCD::uniform_real(engine, -1.6, 1.6));
        const double d = torus_distance(c);
        if (d < 0.0) continue; // centre inside the tube: nesting cases, left out
        out.push_back({Rigid_transform_3<double>(PCCD::testing::uniform_random_rotation(engine), c), d - 1.0});
    }
    return out;
}

/// A near miss the walk itself cannot decide: the sphere's surface a fraction of r from the torus
/// (the smallest of a few gaps where do_intersect answers separate after evaluating f).
Rigid_transform_3<double> near_miss(const Pair& p)
{
    for (const double g : {0.8, 1.0, 1.2, 1.5, 2.0}) {
        const Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.4 + g * p.r, 0.0, 0.0));
        const auto r = PCCD::do_intersect(p.sphere, pose, p.torus, Rigid_transform_3<double>());
        if (r.status == PCCD::Intersection_status::separate && r.counters.f_evaluations > 4) return pose;
    }
    FAIL("no near miss with evaluations of f among the gaps tried");
    return {};
}

} // namespace

TEST_CASE("One truth: do_intersect says intersecting whenever intersection_points finds a point",
          "[intersection][certify]")
{
    const Pair& p = sparse_pair();
    const std::vector<Pose> ps = poses(pccd_test::by_build<std::size_t>(300, 60), 3);
    std::size_t found = 0, violations = 0, missed_without = 0;
    for (const PCCD::Traversal traversal : {PCCD::Traversal::likelihood, PCCD::Traversal::depth_first, PCCD::Traversal::flat}) {
        for (std::size_t k = 0; k < ps.size(); ++k) {
            const PCCD::Intersection_options options{.seed = k, .traversal = traversal};
            const Rigid_transform_3<double> identity;
            const auto all = PCCD::intersection_points(p.sphere, ps[k].sphere, p.torus, identity, options);
            if (all.points.empty()) continue;
            ++found;
            const auto first = PCCD::do_intersect(p.sphere, ps[k].sphere, p.torus, identity, options);
            violations += first.intersects ? 0 : 1;
            PCCD::Intersection_options off = options;
            off.certify_separation = false;
            missed_without += PCCD::do_intersect(p.sphere, ps[k].sphere, p.torus, identity, off).intersects ? 0 : 1;
        }
    }
    std::printf("one truth: %zu poses where intersection_points finds a point; do_intersect disagrees on %zu "
                "(without the certification: %zu)\n",
                found, violations, missed_without);
    CHECK(found > pccd_test::by_build<std::size_t>(100, 15)); // Debug: a fifth of the poses
    CHECK(violations == 0);
}

TEST_CASE("A crossing the verification rejects answers intersecting, separate poses stay separate",
          "[intersection][certify]")
{
    // A verification tolerance no projection reaches (far below rounding): every candidate is rejected, so every contact
    // found rests on a crossing, and the crossing's point must lie near both analytic surfaces.
    const Pair& p = sparse_pair();
    const std::vector<Pose> ps = poses(pccd_test::by_build<std::size_t>(200, 50), 4);
    const Rigid_transform_3<double> identity;
    std::size_t crossing = 0, separated = 0, certified = 0, lost_without = 0, unverified = 0;
    for (std::size_t k = 0; k < ps.size(); ++k) {
        const Pose& pose = ps[k];
        const PCCD::Intersection_options options{.seed = k, .contact_tolerance = 1e-300};
        const auto r = PCCD::do_intersect(p.sphere, pose.sphere, p.torus, identity, options);
        INFO("pose " << k << ", gap " << pose.gap << ", r " << p.r);
        if (pose.gap < -2.0 * p.r) { // crossing clearly
            ++crossing;
            CHECK(r.intersects);
            REQUIRE(r.points.size() == 1);
            const auto& x = r.points.front();
            // A crossing, or (rarely) a projection that lands exactly on both zero sets.
            CHECK(x.kind == (r.counters.unverified_crossings == 1 ? PCCD::Intersection_point_kind::approximate
                                                                   : PCCD::Intersection_point_kind::refined));
            unverified += r.counters.unverified_crossings;
            CHECK(std::abs(torus_distance(x.position)) < 2.0 * p.r);
            CHECK(std::abs((x.position - pose.sphere.translation()).norm() - 1.0) < 2.0 * p.r);
            CHECK(std::isfinite(x.f_a));
            CHECK(std::isfinite(x.f_b));
            PCCD::Intersection_options off = options;
            off.certify_separation = false;
            lost_without += PCCD::do_intersect(p.sphere, pose.sphere, p.torus, identity, off).intersects ? 0 : 1;
        } else if (pose.gap > 2.0 * p.r) {
            ++separated;
            CHECK_FALSE(r.intersects);
            CHECK(r.status == PCCD::Intersection_status::separate);
            certified += r.counters.certification_passes;
        }
    }
    std::printf("crossing rule: %zu crossing poses (%zu answered by a crossing; lost without the certification: "
                "%zu), %zu separated (%zu certified by a search of the rest of the region)\n",
                crossing, unverified, lost_without, separated, certified);
    CHECK(crossing > pccd_test::by_build<std::size_t>(20, 4)); // Debug: a quarter of the poses
    CHECK(separated > pccd_test::by_build<std::size_t>(20, 5));
    CHECK(lost_without > crossing / 2); // the verification alone rejects them
    CHECK(unverified > crossing / 2);
}

TEST_CASE("The walk is completed only when it found nothing, the flat traversal and RST are certified by "
          "the complete search", "[intersection][certify]")
{
    const Pair& p = sparse_pair();
    const Rigid_transform_3<double> identity;
    // Deep overlap: the sphere's centre on the torus' core circle; far: 3.6 apart; and a near miss.
    const Rigid_transform_3<double> deep(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0));
    const Rigid_transform_3<double> far(Eigen::Matrix3d::Identity(), Eigen::Vector3d(5.0, 0.0, 0.0));
    const Rigid_transform_3<double> near = near_miss(p);
    const auto walk = [&](const Rigid_transform_3<double>& pose) { return PCCD::do_intersect(p.sphere, pose, p.torus, identity); };
    CHECK(walk(deep).intersects);
    CHECK(walk(deep).counters.certification_passes == 0);
    CHECK_FALSE(walk(far).intersects);
    CHECK(walk(far).counters.certification_passes == 0); // decided by the separation test
    CHECK(walk(far).counters.f_evaluations == 0);
    const auto miss = walk(near);
    CHECK_FALSE(miss.intersects);
    CHECK(miss.counters.certification_passes == 1);
    const auto walk_only = PCCD::do_intersect(p.sphere, near, p.torus, identity, {.certify_separation = false});
    CHECK(walk_only.counters.certification_passes == 0);
    CHECK(miss.counters.samples >= walk_only.counters.samples);
    // The flat traversal and RST: the complete interpolation search from the query's seed.
    const auto flat = PCCD::do_intersect(p.sphere, near, p.torus, identity, {.traversal = PCCD::Traversal::flat});
    CHECK_FALSE(flat.intersects);
    CHECK(flat.counters.certification_passes == 1);
    const auto rst = PCCD::do_intersect(p.sphere, near, p.torus, identity, {}, PCCD::Randomized_sampling{});
    CHECK_FALSE(rst.intersects);
    CHECK(rst.counters.certification_passes == 1);
    // Random partners: a sample's outcome depends on the engine, so the walk is not completed but
    // followed by the complete search from the query's seed.
    const auto random = PCCD::do_intersect(p.sphere, near, p.torus, identity, {},
                                           PCCD::Interpolation_search{.partner_choice = PCCD::Partner_choice::random});
    CHECK(random.counters.certification_passes == 1);
    CHECK(random.status != PCCD::Intersection_status::undecided);
    // Without verification (the published methods) nothing is certified.
    const auto published = PCCD::do_intersect(p.sphere, near, p.torus, identity, {.verify_contacts = false});
    CHECK(published.counters.certification_passes == 0);
}

TEST_CASE("Budgets: the certification draws on the query's budget and never turns it into separate",
          "[intersection][certify]")
{
    const Pair& p = sparse_pair();
    const Rigid_transform_3<double> identity;
    const Rigid_transform_3<double> near = near_miss(p);
    const auto full = PCCD::do_intersect(p.sphere, near, p.torus, identity);
    REQUIRE(full.status == PCCD::Intersection_status::separate);
    REQUIRE(full.counters.f_evaluations > 4);
    for (std::size_t k = 1; k < full.counters.f_evaluations; k += std::max<std::size_t>(1, full.counters.f_evaluations / 16)) {
        const auto limited = PCCD::do_intersect(p.sphere, near, p.torus, identity, {.max_f_evaluations = k});
        INFO("budget " << k << " of " << full.counters.f_evaluations);
        CHECK(limited.counters.f_evaluations <= k);
        CHECK(limited.status == PCCD::Intersection_status::undecided);
    }
}
