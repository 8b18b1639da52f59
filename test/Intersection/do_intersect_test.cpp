// Tests of the point cloud hierarchy, the overlap region and the stochastic intersection queries
// (doc/manual/intersection.md) against independent truths: brute force over leaves and points, and
// two analytic spheres whose intersection circle is known in closed form.
// Also covers Intersection/Interpolation_search.h, Intersection/Intersection_options.h: the test cases below exercise what they declare.
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/overlapping_leaves.h>
#include <PCCD/Intersection/Interpolation_search.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/pose_generator.h>

#include <PCCD/testing/statistics.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using Catch::Matchers::Contains;

Eigen::Matrix3Xd random_points(std::size_t n, std::uint64_t seed, double flat = 1.0)
{
    PCCD::Random_engine engine(seed);
    Eigen::Matrix3Xd p(3, Eigen::Index(n));
    for (Eigen::Index i = 0; i < p.cols(); ++i)
        p.col(i) = Eigen::Vector3d(PCCD::uniform_real(engine, -1, 1), PCCD::uniform_real(engine, -1, 1),
                                   flat * PCCD::uniform_real(engine, -1, 1));
    return p;
}

Rigid_transform_3<double> random_pose(std::uint64_t seed, double shift)
{
    PCCD::Random_engine engine(seed);
    const Eigen::Matrix3d r = PCCD::testing::uniform_random_rotation(engine);
    const Eigen::Vector3d t(PCCD::uniform_real(engine, -shift, shift), PCCD::uniform_real(engine, -shift, shift),
                            PCCD::uniform_real(engine, -shift, shift));
    return Rigid_transform_3<double>(r, t);
}

bool in_grown_box(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& q, double margin)
{
    return (q.array() >= box.min().array() - margin).all() && (q.array() <= box.max().array() + margin).all();
}

/// Two unit spheres sampled with n points each, the second centred at (d, 0, 0) by its pose.
struct Sphere_pair {
    PCCD::Point_cloud_object<> a;
    PCCD::Point_cloud_object<> b;
    double spacing;
};

const Sphere_pair& sphere_pair()
{
    static const Sphere_pair pair = [] {
        const auto sa = pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 11);
        const auto sb = pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 12);
        PCCD::Point_cloud_object<> a(pccd_test::columns(sa.points));
        PCCD::Point_cloud_object<> b(pccd_test::columns(sb.points));
        const double spacing = std::max(a.cloud().mean_spacing(), b.cloud().mean_spacing());
        return Sphere_pair{std::move(a), std::move(b), spacing};
    }();
    return pair;
}

Rigid_transform_3<double> shifted(double d) { return Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(d, 0, 0)); }

/// Distance from x to the circle where the unit spheres at 0 and (d, 0, 0) meet.
double distance_to_circle(const Eigen::Vector3d& x, double d)
{
    const double radius = std::sqrt(1.0 - d * d / 4.0);
    return std::hypot(x.x() - d / 2.0, std::hypot(x.y(), x.z()) - radius);
}

} // namespace

