// benchmark/hierarchy_benchmark.cpp -- first-hit query time of PCCD's hierarchy traversals against
// FCL on the source mesh, per model, over the benchmark poses (doc/manual/sampling.md), and the
// scale figure (the same poses on a resampled cloud of another size). Results and the commands are
// in doc/benchmarks.md "Point cloud hierarchy".
//
//   hierarchy_benchmark [--models bunny00.off,elephant.off,eight.off] [--points 30000]
//                       [--rotations 50] [--repetitions 3] [--seed 1]
//                       [--traversals flat,depth_first,likelihood] [--volumes box_and_slab,box,sphere]
//                       [--kernels geodesic,euclidean] [--probes DRAWS,STEPS] [--leaf-size 8] [--csv OUT]
//                       [--budgets 5,10,20,50,100 --budget-csv OUT]
//
// Peak memory (getrusage) is printed after each model's preprocessing. Per model: the mesh is normalized into [-1, 1]^3, FCL's OBBRSS hierarchy is built on it, and a
// cloud of --points points is sampled by area and preprocessed with default options. Per pose:
// FCL's collide() and do_intersect() per traversal (the walked ones once per bounding volume of
// --volumes, each volume's object preprocessed alike), each the median of --repetitions runs, on this
// thread's CPU clock (the machine is shared; wall time is noisier). Printed per model: mean and
// median per distance, mean over d in [0, 3] and over the near misses d in [1, 2.25], their ratio to
// FCL's, p99, and how often each traversal's verdict differs from the flat traversal's and from FCL's.
// --kernels euclidean adds (or, alone, runs only) the lean object's likelihood walk ("euclidean"),
// with its own preprocessing time and peak. --probes sets the interpolation search's probes (probe_draws,
// probe_steps; 0,0: none) of every PCCD method; --leaf-size the hierarchies' leaf_size (default 8).
#include "collision_baselines.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/sample_triangle_mesh.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <sys/resource.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Arguments {
    std::vector<std::string> models{"bunny00.off", "elephant.off", "eight.off"};
    std::size_t points = 30000;
    std::size_t rotations = 50;
    int repetitions = 3;
    std::uint64_t seed = 1;
    std::vector<std::string> traversals{"flat", "depth_first", "likelihood"};
    std::vector<std::string> volumes{"box_and_slab"};
    /// geodesic: Point_cloud_object (the traversals above); euclidean: Euclidean_point_cloud_object
    /// (the likelihood walk, method "euclidean").
    std::vector<std::string> kernels{"geodesic"};
    std::string csv;
    std::vector<double> budgets; // time budgets in us for the budget sweep (empty: none)
    std::string budget_csv;
    /// The interpolation search's probes (Interpolation_search::probe_draws, probe_steps); unset: the defaults.
    std::optional<std::size_t> probe_draws;
    std::optional<std::size_t> probe_steps;
    /// Point_cloud_hierarchy_options::leaf_size of every PCCD object.
    std::size_t leaf_size = PCCD::Point_cloud_hierarchy_options{}.leaf_size;
};

/// The leaf intersector of every PCCD method: the default one, with the probes of --probes.
PCCD::Interpolation_search policy_of(const Arguments& args)
{
    PCCD::Interpolation_search policy;
    if (args.probe_draws) policy.probe_draws = *args.probe_draws;
    if (args.probe_steps) policy.probe_steps = *args.probe_steps;
    return policy;
}

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
        else if (key == "--traversals") a.traversals = value == "none" ? std::vector<std::string>{} : split(value);
        else if (key == "--volumes") a.volumes = split(value);
        else if (key == "--kernels") a.kernels = split(value);
        else if (key == "--probes") {
            const std::vector<std::string> v = split(value);
            if (v.size() != 2) throw std::invalid_argument("--probes takes DRAWS,STEPS");
            a.probe_draws = std::stoul(v[0]);
            a.probe_steps = std::stoul(v[1]);
        }
        else if (key == "--leaf-size") a.leaf_size = std::stoul(value);
        else if (key == "--csv") a.csv = value;
        else if (key == "--budgets") {
            for (const auto& item : split(value)) a.budgets.push_back(std::stod(item));
        } else if (key == "--budget-csv") a.budget_csv = value;
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.repetitions < 1 || a.rotations == 0 || a.points < 100 || a.leaf_size == 0)
        throw std::invalid_argument("--repetitions, --rotations and --leaf-size must be >= 1, --points >= 100");
    return a;
}

