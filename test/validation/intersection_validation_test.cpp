// Validation of the stochastic intersection against CGAL's exact answer (doc/manual/exact.md, the
// poses of doc/manual/sampling.md): clouds sampled from the bunny mesh, the benchmark pose
// procedure, do_intersect() of both policies compared with exact_separation() pose by pose
// (grazing poses counted apart), and intersection_points() compared with the exact intersection
// polylines. Prints its figures.
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_intersection.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/sample_triangle_mesh.h>

#include <PCCD/testing/statistics.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include "build_helpers.h"
#include "data_helpers.h"

namespace {

// Release builds run the full benchmark procedure (20 rotations per distance); Debug and
// sanitizer builds a smaller smoke version of the same code (4 rotations), to stay within CI time.
constexpr std::size_t rotations = pccd_test::by_build<std::size_t>(20, 4);
constexpr std::size_t curve_poses = pccd_test::by_build<std::size_t>(20, 4);
constexpr std::size_t cloud_size = 30000;

struct Bunny {
    PCCD::Triangle_mesh_data mesh;
    std::unique_ptr<PCCD::Exact_mesh> exact;
    std::unique_ptr<PCCD::Point_cloud_object<>> object;
    double spacing = 0.0;
    double r = 0.0;
};

/// The bunny mesh normalized into [-1, 1]^3, its exact reference and a cloud of 30k points sampled
/// from it; nullptr without the data (libcgal-demo not installed).
const Bunny* bunny()
{
    static const std::unique_ptr<Bunny> data = []() -> std::unique_ptr<Bunny> {
        const std::string dir = PCCD_DATA_DIR;
        if (dir.empty()) return nullptr;
        auto b = std::make_unique<Bunny>();
        b->mesh = PCCD::IO::read_triangle_mesh(dir + "/bunny00.off");
        Eigen::Matrix3Xd v(3, Eigen::Index(b->mesh.vertices.size()));
        for (std::size_t i = 0; i < b->mesh.vertices.size(); ++i) v.col(Eigen::Index(i)) = b->mesh.vertices[i];
        PCCD::normalize_to_unit_cube(v);
        for (std::size_t i = 0; i < b->mesh.vertices.size(); ++i) b->mesh.vertices[i] = v.col(Eigen::Index(i));
        b->exact = std::make_unique<PCCD::Exact_mesh>(b->mesh);
        PCCD::Random_engine engine(2026);
        const auto sample = PCCD::sample_triangle_mesh(b->mesh.vertices, b->mesh.triangles, cloud_size, engine);
        std::vector<Eigen::Vector3d> points(sample.points.cols());
        for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points[std::size_t(i)] = sample.points.col(i);
        b->object = std::make_unique<PCCD::Point_cloud_object<>>(points);
        b->spacing = b->object->cloud().mean_spacing();
        b->r = b->object->sampling_radius();
        return b;
    }();
    return data.get();
}

struct Tally {
    std::size_t poses = 0, grazing = 0, intersecting = 0, separated = 0;
    std::size_t false_negatives = 0, false_positives = 0;
    std::size_t grazing_reported = 0;
};

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}

} // namespace

TEST_CASE("Validation on the bunny: do_intersect against CGAL's exact answer", "[exact][intersection][validation]")
{
    const Bunny* b = bunny();
    if (!b) {
        PCCD_SKIP_TEST("bunny00.off of libcgal-demo not found (PCCD_DATA_DIR is empty): bunny validation");
    }
    const auto poses = PCCD::testing::generate_benchmark_poses({.rotations_per_distance = rotations, .seed = 1});
    std::map<double, Tally> isearch_by_d, rst_by_d;
    Tally isearch, rst;
    std::size_t pose_index = 0;
    for (const PCCD::testing::Benchmark_pose& pose : poses) {
        const PCCD::Exact_separation separation = PCCD::exact_separation(*b->exact, pose.pose_a, *b->exact, pose.pose_b);
        const PCCD::Pose_class cls = PCCD::classify_pose(separation, b->r);
        const PCCD::Intersection_options options{.seed = 1000 + pose_index++};
        const bool a1 = PCCD::do_intersect(*b->object, pose.pose_a, *b->object, pose.pose_b, options).intersects;
        const bool a2 = PCCD::do_intersect(*b->object, pose.pose_a, *b->object, pose.pose_b, options,
                                           PCCD::Randomized_sampling{})
                            .intersects;
        if ((a1 || a2) != (cls == PCCD::Pose_class::intersecting) && cls != PCCD::Pose_class::grazing)
            std::printf("  wrong answer at d = %.2f, rotation %zu: exact %s (signed separation %.3f r), isearch %d, rst %d\n",
                        pose.distance, pose.rotation_index, cls == PCCD::Pose_class::intersecting ? "intersecting" : "separated",
                        separation.signed_measure() / b->r, int(a1), int(a2));
        for (auto [answer, tallies] : {std::pair{a1, std::pair{&isearch, &isearch_by_d[pose.distance]}},
                                       std::pair{a2, std::pair{&rst, &rst_by_d[pose.distance]}}}) {
            for (Tally* t : {tallies.first, tallies.second}) {
                ++t->poses;
                if (cls == PCCD::Pose_class::grazing) {
                    ++t->grazing;
                    t->grazing_reported += answer;
                } else if (cls == PCCD::Pose_class::intersecting) {
                    ++t->intersecting;
                    t->false_negatives += !answer;
                } else {
                    ++t->separated;
                    t->false_positives += answer;
                }
            }
        }
    }
    std::printf("bunny validation: N = %zu, mean spacing %.5f, r(P) %.5f, %zu rotations per distance\n", cloud_size,
                b->spacing, b->r, rotations);
    std::printf("%6s %6s %8s %10s | %8s %8s %8s | %8s %8s %8s\n", "d", "poses", "grazing", "colliding", "is.FN",
                "is.FP", "is.graz+", "rst.FN", "rst.FP", "rst.graz+");
    for (const auto& [d, t] : isearch_by_d) {
        const Tally& u = rst_by_d[d];
        std::printf("%6.2f %6zu %8zu %10zu | %8zu %8zu %8zu | %8zu %8zu %8zu\n", d, t.poses, t.grazing, t.intersecting,
                    t.false_negatives, t.false_positives, t.grazing_reported, u.false_negatives, u.false_positives,
                    u.grazing_reported);
    }
    const auto rate = [](std::size_t k, std::size_t n) { return n ? double(k) / double(n) : 0.0; };
    std::printf("isearch: FN %zu/%zu = %.2f %%, FP %zu/%zu = %.2f %% (grazing: %zu poses, %zu reported)\n",
                isearch.false_negatives, isearch.intersecting, 100 * rate(isearch.false_negatives, isearch.intersecting),
                isearch.false_positives, isearch.separated, 100 * rate(isearch.false_positives, isearch.separated),
                isearch.grazing, isearch.grazing_reported);
    std::printf("rst:     FN %zu/%zu = %.2f %%, FP %zu/%zu = %.2f %% (grazing: %zu poses, %zu reported)\n",
                rst.false_negatives, rst.intersecting, 100 * rate(rst.false_negatives, rst.intersecting),
                rst.false_positives, rst.separated, 100 * rate(rst.false_positives, rst.separated), rst.grazing,
                rst.grazing_reported);
    REQUIRE(isearch.intersecting > 0);
    REQUIRE(isearch.separated > 0);
    CHECK(rate(isearch.false_negatives, isearch.intersecting) <= 0.01);
    CHECK(rate(isearch.false_positives, isearch.separated) <= 0.01);
    CHECK(rate(rst.false_negatives, rst.intersecting) <= 0.01);
    CHECK(rate(rst.false_positives, rst.separated) <= 0.01);
}

