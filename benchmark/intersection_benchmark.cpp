// intersection_benchmark: WSCG05's evaluation figures for PCCD's do_intersect, on
// the benchmark poses of doc/manual/sampling.md. Two copies of the Stanford bunny (libcgal-demo's
// bunny00.off), normalized into [-1, 1]^3; A at [R_A | 0], B at [R_B | (d, 0, 0)]. The cloud is the
// mesh's vertices, or --points N area-uniform samples of the mesh. Every query runs on one thread,
// one at a time, stops at the first intersection, and is timed with steady_clock as the median of
// --repetitions runs with the same seed. The truth per pose is CGAL's exact answer on the mesh
// (exact_separation); a pose whose gap or penetration is below the cloud's sampling radius r(P) is
// grazing (classify_pose) and counted apart.
//
//   --figure 10   (or 11, the same run) per distance d = 0 .. 3 step 0.25: interpolation search
//                 ("isearch") and randomized sampling ("rst"), each in Overlap_region::object_boxes
//                 (WSCG05's setting: no hierarchy) and leaf_boxes (PCCD's default), beside FCL
//                 (OBBRSS hierarchies of the mesh) and the nearest-neighbour threshold test on the
//                 cloud (benchmark/collision_baselines.h): mean and median query time, mean f
//                 evaluations, colliding answers, false negatives and positives. Then the averages
//                 over d in [0, 1.5], where the copies can meet.
//   --figure 7    error rate per distance of Interpolation_search{.samples = n}, n = 20, 50, 100,
//                 150, 200 (and the default sample count), in both regions.
//   --figure 9    time and f evaluations vs cloud size (--sizes, resampled bunny, fixed seed),
//                 averaged over d in [0, 1.5] with --rotations-fig9 rotation pairs per distance; no
//                 exact truth.
//
//   intersection_benchmark --figure 7|9|10|11 [--points N] [--rotations 20] [--rotations-fig9 10]
//                          [--seed 1] [--repetitions 3] [--sizes 10000,30000,...] [--csv FILE]
//                          [--trace 1] (each PCCD query's counters on stderr)
//
// Plots: benchmark/intersection_plots.gp. Figures and discussion: doc/benchmarks.md.
#include "collision_baselines.h"

#include <common/csv.h>
#include <common/statistics.h>
#include <common/timing.h>

#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Sampling/normalize.h>
#include <PCCD/Sampling/pose_generator.h>
#include <PCCD/Sampling/sample_triangle_mesh.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using pccd_bench::Clock;
using pccd_bench::mean;
using pccd_bench::median;
using pccd_bench::ms_since;
using pccd_bench::us_since;
using Pose = PCCD::Rigid_transform_3<double>;

struct Arguments {
    int figure = 10;
    std::size_t points = 0; // 0: the mesh's vertices
    std::size_t rotations = 20;
    std::size_t rotations_fig9 = 10;
    std::uint64_t seed = 1;
    int repetitions = 3;
    std::vector<std::size_t> sizes = {10000, 30000, 100000, 300000, 1000000};
    std::string csv;
    bool trace = false;
};

std::vector<std::size_t> parse_sizes(const std::string& text)
{
    std::vector<std::size_t> sizes;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) sizes.push_back(std::stoul(item));
    if (sizes.empty()) throw std::invalid_argument("--sizes needs a comma-separated list of point counts");
    return sizes;
}

Arguments parse(int argc, char** argv)
{
    Arguments a;
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--figure") a.figure = std::stoi(value);
        else if (key == "--points") a.points = std::stoul(value);
        else if (key == "--rotations") a.rotations = std::stoul(value);
        else if (key == "--rotations-fig9") a.rotations_fig9 = std::stoul(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--repetitions") a.repetitions = std::stoi(value);
        else if (key == "--sizes") a.sizes = parse_sizes(value);
        else if (key == "--csv") a.csv = value;
        else if (key == "--trace") a.trace = value != "0";
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.figure != 7 && a.figure != 9 && a.figure != 10 && a.figure != 11)
        throw std::invalid_argument("--figure must be 7, 9, 10 or 11");
    if (a.repetitions < 1) throw std::invalid_argument("--repetitions must be >= 1");
    if (a.rotations == 0 || a.rotations_fig9 == 0) throw std::invalid_argument("rotation counts must be >= 1");
    return a;
}