PCCD::Traversal traversal_of(const std::string& name)
{
    if (name == "flat") return PCCD::Traversal::flat;
    if (name == "depth_first") return PCCD::Traversal::depth_first;
    if (name == "likelihood") return PCCD::Traversal::likelihood;
    throw std::invalid_argument("unknown traversal " + name + " (flat, depth_first, likelihood)");
}

PCCD::Bounding_volume volume_of(const std::string& name)
{
    if (const auto v = PCCD::bounding_volume_from_string(name)) return *v;
    throw std::invalid_argument("unknown bounding volume " + name + " (box_and_slab, box, sphere)");
}

/// The options of every PCCD object of the run: the bounding volume `volume` and --leaf-size.
PCCD::Point_cloud_object_options object_options(const Arguments& args, const std::string& volume)
{
    return {.hierarchy = {.leaf_size = args.leaf_size, .volume = volume_of(volume)}};
}

double thread_cpu_us()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e6 + double(t.tv_nsec) * 1e-3;
}

/// Median CPU time (us) of `repetitions` runs of `run`, and its last result.
template <class Run>
auto timed(int repetitions, const Run& run)
{
    std::vector<double> times;
    decltype(run()) result{};
    for (int k = 0; k < repetitions; ++k) {
        const double start = thread_cpu_us();
        result = run();
        times.push_back(thread_cpu_us() - start);
    }
    return std::pair{result, PCCD::testing::median(times)};
}

struct Series {
    std::map<double, std::vector<double>> by_distance;
    std::vector<double> all, near;
    std::size_t differs_flat = 0, differs_fcl = 0;
    double f_evaluations = 0.0;
};

double p99(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return PCCD::testing::sorted_quantile(v, 99);
}

/// The budget sweep: per budget and distance, counts of poses, undecided and wrong answers.
void run_budgets(const std::string& name, const PCCD::Point_cloud_object<>& object,
                 const PCCD::benchmark::Fcl_mesh_baseline& fcl, const std::vector<PCCD::testing::Benchmark_pose>& poses,
                 const Arguments& args, std::ofstream* csv)
{
    struct Tally {
        std::size_t poses = 0, undecided = 0, wrong = 0;
    };
    std::map<double, std::map<double, Tally>> tallies; // budget -> distance -> tally
    for (const auto& pose : poses) {
        const bool truth = fcl.collide(pose.pose_a, pose.pose_b);
        // One untimed run first: a query in a simulation loop finds its data in the caches.
        PCCD::do_intersect(object, pose.pose_a, object, pose.pose_b, {.seed = args.seed});
        for (const double budget : args.budgets) {
            PCCD::Intersection_options options{.seed = args.seed};
            options.max_time_us = budget;
            const auto result = PCCD::do_intersect(object, pose.pose_a, object, pose.pose_b, options);
            Tally& t = tallies[budget][pose.distance];
            ++t.poses;
            if (result.status == PCCD::Intersection_status::undecided)
                ++t.undecided;
            else if (result.intersects != truth)
                ++t.wrong;
        }
    }
    std::printf("budget sweep (%s): undecided / wrong against FCL, per budget\n%-10s %11s %9s\n", name.c_str(),
                "budget_us", "undecided", "wrong");
    for (const auto& [budget, by_distance] : tallies) {
        Tally all;
        for (const auto& [d, t] : by_distance) {
            all.poses += t.poses;
            all.undecided += t.undecided;
            all.wrong += t.wrong;
            if (csv)
                *csv << name << ',' << budget << ',' << d << ',' << t.poses << ',' << t.undecided << ',' << t.wrong << '\n';
        }
        std::printf("%-10.1f %10.2f%% %8.2f%%\n", budget, 100.0 * double(all.undecided) / double(all.poses),
                    100.0 * double(all.wrong) / double(all.poses));
        // Distance -1: all distances together (the rows the plot reads).
        if (csv) *csv << name << ',' << budget << ",-1," << all.poses << ',' << all.undecided << ',' << all.wrong << '\n';
    }
    for (const double budget : args.budgets) {
        std::printf("per distance at %.1f us:", budget);
        for (const auto& [d, t] : tallies[budget])
            std::printf(" d=%.2f %zu/%zu undecided %zu wrong;", d, t.undecided, t.poses, t.wrong);
        std::printf("\n");
    }
}

