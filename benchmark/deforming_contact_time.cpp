// Continuous collision of a deforming cloud (doc/benchmarks.md "Continuous collision of a deforming
// cloud"): the bunny of the deforming contact scene (PCCD/testing/scenes/Bunny_contact_scene.h:
// 5,000 area samples of bunny00.off twisting, breathing and swaying into a rigid sphere of 2,000
// points, 4 s) follows Hermite flightplans through its positions and velocities at 30 Hz key
// frames. The 4 s are cut into windows of 0.5 s; per window the first contact time of
// time_of_contact() with Deforming_motion, against discrete checks (advance_to + do_intersect at
// 30 Hz and 300 Hz, stopping at the first hit) and against the exact first contact of the deformed
// mesh with the analytic sphere, sampled at 6,000 Hz (the scene's own map, of which the flightplans
// are the Hermite interpolation).
//
// Usage: deforming_contact_time [--points N]     (about 90 s, most of it the exact reference; needs
// the bunny of libcgal-demo)
#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Kinetic/Deforming_motion.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Kinetic/Polynomial_flightplan.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/scenes/Bunny_contact_scene.h>
#include <PCCD/testing/timing.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Clock = PCCD::testing::Clock;

/// The first of `steps` + 1 evenly spaced times in [t0, t1] at which the deforming cloud meets the
/// obstacle (advance_to + do_intersect), or NaN.
double first_discrete_hit(PCCD::Deforming_point_cloud_object<>& cloud, std::span<const PCCD::Polynomial_flightplan> plans,
                          const PCCD::Point_cloud_object<>& obstacle, double t0, double t1, int steps)
{
    for (int i = 0; i <= steps; ++i) {
        const double t = t0 + (t1 - t0) * i / steps;
        cloud.advance_to(t, plans);
        if (PCCD::do_intersect(cloud, obstacle).intersects) return t;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

int main(int argc, char** argv)
try {
    PCCD::testing::Bunny_contact_options o;
    for (int i = 1; i < argc; i += 2) {
        const std::string key = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument("option " + key + " needs a value");
        if (key == "--points") o.points = std::stoul(argv[i + 1]);
        else throw std::invalid_argument("unknown option " + key + " (usage: deforming_contact_time [--points N])");
    }
    const std::filesystem::path bunny = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    if (std::string(PCCD_DATA_DIR).empty() || !std::filesystem::exists(bunny))
        throw std::runtime_error("the bunny of libcgal-demo is not in PCCD_DATA_DIR (\"" PCCD_DATA_DIR "\")");
    o.off_file = bunny.string();
    const PCCD::testing::Bunny_contact_scene scene = PCCD::testing::make_bunny_contact_scene(o);

    // Hermite flightplans through the scene's positions and velocities (central differences) at 30 Hz.
    const std::size_t keys = scene.frames();
    std::vector<double> times(keys);
    for (std::size_t k = 0; k < keys; ++k) times[k] = scene.time_of(k);
    std::vector<PCCD::Polynomial_flightplan> plans;
    plans.reserve(std::size_t(scene.rest_points.cols()));
    const double h = 1e-5;
    for (Eigen::Index i = 0; i < scene.rest_points.cols(); ++i) {
        std::vector<Eigen::Vector3d> positions(keys), velocities(keys);
        const Eigen::Vector3d p = scene.rest_points.col(i);
        for (std::size_t k = 0; k < keys; ++k) {
            positions[k] = scene.deform(p, times[k]);
            velocities[k] = (scene.deform(p, times[k] + h) - scene.deform(p, times[k] - h)) / (2.0 * h);
        }
        plans.push_back(PCCD::Polynomial_flightplan::hermite(times, positions, velocities));
    }
    const std::span<const PCCD::Polynomial_flightplan> span(plans);
    PCCD::Deforming_point_cloud_object<> cloud(scene.rest_points);
    std::vector<Eigen::Vector3d> obstacle_items(scene.obstacle_points.colwise().begin(), scene.obstacle_points.colwise().end());
    const PCCD::Point_cloud_object<> obstacle(obstacle_items);
    const double spacing = cloud.cloud().mean_spacing();
    const PCCD::Rigid_transform_3<double> rest;
    const PCCD::Linear_motion still(rest, rest);

    std::printf("deforming contact: %zu points (mean spacing %.4f), obstacle %zu points, %zu key frames at %.0f Hz\n",
                std::size_t(scene.rest_points.cols()), spacing, std::size_t(scene.obstacle_points.cols()), keys,
                o.frame_rate);
    std::printf("%-11s %9s %9s %9s %9s %8s %9s %9s %9s %6s %6s %6s\n", "window s", "exact t", "toc t", "d30 t", "d300 t",
                "toc ms", "d30 ms", "d300 ms", "|toc-ex|/s", "walks", "checks", "frames");
    const double window = 0.5;
    for (double t0 = 0.0; t0 + window <= o.duration + 1e-9; t0 += window) {
        const double t1 = t0 + window;
        // Exact: the first of 3,001 sampled times at which the deformed mesh meets the sphere.
        double exact = std::numeric_limits<double>::quiet_NaN();
        for (int i = 0; i <= 3000 && std::isnan(exact); ++i) {
            const double t = t0 + window * i / 3000.0;
            if (scene.truth_at(t).intersecting) exact = t;
        }
        auto start = Clock::now();
        const PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Polynomial_flightplan> motion(cloud, span, t0, t1);
        const PCCD::Contact_time_result r = PCCD::time_of_contact(cloud, motion, obstacle, still);
        const double toc_ms = PCCD::testing::ms_since(start);
        const double toc_t = r.status == PCCD::Contact_time_status::contact ? motion.time(r.t) : std::nan("");
        start = Clock::now();
        const double d30 = first_discrete_hit(cloud, span, obstacle, t0, t1, 15);
        const double d30_ms = PCCD::testing::ms_since(start);
        start = Clock::now();
        const double d300 = first_discrete_hit(cloud, span, obstacle, t0, t1, 150);
        const double d300_ms = PCCD::testing::ms_since(start);
        // The error in path length: how far the fastest point moves between the two times.
        const double speed = motion.max_point_speed(Eigen::Vector3d::Zero(), 0.0) / window;
        const double error = std::abs(toc_t - exact) * speed / spacing;
        std::printf("[%.1f, %.1f] %9.4f %9.4f %9.4f %9.4f %8.2f %9.2f %9.2f %9.2f %6zu %6zu %6zu\n", t0, t1, exact, toc_t, d30, d300,
                    toc_ms, d30_ms, d300_ms, error, r.counters.advancement_steps, r.counters.near_checks + r.counters.bisection_steps,
                    r.counters.advancement_steps + r.counters.near_checks + r.counters.bisection_steps);
        std::fflush(stdout);
    }
    std::printf("\ncolumns: exact t = first contact of the deformed mesh with the sphere (sampled at 6 kHz; nan: none in the\n"
                "window); toc t = time_of_contact's (flightplan time); d30 / d300 t = first hit of checks at 30 / 300 Hz;\n"
                "times in ms (wall, one thread); |toc-ex|/s = |toc t - exact t| times the flightplans' speed bound, in mean\n"
                "spacings; walks, checks (near-band and bisection) of time_of_contact; frames = the times it looked at (an\n"
                "upper bound: walk and check at one time share the frame)\n");
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "deforming_contact_time: %s\n", e.what());
    return 1;
}