/// The bunny mesh normalized into [-1, 1]^3 (the benchmark procedure, doc/manual/sampling.md), or nothing without the data.
std::optional<PCCD::Triangle_mesh_data> read_bunny()
{
    const std::filesystem::path path = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    if (std::string(PCCD_DATA_DIR).empty() || !std::filesystem::exists(path)) return std::nullopt;
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);
    return mesh;
}

/// The cloud: the mesh's vertices (n = 0) or n area-uniform samples of the mesh drawn with `seed`.
std::vector<Eigen::Vector3d> cloud_points(const PCCD::Triangle_mesh_data& mesh, std::size_t n, std::uint64_t seed)
{
    if (n == 0) return {mesh.vertices.begin(), mesh.vertices.end()};
    PCCD::Random_engine engine(seed);
    const PCCD::Triangle_mesh_sample sample = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, engine);
    std::vector<Eigen::Vector3d> points(std::size_t(sample.points.cols()));
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points[std::size_t(i)] = sample.points.col(i);
    return points;
}

struct Prepared {
    PCCD::Point_cloud_object<> object;
    double preprocess_ms;
};

Prepared prepare(const std::vector<Eigen::Vector3d>& points)
{
    const auto start = Clock::now();
    PCCD::Point_cloud_object<> object(points);
    return {std::move(object), ms_since(start)};
}

/// A method's answer to one pose: whether it reports a collision, and its f evaluations (0 for the
/// baselines, which have no implicit surface).
struct Answer {
    bool colliding = false;
    std::size_t f_evaluations = 0;
    PCCD::Intersection_counters counters = {};
};

/// One method of a figure: a name and its first-hit query on a pose.
struct Method {
    std::string name;
    bool counts_f = true;
    std::function<Answer(const PCCD::Benchmark_pose&, std::uint64_t seed)> query;
};

/// CPU time of the calling thread, in microseconds: on a loaded machine a long query is preempted
/// more often than a short one, so wall times favour short queries; CPU time shows by how much.
double thread_cpu_us()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e6 * double(t.tv_sec) + 1e-3 * double(t.tv_nsec);
}

/// A method's answer (of the last run) and the median wall (steady_clock) and thread CPU times of
/// `repetitions` runs, in microseconds.
struct Timed_answer {
    Answer answer;
    double us = 0.0;
    double cpu_us = 0.0;
};

Timed_answer timed(int repetitions, const Method& method, const PCCD::Benchmark_pose& pose, std::uint64_t seed)
{
    std::vector<double> times, cpu_times;
    Answer answer;
    for (int r = 0; r < repetitions; ++r) {
        const double cpu_start = thread_cpu_us();
        const auto start = Clock::now();
        answer = method.query(pose, seed);
        times.push_back(us_since(start));
        cpu_times.push_back(thread_cpu_us() - cpu_start);
    }
    return {answer, median(times), median(cpu_times)};
}

/// The four PCCD configurations: {isearch, rst} x {object_boxes, leaf_boxes}, default policies.
std::vector<Method> pccd_methods(const PCCD::Point_cloud_object<>& object)
{
    std::vector<Method> methods;
    const auto add = [&](const std::string& name, const auto& policy, PCCD::Overlap_region region) {
        methods.push_back(Method{name, true, [&object, policy, region](const PCCD::Benchmark_pose& p, std::uint64_t seed) {
                                     const PCCD::Intersection_result r = PCCD::do_intersect(
                                         object, p.pose_a, object, p.pose_b,
                                         PCCD::Intersection_options{.seed = seed, .region = region}, policy);
                                     return Answer{r.intersects, r.counters.f_evaluations, r.counters};
                                 }});
    };
    add("isearch_object", PCCD::Interpolation_search{}, PCCD::Overlap_region::object_boxes);
    add("isearch_leaf", PCCD::Interpolation_search{}, PCCD::Overlap_region::leaf_boxes);
    add("rst_object", PCCD::Randomized_sampling{}, PCCD::Overlap_region::object_boxes);
    add("rst_leaf", PCCD::Randomized_sampling{}, PCCD::Overlap_region::leaf_boxes);
    return methods;
}

