// benchmark/distance_benchmark.cpp -- the proximity queries (PCCD::distance, PCCD::within_distance)
// timed against FCL's distance() on the source mesh, and within_distance against its peer, the
// first-hit query do_intersect, per model over the benchmark poses (doc/manual/sampling.md).
// Results and the commands are in doc/benchmarks.md "Proximity queries: distance and clearance
// against FCL".
//
//   distance_benchmark [--models bunny00.off,elephant.off,armadillo.off,ChineseDragon-10kv.off]
//                      [--points 30000] [--rotations 20] [--repetitions 5] [--seed 1]
//                      [--margin 2] [--candidates 2] [--certified 0|1] [--evict 64] [--csv OUT]
//
// Per model: the mesh is normalized into [-1, 1]^3, FCL's OBBRSS hierarchy is built on it, and a
// cloud of --points points is sampled by area and preprocessed with default options. Per pose (d =
// 0 .. 3 step 0.25, --rotations rotation pairs per d), four methods:
//   fcl          FCL's distance() on the mesh, exact (rel_err = abs_err = 0, nearest points on);
//   distance     PCCD::distance() with default options (intersection seed --seed; --candidates
//                sets Distance_options::candidates, default 2 as the library's; --certified 1 sets
//                Distance_options::certified_lower_bound, for within as well);
//   within       PCCD::within_distance() with a margin of --margin mean spacings of the cloud;
//   do_intersect PCCD::do_intersect() with the options the two queries above decide the status with.
// Times are this thread's CPU time in us. Cold: each method once per pose, the four interleaved per
// pose (the order above on even poses, reversed on odd ones), each run after a sweep over a buffer
// of --evict MiB (default 64, twice the L3 cache of the benchmark machine) that evicts what the
// previous method left in the caches: the three PCCD queries share their data and their first
// step (do_intersect), so without it the method run second on a pose would find the first one's
// data cached (--evict 0: no sweep). Warm: then the median of --repetitions runs in a row per
// method. Printed per model: mean and median per method, cold and warm, over all poses
// and over the separate ones (FCL distance > 0); the ratios distance / fcl and within /
// do_intersect; the mean counters; and the accuracy of PCCD's distance against FCL's (exact on the
// mesh) in mean spacings, on the poses both call separate.
#include "collision_baselines.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Arguments {
    std::vector<std::string> models{"bunny00.off", "elephant.off", "armadillo.off", "ChineseDragon-10kv.off"};
    std::size_t points = 30000;
    std::size_t rotations = 20;
    int repetitions = 5;
    std::uint64_t seed = 1;
    double margin_spacings = 2.0;
    std::size_t candidates = PCCD::Distance_options{}.candidates;
    bool certified = false;
    std::size_t evict_mib = 64;
    std::string csv;
};

std::vector<std::string> split(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) items.push_back(item);
    if (items.empty()) throw std::invalid_argument("empty list: " + text);
    return items;
}

Arguments parse(int argc, char** argv)
{
    Arguments a;
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--models") a.models = split(value);
        else if (key == "--points") a.points = std::stoul(value);
        else if (key == "--rotations") a.rotations = std::stoul(value);
        else if (key == "--repetitions") a.repetitions = std::stoi(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--margin") a.margin_spacings = std::stod(value);
        else if (key == "--evict") a.evict_mib = std::stoul(value);
        else if (key == "--candidates") a.candidates = std::stoul(value);
        else if (key == "--certified") a.certified = std::stoi(value) != 0;
        else if (key == "--csv") a.csv = value;
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.repetitions < 1 || a.rotations == 0 || a.points < 100)
        throw std::invalid_argument("--repetitions and --rotations must be >= 1, --points >= 100");
    if (!(std::isfinite(a.margin_spacings) && a.margin_spacings >= 0.0))
        throw std::invalid_argument("--margin must be finite and >= 0 (mean spacings)");
    return a;
}

