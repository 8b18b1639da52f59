// pccd kinetic-bench: plays a recorded scene (cloth falling on a table, deforming point cloud or
// random linear motion) with the kinetic AABB tree, bottom-up refit and full rebuild at one query
// rate, and prints BV updates, events and time per frame of each (doc/manual/kinetic.md, "When to
// use which"; the scenes are benchmark/scenes/, target pccd_kinetic_scenes).
// The queries per frame: the overlap with the scene's obstacle (the table; a range query for the
// point scenes) unless --no-overlap, plus --rays N first-hit ray casts (cloth only; fixed rays, the
// same for every method, see PCCD::Kinetic_run_options::rays_per_frame). --given-positions hands
// the frame's positions to the trees; --warm-up S measures from S seconds into the animation.
#include "commands.h"

#include <PCCD/Error.h>

#include <scenes/Cloth_scene.h>
#include <scenes/Deforming_cloud_scene.h>
#include <scenes/Random_motion_scene.h>
#include <scenes/run_kinetic_scene.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace pccd_tool {
namespace {

struct Kinetic_bench_args {
    std::string scene = "cloth";
    std::size_t size = 1684;
    std::size_t frames = 0;
    double query_hz = 30.0;
    std::size_t rays = 0;
    bool no_overlap = false;
    bool given_positions = false;
    double warm_up = 0.0;
    bool json = false;
};

template <class P>
void run_and_print(const PCCD::Kinetic_scene<P>& scene, const Kinetic_bench_args& args)
{
    const PCCD::Kinetic_run_options options{
        .query_hz = args.query_hz,
        .overlap_query = !args.no_overlap,
        .rays_per_frame = args.rays,
        .given_positions = args.given_positions,
        .warm_up = args.warm_up};
    nlohmann::json out;
    out["scene"] = scene.name;
    out["primitives"] = scene.primitives.size();
    out["vertices"] = scene.flightplans.size();
    out["duration_s"] = scene.end_time - scene.start_time;
    out["query_hz"] = args.query_hz;
    out["rays_per_frame"] = args.rays;
    out["given_positions"] = args.given_positions;
    out["warm_up_s"] = args.warm_up;
    for (const auto method : {PCCD::Kinetic_method::kinetic, PCCD::Kinetic_method::bottom_up,
                              PCCD::Kinetic_method::rebuild}) {
        const auto r = PCCD::run_kinetic_scene(scene, method, options);
        const std::string name = PCCD::to_string(method);
        out["bv_updates"][name] = r.bv_updates;
        out["ms_per_frame"][name] = r.ms_per_frame;
        out["cpu_ms_per_frame"][name] = r.cpu_ms_per_frame;
        out["update_ms_per_frame"][name] = r.update_ms_per_frame;
        out["query_ms_per_frame"][name] = r.query_ms_per_frame;
        out["build_ms"][name] = r.build_ms;
        out["nodes"] = r.nodes;
        out["frames"] = r.frames;
        out["queries"] = r.queries;
        if (method == PCCD::Kinetic_method::kinetic) {
            out["events"] = r.events;
            out["node_updates"] = r.node_updates;
            out["certificate_computations"] = r.certificate_computations;
            out["certificate_reuses"] = r.certificate_reuses;
        }
    }
    if (args.json) {
        std::cout << out.dump(2) << '\n';
        return;
    }
    std::cout << "scene " << scene.name << ": " << scene.primitives.size() << " primitives, " << scene.flightplans.size()
              << " vertices, " << out["duration_s"].get<double>() << " s at " << args.query_hz << " Hz ("
              << out["frames"] << " frames, " << out["queries"] << " queries answered)\n"
              << "events (kinetic): " << out["events"] << ", nodes changed per frame, summed (kinetic): "
              << out["node_updates"] << '\n'
              << std::left << std::setw(11) << "method" << std::right << std::setw(12) << "bv_updates" << std::setw(14)
              << "ms_per_frame" << std::setw(10) << "update" << std::setw(10) << "queries" << std::setw(11)
              << "build_ms" << std::setw(15) << "cpu_ms_frame" << '\n';
    std::cout << std::fixed << std::setprecision(3);
    for (const char* m : {"kinetic", "bottom_up", "rebuild"})
        std::cout << std::left << std::setw(11) << m << std::right << std::setw(12) << out["bv_updates"][m].get<std::uint64_t>()
                  << std::setw(14) << out["ms_per_frame"][m].get<double>() << std::setw(10)
                  << out["update_ms_per_frame"][m].get<double>() << std::setw(10)
                  << out["query_ms_per_frame"][m].get<double>() << std::setw(11) << out["build_ms"][m].get<double>()
                  << std::setw(15) << out["cpu_ms_per_frame"][m].get<double>() << '\n';
}

} // namespace

void register_kinetic_bench(CLI::App& app)
{
    auto args = std::make_shared<Kinetic_bench_args>();
    CLI::App* cmd = app.add_subcommand(
        "kinetic-bench", "Kinetic AABB tree vs bottom-up refit vs rebuild on a recorded scene: BV updates, events, "
                         "time per frame");
    cmd->add_option("--scene", args->scene, "cloth (falling on a table), bunny (twisting, breathing cloud), random")
        ->check(CLI::IsMember({"cloth", "bunny", "random"}))
        ->capture_default_str();
    cmd->add_option("--size", args->size, "cloth: triangles; bunny and random: points")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--frames", args->frames, "query frames to play (animation length = warm-up + frames / query-hz); "
                                              "default: the scene's own length");
    cmd->add_option("--query-hz", args->query_hz, "query frames per second of animation time")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--rays", args->rays, "add N first-hit ray casts per frame to the queries (cloth only)")
        ->capture_default_str();
    cmd->add_flag("--given-positions", args->given_positions,
                  "hand the frame's vertex positions to the trees (as a simulation holds them) instead of "
                  "evaluating flightplans");
    cmd->add_option("--warm-up", args->warm_up, "seconds of animation played untimed before the measured frames")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_flag("--no-overlap", args->no_overlap, "skip the overlap query (the table; range query for points)");
    cmd->add_flag("--json", args->json, "print JSON");
    cmd->callback([args]() {
        if (args->rays > 0 && args->scene != "cloth")
            throw PCCD::Invalid_input("kinetic-bench: --rays " + std::to_string(args->rays) +
                                      " needs a scene of triangles (--scene cloth); scene " + args->scene +
                                      " has points, which rays cannot hit");
        const bool custom_length = args->frames > 0;
        const double duration = custom_length ? args->warm_up + double(args->frames) / args->query_hz : 0.0;
        if (args->scene == "cloth") {
            PCCD::Cloth_scene_options o{.triangles = args->size};
            if (custom_length) o.duration = duration;
            run_and_print(PCCD::make_cloth_scene(o), *args);
        } else if (args->scene == "bunny") {
            const std::string data = PCCD_DATA_DIR;
            PCCD::Deforming_cloud_options o{.off_file = data.empty() ? "" : data + "/bunny00.off", .points = args->size};
            if (custom_length) o.duration = duration;
            if (data.empty()) std::cerr << "pccd: PCCD_DATA_DIR is empty, using a procedural bumpy sphere\n";
            run_and_print(PCCD::make_deforming_cloud_scene(o), *args);
        } else {
            PCCD::Random_motion_options o{.points = args->size};
            if (custom_length) o.duration = duration;
            run_and_print(PCCD::make_random_motion_scene(o), *args);
        }
    });
}

} // namespace pccd_tool
