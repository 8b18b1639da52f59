// benchmark/intersection/figure_10_11.cpp -- WSCG05 Fig. 10 and 11, with FCL and the threshold
// test beside PCCD: the run, its Markdown tables and its CSV file.
#include "baselines.h"
#include "figures.h"
#include "runner.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/statistics.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

namespace pccd_bench::intersection {

using PCCD::testing::mean;
using PCCD::testing::median;
using PCCD::testing::open_csv;

namespace {

/// The header of a table with one column per method after `first` (a header with `first_columns`
/// columns).
void print_method_header(const char* first, std::size_t first_columns, const std::vector<Method>& methods)
{
    std::printf("%s", first);
    for (const Method& m : methods) std::printf(" %s |", m.name.c_str());
    std::printf("\n|---|");
    for (std::size_t c = 1; c < first_columns; ++c) std::printf("---:|");
    for (std::size_t m = 0; m < methods.size(); ++m) std::printf("---:|");
    std::printf("\n");
}

/// Fig. 10 (times), Fig. 11 (f evaluations) and the answers, per distance.
void print_distance_tables(const Arguments& args, const std::vector<Method>& methods,
                           const std::vector<Distance_row>& rows)
{
    std::printf("\nFig. 10 -- query time, us: mean / median over the poses (each pose: median of %d runs)\n\n",
                args.repetitions);
    print_method_header("| d | colliding | grazing |", 3, methods);
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

    std::printf("\nAnswers -- colliding answers, FN / FP on non-grazing poses (FN / FP on grazing poses)\n\n");
    print_method_header("| d | exact colliding | grazing |", 3, methods);
    for (const Distance_row& row : rows) {
        std::printf("| %.2f | %zu | %zu |", row.distance, row.exact_colliding, row.grazing);
        for (const Tally& t : row.tallies)
            std::printf(" %zu: %zu / %zu (%zu / %zu) |", t.colliding, t.false_negatives, t.false_positives,
                        t.grazing_false_negatives, t.grazing_false_positives);
        std::printf("\n");
    }
}

/// Each method's tally pooled over the poses with d <= max_distance.
std::vector<Tally> pooled(const std::vector<Distance_row>& rows, std::size_t methods, double max_distance)
{
    std::vector<Tally> all(methods);
    for (const Distance_row& row : rows)
        if (row.distance <= max_distance)
            for (std::size_t m = 0; m < methods; ++m) all[m].merge(row.tallies[m]);
    return all;
}

/// RST against isearch in each overlap region, over the pooled tallies `all` (methods: 0
/// isearch_object, 1 isearch_leaf, 2 rst_object, 3 rst_leaf).
void print_rst_vs_isearch(const std::vector<Tally>& all)
{
    for (const auto& [i, s, region] : {std::tuple{0, 2, "object_boxes"}, std::tuple{1, 3, "leaf_boxes"}})
        std::printf("\n%s, RST / isearch: mean f %.1fx, mean time %.1fx (CPU time %.1fx), median time %.1fx; "
                    "isearch mean %.1f us, CPU %.1f us (acceptance: >= 5x, >= 5x, <= 100 us)",
                    region, mean(all[s].f_evaluations) / mean(all[i].f_evaluations),
                    mean(all[s].times_us) / mean(all[i].times_us), mean(all[s].cpu_us) / mean(all[i].cpu_us),
                    median(all[s].times_us) / median(all[i].times_us), mean(all[i].times_us), mean(all[i].cpu_us));
    std::printf("\n");
}

/// Averages over d in [0, 1.5] (pooled over the poses), and over all distances.
void print_averages(const std::vector<Method>& methods, const std::vector<Distance_row>& rows)
{
    for (const double max_distance : {1.5, 3.0}) {
        const std::vector<Tally> all = pooled(rows, methods.size(), max_distance);
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
        if (max_distance == 1.5) print_rst_vs_isearch(all);
    }
}

void write_csv(const std::string& path, const std::vector<Method>& methods, const std::vector<Distance_row>& rows)
{
    std::ofstream out = open_csv(path, 8);
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

} // namespace

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
    for (Method& m : baseline_methods(fcl, threshold)) methods.push_back(std::move(m));
    const std::vector<Distance_row> rows = run_poses(args, methods, exact, r, args.repetitions, true);

    print_distance_tables(args, methods, rows);
    print_averages(methods, rows);
    if (!args.csv.empty()) write_csv(args.csv, methods, rows);
    return 0;
}

} // namespace pccd_bench::intersection