/// What one run of a method gives: its verdict (intersecting, or within the margin), the distance
/// (fcl and distance), and the work counters (0 where a method has none).
struct Outcome {
    bool hit = false;
    double value = std::nan("");
    bool separate = false; // PCCD: status separate; FCL: distance > 0
    double node_pairs = 0, leaf_pairs = 0, point_pairs = 0, f_evaluations = 0;
    double intersection_node_pairs = 0, intersection_f_evaluations = 0, refinement_steps = 0;
};

Outcome outcome_of(const PCCD::benchmark::Fcl_distance& d)
{
    Outcome o;
    o.value = d.distance;
    o.hit = d.distance <= 0.0;
    o.separate = d.distance > 0.0;
    return o;
}

Outcome outcome_of_counters(const PCCD::Distance_counters& c)
{
    Outcome o;
    o.node_pairs = double(c.node_pairs);
    o.leaf_pairs = double(c.leaf_pairs);
    o.point_pairs = double(c.point_pairs);
    o.f_evaluations = double(c.f_evaluations);
    o.refinement_steps = double(c.refinement_steps);
    o.intersection_node_pairs = double(c.intersection.node_pairs);
    o.intersection_f_evaluations = double(c.intersection.f_evaluations);
    return o;
}

Outcome outcome_of(const PCCD::Distance_result& r)
{
    Outcome o = outcome_of_counters(r.counters);
    o.value = r.distance;
    o.hit = r.intersecting();
    o.separate = r.status == PCCD::Intersection_status::separate;
    return o;
}

Outcome outcome_of(const PCCD::Clearance_result& r)
{
    Outcome o = outcome_of_counters(r.counters);
    o.hit = r.within;
    o.separate = r.status == PCCD::Intersection_status::separate;
    return o;
}

Outcome outcome_of(const PCCD::Intersection_result& r)
{
    Outcome o;
    o.hit = r.intersects;
    o.separate = r.status == PCCD::Intersection_status::separate;
    o.intersection_node_pairs = double(r.counters.node_pairs);
    o.intersection_f_evaluations = double(r.counters.f_evaluations);
    return o;
}

/// Evicts the caches: reads and writes every cache line of a buffer larger than the last-level
/// cache. Returns a value that depends on the buffer, so the sweep cannot be optimized away.
class Cache_evictor {
public:
    explicit Cache_evictor(std::size_t mib) : m_buffer(mib * 1024 * 1024 / sizeof(std::uint64_t), 1) {}
    std::uint64_t sweep()
    {
        std::uint64_t sum = 0;
        for (std::size_t i = 0; i < m_buffer.size(); i += 8) { // 64-byte lines
            m_buffer[i] += 1;
            sum += m_buffer[i];
        }
        return sum;
    }

private:
    std::vector<std::uint64_t> m_buffer;
};

enum Method { fcl, distance, within, intersect, method_count };
const std::array<const char*, method_count> method_names{"fcl", "distance", "within", "do_intersect"};

struct Sample {
    double d;
    std::size_t rotation;
    bool fcl_separate;
    double cold_us, warm_us;
    Outcome outcome;
};

struct Summary {
    double mean = std::nan(""), median = std::nan("");
};

Summary summarize(const std::vector<Sample>& samples, bool warm, bool separate_only)
{
    std::vector<double> v;
    for (const Sample& s : samples)
        if (!separate_only || s.fcl_separate) v.push_back(warm ? s.warm_us : s.cold_us);
    return {PCCD::testing::mean(v), PCCD::testing::median(v)};
}

double mean_of(const std::vector<Sample>& samples, double Outcome::*field, bool separate_only = false)
{
    std::vector<double> v;
    for (const Sample& s : samples)
        if (!separate_only || s.fcl_separate) v.push_back(s.outcome.*field);
    return PCCD::testing::mean(v);
}

double p99(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? std::nan("") : PCCD::testing::sorted_quantile(v, 99);
}

