// benchmark/tunnel_clearance_benchmark.cpp -- the rail clearance (gauge) check on a scanned tunnel: a wagon
// scan moved along a path through a tunnel scan (PCCD/testing/scenes/Tunnel_scene.h), its clearance
// measured per pose by PCCD::distance with a cap, by the practitioners' kd-tree method (a nanoflann
// kd-tree over the tunnel points, the nearest tunnel point of every posed wagon point), and exactly
// on the meshes the clouds were sampled from (PCCD::exact_distance). Results and the commands are
// in doc/benchmarks.md, "Clearance through a scanned tunnel".
//
//   tunnel_clearance_benchmark [--scene-points 1000000] [--wagon-points 100000] [--poses 60] [--margin 0.05]
//                       [--cap 0.2] [--seed 1] [--threads T] [--repetitions 5] [--write-scene DIR]
//                       [--csv FILE] [--kernel geodesic|euclidean]  (the tunnel's object; the wagon is geodesic)
//                       [--kd all|capped]  (capped: the unbounded kd method is not run, its figures nan)
//                       [--surface default|sharp|sharp-wagon]  (sharp: both objects with the sharp-feature
//                       options of doc/manual/surface.md: Surface_fit::imls, theta_eps 3e-5,
//                       normal_residual_scale 0.25; sharp-wagon: the wagon only)
//                       [--leaf-size L]  (both objects' Point_cloud_hierarchy_options::leaf_size)
//                       [--wagon-fit plane|sphere|imls] [--wagon-theta-eps E] [--wagon-residual-scale S]
//                       (the wagon's Surface_fit, bandwidth.theta_eps and normal_residual_scale, set
//                       after --surface; S = 0 means no robust refit)
//
// Per pose (wagon pose from the scene's path, tunnel at the identity), three answers:
//   exact   exact_distance(wagon mesh, pose, tunnel mesh, identity): the clearance (0 if touching);
//   kd      min over the posed wagon points of the distance to the nearest tunnel point (nanoflann
//           1.4 KDTreeSingleIndexAdaptor, leaves of 10 points, one knnSearch(k = 1) per wagon point);
//           the tree over the tunnel points is built once (its time reported apart);
//   kd_cap  the same minimum, each search bounded by the smaller of --cap and the smallest distance
//           found so far on the pose (subtrees beyond it are skipped); +inf when nothing is within
//           the cap: what a careful practitioner does with the same tree;
//   pccd    PCCD::distance(wagon object, pose, tunnel object, identity, {.max_distance = cap,
//           .intersection = {.seed = seed}}): the distance of the implicit surfaces, 0 when they
//           intersect, +inf ("beyond the cap") when no point pair is within the cap; the two objects
//           are preprocessed once with default options (--threads threads; wall time and the peak
//           resident memory of the preprocessing reported apart).
// Times are this thread's CPU time in us, one query on one thread. Cold: the poses in sequence, each
// method once per pose (in the order above on even poses, reversed on odd ones). Warm: then the median of
// --repetitions runs in a row per pose and method. With --threads: also the whole path at once,
// wall time, PCCD::distance_many (Batch_options::threads) against the kd method with the poses
// split over as many std::threads. Reported: per method mean and median time per pose, cold and
// warm, and the ratios pccd / kd and pccd / kd_cap; for the poses whose exact clearance is below the cap, the error of
// each method against the exact clearance in units of the tunnel cloud's mean spacing (median, p99,
// fraction within 0.5 spacings, signed median); and per pose whether each method puts the wagon
// below the margin, against the exact verdict.
#include <PCCD/testing/csv.h>
#include <PCCD/testing/process_memory.h>
#include <PCCD/testing/scenes/Tunnel_scene.h>
#include <PCCD/sharp_feature_options.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_distance.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Proximity/distance_many.h>

#include <nanoflann.hpp>

#include <malloc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>
#include <vector>