/// --trace 1: one line per pose and PCCD method on stderr, with the query's counters.
void trace(const Arguments& args, const Method& method, const PCCD::Benchmark_pose& pose, std::size_t k,
           const Answer& a, double us)
{
    if (!args.trace || !method.counts_f) return;
    const PCCD::Intersection_counters& c = a.counters;
    std::fprintf(stderr,
                 "trace pose %zu d %.2f rot %zu %s: %s %.1f us, f %zu samples %zu candidates %zu node_pairs %zu "
                 "leaf_pairs %zu brackets %zu/%zu steps %zu (bisection %zu)\n",
                 k, pose.distance, pose.rotation_index, method.name.c_str(), a.colliding ? "hit" : "miss", us,
                 c.f_evaluations, c.samples, c.candidate_points, c.node_pairs, c.leaf_pairs, c.brackets_found,
                 c.brackets_tried, c.search_steps, c.bisection_steps);
}

/// The exact class of a pose.
struct Truth {
    bool colliding = false;
    bool grazing = false;
};

Truth exact_truth(const PCCD::Exact_mesh& exact, const PCCD::Benchmark_pose& pose, double sampling_radius)
{
    const PCCD::Exact_separation separation = PCCD::exact_separation(exact, pose.pose_a, exact, pose.pose_b);
    return {separation.surfaces_intersect,
            PCCD::classify_pose(separation, sampling_radius) == PCCD::Pose_class::grazing};
}

/// One method's figures over a set of poses.
struct Tally {
    std::vector<double> times_us, cpu_us;
    std::vector<double> f_evaluations;
    /// The times of the queries answering "colliding" and of the others.
    std::vector<double> hit_times_us, miss_times_us;
    std::size_t colliding = 0;
    std::size_t false_negatives = 0, false_positives = 0;
    std::size_t grazing_false_negatives = 0, grazing_false_positives = 0;

    void add(const Answer& answer, const Truth& truth, double time_us, double cpu_time_us)
    {
        times_us.push_back(time_us);
        cpu_us.push_back(cpu_time_us);
        f_evaluations.push_back(double(answer.f_evaluations));
        (answer.colliding ? hit_times_us : miss_times_us).push_back(time_us);
        colliding += answer.colliding;
        if (answer.colliding == truth.colliding) return;
        (truth.grazing ? (truth.colliding ? grazing_false_negatives : grazing_false_positives)
                       : (truth.colliding ? false_negatives : false_positives))++;
    }
    void merge(const Tally& o)
    {
        times_us.insert(times_us.end(), o.times_us.begin(), o.times_us.end());
        cpu_us.insert(cpu_us.end(), o.cpu_us.begin(), o.cpu_us.end());
        f_evaluations.insert(f_evaluations.end(), o.f_evaluations.begin(), o.f_evaluations.end());
        hit_times_us.insert(hit_times_us.end(), o.hit_times_us.begin(), o.hit_times_us.end());
        miss_times_us.insert(miss_times_us.end(), o.miss_times_us.begin(), o.miss_times_us.end());
        colliding += o.colliding;
        false_negatives += o.false_negatives;
        false_positives += o.false_positives;
        grazing_false_negatives += o.grazing_false_negatives;
        grazing_false_positives += o.grazing_false_positives;
    }
};

/// The poses of one distance and each method's tally on them.
struct Distance_row {
    double distance = 0.0;
    std::size_t poses = 0, exact_colliding = 0, grazing = 0;
    std::vector<Tally> tallies;

    void add_pose(const Truth& t)
    {
        ++poses;
        exact_colliding += t.colliding;
        grazing += t.grazing;
    }
};

/// Rows per distance, in the order of the poses (generate_benchmark_poses groups them by distance).
Distance_row& row_for(std::vector<Distance_row>& rows, double distance, std::size_t methods)
{
    if (rows.empty() || rows.back().distance != distance) {
        rows.emplace_back();
        rows.back().distance = distance;
        rows.back().tallies.resize(methods);
    }
    return rows.back();
}

/// The seed of the PCCD queries on pose number k (the same for every method and repetition).
std::uint64_t query_seed(const Arguments& args, std::size_t k) { return args.seed * 1000003ULL + k; }

std::ofstream open_csv(const std::string& path) { return pccd_bench::open_csv(path, 8); }

struct Bunny_setup {
    PCCD::Triangle_mesh_data mesh;
    std::vector<Eigen::Vector3d> points;
};