void run_model(const std::string& name, const Arguments& args, std::ofstream* csv, std::ofstream* budget_csv)
{
    const std::filesystem::path path = std::filesystem::path(PCCD_DATA_DIR) / name;
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);
    const PCCD::benchmark::Fcl_mesh_baseline fcl(mesh);
    PCCD::Random_engine engine(args.seed);
    const PCCD::Triangle_mesh_sample sample =
        PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, args.points, engine);
    std::vector<Eigen::Vector3d> points(std::size_t(sample.points.cols()));
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points[std::size_t(i)] = sample.points.col(i);
    const auto has_kernel = [&](const char* k) { return std::find(args.kernels.begin(), args.kernels.end(), k) != args.kernels.end(); };
    const auto report = [&](const char* kind, const auto& object, double preprocess_ms) {
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        std::printf("\n%s (%s object): %zu triangles, %zu points sampled by area, r(P) %.5f, preprocessing %.0f ms, peak "
                    "memory so far %.0f MiB (%.0f bytes per point), hierarchy %zu nodes, depth %zu\n",
                    name.c_str(), kind, mesh.triangles.size(), object.size(), object.sampling_radius(), preprocess_ms,
                    double(usage.ru_maxrss) / 1024.0, double(usage.ru_maxrss) * 1024.0 / double(object.size()),
                    object.hierarchy().nodes().size(), object.hierarchy().height());
    };
    // The lean object first, so that the peak it reports is its own.
    std::optional<PCCD::Euclidean_point_cloud_object<>> lean;
    if (has_kernel("euclidean")) {
        const auto start = PCCD::testing::Clock::now();
        lean.emplace(points, object_options(args, args.volumes.front()));
        report("lean, Euclidean", *lean, PCCD::testing::ms_since(start));
    }
    std::optional<PCCD::Point_cloud_object<>> geodesic;
    std::map<std::string, PCCD::Point_cloud_object<>> with_volume;
    if (has_kernel("geodesic")) {
        const auto start = PCCD::testing::Clock::now();
        geodesic.emplace(points, object_options(args, args.volumes.front()));
        report("geodesic", *geodesic, PCCD::testing::ms_since(start));
        // The same cloud with each further bounding volume (the first is `geodesic`).
        for (std::size_t k = 1; k < args.volumes.size(); ++k)
            with_volume.emplace(args.volumes[k], PCCD::Point_cloud_object<>(points, object_options(args, args.volumes[k])));
    }

    std::vector<double> distances;
    for (int k = 0; k <= 12; ++k) distances.push_back(0.25 * k);
    const auto poses = PCCD::testing::generate_benchmark_poses(
        {.distances = distances, .rotations_per_distance = args.rotations, .seed = args.seed});
    if (!args.budgets.empty() && geodesic) {
        run_budgets(name, *geodesic, fcl, poses, args, budget_csv);
        if (args.traversals.empty()) return;
    }
    // A method is a traversal, with "/volume" for the volumes after the first (flat walks no volume),
    // on the geodesic object; "euclidean" is the likelihood walk on the lean object.
    std::vector<std::string> methods{"fcl"};
    if (geodesic)
        for (const auto& t : args.traversals) {
            methods.push_back(t);
            if (t != "flat")
                for (std::size_t k = 1; k < args.volumes.size(); ++k) methods.push_back(t + "/" + args.volumes[k]);
        }
    if (lean) methods.push_back("euclidean");
    std::map<std::string, Series> series;
    const PCCD::Interpolation_search policy = policy_of(args);
    for (const auto& pose : poses) {
        const auto [fcl_hit, fcl_us] = timed(args.repetitions, [&] { return fcl.collide(pose.pose_a, pose.pose_b); });
        bool flat_hit = fcl_hit;
        const bool near = pose.distance >= 1.0 && pose.distance <= 2.25;
        const auto record = [&](const std::string& method, bool hit, double us, double f, std::size_t node_pairs,
                                std::size_t leaf_pairs) {
            Series& s = series[method];
            s.by_distance[pose.distance].push_back(us);
            s.all.push_back(us);
            if (near) s.near.push_back(us);
            s.differs_fcl += hit != fcl_hit ? 1 : 0;
            s.differs_flat += hit != flat_hit ? 1 : 0;
            s.f_evaluations += f;
            if (csv)
                *csv << name << ',' << method << ',' << pose.distance << ',' << pose.rotation_index << ',' << int(hit)
                     << ',' << us << ',' << f << ',' << node_pairs << ',' << leaf_pairs << '\n';
        };
        record("fcl", fcl_hit, fcl_us, 0.0, 0, 0);
        for (const auto& m : methods) {
            if (m == "fcl") continue;
            if (m == "euclidean") {
                const PCCD::Intersection_options options{.seed = args.seed, .traversal = PCCD::Traversal::likelihood};
                const auto [result, us] = timed(args.repetitions, [&] {
                    return PCCD::do_intersect(*lean, pose.pose_a, *lean, pose.pose_b, options, policy);
                });
                record(m, result.intersects, us, double(result.counters.f_evaluations), result.counters.node_pairs,
                       result.counters.leaf_pairs);
                continue;
            }
            const std::size_t slash = m.find('/');
            const PCCD::Point_cloud_object<>& o = slash == std::string::npos ? *geodesic : with_volume.at(m.substr(slash + 1));
            const PCCD::Intersection_options options{.seed = args.seed, .traversal = traversal_of(m.substr(0, slash))};
            const auto [result, us] = timed(args.repetitions, [&] {
                return PCCD::do_intersect(o, pose.pose_a, o, pose.pose_b, options, policy);
            });
            if (m == "flat") flat_hit = result.intersects;
            record(m, result.intersects, us, double(result.counters.f_evaluations), result.counters.node_pairs,
                   result.counters.leaf_pairs);
        }
    }
    std::printf("%-12s", "d");
    for (const auto& m : methods) std::printf(" %22s", (m + " mean/median").c_str());
    std::printf("\n");
    for (double d : distances) {
        std::printf("%-12.2f", d);
        for (const auto& m : methods) {
            const auto& v = series[m].by_distance[d];
            std::printf(" %13.1f / %6.1f", PCCD::testing::mean(v), PCCD::testing::median(v));
        }
        std::printf("\n");
    }
    const double fcl_all = PCCD::testing::mean(series["fcl"].all), fcl_near = PCCD::testing::mean(series["fcl"].near);
    std::printf("%-20s %10s %10s %8s %10s %8s %8s %9s %9s %8s\n", "method", "mean_us", "median_us", "/fcl", "near_us",
                "/fcl", "p99_us", "!=flat", "!=fcl", "mean_f");
    for (const auto& m : methods) {
        const Series& s = series[m];
        const double all = PCCD::testing::mean(s.all), near = PCCD::testing::mean(s.near);
        std::printf("%-20s %10.1f %10.1f %8.2f %10.1f %8.2f %8.1f %9zu %9zu %8.1f\n", m.c_str(), all,
                    PCCD::testing::median(s.all), all / fcl_all, near, near / fcl_near, p99(s.all), s.differs_flat,
                    s.differs_fcl, s.f_evaluations / double(s.all.size()));
    }
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const Arguments args = parse(argc, argv);
        if (std::string(PCCD_DATA_DIR).empty()) throw std::runtime_error("no libcgal-demo data directory configured");
        std::printf("hierarchy_benchmark: %zu points per cloud, %zu rotation pairs x 13 distances (0:3:0.25), seed "
                    "%llu, median of %d runs per query, thread CPU time in us, one thread\n",
                    args.points, args.rotations, (unsigned long long)args.seed, args.repetitions);
        std::ofstream csv;
        if (!args.csv.empty()) {
            csv = PCCD::testing::open_csv(args.csv);
            csv << "model,method,distance,rotation,intersects,cpu_us,f_evaluations,node_pairs,leaf_pairs\n";
        }
        std::ofstream budget_csv;
        if (!args.budget_csv.empty()) {
            budget_csv = PCCD::testing::open_csv(args.budget_csv);
            budget_csv << "model,budget_us,distance,poses,undecided,wrong\n";
        }
        for (const auto& model : args.models)
            run_model(model, args, args.csv.empty() ? nullptr : &csv, args.budget_csv.empty() ? nullptr : &budget_csv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hierarchy_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
