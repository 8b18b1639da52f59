// pccd kinetic-bench: plays a recorded scene (cloth falling on a table, deforming point cloud or
// random linear motion) with the kinetic AABB tree, bottom-up refit and full rebuild at one query
// rate, and prints BV updates, events and time per frame of each (doc/manual/kinetic.md, "When to
// use which"; the scenes are PCCD/testing/scenes/, target PCCD::testing).
// The queries per frame: the overlap with the scene's obstacle (the table; a range query for the
// point scenes) unless --no-overlap, plus --rays N first-hit ray casts (cloth only; fixed rays, the
// same for every method, see PCCD::testing::Kinetic_run_options::rays_per_frame). --given-positions hands
// the frame's positions to the trees; --warm-up S measures from S seconds into the animation.
// --scene bunny-contact plays the deforming contact scene instead: per frame the verdict and time of
// the deforming object (Deforming_point_cloud_object) against a rigid sphere cloud, and those of a
// reference that rebuilds the object from the frame's points (doc/manual/kinetic.md, "Deforming
// point clouds").
#include "commands.h"

#include <PCCD/Error.h>

#include <PCCD/testing/scenes/Bunny_contact_scene.h>
#include <PCCD/testing/scenes/Cloth_scene.h>
#include <PCCD/testing/scenes/Deforming_cloud_scene.h>
#include <PCCD/testing/scenes/Random_motion_scene.h>
#include <PCCD/testing/scenes/run_contact_scene.h>
#include <PCCD/testing/scenes/run_kinetic_scene.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <fstream>
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
    bool size_given = false;
    unsigned threads = 1;
    std::string normals = "transport";
    std::string csv;
};