void print_setup(const Bunny_setup& bunny, const Prepared& prepared, const Arguments& args)
{
    const PCCD::Point_cloud_object<>& object = prepared.object;
    std::printf("bunny: %zu vertices, %zu triangles; cloud N = %zu (%s), mean spacing %.5f, r(P) = %.5f, "
                "preprocessing %.0f ms; %zu rotation pairs per distance, seed %llu, median of %d runs per query\n",
                bunny.mesh.vertices.size(), bunny.mesh.triangles.size(), object.size(),
                args.points == 0 ? "mesh vertices" : "resampled mesh", object.cloud().mean_spacing(),
                object.sampling_radius(), prepared.preprocess_ms, args.rotations, (unsigned long long)args.seed,
                args.repetitions);
}

/// WSCG05 Fig. 10 and 11, with FCL and the threshold test beside PCCD.
int figure_10_11(const Arguments& args, const Bunny_setup& bunny)
{
    const Prepared prepared = prepare(bunny.points);
    const PCCD::Point_cloud_object<>& object = prepared.object;
    print_setup(bunny, prepared, args);
    const double r = object.sampling_radius();
    const PCCD::Exact_mesh exact(bunny.mesh);
    const PCCD::benchmark::Fcl_mesh_baseline fcl(bunny.mesh);
    const PCCD::benchmark::Threshold_baseline threshold(object.cloud(), object.cloud().coordinates());
    std::printf("threshold test: one mean spacing, %.5f\n", threshold.threshold());

    std::vector<Method> methods = pccd_methods(object);
    methods.push_back(Method{"fcl", false, [&fcl](const PCCD::Benchmark_pose& p, std::uint64_t) {
                                 return Answer{fcl.collide(p.pose_a, p.pose_b), 0};
                             }});
    methods.push_back(Method{"threshold", false, [&threshold](const PCCD::Benchmark_pose& p, std::uint64_t) {
                                 return Answer{threshold.collide(p.pose_a, p.pose_b), 0};
                             }});

    const std::vector<PCCD::Benchmark_pose> poses = PCCD::generate_benchmark_poses(
        PCCD::Pose_options{.rotations_per_distance = args.rotations, .seed = args.seed});
    std::vector<Distance_row> rows;
    const auto start = Clock::now();
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const PCCD::Benchmark_pose& pose = poses[k];
        Distance_row& row = row_for(rows, pose.distance, methods.size());
        const Truth truth = exact_truth(exact, pose, r);
        row.add_pose(truth);
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const Timed_answer t = timed(args.repetitions, methods[m], pose, query_seed(args, k));
            trace(args, methods[m], pose, k, t.answer, t.us);
            row.tallies[m].add(t.answer, truth, t.us, t.cpu_us);
        }
        if (pose.rotation_index + 1 == args.rotations)
            std::fprintf(stderr, "# d = %.2f done (%.0f s)\n", pose.distance, ms_since(start) / 1000.0);
    }

    std::printf("\nFig. 10 -- query time, us: mean / median over the poses (each pose: median of %d runs)\n\n",
                args.repetitions);
    std::printf("| d | colliding | grazing |");
    for (const Method& m : methods) std::printf(" %s |", m.name.c_str());
    std::printf("\n|---|---:|---:|");
    for (std::size_t m = 0; m < methods.size(); ++m) std::printf("---:|");
    std::printf("\n");
    for (const Distance_row& row : rows) {
        std::printf("| %.2f | %zu | %zu |", row.distance, row.exact_colliding, row.grazing);
        for (const Tally& t : row.tallies) std::printf(" %.1f / %.1f |", mean(t.times_us), median(t.times_us));
        std::printf("\n");
    }

    std::printf("\nFig. 11 -- f evaluations: mean / median over the poses\n\n| d |");
    for (const Method& m : methods)
        if (m.counts_f) std::printf(" %s |", m.name.c_str());
    std::printf("\n|---|");
    for (const Method& m : methods)
        if (m.counts_f) std::printf("---:|");
    std::printf("\n");
    for (const Distance_row& row : rows) {
        std::printf("| %.2f |", row.distance);
        for (std::size_t m = 0; m < methods.size(); ++m)
            if (methods[m].counts_f)
                std::printf(" %.0f / %.0f |", mean(row.tallies[m].f_evaluations), median(row.tallies[m].f_evaluations));
        std::printf("\n");
    }

    std::printf("\nAnswers -- colliding answers, FN / FP on non-grazing poses (FN / FP on grazing poses)\n\n"
                "| d | exact colliding | grazing |");
    for (const Method& m : methods) std::printf(" %s |", m.name.c_str());
    std::printf("\n|---|---:|---:|");
    for (std::size_t m = 0; m < methods.size(); ++m) std::printf("---:|");
    std::printf("\n");
    for (const Distance_row& row : rows) {
        std::printf("| %.2f | %zu | %zu |", row.distance, row.exact_colliding, row.grazing);
        for (const Tally& t : row.tallies)
            std::printf(" %zu: %zu / %zu (%zu / %zu) |", t.colliding, t.false_negatives, t.false_positives,
                        t.grazing_false_negatives, t.grazing_false_positives);
        std::printf("\n");
    }

    // Averages over d in [0, 1.5] (pooled over the poses), and over all distances.
    const auto pooled = [&](double max_distance) {
        std::vector<Tally> all(methods.size());
        for (const Distance_row& row : rows)
            if (row.distance <= max_distance)
                for (std::size_t m = 0; m < methods.size(); ++m) all[m].merge(row.tallies[m]);
        return all;
    };
    for (const double max_distance : {1.5, 3.0}) {
        const std::vector<Tally> all = pooled(max_distance);
        std::printf("\nOver d in [0, %.1f] (%zu poses each):\n\n| method | mean us | median us | mean CPU us | mean us: "
                    "colliding answers / others | mean f | median f | FN / FP | grazing FN / FP |\n"
                    "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
                    max_distance, all[0].times_us.size());
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const Tally& t = all[m];
            std::printf("| %s | %.1f | %.1f | %.1f | %.1f (%zu) / %.1f (%zu) | %.0f | %.0f | %zu / %zu | %zu / %zu |\n",
                        methods[m].name.c_str(), mean(t.times_us), median(t.times_us), mean(t.cpu_us), mean(t.hit_times_us),
                        t.hit_times_us.size(), mean(t.miss_times_us), t.miss_times_us.size(), mean(t.f_evaluations),
                        median(t.f_evaluations), t.false_negatives, t.false_positives, t.grazing_false_negatives,
                        t.grazing_false_positives);
        }
        if (max_distance == 1.5) {
            // methods: 0 isearch_object, 1 isearch_leaf, 2 rst_object, 3 rst_leaf.
            for (const auto& [i, s, region] : {std::tuple{0, 2, "object_boxes"}, std::tuple{1, 3, "leaf_boxes"}})
                std::printf("\n%s, RST / isearch: mean f %.1fx, mean time %.1fx (CPU time %.1fx), median time %.1fx; "
                            "isearch mean %.1f us, CPU %.1f us (acceptance: >= 5x, >= 5x, <= 100 us)",
                            region, mean(all[s].f_evaluations) / mean(all[i].f_evaluations),
                            mean(all[s].times_us) / mean(all[i].times_us), mean(all[s].cpu_us) / mean(all[i].cpu_us),
                            median(all[s].times_us) / median(all[i].times_us), mean(all[i].times_us),
                            mean(all[i].cpu_us));
            std::printf("\n");
        }
    }

    if (!args.csv.empty()) {
        std::ofstream out = open_csv(args.csv);
        out << "distance,poses,exact_colliding,grazing";
        for (const Method& m : methods) {
            const std::string& n = m.name;
            out << ',' << n << "_mean_us," << n << "_median_us," << n << "_mean_cpu_us";
            if (m.counts_f) out << ',' << n << "_mean_f," << n << "_median_f";
            out << ',' << n << "_colliding," << n << "_false_negatives," << n << "_false_positives," << n
                << "_grazing_false_negatives," << n << "_grazing_false_positives";
        }
        out << '\n';
        for (const Distance_row& row : rows) {
            out << row.distance << ',' << row.poses << ',' << row.exact_colliding << ',' << row.grazing;
            for (std::size_t m = 0; m < methods.size(); ++m) {
                const Tally& t = row.tallies[m];
                out << ',' << mean(t.times_us) << ',' << median(t.times_us) << ',' << mean(t.cpu_us);
                if (methods[m].counts_f) out << ',' << mean(t.f_evaluations) << ',' << median(t.f_evaluations);
                out << ',' << t.colliding << ',' << t.false_negatives << ',' << t.false_positives << ','
                    << t.grazing_false_negatives << ',' << t.grazing_false_positives;
            }
            out << '\n';
        }
    }
    return 0;
}