TEST_CASE("Point cloud hierarchy: every point in one leaf, tight boxes, logarithmic height", "[hierarchy]")
{
    for (std::size_t n : {1u, 2u, 17u, 1000u, 5003u}) {
        for (std::size_t leaf : {1u, 4u, 16u}) {
            const Eigen::Matrix3Xd p = random_points(n, 3 + n, n % 2 ? 1.0 : 0.0);
            const PCCD::Point_cloud_hierarchy h(p, {.leaf_size = leaf});
            std::vector<int> seen(n, 0);
            for (std::size_t i = 0; i < h.nodes().size(); ++i) {
                const auto& node = h.node(PCCD::Point_cloud_hierarchy::Index(i));
                Eigen::AlignedBox3d box;
                for (auto q : h.points_of(PCCD::Point_cloud_hierarchy::Index(i))) box.extend(p.col(q));
                CHECK(box.isApprox(node.box, 0.0));
                if (node.is_leaf()) {
                    CHECK(node.count <= std::max<std::size_t>(leaf, 1));
                    for (auto q : h.points_of(PCCD::Point_cloud_hierarchy::Index(i))) ++seen[q];
                } else {
                    const auto& l = h.node(h.left(PCCD::Point_cloud_hierarchy::Index(i)));
                    const auto& r = h.node(h.right(PCCD::Point_cloud_hierarchy::Index(i)));
                    CHECK(l.count + r.count == node.count);
                    CHECK(l.first == node.first);
                    CHECK(r.first == node.first + l.count);
                }
            }
            CHECK(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
            const double levels = n <= leaf ? 1.0 : std::ceil(std::log2(double(n) / double(leaf))) + 1.0;
            CHECK(double(h.height()) <= levels + 1.0);
        }
    }
    // All points identical: one leaf, whatever the leaf size.
    const Eigen::Matrix3Xd same = Eigen::Matrix3Xd::Ones(3, 100);
    CHECK(PCCD::Point_cloud_hierarchy(same).nodes().size() == 1);
}

TEST_CASE("Point cloud hierarchy rejects bad input", "[hierarchy]")
{
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(Eigen::Matrix3Xd(3, 0)), Contains("empty"));
    Eigen::Matrix3Xd p = random_points(10, 1);
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p, {.leaf_size = 0}), Contains("leaf_size"));
    p(1, 7) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p), Contains("point 7"));
    const auto sample = pccd_test::sample_shape(pccd_test::unit_sphere(), 50, 0.0, 1);
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>(pccd_test::columns(sample.points), PCCD::Identity_point_map<Eigen::Vector3d>(),
                                                 {.hierarchy = {.leaf_size = 0}}),
                      Contains("leaf_size"));
}

TEST_CASE("Overlapping leaves contain every leaf pair with a point inside the other box", "[hierarchy]")
{
    const Eigen::Matrix3Xd pa = random_points(600, 21), pb = random_points(500, 22, 0.2);
    const PCCD::Point_cloud_hierarchy a(pa, {.leaf_size = 8}), b(pb, {.leaf_size = 8});
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const Rigid_transform_3<double> a_to_b = random_pose(seed, 1.5);
        const double margin = 0.05 * double(seed % 4);
        std::set<std::pair<std::uint32_t, std::uint32_t>> reported;
        PCCD::for_each_overlapping_leaf_pair(a, b, a_to_b, margin, [&](auto i, auto j) { reported.emplace(i, j); });
        for (std::uint32_t i = 0; i < a.nodes().size(); ++i) {
            if (!a.node(i).is_leaf()) continue;
            for (std::uint32_t j = 0; j < b.nodes().size(); ++j) {
                if (!b.node(j).is_leaf()) continue;
                bool touching = false;
                for (auto p : a.points_of(i)) touching |= in_grown_box(b.node(j).box, a_to_b.transform_point(pa.col(p)), margin);
                if (touching) CHECK(reported.count({i, j}) == 1);
            }
        }
    }
}

TEST_CASE("The region sampler draws a uniform permutation of exactly the region points", "[intersection]")
{
    const Eigen::Matrix3Xd pa = random_points(3000, 31), pb = random_points(2000, 32, 0.1);
    const PCCD::Point_cloud_hierarchy a(pa), b(pb);
    const auto position = [&](std::uint32_t i) { return Eigen::Vector3d(pa.col(i)); };
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
        // Shifts from deep overlap (rejection phase throughout) to a small overlap (enumeration).
        const Rigid_transform_3<double> a_to_b = random_pose(seed, 0.3 * double(seed));
        const double margin = 0.03;
        std::set<std::uint32_t> truth;
        for (std::uint32_t p = 0; p < pa.cols(); ++p) {
            const Eigen::Vector3d q = a_to_b.transform_point(pa.col(p));
            for (std::uint32_t j = 0; j < b.nodes().size(); ++j)
                if (b.node(j).is_leaf() && in_grown_box(b.node(j).box, q, margin)) {
                    truth.insert(p);
                    break;
                }
        }
        PCCD::Intersection_counters counters;
        const auto listed = PCCD::internal::region_points(a, b, a_to_b, margin, PCCD::Overlap_region::leaf_boxes,
                                                          position, counters);
        CHECK(std::set<std::uint32_t>(listed.begin(), listed.end()) == truth);
        CHECK(listed.size() == truth.size());
        PCCD::internal::Region_sampler<decltype(position)> sampler(a, b, a_to_b, margin,
                                                                   PCCD::Overlap_region::leaf_boxes, position, counters);
        PCCD::Random_engine engine(seed);
        std::vector<std::uint32_t> drawn;
        std::uint32_t p;
        while (sampler.next(engine, p)) drawn.push_back(p);
        CHECK(drawn.size() == truth.size());
        CHECK(std::set<std::uint32_t>(drawn.begin(), drawn.end()) == truth);
        CHECK(sampler.region_size_known());
        CHECK(sampler.region_size() == Approx(double(truth.size())));
    }
}

