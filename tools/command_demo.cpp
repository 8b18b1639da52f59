// pccd demo: a tour of PCCD on built-in data (the scanned bunny, or the procedural torus when
// libcgal-demo is absent): sampling, the point cloud and its kd-tree, the preprocessed object
// (proximity graph, CPSP map, oriented normals) and its implicit surface, and two copies of it
// collided at benchmark poses (do_intersect with both policies, intersection_points).
#include "commands.h"
#include "demo_data.h"

#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Sampling/pose_generator.h>

#include <common/timing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace pccd_tool {
namespace {

using pccd_bench::Clock;
using pccd_bench::ms_since;

struct Demo_options {
    std::size_t points = 30000;
    std::uint64_t seed = 1;
};

void run_demo(const Demo_options& options)
{
    std::printf("PCCD demo\n=========\n");
    auto start = Clock::now();
    const Demo_object object = load_demo_object(options.points, options.seed);
    std::printf("data: %s\n      %zu points sampled by area in %.1f ms (seed %llu), normalized into [-1,1]^3\n",
                object.source.c_str(), std::size_t(object.points.cols()), ms_since(start),
                static_cast<unsigned long long>(options.seed));

    start = Clock::now();
    const PCCD::Point_cloud<> cloud(object.points);
    std::printf("point cloud: kd-tree built in %.1f ms\n", ms_since(start));
    const auto& box = cloud.bbox();
    std::printf("  bounding box [%.3f %.3f %.3f] - [%.3f %.3f %.3f]\n", box.min().x(), box.min().y(), box.min().z(),
                box.max().x(), box.max().y(), box.max().z());
    const double expected = 0.5 * std::sqrt(object.area / double(cloud.size()));
    std::printf("  mean spacing %.5f (uniform sampling of area %.4f predicts %.5f)\n", cloud.mean_spacing(),
                object.area, expected);

    const Eigen::Vector3d query(0.0, 0.0, 0.0);
    const auto nearest = cloud.k_nearest(query, 5);
    std::printf("  5 nearest points to the origin:");
    for (const auto& n : nearest) std::printf(" %u (%.4f)", n.index, std::sqrt(n.squared_distance));
    std::printf("\n");

    start = Clock::now();
    std::vector<Eigen::Vector3d> points(std::size_t(object.points.cols()));
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = object.points.col(Eigen::Index(i));
    const PCCD::Point_cloud_object<> object_state(points);
    const auto& t = object_state.timings();
    std::printf("preprocessed object in %.0f ms (graph %.0f, r(P) %.0f, CPSP %.0f, normals %.0f)\n", ms_since(start),
                t.graph, t.sampling_radius, t.cpsp, t.normals);
    std::printf("  %s graph: %zu edges (%zu virtual), sampling radius r(P) = %.5f\n",
                PCCD::to_string(object_state.graph().kind(), object_state.graph().parameter()).c_str(),
                object_state.graph().num_edges(), object_state.graph().num_virtual_edges(),
                object_state.sampling_radius());
    std::printf("  bandwidth h = %.5f (eta %.1f, theta_eps %.0e), %zu CPSP entries\n", object_state.bandwidth(),
                object_state.eta(), object_state.theta_eps(), object_state.cpsp().num_entries());

    // f at points pushed off the surface along the sampled (true) normals: its sign says the side and
    // its value the distance, measured against the offset.
    std::printf("implicit surface f(x) = n(x).(x - a(x)) at x = p + s n(p), s in spacings:\n");
    const double spacing = cloud.mean_spacing();
    for (const double s : {-2.0, -1.0, 0.0, 1.0, 2.0}) {
        double sum = 0.0;
        int defined = 0;
        const int probes = 200;
        for (int i = 0; i < probes; ++i) {
            const Eigen::Index k = Eigen::Index(i) * (object.points.cols() / probes);
            const Eigen::Vector3d x = object.points.col(k) + s * spacing * object.normals.col(k);
            if (const auto f = object_state.surface().value(x)) {
                sum += *f / spacing;
                ++defined;
            }
        }
        std::printf("  s = %+.0f: mean f = %+.3f spacings over %d defined of %d probes\n", s,
                    defined > 0 ? sum / defined : 0.0, defined, probes);
    }

    const auto poses = PCCD::generate_benchmark_poses({.distances = {0.0, 1.0, 1.5, 2.0, 2.5},
                                                       .rotations_per_distance = 1, .seed = options.seed});
    std::printf("collisions of two copies (ALGORITHMS.md sections 5, 6, 8): A = [R_A | 0], B = [R_B | (d, 0, 0)]\n");
    for (const auto& pose : poses) {
        auto t0 = Clock::now();
        const PCCD::Intersection_result hit = PCCD::do_intersect(object_state, pose.pose_a, object_state, pose.pose_b);
        const double isearch_us = 1000.0 * ms_since(t0);
        t0 = Clock::now();
        const PCCD::Intersection_result rst = PCCD::do_intersect(object_state, pose.pose_a, object_state, pose.pose_b,
                                                                 {}, PCCD::Randomized_sampling{});
        const double rst_us = 1000.0 * ms_since(t0);
        std::printf("  d = %.2f: interpolation search %-12s %5zu f evaluations %8.1f us | RST %-12s %6zu f evaluations %9.1f us\n",
                    pose.distance, hit.intersects ? "intersecting" : "separate", hit.counters.f_evaluations, isearch_us,
                    rst.intersects ? "intersecting" : "separate", rst.counters.f_evaluations, rst_us);
        if (hit.intersects && pose.distance == 1.0) {
            t0 = Clock::now();
            const PCCD::Intersection_result curve =
                PCCD::intersection_points(object_state, pose.pose_a, object_state, pose.pose_b);
            double worst = 0.0;
            for (const auto& p : curve.points)
                if (p.kind == PCCD::Intersection_point_kind::refined)
                    worst = std::max(worst, std::max(std::abs(p.f_a), std::abs(p.f_b)));
            std::printf("            intersection_points: %zu points on the curves in %.1f ms, max(|f_A|, |f_B|) <= %.2g\n",
                        curve.points.size(), ms_since(t0), worst);
        }
    }
}

} // namespace

void register_demo(CLI::App& app)
{
    auto* cmd = app.add_subcommand("demo", "Run PCCD on built-in data (the scanned bunny, or a procedural torus)");
    auto options = std::make_shared<Demo_options>();
    cmd->add_option("--points", options->points, "Points to sample")->check(CLI::Range(2, 10000000));
    cmd->add_option("--seed", options->seed, "Random seed");
    cmd->callback([options] { run_demo(*options); });
}

} // namespace pccd_tool