namespace {

struct Arguments {
    std::size_t scene_points = 1'000'000;
    std::size_t wagon_points = 100'000;
    std::size_t poses = 60;
    double margin = 0.05;
    double cap = 0.2;
    std::uint64_t seed = 1;
    std::optional<unsigned> threads;
    int repetitions = 5;
    std::string write_scene;
    std::string csv;
    /// The tunnel's object: geodesic (Point_cloud_object) or euclidean (the lean
    /// Euclidean_point_cloud_object); the wagon is a Point_cloud_object either way.
    std::string kernel = "geodesic";
    /// --kd all (default) or capped: with capped the unbounded kd method is not run (its figures are
    /// nan); the bounded one gives the same clearances below the cap in a thousandth of the time.
    bool skip_kd = false;
    /// Which objects get the sharp-feature surface: --surface sharp both, sharp-wagon the wagon only,
    /// default neither.
    bool sharp_wagon = false;
    bool sharp_tunnel = false;
    /// --leaf-size: Point_cloud_hierarchy_options::leaf_size of both objects (default: the library's).
    std::size_t leaf_size = PCCD::Point_cloud_hierarchy_options{}.leaf_size;
    /// --wagon-fit, --wagon-theta-eps, --wagon-residual-scale: single fields of the wagon's surface
    /// options, applied after --surface (residual scale 0: no robust refit).
    std::optional<PCCD::Surface_fit> wagon_fit;
    std::optional<double> wagon_theta_eps;
    std::optional<double> wagon_residual_scale;
};

Arguments parse(int argc, char** argv)
{
    Arguments a;
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--scene-points") a.scene_points = std::stoul(value);
        else if (key == "--wagon-points") a.wagon_points = std::stoul(value);
        else if (key == "--poses") a.poses = std::stoul(value);
        else if (key == "--margin") a.margin = std::stod(value);
        else if (key == "--cap") a.cap = std::stod(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--threads") a.threads = unsigned(std::stoul(value));
        else if (key == "--repetitions") a.repetitions = std::stoi(value);
        else if (key == "--write-scene") a.write_scene = value;
        else if (key == "--csv") a.csv = value;
        else if (key == "--kernel" && (value == "geodesic" || value == "euclidean")) a.kernel = value;
        else if (key == "--kd" && (value == "all" || value == "capped")) a.skip_kd = value == "capped";
        else if (key == "--surface" && (value == "default" || value == "sharp" || value == "sharp-wagon")) {
            a.sharp_wagon = value != "default";
            a.sharp_tunnel = value == "sharp";
        }
        else if (key == "--leaf-size") a.leaf_size = std::stoul(value);
        else if (key == "--wagon-fit" && PCCD::surface_fit_from_string(value)) a.wagon_fit = PCCD::surface_fit_from_string(value);
        else if (key == "--wagon-theta-eps") a.wagon_theta_eps = std::stod(value);
        else if (key == "--wagon-residual-scale") a.wagon_residual_scale = std::stod(value);
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.repetitions < 1 || a.leaf_size == 0) throw std::invalid_argument("--repetitions and --leaf-size must be >= 1");
    if (!(std::isfinite(a.margin) && a.margin > 0.0 && std::isfinite(a.cap) && a.cap >= a.margin))
        throw std::invalid_argument("--margin must be finite and > 0, --cap finite and >= --margin");
    if (a.threads && *a.threads == 0) throw std::invalid_argument("--threads must be >= 1");
    return a;
}

/// nanoflann's view of the tunnel cloud (columns of a 3 x N matrix).
struct Cloud_adaptor {
    const Eigen::Matrix3Xd* points;
    std::size_t kdtree_get_point_count() const { return std::size_t(points->cols()); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)(Eigen::Index(dim), Eigen::Index(i)); }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};
using Nanoflann_tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud_adaptor>, Cloud_adaptor, 3, std::size_t>;

/// The kd-tree method: the smallest distance from a posed wagon point to its nearest tunnel point.
double kd_clearance(const Nanoflann_tree& tree, const Eigen::Matrix3Xd& wagon, const PCCD::Rigid_transform_3<double>& pose)
{
    const Eigen::Matrix3d& r = pose.rotation();
    const Eigen::Vector3d& t = pose.translation();
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < wagon.cols(); ++i) {
        const Eigen::Vector3d q = r * wagon.col(i) + t;
        std::size_t index = 0;
        double squared = 0.0;
        tree.knnSearch(q.data(), 1, &index, &squared);
        best = std::min(best, squared);
    }
    return std::sqrt(best);
}

/// A nanoflann result set for the nearest point closer than a bound: nanoflann skips every
/// subtree farther than worstDist(), which starts at the bound and shrinks with each point found.
struct Bounded_nearest {
    double best_squared;
    std::size_t index = std::numeric_limits<std::size_t>::max();
    bool full() const { return true; }
    bool addPoint(double squared, std::size_t i)
    {
        if (squared < best_squared) {
            best_squared = squared;
            index = i;
        }
        return true;
    }
    double worstDist() const { return best_squared; }
};

