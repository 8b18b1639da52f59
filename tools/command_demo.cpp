// pccd demo: a tour of PCCD on built-in data (the scanned bunny, or the procedural torus when
// libcgal-demo is absent): sampling, the point cloud and its kd-tree, the preprocessed object
// (proximity graph, CPSP map, oriented normals) and its implicit surface, and two copies of it
// collided at benchmark poses (do_intersect with both policies, intersection_points). It draws the
// two posed copies and their intersection curve (pccd-demo.png) and, when gnuplot is installed, its
// table of query times (pccd-demo-times.png), and says where.
#include "commands.h"
#include "progress.h"
#include "demo_data.h"
#include "render_objects.h"

#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/pose_generator.h>

#include <PCCD/testing/timing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace pccd_tool {
namespace {

using PCCD::testing::Clock;
using PCCD::testing::ms_since;

struct Demo_options {
    std::size_t points = 30000;
    std::uint64_t seed = 1;
    std::string png = "pccd-demo.png";
    std::string times_png = "pccd-demo-times.png";
    std::string size = "800x600";
};

/// One row of the demo's table of collisions.
struct Timing_row {
    double distance;
    double isearch_us, rst_us;
    std::size_t isearch_f, rst_f;
};

/// The gnuplot executable on PATH, if any.
std::optional<std::filesystem::path> find_gnuplot()
{
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path != nullptr ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        if (dir.empty()) continue;
        const std::filesystem::path candidate = std::filesystem::path(dir) / "gnuplot";
        std::error_code error;
        if (std::filesystem::is_regular_file(candidate, error)) return candidate;
    }
    return std::nullopt;
}

/// Plots the demo's query times per distance (both policies, log scale) into `path` with gnuplot;
/// returns an empty string on success, else what went wrong.
std::string plot_times(const std::filesystem::path& gnuplot, const std::vector<Timing_row>& rows,
                       const std::string& object, const std::string& path)
{
    std::ostringstream script;
    script << "set terminal pngcairo size 800,480 font 'sans,11'\n"
           << "set output '" << path << "'\n"
           << "set title 'pccd demo: first-hit queries on two copies of the " << object << " at distance d'\n"
           << "set xlabel 'distance d of the centres (object normalized into [-1,1]^3)'\n"
           << "set ylabel 'query time (microseconds)'\nset logscale y\nset grid\nset key top right\n"
           << "set xrange [-0.25:" << (rows.empty() ? 3.0 : rows.back().distance + 0.25) << "]\n"
           << "$times << EOD\n";
    for (const Timing_row& r : rows)
        script << r.distance << ' ' << r.isearch_us << ' ' << r.rst_us << ' ' << r.isearch_f << ' ' << r.rst_f << '\n';
    script << "EOD\n"
           << "plot $times using 1:2 with linespoints lw 2 pt 7 title 'interpolation search', "
              "$times using 1:3 with linespoints lw 2 pt 5 title 'randomized sampling (RST)'\n";
    const std::string command = "'" + gnuplot.string() + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "w");
    if (pipe == nullptr) return "cannot start " + gnuplot.string();
    const std::string text = script.str();
    std::fwrite(text.data(), 1, text.size(), pipe);
    const int status = pclose(pipe);
    if (status != 0) return gnuplot.string() + " failed (status " + std::to_string(status) + ")";
    if (!std::filesystem::exists(path)) return gnuplot.string() + " wrote no file";
    return {};
}

void run_demo(const Demo_options& options)
{
    const auto [width, height] = pccd_render::parse_size(options.size);
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
    const PCCD::Point_cloud_object<> object_state(object.points, with_progress({}, object.name));
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

    const auto poses = PCCD::testing::generate_benchmark_poses({.distances = {0.0, 1.0, 1.5, 2.0, 2.5},
                                                       .rotations_per_distance = 1, .seed = options.seed});
    std::printf("collisions of two copies (doc/algorithms.md, \"Benchmark procedure\"): A = [R_A | 0], B = [R_B | (d, 0, 0)]\n");
    std::vector<Timing_row> rows;
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
        rows.push_back({pose.distance, isearch_us, rst_us, hit.counters.f_evaluations, rst.counters.f_evaluations});
        if (pose.distance == 1.0) {
            t0 = Clock::now();
            const PCCD::Intersection_result curve =
                PCCD::intersection_points(object_state, pose.pose_a, object_state, pose.pose_b,
                                          {.point_spacing = 0.5 * spacing});
            double worst = 0.0;
            for (const auto& p : curve.points)
                if (p.kind == PCCD::Intersection_point_kind::refined)
                    worst = std::max(worst, std::max(std::abs(p.f_a), std::abs(p.f_b)));
            std::printf("            intersection_points: %zu points on the curves in %.1f ms, max(|f_A|, |f_B|) <= %.2g\n",
                        curve.points.size(), ms_since(t0), worst);
            if (!options.png.empty()) {
                pccd_render::Scene scene;
                scene.clouds.push_back(cloud_layer(object_state, pose.pose_a, pccd_render::colour_a));
                scene.clouds.push_back(cloud_layer(object_state, pose.pose_b, pccd_render::colour_b));
                scene.markers.push_back(curve_layer(curve.points, 0.5 * scene.clouds.front().splat_radius));
                render_to_png(scene, std::nullopt, width, height, options.png);
                std::printf("            picture: %s (A blue, B gold, the intersection curve red)\n",
                            std::filesystem::absolute(options.png).c_str());
            }
        }
    }
    if (!options.times_png.empty()) {
        if (const std::optional<std::filesystem::path> gnuplot = find_gnuplot()) {
            const std::string problem = plot_times(*gnuplot, rows, object.name, options.times_png);
            if (problem.empty())
                std::printf("plot of the query times: %s\n", std::filesystem::absolute(options.times_png).c_str());
            else
                std::printf("plot of the query times not written: %s\n", problem.c_str());
        } else {
            std::printf("plot of the query times not written: gnuplot is not installed (Debian package gnuplot-nox)\n");
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
    cmd->add_option("--png", options->png,
                    "Picture of the two posed copies and their intersection curve (default pccd-demo.png; "
                    "empty: none)");
    cmd->add_option("--size", options->size, "Size of the picture, WIDTHxHEIGHT (default 800x600)");
    cmd->add_option("--times-png", options->times_png,
                    "Plot of the query times, drawn by gnuplot when installed (default pccd-demo-times.png; "
                    "empty: none)");
    cmd->callback([options] { run_demo(*options); });
}

} // namespace pccd_tool