/// --scene bunny-contact: the deforming contact scene, frame by frame.
void run_contact(const Kinetic_bench_args& args)
{
    const std::string data = PCCD_DATA_DIR;
    PCCD::testing::Bunny_contact_options o{.off_file = data.empty() ? "" : data + "/bunny00.off"};
    if (args.size_given) o.points = args.size;
    o.frame_rate = args.query_hz;
    if (args.frames > 0) o.duration = double(args.frames - 1) / args.query_hz;
    if (data.empty()) std::cerr << "pccd: PCCD_DATA_DIR is empty, using a procedural bumpy sphere\n";
    const PCCD::testing::Bunny_contact_scene scene = PCCD::testing::make_bunny_contact_scene(o);
    const PCCD::testing::Contact_run run = PCCD::testing::run_contact_scene(
        scene, {.threads = args.threads,
                .normals = args.normals == "refit" ? PCCD::Normal_update::refit : PCCD::Normal_update::transport});
    using F = PCCD::testing::Contact_frame;
    if (!args.csv.empty()) {
        std::ofstream file(args.csv);
        if (!file) throw PCCD::File_error(args.csv, "kinetic-bench cannot open it for writing");
        file << "frame,time,kinetic,rebuild,exact,grazing,margin,kinetic_ms,kinetic_cpu_ms,update_ms,rebuild_ms,"
                "rebuild_cpu_ms,min_stretch,max_stretch\n";
        file << std::setprecision(9);
        for (std::size_t k = 0; k < run.frames.size(); ++k) {
            const F& f = run.frames[k];
            file << k << ',' << f.time << ',' << f.kinetic << ',' << f.rebuild << ',' << f.truth << ',' << f.grazing
                 << ',' << f.margin << ',' << f.kinetic_ms << ',' << f.kinetic_cpu_ms << ',' << f.update_ms << ','
                 << f.rebuild_ms << ',' << f.rebuild_cpu_ms << ',' << f.min_stretch << ',' << f.max_stretch << '\n';
        }
        if (!file) throw PCCD::File_error(args.csv, "kinetic-bench could not write it");
    }
    if (args.json) {
        nlohmann::json out;
        out["scene"] = scene.name;
        out["points"] = scene.rest_points.cols();
        out["obstacle_points"] = scene.obstacle_points.cols();
        out["frame_rate"] = o.frame_rate;
        out["threads"] = args.threads;
        out["normals"] = args.normals;
        out["frames"] = run.frames.size();
        out["grazing_frames"] = run.frames.size() - run.compared;
        out["contact_frames"] = run.contact_frames;
        out["agreement"] = run.agreement();
        out["kinetic_exact"] = run.compared == 0 ? 1.0 : double(run.kinetic_exact) / double(run.compared);
        out["rebuild_exact"] = run.compared == 0 ? 1.0 : double(run.rebuild_exact) / double(run.compared);
        out["rest_build_ms"] = run.rest_build_ms;
        out["ms_per_frame"] = {{"kinetic", run.mean(&F::kinetic_ms)}, {"rebuild", run.mean(&F::rebuild_ms)}};
        out["cpu_ms_per_frame"] = {{"kinetic", run.mean(&F::kinetic_cpu_ms)}, {"rebuild", run.mean(&F::rebuild_cpu_ms)}};
        out["update_ms_per_frame"] = run.mean(&F::update_ms);
        nlohmann::json frames = nlohmann::json::array();
        for (const F& f : run.frames)
            frames.push_back({{"time", f.time}, {"kinetic", f.kinetic}, {"rebuild", f.rebuild}, {"exact", f.truth},
                              {"grazing", f.grazing}, {"margin", f.margin}, {"kinetic_ms", f.kinetic_ms},
                              {"rebuild_ms", f.rebuild_ms}, {"min_stretch", f.min_stretch},
                              {"max_stretch", f.max_stretch}});
        out["per_frame"] = frames;
        std::cout << out.dump(2) << '\n';
        return;
    }
    std::cout << "scene " << scene.name << ": " << scene.rest_points.cols() << " deforming points against "
              << scene.obstacle_points.cols() << " obstacle points, " << run.frames.size() << " frames at "
              << o.frame_rate << " Hz, " << args.threads << " thread(s), normals " << args.normals << '\n'
              << std::left << std::setw(6) << "frame" << std::right << std::setw(8) << "time" << std::setw(9)
              << "kinetic" << std::setw(12) << "kinetic_ms" << std::setw(9) << "rebuild" << std::setw(12) << "rebuild_ms"
              << std::setw(7) << "exact" << std::setw(9) << "grazing" << std::setw(9) << "stretch" << '\n';
    std::cout << std::fixed;
    for (std::size_t k = 0; k < run.frames.size(); ++k) {
        const F& f = run.frames[k];
        std::cout << std::left << std::setw(6) << k << std::right << std::setprecision(3) << std::setw(8) << f.time
                  << std::setw(9) << (f.kinetic ? "yes" : "no") << std::setw(12) << f.kinetic_ms << std::setw(9)
                  << (f.rebuild ? "yes" : "no") << std::setw(12) << f.rebuild_ms << std::setw(7)
                  << (f.truth ? "yes" : "no") << std::setw(9) << (f.grazing ? "grazing" : "") << std::setw(9)
                  << f.max_stretch << '\n';
    }
    std::cout << "agreement (non-grazing frames): " << run.agreeing << " of " << run.compared << " ("
              << std::setprecision(1) << 100.0 * run.agreement() << " %); exact: kinetic " << run.kinetic_exact
              << ", rebuild " << run.rebuild_exact << '\n'
              << std::setprecision(3) << "ms per frame: kinetic " << run.mean(&F::kinetic_ms) << " (update "
              << run.mean(&F::update_ms) << "), rebuild " << run.mean(&F::rebuild_ms) << " (ratio "
              << run.mean(&F::kinetic_ms) / run.mean(&F::rebuild_ms) << ")\n";
}