/// The kd-tree method with a cap: the same minimum when it is below `cap` (+inf otherwise), each
/// search bounded by the smaller of the cap and the smallest distance found so far on the pose.
double kd_capped_clearance(const Nanoflann_tree& tree, const Eigen::Matrix3Xd& wagon,
                           const PCCD::Rigid_transform_3<double>& pose, double cap)
{
    const Eigen::Matrix3d& r = pose.rotation();
    const Eigen::Vector3d& t = pose.translation();
    double bound = cap * cap;
    for (Eigen::Index i = 0; i < wagon.cols(); ++i) {
        const Eigen::Vector3d q = r * wagon.col(i) + t;
        Bounded_nearest result{bound};
        tree.findNeighbors(result, q.data(), nanoflann::SearchParams());
        bound = result.best_squared;
    }
    return bound < cap * cap ? std::sqrt(bound) : std::numeric_limits<double>::infinity();
}

/// The clearance PCCD reports: 0 when intersecting, the distance when separate (+inf beyond the
/// cap), NaN when undecided.
double pccd_clearance(const PCCD::Distance_result& r)
{
    if (r.intersecting()) return 0.0;
    if (r.status == PCCD::Intersection_status::separate) return r.distance;
    return std::nan("");
}

/// Resident memory of this process (VmRSS) and its peak (VmHWM) in MiB.
std::array<double, 2> memory_mib()
{
    return {double(PCCD::testing::status_bytes("VmRSS")) / 1048576.0, double(PCCD::testing::status_bytes("VmHWM")) / 1048576.0};
}

/// Returns the free heap pages to the system, then resets the peak (VmHWM) to the current resident
/// memory, so that the next peak is that of what follows.
void reset_peak_memory() { PCCD::testing::reset_peak(true); }

enum Method { kd, kd_cap, pccd, method_count };
const std::array<const char*, method_count> method_names{"kd", "kd_cap", "pccd"};

struct Pose_result {
    double exact = 0.0;
    std::array<double, method_count> value{};
    std::array<double, method_count> cold_us{}, warm_us{};
};

double quantile(std::vector<double> v, std::size_t percent)
{
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    return PCCD::testing::sorted_quantile(v, percent);
}

