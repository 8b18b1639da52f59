// pccd world [SCENE.csv] [--generate FILE:COUNT ...] [--side L] [--scene-seed S] [--write-scene OUT.csv]
//   [--normalize] [--seed S] [--hierarchy H] [--budget-us B] [--threads N] [--kernel K] [--json] [--png F.png]
//   [--size WxH] [--view V]:
// builds a Collision_world from a scene -- rows "file, 12 numbers of the 3x4 pose [R | t] row by
// row[, group, mask]" of a CSV file, or COUNT copies of each FILE at seeded random poses -- and
// prints every pair of instances whose surfaces intersect (Collision_world::intersecting_pairs).
// Each distinct file is read and preprocessed once; its instances share the object. --png draws
// the scene, the instances that touch another one in red, the others grey, the pairs' intersection
// points dark. Implements doc/manual/world.md, "The command line".
#include "commands.h"
#include "intersection_support.h"
#include "render_objects.h"
#include "transform_options.h"

#include <PCCD/Random.h>
#include <PCCD/World/Collision_world.h>
#include <PCCD/testing/pose_generator.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

namespace pccd_tool {
namespace {

struct World_command_options {
    std::string scene;
    std::vector<std::string> generate;
    double side = 0.0;
    std::uint64_t scene_seed = 1;
    std::string write_scene;
    bool normalize = false;
    std::uint64_t seed = PCCD::Intersection_options{}.seed;
    std::string hierarchy = "likelihood";
    double budget_us = 0.0;
    unsigned threads = 0;
    bool json = false;
    std::string png;
    std::string size = "1200x800";
    std::string view = "30,25";
    std::string kernel = "auto"; // auto, geodesic or euclidean
    Object_settings object;
};

/// One row of the scene: the file, its pose and its collision filter; for a generated row also the
/// 12 numbers the pose was built from (what --write-scene writes: read back, they give the same
/// pose bit for bit, as Rigid_transform_3 stores the nearest rotation to the matrix given).
struct Scene_row {
    std::string file;
    PCCD::Rigid_transform_3<double> pose;
    PCCD::Collision_filter filter;
    std::array<double, 12> given{};
};

std::uint32_t filter_field(const std::string& field, const std::string& where, const char* name)
{
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(field, &used, 0);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != field.size() || field.front() == '-' || value > 0xFFFFFFFFull)
        throw PCCD::Invalid_input(where + ": " + name + " \"" + field +
                                  "\" is not an integer in [0, 2^32) (decimal or 0x hexadecimal)");
    return std::uint32_t(value);
}

/// The rows of a scene CSV: "file, r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2[, group, mask]"
/// (commas and/or white space; file names without spaces, relative to the current directory);
/// blank lines and lines starting with '#' are skipped, and a first row whose second field is not
/// a number is a header. Anything else throws, naming the file and the line.
std::vector<Scene_row> read_scene(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw PCCD::File_error(path, std::filesystem::exists(path) ? "cannot open the scene file"
                                                                   : "cannot open the scene file: it does not exist");
    std::vector<Scene_row> rows;
    bool first_row = true;
    std::string text;
    for (std::size_t line = 1; std::getline(in, text); ++line) {
        const std::vector<std::string> fields = split_fields(text);
        if (fields.empty() || fields.front().front() == '#') continue;
        const bool header = first_row && (fields.size() < 2 || !parse_number(fields[1]));
        first_row = false;
        if (header) continue;
        const std::string where = path + ":" + std::to_string(line);
        if (fields.size() != 13 && fields.size() != 15)
            throw PCCD::Invalid_input(where + ": expected a file and 12 numbers (the 3x4 pose [R | t] row by row), "
                                              "optionally followed by group and mask; got " +
                                      std::to_string(fields.size()) + " fields");
        Scene_row row{fields[0], make_transform(fields, 1, where + ": pose"), {}};
        if (fields.size() == 15)
            row.filter = {filter_field(fields[13], where, "group"), filter_field(fields[14], where, "mask")};
        rows.push_back(std::move(row));
    }
    if (rows.empty()) throw PCCD::Invalid_input(path + ": no instances (expected rows: file, 12 numbers)");
    return rows;
}

/// --generate FILE:COUNT, split at the last ':'.
std::pair<std::string, std::size_t> generate_spec(const std::string& spec)
{
    const std::size_t colon = spec.rfind(':');
    const std::optional<double> count =
        colon == std::string::npos ? std::nullopt : parse_number(spec.substr(colon + 1));
    if (!count || *count < 1 || *count > 1e6 || std::floor(*count) != *count)
        throw PCCD::Invalid_input("--generate " + spec + ": expected FILE:COUNT with COUNT an integer from 1 to 10^6");
    return {spec.substr(0, colon), std::size_t(*count)};
}

std::string pose_text(const std::array<double, 12>& m)
{
    std::string text;
    for (const double v : m) {
        text += ',';
        text += PCCD::Rigid_transform_3<double>::full_digits(v);
    }
    return text;
}

void run_world(const World_command_options& o)
{
    if (o.scene.empty() == o.generate.empty())
        throw PCCD::Invalid_input("give either a scene file (SCENE.csv) or --generate FILE:COUNT, not both or neither");
    if (!o.generate.empty() && !(std::isfinite(o.side) && o.side >= 0.0))
        throw PCCD::Invalid_input("--side must be finite and >= 0 (0: automatic)");
    if (o.scene.size() && (o.side != 0.0 || !o.write_scene.empty()))
        throw PCCD::Invalid_input("--side and --write-scene apply to --generate only");
    PCCD::World_options world_options;
    world_options.intersection = query_options(o.seed, o.hierarchy, o.budget_us);
    if (o.threads) world_options.threads = o.threads;
    std::optional<pccd_render::View> view;
    int width = 0, height = 0;
    if (!o.png.empty()) {
        view = view_option(o.view);
        std::tie(width, height) = pccd_render::parse_size(o.size);
    }

    // The rows (read and checked before the slow preprocessing), then each distinct file once.
    std::vector<Scene_row> rows;
    std::vector<std::pair<std::string, std::size_t>> specs;
    if (!o.scene.empty())
        rows = read_scene(o.scene);
    else
        for (const std::string& spec : o.generate) specs.push_back(generate_spec(spec));
    std::vector<std::string> files;
    std::map<std::string, std::size_t> file_index;
    const auto add_file = [&](const std::string& file) {
        if (file_index.emplace(file, files.size()).second) files.push_back(file);
    };
    for (const Scene_row& row : rows) add_file(row.file);
    for (const auto& [file, count] : specs) add_file(file);
    std::vector<Object_input> inputs; // every file read before any is preprocessed
    for (const std::string& file : files) inputs.push_back(read_object_input(file, o.normalize));
    // The objects, the world and the output, for the object type --kernel chooses (by the largest
    // file), or the prepared object files' one kind.
    std::size_t largest = 0;
    for (const Object_input& input : inputs) largest = std::max(largest, input.size());
    std::string kernel = o.kernel;
    const Object_input* first_prepared = nullptr;
    for (const Object_input& input : inputs) {
        if (!input.is_prepared()) continue;
        if (first_prepared && input.prepared != first_prepared->prepared)
            throw PCCD::Invalid_input("a world holds objects of one kernel: " + first_prepared->file + " is a prepared " +
                                      PCCD::to_string(first_prepared->prepared) + " object file, " + input.file +
                                      " a " + PCCD::to_string(input.prepared) + " one");
        kernel = kernel_of_input(o.kernel, input.prepared, input.file);
        first_prepared = &input;
    }
    const auto run = [&]<class Object>(std::type_identity<Object>) {
        std::vector<std::shared_ptr<const Object>> objects;
        nlohmann::ordered_json object_entries = nlohmann::ordered_json::array(); // the JSON's "objects"
        for (std::size_t i = 0; i < files.size(); ++i) {
            Prepared_object<Object> prepared = make_object<Object>(inputs[i], o.object);
            object_entries.push_back(object_json(files[i], prepared));
            objects.push_back(std::make_shared<const Object>(std::move(prepared.object)));
        }

        // Generated poses: uniform rotations, translations uniform in [0, side]^3; the automatic side
        // gives each instance a cube 0.9 times the mean box diagonal wide, so that the scene has
        // contacts without being a heap.
        if (!specs.empty()) {
            std::size_t total = 0;
            double diagonal = 0.0;
            for (const auto& [file, count] : specs) {
                total += count;
                diagonal += double(count) * objects[file_index[file]]->hierarchy().node(0).box.diagonal().norm();
            }
            const double side = o.side > 0.0 ? o.side : 0.9 * (diagonal / double(total)) * std::cbrt(double(total));
            PCCD::Random_engine engine(o.scene_seed);
            for (const auto& [file, count] : specs)
                for (std::size_t i = 0; i < count; ++i) {
                    const Eigen::Matrix3d r = PCCD::testing::uniform_random_rotation(engine);
                    const Eigen::Vector3d t(PCCD::uniform_real(engine, 0, side), PCCD::uniform_real(engine, 0, side),
                                            PCCD::uniform_real(engine, 0, side));
                    std::array<double, 12> m;
                    for (int row = 0; row < 3; ++row)
                        for (int col = 0; col < 4; ++col) m[std::size_t(4 * row + col)] = col < 3 ? r(row, col) : t(row);
                    rows.push_back({file, PCCD::Rigid_transform_3<double>(m), {}, m});
                }
            if (!o.write_scene.empty()) {
                std::ofstream out(o.write_scene);
                if (!out) throw PCCD::File_error(o.write_scene, "cannot write the scene file");
                out << "# pccd world --generate, scene seed " << o.scene_seed << ", side "
                    << PCCD::Rigid_transform_3<double>::full_digits(side) << "\nfile,r00,r01,r02,t0,r10,r11,r12,t1,r20,r21,r22,t2\n";
                for (const Scene_row& row : rows) out << row.file << pose_text(row.given) << '\n';
                if (!out) throw PCCD::File_error(o.write_scene, "cannot write the scene file");
            }
        }

        PCCD::Collision_world<Object> world(world_options);
        std::vector<std::size_t> object_of;
        for (const Scene_row& row : rows) {
            world.insert(objects[file_index[row.file]], row.pose, row.filter);
            object_of.push_back(file_index[row.file]);
        }
        const Clock::time_point start = Clock::now();
        const std::vector<PCCD::World_pair> pairs = world.intersecting_pairs();
        const double query_ms = ms_since(start);
        std::set<std::uint32_t> touching;
        for (const PCCD::World_pair& p : pairs) {
            touching.insert(p.a.index);
            touching.insert(p.b.index);
        }

        nlohmann::ordered_json r;
        r["objects"] = std::move(object_entries);
        r["instances"] = rows.size();
        r["normalize"] = o.normalize;
        r["seed"] = o.seed;
        r["threads"] = o.threads ? nlohmann::ordered_json(o.threads) : nlohmann::ordered_json(nullptr);
        r["pairs"] = nlohmann::ordered_json::array();
        for (const PCCD::World_pair& p : pairs)
            r["pairs"].push_back({{"a", p.a.index}, {"b", p.b.index}, {"status", PCCD::to_string(p.status)},
                                  {"point", vector_json(p.point)}});
        r["touching_instances"] = touching.size();
        const PCCD::World_counters& c = world.counters();
        r["counters"] = {{"broad_phase_pairs", c.broad_phase_pairs},
                         {"filtered_pairs", c.filtered_pairs},
                         {"cached_pairs", c.cached_pairs},
                         {"narrow_phase_queries", c.narrow_phase_queries},
                         {"reported_pairs", c.reported_pairs}};
        r["query_ms"] = query_ms;
        r["memory_bytes"] = world.memory_bytes();
        r["scene"] = o.write_scene.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.write_scene);
        r["png"] = nullptr;

        if (!o.png.empty()) {
            constexpr pccd_render::Rgb touching_colour{215, 50, 40};
            constexpr pccd_render::Rgb apart_colour{175, 175, 180};
            pccd_render::Scene scene;
            double smallest_splat = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < rows.size(); ++i) {
                scene.clouds.push_back(cloud_layer(*objects[object_of[i]], rows[i].pose,
                                                   touching.contains(std::uint32_t(i)) ? touching_colour : apart_colour));
                smallest_splat = std::min(smallest_splat, scene.clouds.back().splat_radius);
            }
            pccd_render::Marker_layer markers;
            markers.colour = {40, 20, 20};
            markers.radius = 2.0 * smallest_splat;
            markers.min_pixels = 3.0;
            std::vector<Eigen::Vector3d> points;
            for (const PCCD::World_pair& p : pairs)
                if (p.point.allFinite()) points.push_back(p.point);
            markers.points.resize(3, Eigen::Index(points.size()));
            for (std::size_t i = 0; i < points.size(); ++i) markers.points.col(Eigen::Index(i)) = points[i];
            scene.markers.push_back(std::move(markers));
            render_to_png(scene, view, width, height, o.png);
            r["png"] = std::filesystem::absolute(o.png).string();
        }

