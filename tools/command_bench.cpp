// pccd bench FILE [--method isearch|rst] [--distances 0:3:0.25] [--rotations R] [--seed S]
//   [--points N] [--csv OUT]: the benchmark procedure of doc/manual/sampling.md on one object:
// two copies of it, normalized into [-1, 1]^3, A at [R_A | 0] and B at [R_B | (d, 0, 0)] for every
// distance d and R random rotation pairs; one first-hit query (do_intersect) per pose, single
// thread, timed with steady_clock; per distance: poses, colliding poses, mean and median time,
// mean f evaluations.
#include "commands.h"
#include "intersection_support.h"
#include "parse_number.h"

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/sample_triangle_mesh.h>

#include <PCCD/testing/statistics.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace pccd_tool {
namespace {

struct Bench_options {
    std::string file;
    std::string method = "isearch";
    std::string distances = "0:3:0.25";
    std::size_t rotations = 20;
    std::uint64_t seed = 1;
    std::size_t points = 30000;
    std::string csv;
    std::string hierarchy = "likelihood";
    double budget_us = 0.0;
    Object_settings object;
};

double parse_distance(const std::string& text, const std::string& spec)
{
    return parse_finite_number(text, "--distances \"" + spec + "\"");
}

/// "start:stop:step" (stop included within rounding), a single distance, or a comma-separated list.
std::vector<double> parse_distances(const std::string& spec)
{
    std::vector<std::string> parts;
    const char separator = spec.find(':') != std::string::npos ? ':' : ',';
    for (std::size_t begin = 0;;) {
        const std::size_t end = spec.find(separator, begin);
        parts.push_back(spec.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
        if (end == std::string::npos) break;
        begin = end + 1;
    }
    std::vector<double> values;
    for (const std::string& p : parts) values.push_back(parse_distance(p, spec));
    if (separator == ',') return values;
    if (values.size() != 3)
        throw PCCD::Invalid_input("--distances \"" + spec + "\": expected start:stop:step");
    const double start = values[0], stop = values[1], step = values[2];
    if (!(step > 0.0) || stop < start)
        throw PCCD::Invalid_input("--distances \"" + spec + "\": expected step > 0 and stop >= start");
    const double count = std::floor((stop - start) / step + 1e-9);
    if (count > 1e6) throw PCCD::Invalid_input("--distances \"" + spec + "\": more than a million distances");
    std::vector<double> distances;
    for (std::size_t i = 0; i <= std::size_t(count); ++i) distances.push_back(start + double(i) * step);
    return distances;
}

/// The benchmark object: N points sampled by area from a mesh (OFF, or PLY with faces), or the
/// points of a point cloud; normalized into [-1, 1]^3 either way.
/// \throws PCCD::Invalid_input, naming the file, for a prepared object file: the benchmark
///         normalizes its object, which a prepared object cannot be (it keeps its points).
Object_points load_bench_points(const Bench_options& o, std::string& description)
{
    if (const PCCD::Object_file_info info = prepared_file_info(o.file); info.kind != PCCD::Object_file_kind::none)
        throw PCCD::Invalid_input(o.file + ": a prepared object file (" + PCCD::to_string(info.kind) +
                                  " kernel); pccd bench normalizes its object into [-1,1]^3, which a prepared "
                                  "object cannot be: give the mesh or point file it was prepared from");
    const std::optional<PCCD::IO::Format> format = PCCD::IO::format_from_extension(o.file);
    if (format == PCCD::IO::Format::off || format == PCCD::IO::Format::ply) {
        std::optional<PCCD::Triangle_mesh_data> mesh;
        try {
            mesh = PCCD::IO::read_triangle_mesh(o.file);
        } catch (const PCCD::File_error&) {
            // No faces (or unusable faces): read it as a point cloud below, which reports any
            // problem the points have.
        }
        if (mesh) {
            normalize_points(mesh->vertices);
            PCCD::Random_engine engine(o.seed);
            const PCCD::Triangle_mesh_sample sample =
                PCCD::sample_triangle_mesh(mesh->vertices, mesh->triangles, o.points, engine);
            Object_points result;
            for (Eigen::Index i = 0; i < sample.points.cols(); ++i) result.points.push_back(sample.points.col(i));
            description = "mesh, " + std::to_string(mesh->triangles.size()) + " triangles, " +
                          std::to_string(o.points) + " points sampled by area (seed " + std::to_string(o.seed) + ")";
            return result;
        }
    }
    Object_points result = read_object_points(o.file, true);
    description = "point cloud, " + std::to_string(result.points.size()) + " points";
    return result;
}

using PCCD::testing::mean;
using PCCD::testing::median;

void run_bench(const Bench_options& o)
{
    const std::vector<double> distances = parse_distances(o.distances);
    const std::vector<PCCD::testing::Benchmark_pose> poses = PCCD::testing::generate_benchmark_poses(
        {.distances = distances, .rotations_per_distance = o.rotations, .seed = o.seed});
    const bool write_csv = !o.csv.empty();
    std::ofstream csv;
    if (write_csv) {
        csv.open(o.csv);
        if (!csv) throw PCCD::File_error(o.csv, "cannot open the CSV file for writing");
    }

    std::string description;
    const Object_points points = load_bench_points(o, description);
    const Prepared_object prepared = prepare_object(points, o.file, o.object);
    const PCCD::Point_cloud_object<>& object = prepared.object;
    std::printf("object: %s (%s), normalized into [-1,1]^3\n", o.file.c_str(), description.c_str());
    std::printf("preprocessed in %.0f ms: %zu points, r(P) %.5f\n", prepared.preprocess_ms, object.size(),
                object.sampling_radius());
    std::printf("method %s, first hit, %zu distances x %zu rotations, seed %llu, one query per pose, one thread\n",
                o.method.c_str(), distances.size(), o.rotations, static_cast<unsigned long long>(o.seed));

    const PCCD::Intersection_options options = query_options(o.seed, o.hierarchy, o.budget_us);
    // One untimed query first, so that the first timed pose does not pay for cold caches.
    run_timed_query(object, poses.front().pose_a, object, poses.front().pose_b, options, o.method, true);

    if (write_csv) {
        csv << "distance,rotation,intersects,status,query_us";
        for (const std::string& name : counter_names()) csv << ',' << name;
        csv << '\n';
    }
    std::printf("%8s %6s %9s %11s %11s %12s\n", "distance", "poses", "colliding", "mean_us", "median_us", "mean_f_evals");
    std::size_t next = 0;
    for (const double d : distances) {
        std::vector<double> times, evaluations;
        std::size_t colliding = 0;
        for (; next < poses.size() && poses[next].distance == d; ++next) {
            const PCCD::testing::Benchmark_pose& pose = poses[next];
            const Timed_result t = run_timed_query(object, pose.pose_a, object, pose.pose_b, options, o.method, true);
            times.push_back(t.query_us);
            evaluations.push_back(double(t.result.counters.f_evaluations));
            colliding += t.result.intersects ? 1 : 0;
            if (write_csv) {
                char row[160];
                std::snprintf(row, sizeof row, "%.17g,%zu,%d,%s,%.3f", d, pose.rotation_index,
                              t.result.intersects ? 1 : 0, PCCD::to_string(t.result.status), t.query_us);
                csv << row;
                for (const std::size_t value : counter_values(t.result.counters)) csv << ',' << value;
                csv << '\n';
            }
        }
        std::printf("%8.3f %6zu %9zu %11.1f %11.1f %12.1f\n", d, times.size(), colliding, mean(times), median(times),
                    mean(evaluations));
        std::fflush(stdout);
    }
    if (write_csv) {
        csv.close();
        if (!csv) throw PCCD::File_error(o.csv, "writing the CSV file failed");
        std::printf("per-pose rows written to %s\n", o.csv.c_str());
    }
}

} // namespace

void register_bench(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "bench", "Benchmark procedure of doc/algorithms.md (\"Benchmark procedure\"): first-hit queries over random poses per distance");
    auto o = std::make_shared<Bench_options>();
    cmd->add_option("FILE", o->file, "Mesh (.off, .ply with faces: sampled) or point cloud (.ply, .off, .xyz, .pwn)")
        ->required();
    cmd->add_option("--method", o->method, "Leaf intersector: isearch (interpolation search, default) or rst")
        ->check(CLI::IsMember(method_names()));
    cmd->add_option("--distances", o->distances,
                    "Distances d of B along x: start:stop:step (stop included), or a comma-separated list "
                    "(default 0:3:0.25)");
    cmd->add_option("--rotations", o->rotations, "Random rotation pairs per distance (default 20)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1000000)));
    cmd->add_option("--seed", o->seed, "Seed of the mesh sampling, the poses and the queries (default 1)");
    cmd->add_option("--points", o->points, "Points sampled from a mesh (default 30000; ignored for point clouds)")
        ->check(CLI::Range(std::size_t(2), std::size_t(100000000)));
    cmd->add_option("--csv", o->csv, "Write one row per pose to this CSV file");
    cmd->add_option("--hierarchy", o->hierarchy, "How the hierarchies are walked: likelihood (default), depth-first, flat")
        ->check(CLI::IsMember(traversal_names()));
    cmd->add_option("--budget-us", o->budget_us, "Time budget per query in microseconds (default 0: none)")
        ->check(CLI::NonNegativeNumber);
    add_object_settings(cmd, o->object, true);
    cmd->callback([o] { run_bench(*o); });
}

} // namespace pccd_tool
