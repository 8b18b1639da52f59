// pccd prepare POINTS OUT [--kernel auto|geodesic|euclidean] [--normalize] [--leaf-size N|auto]
//   [--volume V] [--surface default|sharp] [--json]: preprocesses a point file once and saves the
// object (Point_cloud_object::save or Euclidean_point_cloud_object::save), so that collide,
// distance, clearance, contact-time, world and render load it instead of preprocessing it again
// (doc/manual/cli_collide.md, "Prepared objects").
#include "commands.h"
#include "intersection_support.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <type_traits>

namespace pccd_tool {
namespace {

struct Prepare_options {
    std::string input;
    std::string output;
    bool normalize = false;
    bool json = false;
    std::string kernel = "auto";
    Object_settings object;
};

template <class Object>
void prepare_and_save(const Prepare_options& o, Object_points&& points)
{
    // The points are the object's to free once it holds its copy (the lean object does).
    const Prepared_object<Object> prepared = prepare_object<Object>(std::move(points), o.input, o.object);
    const Clock::time_point start = Clock::now();
    prepared.object.save(o.output);
    const double save_ms = ms_since(start);
    const auto bytes = std::uintmax_t(std::filesystem::file_size(o.output));
    nlohmann::ordered_json r = object_json(o.input, prepared);
    r["normalize"] = o.normalize;
    r["output"] = o.output;
    r["bytes"] = bytes;
    r["save_ms"] = save_ms;
    if (o.json) {
        std::cout << r.dump(2) << '\n';
        return;
    }
    print_object_line("object", r);
    std::printf("surface fit %s, leaf size %zu%s\n", r["surface_fit"].get<std::string>().c_str(),
                r["leaf_size"].get<std::size_t>(), o.normalize ? ", normalized into [-1,1]^3" : "");
    std::printf("wrote %s: %ju bytes (%.0f per point) in %.1f ms\n", o.output.c_str(), bytes,
                double(bytes) / double(prepared.object.size()), save_ms);
}

void run_prepare(const Prepare_options& o)
{
    if (same_file(o.input, o.output))
        throw PCCD::Invalid_input("pccd prepare: the output " + o.output + " is the input file");
    Object_input input = read_object_input(o.input, o.normalize);
    if (input.is_prepared())
        throw PCCD::Invalid_input(o.input + ": already a prepared object file (" + PCCD::to_string(input.prepared) +
                                  " kernel); pccd prepare reads point files (.ply, .off, .xyz)");
    with_kernel(o.kernel, input.size(), [&]<class Object>(std::type_identity<Object>) {
        prepare_and_save<Object>(o, std::move(input.points));
    });
}

} // namespace

void register_prepare(CLI::App& app)
{
    auto o = std::make_shared<Prepare_options>();
    CLI::App* cmd = app.add_subcommand(
        "prepare", "Preprocess a point file once and save the object, which collide, distance, clearance, "
                   "contact-time, world and render then load instead of preprocessing it again");
    cmd->add_option("points", o->input, "Point file (.ply, .off, .xyz)")->required();
    cmd->add_option("out", o->output,
                    "The object file to write (replaced if it exists); by habit .pccdobj for the geodesic kernel, "
                    ".pccdlean for the euclidean one")
        ->required();
    cmd->add_flag("--normalize", o->normalize,
                  "Centre and scale the points into [-1,1]^3 (bounding box) before preprocessing");
    add_object_settings(cmd, o->object, true);
    cmd->add_option("--kernel", o->kernel, kernel_option_help())->check(CLI::IsMember(kernel_names()));
    cmd->add_flag("--json", o->json, "Print one JSON object instead of text");
    cmd->callback([o] { run_prepare(*o); });
}

} // namespace pccd_tool
