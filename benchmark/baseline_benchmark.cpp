// baseline_benchmark: the alternatives a user has today, timed on the benchmark poses of
// doc/manual/sampling.md (the pose generator) and scored against CGAL's exact answer. Two copies of the
// Stanford bunny (libcgal-demo), normalized into [-1, 1]^3; A at [R_A | 0], B at [R_B | (d, 0, 0)].
// Methods (benchmark/collision_baselines.h), each single-threaded and stopping at the first contact:
//   fcl        FCL 0.7, OBBRSS hierarchies over the two meshes (the mesh the cloud was sampled from)
//   threshold  the N-point cloud, collision iff a point of B is within one mean spacing of A
// Per pose: the exact answer and the pose class (exact_separation + classify_pose with the cloud's
// sampling radius r(P): a pose with |gap or penetration| < r(P) is grazing and counted apart), and
// each method's time, the median of --repetitions runs. Figures in doc/benchmarks.md.
//
//   baseline_benchmark [--points 30000] [--rotations 20] [--seed 1] [--repetitions 5]
//                      [--threshold 1] (in mean spacings) [--csv FILE]
//
// CSV (one row per distance): distance, poses, exact_colliding, grazing, grazing_exact_colliding,
// then per method <m>_mean_us, <m>_median_us (over the poses' medians), <m>_false_negatives,
// <m>_false_positives (non-grazing poses), <m>_grazing_false_negatives, <m>_grazing_false_positives.
#include "collision_baselines.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/sample_triangle_mesh.h>
#include <PCCD/sampling_radius.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using PCCD::testing::Clock;
using PCCD::testing::mean;
using PCCD::testing::median;
using PCCD::testing::ms_since;
using PCCD::testing::us_since;

struct Arguments {
    std::size_t points = 30000;
    std::size_t rotations = 20;
    std::uint64_t seed = 1;
    int repetitions = 5;
    double threshold = 1.0; // in mean spacings of the cloud
    std::string csv;
};

Arguments parse(int argc, char** argv)
{
    Arguments a;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--points") a.points = std::stoul(value);
        else if (key == "--rotations") a.rotations = std::stoul(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--repetitions") a.repetitions = std::stoi(value);
        else if (key == "--threshold") a.threshold = std::stod(value);
        else if (key == "--csv") a.csv = value;
        else throw std::invalid_argument("unknown option " + key);
    }
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    if (a.repetitions < 1) throw std::invalid_argument("--repetitions must be >= 1");
    return a;
}

/// The answer of one query and the median of its run times, in microseconds.
template <class Query>
std::pair<bool, double> timed(int repetitions, const Query& query)
{
    std::vector<double> times;
    bool answer = false;
    for (int r = 0; r < repetitions; ++r) {
        const auto start = Clock::now();
        answer = query();
        times.push_back(us_since(start));
    }
    return {answer, median(times)};
}

/// One method's figures over a set of poses.
struct Method_figures {
    std::vector<double> times_us;
    std::size_t false_negatives = 0, false_positives = 0;
    std::size_t grazing_false_negatives = 0, grazing_false_positives = 0;

    void add(bool answer, bool exact, bool grazing, double time_us)
    {
        times_us.push_back(time_us);
        if (answer == exact) return;
        (grazing ? (exact ? grazing_false_negatives : grazing_false_positives)
                 : (exact ? false_negatives : false_positives))++;
    }
};

constexpr std::array<const char*, 2> method_names = {"fcl", "threshold"};

struct Distance_figures {
    double distance = 0.0;
    std::size_t poses = 0, exact_colliding = 0, grazing = 0, grazing_exact_colliding = 0;
    std::array<Method_figures, 2> methods;

    void add_pose(bool exact, bool grazing_pose)
    {
        ++poses;
        exact_colliding += exact;
        grazing += grazing_pose;
        grazing_exact_colliding += exact && grazing_pose;
    }
};

} // namespace