TEST_CASE("Two spheres: do_intersect agrees with the analytic answer for both policies", "[intersection]")
{
    const Sphere_pair& s = sphere_pair();
    const double r = std::max(s.a.sampling_radius(), s.b.sampling_radius());
    // Centre distances: intersecting below 2, separate above; grazing within one sampling radius of
    // 2 is not asked.
    for (double d : {0.0, 0.4, 1.0, 1.6, 1.9, 2.0 - 1.5 * r, 2.0 + 1.5 * r, 2.3, 2.9, 4.0}) {
        const bool truth = d < 2.0;
        for (std::uint64_t seed = 0; seed < 5; ++seed) {
            INFO("d = " << d << ", seed " << seed);
            const PCCD::Intersection_options options{.seed = seed};
            const auto isearch = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(d), options);
            CHECK(isearch.intersects == truth);
            CHECK(isearch.status == (truth ? PCCD::Intersection_status::intersecting : PCCD::Intersection_status::separate));
            const auto rst = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(d), options,
                                                PCCD::Randomized_sampling{});
            CHECK(rst.intersects == truth);
            if (truth) {
                REQUIRE(isearch.points.size() == 1);
                REQUIRE(rst.points.size() == 1);
                // The first hit is a verified contact: projected onto both surfaces, so it lies near
                // both analytic spheres (within the surfaces' own error, a fraction of r).
                const Eigen::Vector3d x = isearch.points[0].position;
                CHECK(std::abs(x.norm() - 1.0) < 0.5 * r);
                CHECK(std::abs((x - Eigen::Vector3d(d, 0, 0)).norm() - 1.0) < 0.5 * r);
                const Eigen::Vector3d y = rst.points[0].position;
                CHECK(std::abs(y.norm() - 1.0) < 0.5 * r);
                CHECK(std::abs((y - Eigen::Vector3d(d, 0, 0)).norm() - 1.0) < 0.5 * r);
                CHECK(isearch.points[0].kind == PCCD::Intersection_point_kind::refined);
                CHECK(rst.points[0].kind == PCCD::Intersection_point_kind::refined);
                // Unverified (the published methods): an AIP and an RST sample, as found.
                PCCD::Intersection_options raw = options;
                raw.verify_contacts = false;
                CHECK(PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(d), raw,
                                         PCCD::Randomized_sampling{})
                          .points[0]
                          .kind == PCCD::Intersection_point_kind::sampled);
                CHECK(isearch.counters.brackets_found + 1 >= 1);
            }
            CHECK(isearch.counters.f_evaluations >= isearch.counters.search_steps);
        }
    }
}