/// WSCG05 Fig. 7: error rate vs distance for a fixed sample count n per role.
int figure_7(const Arguments& args, const Bunny_setup& bunny)
{
    const Prepared prepared = prepare(bunny.points);
    const PCCD::Point_cloud_object<>& object = prepared.object;
    print_setup(bunny, prepared, args);
    const double r = object.sampling_radius();
    const PCCD::Exact_mesh exact(bunny.mesh);

    // n = 0 stands for the default sample count (the covering formula, at least 200).
    const std::vector<std::size_t> counts = {20, 50, 100, 150, 200, 0};
    std::vector<Method> methods;
    for (const auto& [region, region_name] : {std::pair{PCCD::Overlap_region::object_boxes, "object"},
                                              std::pair{PCCD::Overlap_region::leaf_boxes, "leaf"}})
        for (const std::size_t n : counts) {
            PCCD::Interpolation_search policy;
            if (n > 0) policy.samples = n;
            const std::string name = std::string(region_name) + "_n" + (n > 0 ? std::to_string(n) : "default");
            methods.push_back(Method{name, true, [&object, policy, region](const PCCD::Benchmark_pose& p, std::uint64_t seed) {
                                         const PCCD::Intersection_result res = PCCD::do_intersect(
                                             object, p.pose_a, object, p.pose_b,
                                             PCCD::Intersection_options{.seed = seed, .region = region}, policy);
                                         return Answer{res.intersects, res.counters.f_evaluations, res.counters};
                                     }});
        }

    const std::vector<PCCD::Benchmark_pose> poses = PCCD::generate_benchmark_poses(
        PCCD::Pose_options{.rotations_per_distance = args.rotations, .seed = args.seed});
    std::vector<Distance_row> rows;
    const auto start = Clock::now();
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const PCCD::Benchmark_pose& pose = poses[k];
        Distance_row& row = row_for(rows, pose.distance, methods.size());
        const Truth truth = exact_truth(exact, pose, r);
        row.add_pose(truth);
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const Timed_answer t = timed(1, methods[m], pose, query_seed(args, k));
            row.tallies[m].add(t.answer, truth, t.us, t.cpu_us);
        }
        if (pose.rotation_index + 1 == args.rotations)
            std::fprintf(stderr, "# d = %.2f done (%.0f s)\n", pose.distance, ms_since(start) / 1000.0);
    }

    const auto error_rate = [](const Distance_row& row, const Tally& t) {
        const std::size_t decidable = row.poses - row.grazing;
        return decidable == 0 ? std::nan("") : double(t.false_negatives + t.false_positives) / double(decidable);
    };
    std::printf("\nFig. 7 -- error rate (FN + FP) / non-grazing poses, %% (FN / FP)\n\n| d | non-grazing |");
    for (const Method& m : methods) std::printf(" %s |", m.name.c_str());
    std::printf("\n|---|---:|");
    for (std::size_t m = 0; m < methods.size(); ++m) std::printf("---:|");
    std::printf("\n");
    std::vector<Tally> all(methods.size());
    std::size_t decidable = 0;
    for (const Distance_row& row : rows) {
        std::printf("| %.2f | %zu |", row.distance, row.poses - row.grazing);
        decidable += row.poses - row.grazing;
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const Tally& t = row.tallies[m];
            all[m].merge(t);
            std::printf(" %.1f (%zu / %zu) |", 100.0 * error_rate(row, t), t.false_negatives, t.false_positives);
        }
        std::printf("\n");
    }
    std::printf("\nOver all %zu non-grazing poses: | method | FN | FP | error %% | mean f | grazing FN / FP |\n",
                decidable);
    for (std::size_t m = 0; m < methods.size(); ++m)
        std::printf("| %s | %zu | %zu | %.2f | %.0f | %zu / %zu |\n", methods[m].name.c_str(), all[m].false_negatives,
                    all[m].false_positives,
                    100.0 * double(all[m].false_negatives + all[m].false_positives) / double(decidable),
                    mean(all[m].f_evaluations), all[m].grazing_false_negatives, all[m].grazing_false_positives);

    if (!args.csv.empty()) {
        std::ofstream out = open_csv(args.csv);
        out << "distance,poses,exact_colliding,grazing,non_grazing";
        for (const Method& m : methods)
            out << ',' << m.name << "_error_rate," << m.name << "_false_negatives," << m.name << "_false_positives,"
                << m.name << "_mean_f";
        out << '\n';
        for (const Distance_row& row : rows) {
            out << row.distance << ',' << row.poses << ',' << row.exact_colliding << ',' << row.grazing << ','
                << row.poses - row.grazing;
            for (const Tally& t : row.tallies)
                out << ',' << error_rate(row, t) << ',' << t.false_negatives << ',' << t.false_positives << ','
                    << mean(t.f_evaluations);
            out << '\n';
        }
    }
    return 0;
}

