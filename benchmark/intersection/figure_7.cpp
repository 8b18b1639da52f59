// benchmark/intersection/figure_7.cpp -- WSCG05 Fig. 7: the error rate per distance of
// Interpolation_search with a fixed sample count n per role, in both overlap regions; its Markdown
// tables and its CSV file.
#include "figures.h"
#include "runner.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/statistics.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace pccd_bench::intersection {

using PCCD::testing::mean;
using PCCD::testing::open_csv;

namespace {

/// Interpolation_search with n = 20, 50, 100, 150, 200 and the default sample count (the covering
/// formula, at least 200), in object_boxes then leaf_boxes.
std::vector<Method> sample_count_methods(const PCCD::Point_cloud_object<>& object)
{
    // n = 0 stands for the default sample count.
    const std::vector<std::size_t> counts = {20, 50, 100, 150, 200, 0};
    std::vector<Method> methods;
    for (const auto& [region, region_name] : {std::pair{PCCD::Overlap_region::object_boxes, "object"},
                                              std::pair{PCCD::Overlap_region::leaf_boxes, "leaf"}})
        for (const std::size_t n : counts) {
            PCCD::Interpolation_search policy;
            if (n > 0) policy.samples = n;
            const std::string name = std::string(region_name) + "_n" + (n > 0 ? std::to_string(n) : "default");
            methods.push_back(pccd_method(name, object, policy, region));
        }
    return methods;
}

/// (FN + FP) / non-grazing poses of `row`; NaN when every pose is grazing.
double error_rate(const Distance_row& row, const Tally& t)
{
    const std::size_t decidable = row.poses - row.grazing;
    return decidable == 0 ? std::nan("") : double(t.false_negatives + t.false_positives) / double(decidable);
}

void print_tables(const std::vector<Method>& methods, const std::vector<Distance_row>& rows)
{
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
}

void write_csv(const std::string& path, const std::vector<Method>& methods, const std::vector<Distance_row>& rows)
{
    std::ofstream out = open_csv(path, 8);
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

} // namespace

int figure_7(const Arguments& args, const Bunny_setup& bunny)
{
    const Prepared prepared = prepare(bunny.points);
    const PCCD::Point_cloud_object<>& object = prepared.object;
    print_setup(bunny, prepared, args);
    const double r = object.sampling_radius();
    const PCCD::Exact_mesh exact(bunny.mesh);

    const std::vector<Method> methods = sample_count_methods(object);
    const std::vector<Distance_row> rows = run_poses(args, methods, exact, r, 1, false);
    print_tables(methods, rows);
    if (!args.csv.empty()) write_csv(args.csv, methods, rows);
    return 0;
}

} // namespace pccd_bench::intersection
