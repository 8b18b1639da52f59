// benchmark/intersection/figure_9.cpp -- WSCG05 Fig. 9: time and f evaluations vs cloud size
// (resampled bunny, fixed seed), averaged over d in [0, 1.5]; its Markdown table and CSV file.
#include "figures.h"
#include "runner.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/statistics.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace pccd_bench::intersection {

using PCCD::testing::mean;
using PCCD::testing::median;
using PCCD::testing::open_csv;

namespace {

const std::vector<std::string> method_names = {"isearch_object", "isearch_leaf", "rst_object", "rst_leaf"};

/// The benchmark poses with d <= 1.5, args.rotations_fig9 rotation pairs per distance.
std::vector<PCCD::testing::Benchmark_pose> near_poses(const Arguments& args)
{
    std::vector<double> distances;
    for (const double d : PCCD::testing::default_benchmark_distances())
        if (d <= 1.5) distances.push_back(d);
    return PCCD::testing::generate_benchmark_poses(
        PCCD::testing::Pose_options{.distances = distances, .rotations_per_distance = args.rotations_fig9, .seed = args.seed});
}

/// The CSV file (with its header) when --csv is given, else a closed stream.
std::ofstream open_fig9_csv(const Arguments& args)
{
    std::ofstream out;
    if (args.csv.empty()) return out;
    out = open_csv(args.csv, 8);
    out << "points,loglog_n,preprocess_ms,sampling_radius,poses";
    for (const std::string& n : method_names)
        out << ',' << n << "_mean_us," << n << "_median_us," << n << "_mean_cpu_us," << n << "_mean_f," << n
            << "_median_f," << n << "_colliding";
    out << '\n';
    return out;
}

void print_header()
{
    std::printf("| N | ln ln N | preprocessing ms | r(P) |");
    for (const std::string& n : method_names) std::printf(" %s mean / median us | mean f | colliding |", n.c_str());
    std::printf("\n|---:|---:|---:|---:|");
    for (std::size_t m = 0; m < method_names.size(); ++m) std::printf("---:|---:|---:|");
    std::printf("\n");
    std::fflush(stdout);
}

/// Each PCCD method's tally on `poses` (the answers taken as truth: no exact check).
std::vector<Tally> run_size(const Arguments& args, const Prepared& prepared,
                            const std::vector<PCCD::testing::Benchmark_pose>& poses)
{
    const std::vector<Method> methods = pccd_methods(prepared.object);
    std::vector<Tally> tallies(methods.size());
    for (std::size_t k = 0; k < poses.size(); ++k)
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const Timed_answer t = timed(args.repetitions, methods[m], poses[k], query_seed(args, k));
            trace(args, methods[m], poses[k], k, t.answer, t.us);
            tallies[m].add(t.answer, Truth{t.answer.colliding, false}, t.us, t.cpu_us);
        }
    return tallies;
}

} // namespace

int figure_9(const Arguments& args, const PCCD::Triangle_mesh_data& mesh)
{
    const std::vector<PCCD::testing::Benchmark_pose> poses = near_poses(args);
    std::printf("Fig. 9: resampled bunny (sample seed %llu), %zu poses (d = 0 .. 1.5, %zu rotation pairs each), "
                "median of %d runs per query\n\n",
                (unsigned long long)args.seed, poses.size(), args.rotations_fig9, args.repetitions);
    std::ofstream out = open_fig9_csv(args);
    print_header();
    for (const std::size_t size : args.sizes) {
        const Prepared prepared = prepare(cloud_points(mesh, size, args.seed));
        const std::vector<Tally> tallies = run_size(args, prepared, poses);
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

} // namespace pccd_bench::intersection