void run_model(const std::string& name, const Arguments& args, std::ofstream* csv)
{
    const std::filesystem::path path = std::filesystem::path(PCCD_DATA_DIR) / name;
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);
    const PCCD::benchmark::Fcl_mesh_baseline fcl_mesh(mesh);
    PCCD::Random_engine engine(args.seed);
    const PCCD::Triangle_mesh_sample sample =
        PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, args.points, engine);
    std::vector<Eigen::Vector3d> points(std::size_t(sample.points.cols()));
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points[std::size_t(i)] = sample.points.col(i);
    const auto start = PCCD::testing::Clock::now();
    const PCCD::Point_cloud_object<> object(points);
    const double preprocess_s = PCCD::testing::seconds_since(start);
    const double spacing = object.cloud().mean_spacing();
    const double margin = args.margin_spacings * spacing;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("\n%s: %zu triangles, %zu points sampled by area, mean spacing %.5f, r(P) %.5f, margin %.5f "
                "(%.2f mean spacings), preprocessing %.2f s, peak memory so far %.0f MiB, hierarchy %zu nodes\n",
                name.c_str(), mesh.triangles.size(), object.size(), spacing, object.sampling_radius(), margin,
                args.margin_spacings, preprocess_s, double(usage.ru_maxrss) / 1024.0,
                object.hierarchy().nodes().size());
    std::fflush(stdout);

    const auto poses = PCCD::testing::generate_benchmark_poses(
        {.distances = PCCD::testing::default_benchmark_distances(), .rotations_per_distance = args.rotations,
         .seed = args.seed});
    const PCCD::Intersection_options intersection_options{.seed = args.seed};
    const PCCD::Distance_options distance_options{
        .candidates = args.candidates, .certified_lower_bound = args.certified, .intersection = intersection_options};

    // One run of method m on a pose, its CPU time and outcome.
    const auto run = [&](int m, const PCCD::testing::Benchmark_pose& pose) {
        const double t0 = PCCD::testing::thread_cpu_us();
        Outcome o;
        switch (m) {
        case fcl: o = outcome_of(fcl_mesh.distance(pose.pose_a, pose.pose_b)); break;
        case distance: o = outcome_of(PCCD::distance(object, pose.pose_a, object, pose.pose_b, distance_options)); break;
        case within:
            o = outcome_of(PCCD::within_distance(object, pose.pose_a, object, pose.pose_b, margin, distance_options));
            break;
        default: o = outcome_of(PCCD::do_intersect(object, pose.pose_a, object, pose.pose_b, intersection_options));
        }
        const double us = PCCD::testing::thread_cpu_us() - t0;
        return std::pair{o, us};
    };

    std::array<std::vector<Sample>, method_count> samples;
    Cache_evictor evictor(args.evict_mib);
    std::uint64_t evictor_sum = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const auto& pose = poses[k];
        std::array<int, method_count> order{fcl, distance, within, intersect};
        if (k % 2 == 1) std::reverse(order.begin(), order.end());
        std::array<Sample, method_count> now{};
        for (const int m : order) { // cold: each once, after the caches were evicted
            if (args.evict_mib > 0) evictor_sum += evictor.sweep();
            const auto [o, us] = run(m, pose);
            now[std::size_t(m)] = {pose.distance, pose.rotation_index, false, us, 0.0, o};
        }
        for (const int m : order) { // warm: the median of runs in a row
            std::vector<double> times;
            for (int r = 0; r < args.repetitions; ++r) times.push_back(run(m, pose).second);
            now[std::size_t(m)].warm_us = PCCD::testing::median(times);
        }
        const bool fcl_separate = now[fcl].outcome.separate;
        for (int m = 0; m < method_count; ++m) {
            Sample& s = now[std::size_t(m)];
            s.fcl_separate = fcl_separate;
            samples[std::size_t(m)].push_back(s);
            if (csv) {
                const Outcome& o = s.outcome;
                *csv << name << ',' << method_names[std::size_t(m)] << ',' << pose.distance << ',' << pose.rotation_index
                     << ',' << int(fcl_separate) << ',' << int(o.hit) << ',' << int(o.separate) << ',' << o.value << ','
                     << s.cold_us << ',' << s.warm_us << ',' << o.node_pairs << ',' << o.leaf_pairs << ','
                     << o.point_pairs << ',' << o.f_evaluations << ',' << o.refinement_steps << ','
                     << o.intersection_node_pairs << ',' << o.intersection_f_evaluations << '\n';
            }
        }
    }

    // Per distance: cold mean per method.
    std::printf("%-6s", "d");
    for (int m = 0; m < method_count; ++m) std::printf(" %14s", (std::string(method_names[std::size_t(m)]) + " cold").c_str());
    for (int m = 0; m < method_count; ++m) std::printf(" %14s", (std::string(method_names[std::size_t(m)]) + " warm").c_str());
    std::printf("   (mean us)\n");
    for (const double d : PCCD::testing::default_benchmark_distances()) {
        std::printf("%-6.2f", d);
        for (const bool warm : {false, true})
            for (int m = 0; m < method_count; ++m) {
                std::vector<double> v;
                for (const Sample& s : samples[std::size_t(m)])
                    if (s.d == d) v.push_back(warm ? s.warm_us : s.cold_us);
                std::printf(" %14.1f", PCCD::testing::mean(v));
            }
        std::printf("\n");
    }

    // Per method: times over all poses and over the separate ones.
    std::printf("%-13s %9s %9s %9s %9s %9s %9s %9s %9s %8s %8s\n", "method", "cold_mean", "cold_med", "warm_mean",
                "warm_med", "sep_cold", "sep_c_med", "sep_warm", "sep_w_med", "p99cold", "p99warm");
    std::array<std::array<Summary, 4>, method_count> table{}; // [method][cold all, warm all, cold sep, warm sep]
    for (int m = 0; m < method_count; ++m) {
        const auto& s = samples[std::size_t(m)];
        table[std::size_t(m)] = {summarize(s, false, false), summarize(s, true, false), summarize(s, false, true),
                                 summarize(s, true, true)};
        std::vector<double> cold, warm;
        for (const Sample& x : s) {
            cold.push_back(x.cold_us);
            warm.push_back(x.warm_us);
        }
        const auto& t = table[std::size_t(m)];
        std::printf("%-13s %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %8.1f %8.1f\n", method_names[std::size_t(m)],
                    t[0].mean, t[0].median, t[1].mean, t[1].median, t[2].mean, t[2].median, t[3].mean, t[3].median,
                    p99(cold), p99(warm));
    }
    const auto ratio_line = [&](const char* label, int num, int den) {
        const auto& a = table[std::size_t(num)];
        const auto& b = table[std::size_t(den)];
        std::printf("%-24s mean cold %.3f warm %.3f | median cold %.3f warm %.3f | separate: mean cold %.3f warm "
                    "%.3f, median cold %.3f warm %.3f\n",
                    label, a[0].mean / b[0].mean, a[1].mean / b[1].mean, a[0].median / b[0].median,
                    a[1].median / b[1].median, a[2].mean / b[2].mean, a[3].mean / b[3].mean, a[2].median / b[2].median,
                    a[3].median / b[3].median);
    };
    ratio_line("distance / fcl", distance, fcl);
    ratio_line("within / do_intersect", within, intersect);

    // Work counters, all poses and separate poses.
    std::printf("%-13s %8s %9s %9s %10s %8s %10s %9s | separate: %8s %9s %9s %9s\n", "mean counts", "f_total", "f_own",
                "f_inter", "node_pairs", "leaves", "pt_pairs", "inter_np", "f_total", "f_inter", "node_pairs",
                "inter_np");
    for (int m = distance; m < method_count; ++m) {
        const auto& s = samples[std::size_t(m)];
        std::printf("%-13s %8.1f %9.1f %9.1f %10.1f %8.1f %10.1f %9.1f | separate: %8.1f %9.1f %9.1f %9.1f\n",
                    method_names[std::size_t(m)],
                    mean_of(s, &Outcome::f_evaluations) + mean_of(s, &Outcome::intersection_f_evaluations),
                    mean_of(s, &Outcome::f_evaluations), mean_of(s, &Outcome::intersection_f_evaluations),
                    mean_of(s, &Outcome::node_pairs), mean_of(s, &Outcome::leaf_pairs),
                    mean_of(s, &Outcome::point_pairs), mean_of(s, &Outcome::intersection_node_pairs),
                    mean_of(s, &Outcome::f_evaluations, true) + mean_of(s, &Outcome::intersection_f_evaluations, true),
                    mean_of(s, &Outcome::intersection_f_evaluations, true), mean_of(s, &Outcome::node_pairs, true),
                    mean_of(s, &Outcome::intersection_node_pairs, true));
    }

    // Accuracy of PCCD's distance against FCL's on the mesh, and the verdicts.
    std::vector<double> errors, signed_errors;
    std::size_t pccd_hit_fcl_sep = 0, pccd_sep_fcl_hit = 0, undecided = 0, within_differs = 0, within_vs_distance = 0;
    std::size_t fcl_sep = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const Outcome& f = samples[fcl][k].outcome;
        const Outcome& p = samples[distance][k].outcome;
        const Outcome& w = samples[within][k].outcome;
        fcl_sep += f.separate ? 1 : 0;
        if (!p.separate && !p.hit) ++undecided;
        if (p.hit && f.separate) ++pccd_hit_fcl_sep;
        if (p.separate && !f.separate) ++pccd_sep_fcl_hit;
        if (w.hit != (f.value <= margin)) ++within_differs;
        if (w.hit != (p.hit || (p.separate && p.value <= margin))) ++within_vs_distance;
        if (p.separate && f.separate && std::isfinite(p.value)) {
            errors.push_back(std::abs(p.value - f.value) / spacing);
            signed_errors.push_back((p.value - f.value) / spacing);
        }
    }
    std::sort(errors.begin(), errors.end());
    std::printf("accuracy: %zu poses both separate (FCL separate %zu of %zu): |PCCD - FCL| in mean spacings median "
                "%.3f, p90 %.3f, max %.3f; signed median %.3f; PCCD intersecting where FCL separate %zu, PCCD separate "
                "where FCL intersecting %zu, undecided %zu; within != (FCL distance <= margin) %zu, within != "
                "(distance <= margin) %zu\n",
                errors.size(), fcl_sep, poses.size(), errors.empty() ? std::nan("") : PCCD::testing::median(errors),
                errors.empty() ? std::nan("") : PCCD::testing::sorted_quantile(errors, 90),
                errors.empty() ? std::nan("") : errors.back(), PCCD::testing::median(signed_errors), pccd_hit_fcl_sep,
                pccd_sep_fcl_hit, undecided, within_differs, within_vs_distance);
    if (evictor_sum == 1) std::printf("(evictor)\n"); // keeps the sweeps observable
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const Arguments args = parse(argc, argv);
        if (std::string(PCCD_DATA_DIR).empty()) throw std::runtime_error("no libcgal-demo data directory configured");
        std::printf("distance_benchmark: %zu points per cloud, %zu rotation pairs x 13 distances (0:3:0.25), seed %llu, "
                    "margin %.2f mean spacings, %zu candidates%s; cold = one run per pose (methods interleaved, each after a %zu MiB cache "
                    "sweep), warm = median of %d runs in a row; thread CPU time in us, one thread\n",
                    args.points, args.rotations, (unsigned long long)args.seed, args.margin_spacings, args.candidates,
                    args.certified ? ", certified lower bound" : "", args.evict_mib,
                    args.repetitions);
        std::ofstream csv;
        if (!args.csv.empty()) {
            csv = PCCD::testing::open_csv(args.csv);
            csv << "model,method,distance,rotation,fcl_separate,hit,separate,value,cold_us,warm_us,node_pairs,"
                   "leaf_pairs,point_pairs,f_evaluations,refinement_steps,intersection_node_pairs,"
                   "intersection_f_evaluations\n";
        }
        for (const auto& model : args.models) run_model(model, args, args.csv.empty() ? nullptr : &csv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "distance_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