        if (o.json) {
            std::cout << r.dump(2) << '\n';
            return;
        }
        std::printf("world: %zu instances of %zu object%s", rows.size(), files.size(), files.size() == 1 ? "" : "s");
        for (std::size_t i = 0; i < files.size(); ++i)
            std::printf("%s %s (%zu points)", i ? "," : ":", files[i].c_str(), objects[i]->size());
        std::printf("; %s kernel", kernel_name<Object>());
        std::printf("\nseed %llu, threads %s%s\n", static_cast<unsigned long long>(o.seed),
                    o.threads ? std::to_string(o.threads).c_str() : "all", o.normalize ? ", normalized into [-1,1]^3" : "");
        std::printf("broad phase: %zu box pairs, %zu filtered; narrow phase: %zu queries in %.1f ms\n", c.broad_phase_pairs,
                    c.filtered_pairs, c.narrow_phase_queries, query_ms);
        std::printf("intersecting pairs: %zu (%zu of %zu instances touch another)\n", pairs.size(), touching.size(),
                    rows.size());
        for (const PCCD::World_pair& p : pairs) {
            std::printf("  %u %u %s", p.a.index, p.b.index, PCCD::to_string(p.status));
            if (p.point.allFinite()) std::printf(" at %.6g %.6g %.6g", p.point.x(), p.point.y(), p.point.z());
            std::printf("\n");
        }
        if (!o.write_scene.empty()) std::printf("wrote the scene to %s\n", o.write_scene.c_str());
        if (!r["png"].is_null())
            std::printf("wrote %s: touching instances red, the others grey, intersection points dark\n",
                        r["png"].get<std::string>().c_str());
    };
    with_kernel(kernel, largest, run);
}

} // namespace

