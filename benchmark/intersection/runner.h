// benchmark/intersection/runner.h -- running methods on the benchmark poses of
// doc/manual/sampling.md: a method is a named first-hit query (PCCD's do_intersect of
// doc/manual/intersection.md, or a baseline); each pose's truth is CGAL's exact answer and pose
// class (doc/manual/exact.md); each method's answers and times are tallied per distance.
#pragma once

#include "arguments.h"

#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/pose_generator.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pccd_bench::intersection {

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
    std::function<Answer(const PCCD::testing::Benchmark_pose&, std::uint64_t seed)> query;
};

/// A method's answer (of the last run) and the median wall (steady_clock) and thread CPU times of
/// `repetitions` runs, in microseconds.
struct Timed_answer {
    Answer answer;
    double us = 0.0;
    double cpu_us = 0.0;
};

Timed_answer timed(int repetitions, const Method& method, const PCCD::testing::Benchmark_pose& pose, std::uint64_t seed);

/// A PCCD method: do_intersect on `object` posed twice, with `policy` in `region` under the flat
/// traversal (WSCG05's region sampling; the regions apply to it only, and the figures of
/// doc/benchmarks.md "Intersection queries" were measured so. The walked traversals, the default
/// since, are measured by hierarchy_benchmark).
template <class Policy>
Method pccd_method(const std::string& name, const PCCD::Point_cloud_object<>& object, const Policy& policy,
                   PCCD::Overlap_region region)
{
    return Method{name, true, [&object, policy, region](const PCCD::testing::Benchmark_pose& p, std::uint64_t seed) {
                      const PCCD::Intersection_result r =
                          PCCD::do_intersect(object, p.pose_a, object, p.pose_b,
                                             PCCD::Intersection_options{.seed = seed,
                                                                        .region = region,
                                                                        .traversal = PCCD::Traversal::flat},
                                             policy);
                      return Answer{r.intersects, r.counters.f_evaluations, r.counters};
                  }};
}

/// The four PCCD configurations: {isearch, rst} x {object_boxes, leaf_boxes}, default policies.
std::vector<Method> pccd_methods(const PCCD::Point_cloud_object<>& object);

/// --trace 1: one line per pose and PCCD method on stderr, with the query's counters.
void trace(const Arguments& args, const Method& method, const PCCD::testing::Benchmark_pose& pose, std::size_t k,
           const Answer& a, double us);

/// The exact class of a pose.
struct Truth {
    bool colliding = false;
    bool grazing = false;
};

Truth exact_truth(const PCCD::Exact_mesh& exact, const PCCD::testing::Benchmark_pose& pose, double sampling_radius);

/// One method's figures over a set of poses.
struct Tally {
    std::vector<double> times_us, cpu_us;
    std::vector<double> f_evaluations;
    /// The times of the queries answering "colliding" and of the others.
    std::vector<double> hit_times_us, miss_times_us;
    std::size_t colliding = 0;
    std::size_t false_negatives = 0, false_positives = 0;
    std::size_t grazing_false_negatives = 0, grazing_false_positives = 0;

    void add(const Answer& answer, const Truth& truth, double time_us, double cpu_time_us);
    void merge(const Tally& o);
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

/// Runs every method on the benchmark poses (args.rotations rotation pairs per default distance,
/// args.seed), each timed as the median of `repetitions` runs and traced when `traced`, against the
/// exact truth of `exact` with grazing band `sampling_radius`; reports each finished distance on
/// stderr. One row per distance, in the poses' order.
std::vector<Distance_row> run_poses(const Arguments& args, const std::vector<Method>& methods,
                                    const PCCD::Exact_mesh& exact, double sampling_radius, int repetitions,
                                    bool traced);

} // namespace pccd_bench::intersection