void run(const Arguments& args)
{
    using PCCD::testing::Clock;
    PCCD::testing::Tunnel_scene_options scene_options;
    scene_options.scene_points = args.scene_points;
    scene_options.wagon_points = args.wagon_points;
    scene_options.poses = args.poses;
    scene_options.seed = args.seed;
    auto start = Clock::now();
    const PCCD::testing::Tunnel_scene scene = PCCD::testing::make_tunnel_scene(scene_options);
    std::printf("scene: tunnel %.1f m along an arc of radius %.0f m, vault radius %.1f m; mesh %zu triangles (%.0f m^2), "
                "cloud %zu points (%zu outliers, %zu holes), sigma %.4f m; wagon %.0f m, mesh %zu triangles (%.0f m^2), "
                "cloud %zu points, sigma %.4f m; %zu poses (%zu pushed toward the wall); generated in %.1f s\n",
                scene_options.tunnel_length, scene_options.curve_radius, scene_options.tunnel_radius,
                scene.tunnel_mesh.triangles.size(), scene.tunnel_area, std::size_t(scene.tunnel_points.cols()),
                scene_options.outliers, scene.holes.size(), scene.tunnel_sigma, scene_options.wagon_length,
                scene.wagon_mesh.triangles.size(), scene.wagon_area, std::size_t(scene.wagon_points.cols()),
                scene.wagon_sigma, scene.path.size(),
                std::size_t(std::count_if(scene.path.begin(), scene.path.end(), [](const auto& p) { return p.deliberate; })),
                PCCD::testing::seconds_since(start));
    if (!args.write_scene.empty()) {
        PCCD::testing::write_tunnel_scene(scene, args.write_scene);
        std::printf("wrote tunnel.ply, wagon.ply, tunnel.off, wagon.off, poses.csv, cases.csv into %s\n", args.write_scene.c_str());
    }
    std::fflush(stdout);

    // Exact truth.
    start = Clock::now();
    const PCCD::Exact_mesh tunnel_mesh(scene.tunnel_mesh), wagon_mesh(scene.wagon_mesh);
    const double exact_setup_s = PCCD::testing::seconds_since(start);
    const PCCD::Rigid_transform_3<double> identity;
    std::vector<Pose_result> results(scene.path.size());
    start = Clock::now();
    for (std::size_t k = 0; k < scene.path.size(); ++k) {
        const PCCD::Exact_distance d = PCCD::exact_distance(wagon_mesh, scene.path[k].pose, tunnel_mesh, identity);
        results[k].exact = d.surfaces_intersect ? 0.0 : d.distance;
    }
    std::printf("exact: meshes prepared in %.2f s, %zu exact distances in %.2f s\n", exact_setup_s, scene.path.size(),
                PCCD::testing::seconds_since(start));

    // Preprocessing: the kd-tree, then the two PCCD objects.
    reset_peak_memory();
    const auto before_tree = memory_mib();
    start = Clock::now();
    const Cloud_adaptor adaptor{&scene.tunnel_points};
    const Nanoflann_tree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    const double tree_s = PCCD::testing::seconds_since(start);
    const auto after_tree = memory_mib();
    std::printf("kd: nanoflann tree over %zu points built in %.3f s (wall), peak memory +%.0f MiB\n",
                std::size_t(scene.tunnel_points.cols()), tree_s, after_tree[1] - before_tree[0]);
    std::fflush(stdout);

    // The rest for the tunnel object of --kernel.
    const auto with_tunnel = [&](auto tag) {
    using Tunnel = typename decltype(tag)::type;
    const PCCD::Point_cloud_object_options defaults{.hierarchy = {.leaf_size = args.leaf_size}, .threads = args.threads};
    PCCD::Point_cloud_object_options wagon_options =
        args.sharp_wagon ? PCCD::sharp_feature_options(defaults) : defaults;
    if (args.wagon_fit) wagon_options.surface_fit = *args.wagon_fit;
    if (args.wagon_theta_eps) wagon_options.bandwidth.theta_eps = *args.wagon_theta_eps;
    if (args.wagon_residual_scale)
        wagon_options.normal_residual_scale =
            *args.wagon_residual_scale > 0.0 ? std::optional<double>(*args.wagon_residual_scale) : std::nullopt;
    const PCCD::Point_cloud_object_options tunnel_options =
        args.sharp_tunnel ? PCCD::sharp_feature_options(defaults) : defaults;
    reset_peak_memory();
    const auto before_objects = memory_mib();
    start = Clock::now();
    const PCCD::Point_cloud_object<> wagon(scene.wagon_points, wagon_options);
    const double wagon_s = PCCD::testing::seconds_since(start);
    start = Clock::now();
    const Tunnel tunnel(scene.tunnel_points, tunnel_options);
    const double tunnel_s = PCCD::testing::seconds_since(start);
    const auto after_objects = memory_mib();
    const double spacing = tunnel.cloud().mean_spacing();
    std::printf("pccd: preprocessing wagon %.2f s, tunnel %.2f s (wall, %s threads); peak memory +%.0f MiB over the "
                "%.0f MiB before (%.0f B per point of both clouds), resident after +%.0f MiB; tunnel mean spacing %.4f m "
                "(wagon %.4f m), r(P) %.4f m\n",
                wagon_s, tunnel_s, args.threads ? std::to_string(*args.threads).c_str() : "all", after_objects[1] - before_objects[0],
                before_objects[0],
                (after_objects[1] - before_objects[0]) * 1048576.0 / double(wagon.size() + tunnel.size()),
                after_objects[0] - before_objects[0], spacing, wagon.cloud().mean_spacing(), tunnel.sampling_radius());
    std::fflush(stdout);

    const PCCD::Distance_options options{.max_distance = args.cap, .intersection = {.seed = args.seed}};
    const auto run_method = [&](int m, std::size_t k) {
        if (m == kd && args.skip_kd) return std::pair{std::nan(""), std::nan("")};
        const double t0 = PCCD::testing::thread_cpu_us();
        const double v = m == kd       ? kd_clearance(tree, scene.wagon_points, scene.path[k].pose)
                         : m == kd_cap ? kd_capped_clearance(tree, scene.wagon_points, scene.path[k].pose, args.cap)
                                       : pccd_clearance(PCCD::distance(wagon, scene.path[k].pose, tunnel, identity, options));
        return std::pair{v, PCCD::testing::thread_cpu_us() - t0};
    };
    for (std::size_t k = 0; k < scene.path.size(); ++k) { // cold
        std::array<int, method_count> order{kd, kd_cap, pccd};
        if (k % 2 == 1) std::reverse(order.begin(), order.end());
        for (const int m : order) std::tie(results[k].value[std::size_t(m)], results[k].cold_us[std::size_t(m)]) = run_method(m, k);
    }
    for (std::size_t k = 0; k < scene.path.size(); ++k) // warm
        for (int m = 0; m < method_count; ++m) {
            std::vector<double> times;
            for (int r = 0; r < args.repetitions; ++r) times.push_back(run_method(m, k).second);
            results[k].warm_us[std::size_t(m)] = PCCD::testing::median(times);
        }

    // The whole path at once on --threads threads (wall time).
    if (args.threads) {
        std::vector<PCCD::Posed_pair<PCCD::Point_cloud_object<>, Tunnel>> pairs;
        for (const auto& p : scene.path) pairs.push_back({&wagon, p.pose, &tunnel, identity});
        start = Clock::now();
        const auto batch = PCCD::distance_many(pairs, {.threads = args.threads}, options);
        const double pccd_batch_s = PCCD::testing::seconds_since(start);
        start = Clock::now();
        const auto kd_batch = [&](bool capped) {
            const auto begin = Clock::now();
            std::vector<double> values(scene.path.size());
            std::vector<std::thread> workers;
            for (unsigned w = 0; w < *args.threads; ++w)
                workers.emplace_back([&, w] {
                    for (std::size_t k = w; k < scene.path.size(); k += *args.threads)
                        values[k] = capped ? kd_capped_clearance(tree, scene.wagon_points, scene.path[k].pose, args.cap)
                                           : kd_clearance(tree, scene.wagon_points, scene.path[k].pose);
                });
            for (auto& w : workers) w.join();
            return PCCD::testing::seconds_since(begin);
        };
        const double kd_batch_s = args.skip_kd ? std::nan("") : kd_batch(false), kd_cap_batch_s = kd_batch(true);
        std::size_t differ = 0;
        for (std::size_t k = 0; k < batch.size(); ++k)
            if (!(pccd_clearance(batch[k]) == results[k].value[pccd]) &&
                !(std::isnan(pccd_clearance(batch[k])) && std::isnan(results[k].value[pccd])))
                ++differ;
        std::printf("whole path on %u threads (wall): pccd distance_many %.3f s, kd %.3f s, kd_cap %.3f s; pccd / kd %.4f, "
                    "pccd / kd_cap %.4f; distance_many differs from the single queries on %zu poses (pair seeds)\n",
                    *args.threads, pccd_batch_s, kd_batch_s, kd_cap_batch_s, pccd_batch_s / kd_batch_s,
                    pccd_batch_s / kd_cap_batch_s, differ);
    }

    // Times.
    std::printf("%-6s %10s %10s %10s %10s %10s %10s   (thread CPU us per pose)\n", "method", "cold_mean", "cold_med",
                "warm_mean", "warm_med", "p99_cold", "p99_warm");
    std::array<std::array<double, 4>, method_count> summary{};
    for (int m = 0; m < method_count; ++m) {
        std::vector<double> cold, warm;
        for (const auto& r : results) {
            cold.push_back(r.cold_us[std::size_t(m)]);
            warm.push_back(r.warm_us[std::size_t(m)]);
        }
        summary[std::size_t(m)] = {PCCD::testing::mean(cold), PCCD::testing::median(cold), PCCD::testing::mean(warm),
                                   PCCD::testing::median(warm)};
        const auto& s = summary[std::size_t(m)];
        std::printf("%-6s %10.1f %10.1f %10.1f %10.1f %10.1f %10.1f\n", method_names[std::size_t(m)], s[0], s[1], s[2], s[3],
                    quantile(cold, 99), quantile(warm, 99));
    }
    for (const int base : {kd, kd_cap})
        std::printf("pccd / %s: mean cold %.4f warm %.4f | median cold %.4f warm %.4f\n", method_names[std::size_t(base)],
                    summary[pccd][0] / summary[std::size_t(base)][0], summary[pccd][2] / summary[std::size_t(base)][2],
                    summary[pccd][1] / summary[std::size_t(base)][1], summary[pccd][3] / summary[std::size_t(base)][3]);

    // Accuracy against the exact clearance, poses below the cap.
    std::size_t below_cap = 0;
    for (const auto& r : results) below_cap += r.exact < args.cap ? 1 : 0;
    std::printf("accuracy on the %zu of %zu poses with exact clearance below the cap %.3f m (in tunnel mean spacings %.4f m):\n",
                below_cap, results.size(), args.cap, spacing);
    std::printf("%-6s %8s %8s %8s %10s %10s %12s %10s\n", "method", "median", "p99", "max", "within0.5", "signed_med",
                "beyond_cap", "undecided");
    for (int m = 0; m < method_count; ++m) {
        if (m == kd && args.skip_kd) continue; // not run (--kd capped)
        std::vector<double> error, signed_error;
        std::size_t beyond = 0, undecided = 0, within = 0;
        for (const auto& r : results) {
            if (!(r.exact < args.cap)) continue;
            const double v = r.value[std::size_t(m)];
            if (std::isnan(v)) { ++undecided; continue; }
            if (std::isinf(v)) { ++beyond; continue; }
            error.push_back(std::abs(v - r.exact) / spacing);
            signed_error.push_back((v - r.exact) / spacing);
            within += error.back() <= 0.5 ? 1 : 0;
        }
        std::printf("%-6s %8.3f %8.3f %8.3f %10.3f %10.3f %12zu %10zu\n", method_names[std::size_t(m)],
                    PCCD::testing::median(error), quantile(error, 99), quantile(error, 100),
                    error.empty() ? std::nan("") : double(within) / double(error.size()), PCCD::testing::median(signed_error),
                    beyond, undecided);
    }

    // Below the margin: per pose, against the exact verdict.
    std::size_t exact_below = 0;
    for (const auto& r : results) exact_below += r.exact < args.margin ? 1 : 0;
    std::printf("below the margin %.3f m: exact %zu of %zu poses\n", args.margin, exact_below, results.size());
    for (int m = 0; m < method_count; ++m) {
        if (m == kd && args.skip_kd) continue; // not run (--kd capped)
        std::size_t agree = 0, false_alarm = 0, missed = 0;
        for (const auto& r : results) {
            const double v = r.value[std::size_t(m)];
            const bool below = !std::isnan(v) && v < args.margin;
            const bool truth = r.exact < args.margin;
            agree += below == truth ? 1 : 0;
            false_alarm += below && !truth ? 1 : 0;
            missed += !below && truth ? 1 : 0;
        }
        std::printf("%-6s agrees on %zu of %zu poses: %zu false alarms, %zu missed\n", method_names[std::size_t(m)], agree,
                    results.size(), false_alarm, missed);
    }
    std::printf("%-5s %8s %8s %6s %9s %9s %9s %9s %10s %10s\n", "pose", "s", "lateral", "target", "exact", "kd", "pccd",
                "kd_warm", "kdcap_warm", "pccd_warm");
    for (std::size_t k = 0; k < results.size(); ++k) {
        const auto& r = results[k];
        const auto& p = scene.path[k];
        std::printf("%-5zu %8.2f %8.4f %6.3f %9.4f %9.4f %9.4f %9.0f %10.0f %10.0f\n", k, p.s, p.lateral, p.target_clearance,
                    r.exact, r.value[kd], r.value[pccd], r.warm_us[kd], r.warm_us[kd_cap], r.warm_us[pccd]);
    }

    if (!args.csv.empty()) {
        std::ofstream csv = PCCD::testing::open_csv(args.csv, 10);
        csv << "scene_points,wagon_points,pose,s,lateral,deliberate,target_clearance,exact,method,value,cold_us,warm_us,"
               "spacing,margin,cap\n";
        for (std::size_t k = 0; k < results.size(); ++k)
            for (int m = 0; m < method_count; ++m) {
                const auto& r = results[k];
                const auto& p = scene.path[k];
                csv << args.scene_points << ',' << args.wagon_points << ',' << k << ',' << p.s << ',' << p.lateral << ','
                    << int(p.deliberate) << ',' << p.target_clearance << ',' << r.exact << ',' << method_names[std::size_t(m)]
                    << ',' << r.value[std::size_t(m)] << ',' << r.cold_us[std::size_t(m)] << ',' << r.warm_us[std::size_t(m)]
                    << ',' << spacing << ',' << args.margin << ',' << args.cap << '\n';
            }
    }
    std::fflush(stdout);
    };
    if (args.kernel == "euclidean")
        with_tunnel(std::type_identity<PCCD::Euclidean_point_cloud_object<>>{});
    else
        with_tunnel(std::type_identity<PCCD::Point_cloud_object<>>{});
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const Arguments args = parse(argc, argv);
        std::printf("tunnel_clearance_benchmark: %zu scene points, %zu wagon points, %zu poses, margin %.3f m, cap %.3f m, seed %llu, "
                    "%d repetitions (warm), tunnel kernel %s\n",
                    args.scene_points, args.wagon_points, args.poses, args.margin, args.cap,
                    (unsigned long long)args.seed, args.repetitions, args.kernel.c_str());
        run(args);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tunnel_clearance_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