void register_world(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "world", "Every intersecting pair of a scene of many posed point clouds (a collision world)");
    auto o = std::make_shared<World_command_options>();
    cmd->add_option("SCENE", o->scene,
                    "Scene CSV: rows 'file, 12 numbers (3x4 pose [R | t] row by row)[, group, mask]'; '#' comments, "
                    "optional header; files relative to the current directory");
    cmd->add_option("--generate", o->generate,
                    "Instead of a scene file: COUNT copies of FILE at seeded random poses (FILE:COUNT, repeatable)");
    cmd->add_option("--side", o->side,
                    "--generate: translations uniform in [0, L]^3 (default 0: automatic, from the objects' size and "
                    "count)");
    cmd->add_option("--scene-seed", o->scene_seed, "--generate: seed of the random poses (default 1)");
    cmd->add_option("--write-scene", o->write_scene, "--generate: write the generated scene as a scene CSV");
    cmd->add_flag("--normalize", o->normalize,
                  "Centre and scale each object into [-1,1]^3 (bounding box) before preprocessing");
    cmd->add_option("--seed", o->seed, "Seed of the narrow phase (pair (a, b) uses pair_seed(seed, key(a, b)))");
    cmd->add_option("--hierarchy", o->hierarchy, "Traversal of the narrow phase: likelihood (default), depth-first, flat")
        ->check(CLI::IsMember(traversal_names()));
    cmd->add_option("--budget-us", o->budget_us,
                    "Time budget per pair in microseconds (0: none); a pair that runs out is reported 'undecided'");
    cmd->add_option("--threads", o->threads, "Worker threads of the narrow phase (default: all available)")
        ->check(CLI::Range(1u, 4096u));
    add_object_settings(cmd, o->object, false);
    cmd->add_option("--kernel", o->kernel,
                    "The objects' surface kernel, one for all: geodesic (Point_cloud_object), euclidean (the lean "
                    "Euclidean_point_cloud_object, about a fifth of the memory) or auto (default: euclidean when a "
                    "file has 10^6 points or more; prepared object files (pccd prepare) fix it)")
        ->check(CLI::IsMember(kernel_names()));
    cmd->add_flag("--json", o->json, "Print the result as JSON");
    cmd->add_option("--png", o->png, "Draw the scene into this PNG file: touching instances red, the others grey");
    cmd->add_option("--size", o->size, "--png: image size WIDTHxHEIGHT (default 1200x800)");
    cmd->add_option("--view", o->view, "--png: camera direction AZIMUTH,ELEVATION or front/back/side/top/iso/auto "
                                       "(default 30,25)");
    cmd->callback([o] { run_world(*o); });
}

} // namespace pccd_tool