TEST_CASE("Two spheres: intersection_points lie on the exact circle and cover it", "[intersection]")
{
    const Sphere_pair& s = sphere_pair();
    for (double d : {0.5, 1.2, 1.8}) {
        for (PCCD::Refinement refinement : {PCCD::Refinement::projection, PCCD::Refinement::sampling, PCCD::Refinement::none}) {
            INFO("d = " << d << ", refinement " << int(refinement));
            const auto result = PCCD::intersection_points(s.a, Rigid_transform_3<double>(), s.b, shifted(d),
                                                          {.seed = 3, .refinement = refinement});
            REQUIRE(result.intersects);
            std::vector<double> errors;
            for (const auto& p : result.points) errors.push_back(distance_to_circle(p.position, d));
            std::sort(errors.begin(), errors.end());
            const double median = PCCD::testing::sorted_quantile(errors, 50);
            const double p95 = PCCD::testing::sorted_quantile(errors, 95);
            // Coverage: exact circle samples with a returned point within 3 spacings.
            const double radius = std::sqrt(1.0 - d * d / 4.0);
            std::size_t covered = 0, total = 720;
            for (std::size_t k = 0; k < total; ++k) {
                const double t = 2.0 * std::numbers::pi * double(k) / double(total);
                const Eigen::Vector3d c(d / 2.0, radius * std::cos(t), radius * std::sin(t));
                for (const auto& p : result.points)
                    if ((p.position - c).norm() <= 3.0 * s.spacing) {
                        ++covered;
                        break;
                    }
            }
            const double coverage = double(covered) / double(total);
            INFO("points " << result.points.size() << ", median " << median / s.spacing << " spacing, p95 "
                           << p95 / s.spacing << ", coverage " << coverage);
            CHECK(median <= 0.5 * s.spacing);
            CHECK(p95 <= 2.0 * s.spacing);
            CHECK(coverage >= 0.9);
            // No two points closer than the requested spacing (refinement moves points slightly).
            if (refinement == PCCD::Refinement::none) {
                const double spacing = std::max(s.a.sampling_radius(), s.b.sampling_radius());
                for (std::size_t i = 0; i < result.points.size(); ++i)
                    for (std::size_t j = i + 1; j < result.points.size(); ++j)
                        CHECK((result.points[i].position - result.points[j].position).norm() >= spacing * (1 - 1e-12));
            }
            if (refinement == PCCD::Refinement::projection) {
                std::size_t refined = 0;
                for (const auto& p : result.points) refined += p.kind == PCCD::Intersection_point_kind::refined;
                CHECK(refined >= result.points.size() * 9 / 10);
            }
        }
    }
}

TEST_CASE("Queries are deterministic, pose-invariant and respect the budget", "[intersection]")
{
    const Sphere_pair& s = sphere_pair();
    const auto first = PCCD::intersection_points(s.a, Rigid_transform_3<double>(), s.b, shifted(1.0), {.seed = 9});
    const auto again = PCCD::intersection_points(s.a, Rigid_transform_3<double>(), s.b, shifted(1.0), {.seed = 9});
    CHECK(first.counters == again.counters);
    REQUIRE(first.points.size() == again.points.size());
    for (std::size_t k = 0; k < first.points.size(); ++k) CHECK(first.points[k].position == again.points[k].position);

    // Moving both objects by the same rigid motion moves the answer with them.
    const Rigid_transform_3<double> g = random_pose(5, 3.0);
    for (double d : {0.7, 1.5, 2.5}) {
        const auto plain = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(d), {.seed = 4});
        const auto moved = PCCD::do_intersect(s.a, g, s.b, g * shifted(d), {.seed = 4});
        CHECK(plain.intersects == moved.intersects);
        if (plain.intersects && moved.intersects)
            CHECK((g.transform_point(plain.points[0].position) - moved.points[0].position).norm() < 1e-9);
    }

    // A budget stops a query that would otherwise search on (separate spheres, just out of reach of
    // the flat traversal's kernel support; the default traversal proves them separate at once).
    const double r = s.a.sampling_radius();
    const auto walked = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(2.0 + 2 * r), {.seed = 1});
    CHECK(walked.status == PCCD::Intersection_status::separate);
    CHECK(walked.counters.f_evaluations == 0);
    const PCCD::Traversal flat = PCCD::Traversal::flat;
    const auto full = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(2.0 + 2 * r),
                                         {.seed = 1, .traversal = flat});
    REQUIRE(full.status == PCCD::Intersection_status::separate);
    REQUIRE(full.counters.f_evaluations > 20);
    const auto limited = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(2.0 + 2 * r),
                                            {.seed = 1, .traversal = flat, .max_f_evaluations = 20});
    CHECK(limited.counters.f_evaluations == 20);
    CHECK(limited.status == PCCD::Intersection_status::undecided);
    CHECK_FALSE(limited.intersects);
    // RST on a pose where its full sampling needs more than the budget (a tiny epsilon: many cells, few hits).
    const auto rst_full = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(1.0),
                                             {.seed = 1, .epsilon = 0.01 * r}, PCCD::Randomized_sampling{});
    REQUIRE(rst_full.counters.f_evaluations > 20);
    const auto rst_limited = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(1.0),
                                                {.seed = 1, .epsilon = 0.01 * r, .max_f_evaluations = 20},
                                                PCCD::Randomized_sampling{});
    CHECK(rst_limited.counters.f_evaluations <= 20);
    if (!rst_limited.intersects) CHECK(rst_limited.status == PCCD::Intersection_status::undecided);
}

