// benchmark/intersection/runner.cpp -- timing the methods and tallying their answers.
#include "runner.h"

#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/Exact/mesh_separation.h>

#include <cstdio>
#include <ctime>

namespace pccd_bench::intersection {

using PCCD::testing::Clock;
using PCCD::testing::median;
using PCCD::testing::ms_since;
using PCCD::testing::us_since;

namespace {

/// CPU time of the calling thread, in microseconds: on a loaded machine a long query is preempted
/// more often than a short one, so wall times favour short queries; CPU time shows by how much.
double thread_cpu_us()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e6 * double(t.tv_sec) + 1e-3 * double(t.tv_nsec);
}

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

} // namespace

Timed_answer timed(int repetitions, const Method& method, const PCCD::testing::Benchmark_pose& pose, std::uint64_t seed)
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

std::vector<Method> pccd_methods(const PCCD::Point_cloud_object<>& object)
{
    return {pccd_method("isearch_object", object, PCCD::Interpolation_search{}, PCCD::Overlap_region::object_boxes),
            pccd_method("isearch_leaf", object, PCCD::Interpolation_search{}, PCCD::Overlap_region::leaf_boxes),
            pccd_method("rst_object", object, PCCD::Randomized_sampling{}, PCCD::Overlap_region::object_boxes),
            pccd_method("rst_leaf", object, PCCD::Randomized_sampling{}, PCCD::Overlap_region::leaf_boxes)};
}

void trace(const Arguments& args, const Method& method, const PCCD::testing::Benchmark_pose& pose, std::size_t k,
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

Truth exact_truth(const PCCD::Exact_mesh& exact, const PCCD::testing::Benchmark_pose& pose, double sampling_radius)
{
    const PCCD::Exact_separation separation = PCCD::exact_separation(exact, pose.pose_a, exact, pose.pose_b);
    return {separation.surfaces_intersect,
            PCCD::classify_pose(separation, sampling_radius) == PCCD::Pose_class::grazing};
}

void Tally::add(const Answer& answer, const Truth& truth, double time_us, double cpu_time_us)
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

void Tally::merge(const Tally& o)
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

std::vector<Distance_row> run_poses(const Arguments& args, const std::vector<Method>& methods,
                                    const PCCD::Exact_mesh& exact, double sampling_radius, int repetitions,
                                    bool traced)
{
    const std::vector<PCCD::testing::Benchmark_pose> poses = PCCD::testing::generate_benchmark_poses(
        PCCD::testing::Pose_options{.rotations_per_distance = args.rotations, .seed = args.seed});
    std::vector<Distance_row> rows;
    const auto start = Clock::now();
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const PCCD::testing::Benchmark_pose& pose = poses[k];
        Distance_row& row = row_for(rows, pose.distance, methods.size());
        const Truth truth = exact_truth(exact, pose, sampling_radius);
        row.add_pose(truth);
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const Timed_answer t = timed(repetitions, methods[m], pose, query_seed(args, k));
            if (traced) trace(args, methods[m], pose, k, t.answer, t.us);
            row.tallies[m].add(t.answer, truth, t.us, t.cpu_us);
        }
        if (pose.rotation_index + 1 == args.rotations)
            std::fprintf(stderr, "# d = %.2f done (%.0f s)\n", pose.distance, ms_since(start) / 1000.0);
    }
    return rows;
}

} // namespace pccd_bench::intersection