TEST_CASE("Validation on the bunny: intersection points against the exact polylines", "[exact][intersection][validation]")
{
    const Bunny* b = bunny();
    if (!b) {
        PCCD_SKIP_TEST("bunny00.off of libcgal-demo not found (PCCD_DATA_DIR is empty): bunny curve validation");
    }
    // Intersecting, non-grazing poses spread over the distances.
    const auto poses = PCCD::testing::generate_benchmark_poses(
        {.distances = {0.25, 0.5, 0.75, 1.0, 1.25, 1.5}, .rotations_per_distance = 8, .seed = 7});
    std::vector<double> errors;
    std::size_t curve_samples = 0, covered = 0, used = 0, points = 0, refined = 0;
    for (std::size_t k = 0; k < poses.size() && used < curve_poses; ++k) {
        const PCCD::testing::Benchmark_pose& pose = poses[(k * 7) % poses.size()];
        if (PCCD::classify_pose(*b->exact, pose.pose_a, *b->exact, pose.pose_b, b->r) != PCCD::Pose_class::intersecting)
            continue;
        ++used;
        const auto polylines = PCCD::exact_intersection_polylines(*b->exact, pose.pose_a, *b->exact, pose.pose_b);
        const auto result = PCCD::intersection_points(*b->object, pose.pose_a, *b->object, pose.pose_b, {.seed = k});
        REQUIRE(result.intersects);
        points += result.points.size();
        for (const auto& p : result.points) {
            refined += p.kind == PCCD::Intersection_point_kind::refined;
            double best = std::numeric_limits<double>::infinity();
            for (const auto& line : polylines)
                for (std::size_t s = 0; s + 1 < line.size(); ++s)
                    best = std::min(best, point_segment_distance(p.position, line[s], line[s + 1]));
            errors.push_back(best);
        }
        // Coverage: samples every half spacing along the exact curves.
        for (const auto& line : polylines)
            for (std::size_t s = 0; s + 1 < line.size(); ++s) {
                const double length = (line[s + 1] - line[s]).norm();
                const std::size_t steps = std::max<std::size_t>(1, std::size_t(std::ceil(length / (0.5 * b->spacing))));
                for (std::size_t t = 0; t < steps; ++t) {
                    const Eigen::Vector3d c = line[s] + (double(t) / double(steps)) * (line[s + 1] - line[s]);
                    ++curve_samples;
                    for (const auto& p : result.points)
                        if ((p.position - c).norm() <= 3.0 * b->spacing) {
                            ++covered;
                            break;
                        }
                }
            }
    }
    REQUIRE(used == curve_poses);
    REQUIRE(!errors.empty());
    std::sort(errors.begin(), errors.end());
    const double median = PCCD::testing::sorted_quantile(errors, 50);
    const double p95 = PCCD::testing::sorted_quantile(errors, 95);
    const double coverage = double(covered) / double(std::max<std::size_t>(curve_samples, 1));
    std::printf("bunny curves: %zu poses, %zu points (%zu refined), distance to the exact polylines: median %.3f, "
                "p95 %.3f mean spacings; coverage (3 spacings) %.1f %% of %zu curve samples\n",
                used, points, refined, median / b->spacing, p95 / b->spacing, 100 * coverage, curve_samples);
    CHECK(median <= 0.5 * b->spacing);
    CHECK(p95 <= 2.0 * b->spacing);
    CHECK(coverage >= 0.9);
}