TEST_CASE("Invalid query options are rejected with a message naming them", "[intersection]")
{
    const Sphere_pair& s = sphere_pair();
    const Rigid_transform_3<double> id;
    const auto query = [&](const PCCD::Intersection_options& o) { return PCCD::do_intersect(s.a, id, s.b, id, o); };
    CHECK_THROWS_WITH(query({.epsilon = 0.0}), Contains("epsilon"));
    CHECK_THROWS_WITH(query({.epsilon = -1.0}), Contains("epsilon"));
    CHECK_THROWS_WITH(query({.epsilon = std::numeric_limits<double>::quiet_NaN()}), Contains("epsilon"));
    CHECK_THROWS_WITH(query({.point_spacing = 0.0}), Contains("point_spacing"));
    CHECK_THROWS_WITH(query({.max_f_evaluations = 0}), Contains("budget"));
    CHECK_THROWS_WITH(query({.refinement = PCCD::Refinement::sampling, .refinement_samples = 0}), Contains("refinement_samples"));
    const auto isearch = [&](const PCCD::Interpolation_search& p) { return PCCD::do_intersect(s.a, id, s.b, id, {}, p); };
    CHECK_THROWS_WITH(isearch({.min_samples = 0}), Contains("min_samples"));
    CHECK_THROWS_WITH(isearch({.annulus_outer = 1.5}), Contains("annulus_outer"));
    CHECK_THROWS_WITH(isearch({.annulus_width = 0.0}), Contains("annulus_width"));
    CHECK_THROWS_WITH(isearch({.partner_candidates = 0}), Contains("partner_candidates"));
    CHECK_THROWS_WITH(isearch({.lipschitz_slack = 0.5}), Contains("lipschitz_slack"));
    const auto rst = [&](const PCCD::Randomized_sampling& p) { return PCCD::do_intersect(s.a, id, s.b, id, {}, p); };
    CHECK_THROWS_WITH(rst({.max_samples = 0}), Contains("max_samples"));
    CHECK_THROWS_WITH(rst({.epsilon_factor = -1.0}), Contains("epsilon_factor"));
    // Two identical objects at the identical pose (coincident surfaces, doc/manual/intersection.md):
    // RST reports them; isearch does here (a sample's |f| is below epsilon), not on every cloud.
    CHECK(PCCD::do_intersect(s.a, id, s.a, id).intersects);
    CHECK(PCCD::do_intersect(s.a, id, s.a, id, {}, PCCD::Randomized_sampling{}).intersects);
}

TEST_CASE("Objects of different kernels collide with each other", "[intersection]")
{
    const auto sa = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 41);
    const auto sb = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 42);
    std::vector<Eigen::Vector3f> fb;
    for (Eigen::Index i = 0; i < sb.points.cols(); ++i) fb.push_back(sb.points.col(i).cast<float>());
    const PCCD::Point_cloud_object<> a(pccd_test::columns(sa.points));
    const PCCD::Point_cloud_object<PCCD::Eigen_kernel<float>> b(fb);
    for (double d : {0.5, 1.5, 2.5}) {
        const auto isearch = PCCD::do_intersect(a, Rigid_transform_3<double>(), b, shifted(d));
        const auto rst = PCCD::do_intersect(a, Rigid_transform_3<double>(), b, shifted(d), {}, PCCD::Randomized_sampling{});
        CHECK(isearch.intersects == (d < 2.0));
        CHECK(rst.intersects == (d < 2.0));
    }
}