/// WSCG05 Fig. 9: time vs cloud size, averaged over d in [0, 1.5].
int figure_9(const Arguments& args, const PCCD::Triangle_mesh_data& mesh)
{
    std::vector<double> distances;
    for (const double d : PCCD::default_benchmark_distances())
        if (d <= 1.5) distances.push_back(d);
    const std::vector<PCCD::Benchmark_pose> poses = PCCD::generate_benchmark_poses(
        PCCD::Pose_options{.distances = distances, .rotations_per_distance = args.rotations_fig9, .seed = args.seed});
    std::printf("Fig. 9: resampled bunny (sample seed %llu), %zu poses (d = 0 .. 1.5, %zu rotation pairs each), "
                "median of %d runs per query\n\n",
                (unsigned long long)args.seed, poses.size(), args.rotations_fig9, args.repetitions);

    const std::vector<std::string> names = {"isearch_object", "isearch_leaf", "rst_object", "rst_leaf"};
    std::ofstream out;
    if (!args.csv.empty()) {
        out = open_csv(args.csv);
        out << "points,loglog_n,preprocess_ms,sampling_radius,poses";
        for (const std::string& n : names)
            out << ',' << n << "_mean_us," << n << "_median_us," << n << "_mean_cpu_us," << n << "_mean_f," << n
                << "_median_f," << n << "_colliding";
        out << '\n';
    }
    std::printf("| N | ln ln N | preprocessing ms | r(P) |");
    for (const std::string& n : names) std::printf(" %s mean / median us | mean f | colliding |", n.c_str());
    std::printf("\n|---:|---:|---:|---:|");
    for (std::size_t m = 0; m < names.size(); ++m) std::printf("---:|---:|---:|");
    std::printf("\n");
    std::fflush(stdout);
    for (const std::size_t size : args.sizes) {
        const Prepared prepared = prepare(cloud_points(mesh, size, args.seed));
        const std::vector<Method> methods = pccd_methods(prepared.object);
        std::vector<Tally> tallies(methods.size());
        for (std::size_t k = 0; k < poses.size(); ++k)
            for (std::size_t m = 0; m < methods.size(); ++m) {
                const Timed_answer t = timed(args.repetitions, methods[m], poses[k], query_seed(args, k));
                trace(args, methods[m], poses[k], k, t.answer, t.us);
                tallies[m].add(t.answer, Truth{t.answer.colliding, false}, t.us, t.cpu_us);
            }
        const double loglog = std::log(std::log(double(size)));
        std::printf("| %zu | %.3f | %.0f | %.5f |", size, loglog, prepared.preprocess_ms,
                    prepared.object.sampling_radius());
        for (const Tally& t : tallies)
            std::printf(" %.1f / %.1f | %.0f | %zu |", mean(t.times_us), median(t.times_us), mean(t.f_evaluations),
                        t.colliding);
        std::printf("\n");
        std::fflush(stdout);
        if (out.is_open()) {
            out << size << ',' << loglog << ',' << prepared.preprocess_ms << ',' << prepared.object.sampling_radius()
                << ',' << poses.size();
            for (const Tally& t : tallies)
                out << ',' << mean(t.times_us) << ',' << median(t.times_us) << ',' << mean(t.cpu_us) << ','
                    << mean(t.f_evaluations) << ',' << median(t.f_evaluations) << ',' << t.colliding;
            out << '\n' << std::flush;
        }
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
try {
    const Arguments args = parse(argc, argv);
    std::optional<PCCD::Triangle_mesh_data> mesh = read_bunny();
    if (!mesh) {
        std::cerr << "# bunny00.off not found (install libcgal-demo): the figures need the bunny; nothing to do\n";
        return 0;
    }
    if (args.figure == 9) return figure_9(args, *mesh);
    Bunny_setup bunny{*mesh, cloud_points(*mesh, args.points, args.seed)};
    return args.figure == 7 ? figure_7(args, bunny) : figure_10_11(args, bunny);
} catch (const std::exception& e) {
    std::cerr << "intersection_benchmark: " << e.what() << '\n';
    return 1;
}