int main(int argc, char** argv)
try {
    const Arguments args = parse(argc, argv);
    const std::filesystem::path bunny = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    if (std::string(PCCD_DATA_DIR).empty() || !std::filesystem::exists(bunny)) {
        std::cerr << "# bunny00.off not found (install libcgal-demo): the baselines need the mesh; nothing to do\n";
        return 0;
    }
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(bunny.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);

    PCCD::Random_engine engine(args.seed);
    const PCCD::Triangle_mesh_sample sample =
        PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, args.points, engine);

    auto start = Clock::now();
    const PCCD::Exact_mesh exact(mesh);
    const double exact_ms = ms_since(start);
    start = Clock::now();
    const PCCD::benchmark::Fcl_mesh_baseline fcl(mesh);
    const double fcl_ms = ms_since(start);
    start = Clock::now();
    const PCCD::Point_cloud<> cloud(sample.points);
    const double kd_ms = ms_since(start);
    const double spacing = cloud.mean_spacing();
    const double radius = PCCD::sampling_radius(cloud);
    const PCCD::benchmark::Threshold_baseline threshold(cloud, cloud.coordinates(), args.threshold * spacing);

    std::printf("bunny: %zu vertices, %zu triangles; cloud N = %zu (seed %llu), mean spacing %.5f, r(P) = %.5f "
                "(%.2f spacings), threshold %.5f\n",
                mesh.vertices.size(), mesh.triangles.size(), cloud.size(), (unsigned long long)args.seed, spacing,
                radius, radius / spacing, threshold.threshold());
    std::printf("preprocessing: Exact_mesh %.0f ms, FCL OBBRSS BVH %.0f ms (%zu nodes), kd-tree %.0f ms\n", exact_ms,
                fcl_ms, fcl.number_of_nodes(), kd_ms);

    const std::vector<PCCD::testing::Benchmark_pose> poses = PCCD::testing::generate_benchmark_poses(
        PCCD::testing::Pose_options{.rotations_per_distance = args.rotations, .seed = args.seed});
    std::vector<Distance_figures> rows;
    double exact_total_ms = 0.0;
    for (const PCCD::testing::Benchmark_pose& pose : poses) {
        if (rows.empty() || rows.back().distance != pose.distance) {
            rows.emplace_back();
            rows.back().distance = pose.distance;
        }
        Distance_figures& row = rows.back();
        start = Clock::now();
        // Its surfaces_intersect is exact_do_intersect's answer, computed on the way.
        const PCCD::Exact_separation separation = PCCD::exact_separation(exact, pose.pose_a, exact, pose.pose_b);
        exact_total_ms += ms_since(start);
        const bool truth = separation.surfaces_intersect;
        const bool grazing = PCCD::classify_pose(separation, radius) == PCCD::Pose_class::grazing;
        row.add_pose(truth, grazing);
        const auto [fcl_answer, fcl_us] =
            timed(args.repetitions, [&] { return fcl.collide(pose.pose_a, pose.pose_b); });
        row.methods[0].add(fcl_answer, truth, grazing, fcl_us);
        const auto [threshold_answer, threshold_us] =
            timed(args.repetitions, [&] { return threshold.collide(pose.pose_a, pose.pose_b); });
        row.methods[1].add(threshold_answer, truth, grazing, threshold_us);
    }
    std::printf("exact reference: %.1f ms per pose on average (%zu poses)\n\n", exact_total_ms / double(poses.size()),
                poses.size());

    std::printf("| d | poses | colliding | grazing | FCL mean / median us | FCL FN / FP (grazing) "
                "| threshold mean / median us | threshold FN / FP (grazing) |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Distance_figures& row : rows) {
        std::printf("| %.2f | %zu | %zu | %zu", row.distance, row.poses, row.exact_colliding, row.grazing);
        for (const Method_figures& m : row.methods)
            std::printf(" | %.1f / %.1f | %zu / %zu (%zu / %zu)", mean(m.times_us), median(m.times_us),
                        m.false_negatives, m.false_positives, m.grazing_false_negatives, m.grazing_false_positives);
        std::printf(" |\n");
    }

    // Overall figures over the distances where the objects can meet, d in [0, 1.5].
    std::printf("\nover d in [0, 1.5]:");
    for (std::size_t k = 0; k < method_names.size(); ++k) {
        std::vector<double> times;
        std::size_t errors = 0, grazing_errors = 0;
        for (const Distance_figures& row : rows) {
            if (row.distance > 1.5) continue;
            const Method_figures& m = row.methods[k];
            times.insert(times.end(), m.times_us.begin(), m.times_us.end());
            errors += m.false_negatives + m.false_positives;
            grazing_errors += m.grazing_false_negatives + m.grazing_false_positives;
        }
        std::printf("%s %s mean %.1f us, median %.1f us, %zu errors on non-grazing poses, %zu on grazing ones",
                    k == 0 ? "" : ";", method_names[k], mean(times), median(times), errors, grazing_errors);
    }
    std::printf(".\n");

    if (!args.csv.empty()) {
        std::ofstream out = PCCD::testing::open_csv(args.csv);
        out << "distance,poses,exact_colliding,grazing,grazing_exact_colliding";
        for (const char* name : method_names)
            out << ',' << name << "_mean_us," << name << "_median_us," << name << "_false_negatives," << name
                << "_false_positives," << name << "_grazing_false_negatives," << name << "_grazing_false_positives";
        out << '\n';
        for (const Distance_figures& row : rows) {
            out << row.distance << ',' << row.poses << ',' << row.exact_colliding << ',' << row.grazing << ','
                << row.grazing_exact_colliding;
            for (const Method_figures& m : row.methods)
                out << ',' << mean(m.times_us) << ',' << median(m.times_us) << ',' << m.false_negatives << ','
                    << m.false_positives << ',' << m.grazing_false_negatives << ',' << m.grazing_false_positives;
            out << '\n';
        }
    }
    return 0;
} catch (const std::exception& e) {
    std::cerr << "baseline_benchmark: " << e.what() << '\n';
    return 1;
}