template <class P>
void run_and_print(const PCCD::testing::Kinetic_scene<P>& scene, const Kinetic_bench_args& args)
{
    const PCCD::testing::Kinetic_run_options options{
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
    for (const auto method : {PCCD::testing::Kinetic_method::kinetic, PCCD::testing::Kinetic_method::bottom_up,
                              PCCD::testing::Kinetic_method::rebuild}) {
        const auto r = PCCD::testing::run_kinetic_scene(scene, method, options);
        const std::string name = PCCD::testing::to_string(method);
        out["bv_updates"][name] = r.bv_updates;
        out["ms_per_frame"][name] = r.ms_per_frame;
        out["cpu_ms_per_frame"][name] = r.cpu_ms_per_frame;
        out["update_ms_per_frame"][name] = r.update_ms_per_frame;
        out["query_ms_per_frame"][name] = r.query_ms_per_frame;
        out["build_ms"][name] = r.build_ms;
        out["nodes"] = r.nodes;
        out["frames"] = r.frames;
        out["queries"] = r.queries;
        if (method == PCCD::testing::Kinetic_method::kinetic) {
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
    cmd->add_option("--scene", args->scene,
                    "cloth (falling on a table), bunny (twisting, breathing cloud), random, bunny-contact (the "
                    "deforming cloud against a rigid sphere cloud, kinetic verdicts against a rebuild)")
        ->check(CLI::IsMember({"cloth", "bunny", "random", "bunny-contact"}))
        ->capture_default_str();
    auto* size = cmd->add_option("--size", args->size,
                                 "cloth: triangles; bunny and random: points; bunny-contact: points (default 5000)")
                     ->check(CLI::PositiveNumber)
                     ->capture_default_str();
    cmd->add_option("--threads", args->threads, "bunny-contact: threads of the update and of the rebuild (0: all)")
        ->capture_default_str();
    cmd->add_option("--csv", args->csv, "bunny-contact: also write every frame to this CSV file");
    cmd->add_option("--normals", args->normals, "bunny-contact: how the deforming object updates normals")
        ->check(CLI::IsMember({"transport", "refit"}))
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
    cmd->callback([args, size]() {
        args->size_given = size->count() > 0;
        if (args->rays > 0 && args->scene != "cloth")
            throw PCCD::Invalid_input("kinetic-bench: --rays " + std::to_string(args->rays) +
                                      " needs a scene of triangles (--scene cloth); scene " + args->scene +
                                      " has points, which rays cannot hit");
        if (args->scene == "bunny-contact") {
            if (args->given_positions || args->no_overlap || args->warm_up > 0.0)
                throw PCCD::Invalid_input("kinetic-bench: --given-positions, --no-overlap and --warm-up do not apply "
                                          "to --scene bunny-contact (it hands every frame's positions to the object "
                                          "and asks one intersection query per frame)");
            run_contact(*args);
            return;
        }
        if (args->normals != "transport" || args->threads != 1 || !args->csv.empty())
            throw PCCD::Invalid_input("kinetic-bench: --normals, --threads and --csv apply to --scene bunny-contact only");
        const bool custom_length = args->frames > 0;
        const double duration = custom_length ? args->warm_up + double(args->frames) / args->query_hz : 0.0;
        if (args->scene == "cloth") {
            PCCD::testing::Cloth_scene_options o{.triangles = args->size};
            if (custom_length) o.duration = duration;
            run_and_print(PCCD::testing::make_cloth_scene(o), *args);
        } else if (args->scene == "bunny") {
            const std::string data = PCCD_DATA_DIR;
            PCCD::testing::Deforming_cloud_options o{.off_file = data.empty() ? "" : data + "/bunny00.off", .points = args->size};
            if (custom_length) o.duration = duration;
            if (data.empty()) std::cerr << "pccd: PCCD_DATA_DIR is empty, using a procedural bumpy sphere\n";
            run_and_print(PCCD::testing::make_deforming_cloud_scene(o), *args);
        } else {
            PCCD::testing::Random_motion_options o{.points = args->size};
            if (custom_length) o.duration = duration;
            run_and_print(PCCD::testing::make_random_motion_scene(o), *args);
        }
    });
}

} // namespace pccd_tool
