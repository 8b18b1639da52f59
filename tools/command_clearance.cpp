// pccd clearance OBJECT SCENE --path poses.csv --margin M [--max-distance CAP] [--tolerance T]
//   [--relative-tolerance R] [--budget-us T] [--max-node-pairs N] [--certified-lower-bound] [--penetration] [--seed S]
//   [--threads N] [--orthonormalize] [--json] [--png F]:
// the clearance of an object moved along a path of poses through a scene (PCCD::clearance: at each
// pose the distance between the two implicit surfaces placed against the margin, with its honest
// interval and witness points; the first pose below the margin and the minimum), one CSV line per
// pose and a summary, or one JSON object; --png draws the clearance profile (clearance against the
// pose index, the margin and the cap as levels). Each object is preprocessed once. Implements
// doc/manual/proximity-cli-python.md, "pccd clearance".
#include "commands.h"
#include "intersection_support.h"
#include "parse_number.h"
#include "pose_cases.h"
#include "render/plot.h"

#include <PCCD/Proximity/clearance.h>
#include <PCCD/Rigid_transform_3.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pccd_tool {
namespace {

struct Clearance_cli_options {
    std::string file_object;
    std::string file_scene;
    std::string path;
    std::string margin;
    std::string max_distance;       // empty: no cap
    std::string tolerance;          // empty: automatic
    std::string relative_tolerance; // empty: 0
    std::string budget_us;          // empty or 0: none
    std::string kernel = "auto";    // auto, geodesic or euclidean
    std::string kernel_object;      // empty: as --kernel
    Object_settings object;
    std::size_t max_node_pairs = 0; // 0: none
    bool certified_lower_bound = false;
    bool penetration = false;
    bool orthonormalize = false;
    std::uint64_t seed = PCCD::Intersection_options{}.seed;
    unsigned threads = 0; // 0: all available
    bool json = false;
    std::string png;
};

/// The number an option was given, checked: finite, and >= 0 (or > 0 when `positive`).
double option_number(const std::string& text, const std::string& option, bool positive)
{
    const double value = parse_finite_number(text, option);
    if (positive ? !(value > 0.0) : !(value >= 0.0))
        throw PCCD::Invalid_input(option + " " + text + ": must be " + (positive ? "> 0" : ">= 0"));
    return value;
}

/// The library's options from the command line, checked before any work by the library's own rule.
PCCD::Clearance_options clearance_options(const Clearance_cli_options& o, double margin)
{
    PCCD::Clearance_options options;
    if (!o.max_distance.empty()) options.max_distance = option_number(o.max_distance, "--max-distance", false);
    PCCD::Distance_options& d = options.distance;
    d.penetration = o.penetration;
    d.intersection.seed = o.seed;
    if (!o.tolerance.empty()) d.absolute_tolerance = option_number(o.tolerance, "--tolerance", true);
    if (!o.relative_tolerance.empty()) d.relative_tolerance = option_number(o.relative_tolerance, "--relative-tolerance", false);
    if (!o.budget_us.empty()) {
        const double us = option_number(o.budget_us, "--budget-us", false);
        if (us != 0.0) d.max_time_us = us; // 0: no budget, as for pccd distance
    }
    if (o.max_node_pairs != 0) d.max_node_pairs = o.max_node_pairs;
    d.certified_lower_bound = o.certified_lower_bound;
    if (o.threads > PCCD::Batch_options::max_threads)
        throw PCCD::Invalid_input("--threads " + std::to_string(o.threads) + ": must be at most " +
                                  std::to_string(PCCD::Batch_options::max_threads) + " (0: all available)");
    if (o.threads != 0) options.batch.threads = o.threads;
    if (options.max_distance && *options.max_distance < margin)
        throw PCCD::Invalid_input("--max-distance " + o.max_distance + ": must be >= the margin " + o.margin);
    PCCD::internal::check_options(options, margin, "pccd clearance");
    return options;
}

nlohmann::ordered_json optional_json(const std::optional<std::size_t>& i)
{
    return i ? nlohmann::ordered_json(*i) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json counters_json(const PCCD::Distance_counters& counters)
{
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    PCCD::for_each_counter(counters, [&](const char* name, std::size_t value) { out[name] = value; });
    PCCD::for_each_counter(counters.intersection,
                           [&](const char* name, std::size_t value) { out[std::string("intersection_") + name] = value; });
    return out;
}

/// The profile's fields named as in C++ (NaN and infinity: null).
nlohmann::ordered_json profile_json(const PCCD::Clearance_profile& p)
{
    nlohmann::ordered_json j;
    j["margin"] = p.margin;
    j["max_distance"] = p.max_distance ? nlohmann::ordered_json(*p.max_distance) : nullptr;
    nlohmann::ordered_json samples = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < p.samples.size(); ++i) {
        const PCCD::Clearance_sample& s = p.samples[i];
        samples.push_back({{"index", i},
                           {"status", PCCD::to_string(s.status)},
                           {"clearance", s.clearance},
                           {"lower_bound", s.lower_bound},
                           {"upper_bound", s.upper_bound},
                           {"point_object", vector_json(s.point_object)},
                           {"point_scene", vector_json(s.point_scene)},
                           {"depth", s.depth}});
    }
    j["samples"] = std::move(samples);
    j["first_below_margin"] = optional_json(p.first_below_margin);
    j["first_point_object"] = vector_json(p.first_point_object);
    j["first_point_scene"] = vector_json(p.first_point_scene);
    j["minimum"] = optional_json(p.minimum);
    j["minimum_clearance"] = p.minimum_clearance;
    j["first_undecided"] = optional_json(p.first_undecided);
    j["all_clear"] = p.all_clear();
    const PCCD::Clearance_counters& c = p.counters;
    j["counters"] = {{"clear", c.clear},           {"below_margin", c.below_margin}, {"intersecting", c.intersecting},
                     {"beyond_cap", c.beyond_cap}, {"undecided", c.undecided},       {"work", counters_json(c.work)}};
    return j;
}

/// A number of the text output: 9 significant digits, nan and inf as such.
std::string number(double x)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", x);
    return buffer;
}

std::string point_text(const Eigen::Vector3d& v)
{
    return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
}

/// The colour of a pose's dot in the profile plot.
pccd_render::Rgb status_colour(PCCD::Clearance_status s)
{
    switch (s) {
    case PCCD::Clearance_status::clear: return pccd_render::colour_a;
    case PCCD::Clearance_status::below_margin:
    case PCCD::Clearance_status::intersecting: return pccd_render::colour_curve;
    case PCCD::Clearance_status::beyond_cap: return {150, 150, 150};
    case PCCD::Clearance_status::undecided: return pccd_render::colour_b;
    }
    return pccd_render::colour_a;
}

/// The clearance profile: the clearance at each pose (blue, dots red below the margin, grey at the
/// top beyond the cap), the intervals as light bars, the margin red, the cap dashed grey, the first
/// pose below the margin a dashed red vertical.
void write_profile_png(const PCCD::Clearance_profile& p, const std::string& file)
{
    pccd_render::Profile_plot plot;
    double top = std::max(p.margin, 1e-12);
    for (const PCCD::Clearance_sample& s : p.samples) {
        plot.values.push_back(s.clearance);
        plot.dot_colours.push_back(status_colour(s.status));
        plot.lower.push_back(s.lower_bound);
        plot.upper.push_back(s.upper_bound);
        for (const double v : {s.clearance, s.upper_bound})
            if (std::isfinite(v) && s.status != PCCD::Clearance_status::beyond_cap) top = std::max(top, v);
    }
    if (p.max_distance) top = std::max(top, *p.max_distance);
    plot.y_max = 1.1 * top;
    plot.levels.push_back({p.margin, pccd_render::colour_curve, false});
    if (p.max_distance) plot.levels.push_back({*p.max_distance, {150, 150, 150}, true});
    plot.marker = p.first_below_margin;
    pccd_render::write_png(file, pccd_render::plot_profile(plot, 800, 480));
}

/// The clearance of the object's points (`clouds.a`, preprocessed into an `Object`) along `poses`
/// through the scene's (`clouds.b`, into a `Scene`; the same object when `clouds.same` and the two
/// types agree), and its output.
template <class Object, class Scene>
void run_clearance_with(const Clearance_cli_options& o, double margin, const PCCD::Clearance_options& options,
                        const std::vector<PCCD::Rigid_transform_3<double>>& poses, const Two_clouds& clouds)
{
    const Prepared_pair<Object, Scene> objects = prepare_pair<Object, Scene>(clouds, o.object);
    const Prepared_object<Object>& object = objects.a;
    const Prepared_object<Scene>& scene = objects.b;
    const bool same = objects.shared;

    const Clock::time_point start = Clock::now();
    const PCCD::Clearance_profile p = PCCD::clearance(object.object, scene.object, poses, margin, options);
    const double query_ms = ms_since(start);
    if (!o.png.empty()) write_profile_png(p, o.png);

    if (o.json) {
        nlohmann::ordered_json r;
        r["object"] = object_json(o.file_object, object);
        r["scene"] = object_json(o.file_scene, scene);
        r["path"] = o.path;
        r["poses"] = poses.size();
        r["seed"] = o.seed;
        r["threads"] = o.threads == 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.threads);
        r["penetration"] = o.penetration;
        r.update(profile_json(p));
        r["query_ms"] = query_ms;
        r["png"] = o.png.empty() ? nlohmann::ordered_json(nullptr)
                                 : nlohmann::ordered_json(std::filesystem::absolute(o.png).string());
        std::cout << r.dump(2) << '\n';
        return;
    }
    print_object_line("object", object_json(o.file_object, object));
    if (same)
        std::printf("scene: the same object\n");
    else
        print_object_line("scene", object_json(o.file_scene, scene));
    std::printf("path: %s, %zu poses, margin %s, max_distance %s, seed %llu\n", o.path.c_str(), poses.size(),
                number(margin).c_str(), options.max_distance ? number(*options.max_distance).c_str() : "none",
                static_cast<unsigned long long>(o.seed));
    std::printf("pose,status,clearance,lower_bound,upper_bound\n");
    for (std::size_t i = 0; i < p.samples.size(); ++i) {
        const PCCD::Clearance_sample& s = p.samples[i];
        std::printf("%zu,%s,%.17g,%.17g,%.17g\n", i, PCCD::to_string(s.status), s.clearance, s.lower_bound, s.upper_bound);
    }
    if (p.first_below_margin) {
        const PCCD::Clearance_sample& s = p.samples[*p.first_below_margin];
        std::printf("first_below_margin: %zu (%s, clearance %s)\n", *p.first_below_margin, PCCD::to_string(s.status),
                    number(s.clearance).c_str());
        std::printf("first_point_object: %s\nfirst_point_scene: %s\n", point_text(p.first_point_object).c_str(),
                    point_text(p.first_point_scene).c_str());
    } else
        std::printf("first_below_margin: none\n");
    if (p.minimum)
        std::printf("minimum: %zu, minimum_clearance %s\n", *p.minimum, number(p.minimum_clearance).c_str());
    else
        std::printf("minimum: none, minimum_clearance inf\n");
    if (p.first_undecided) std::printf("first_undecided: %zu\n", *p.first_undecided);
    const PCCD::Clearance_counters& c = p.counters;
    std::printf("poses: clear %zu, below_margin %zu, intersecting %zu, beyond_cap %zu, undecided %zu\n", c.clear,
                c.below_margin, c.intersecting, c.beyond_cap, c.undecided);
    std::printf("all_clear: %s\n", p.all_clear() ? "yes" : "no");
    std::printf("counters:");
    const nlohmann::ordered_json work = counters_json(c.work);
    for (const auto& [name, value] : work.items()) std::printf(" %s %zu", name.c_str(), value.template get<std::size_t>());
    std::printf("\nquery_ms: %.1f\n", query_ms);
    if (!o.png.empty())
        std::printf("wrote %s: clearance per pose blue (dots red below the margin, grey beyond the cap), intervals light "
                    "blue, the margin red, the cap dashed grey, the first pose below the margin dashed red\n",
                    std::filesystem::absolute(o.png).c_str());
}

void run_clearance(const Clearance_cli_options& o)
{
    // Everything is read and checked before the (slow) preprocessing.
    const double margin = option_number(o.margin, "--margin", false);
    const PCCD::Clearance_options options = clearance_options(o, margin);
    const std::vector<PCCD::Rigid_transform_3<double>> poses = read_path(o.path, o.orthonormalize);
    const Two_clouds clouds = read_two_clouds(o.file_object, o.file_scene, false);
    // --kernel-object, when given, overrides --kernel for the moving object alone; auto decides by
    // each object's own size.
    with_kernels(o.kernel, o.kernel_object, "", clouds, [&]<class Object, class Scene>(std::type_identity<Object>, std::type_identity<Scene>) {
        run_clearance_with<Object, Scene>(o, margin, options, poses, clouds);
    });
}

} // namespace

void register_clearance(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "clearance", "The clearance of an object moved along a path of poses through a scene: per pose the distance "
                     "between the implicit surfaces against a margin, the first pose below it, the minimum");
    auto o = std::make_shared<Clearance_cli_options>();
    cmd->add_option("OBJECT", o->file_object, "The moving object's point file (.ply, .off, .xyz, .pwn)")->required();
    cmd->add_option("SCENE", o->file_scene, "The scene's point file (at the identity; may be the same as OBJECT)")->required();
    cmd->add_option("--path", o->path,
                    "CSV of the object's poses in the scene's frame, 12 numbers a row (3x4 [R | t] row-major); "
                    "blank lines, # comments and one header line are skipped")
        ->required();
    cmd->add_option("--margin", o->margin, "The safety margin M (world units, >= 0)")->required();
    cmd->add_option("--max-distance", o->max_distance,
                    "The cap (world units, >= the margin): poses farther apart are reported beyond_cap (clearance inf), "
                    "cheaply; default: no cap");
    cmd->add_option("--tolerance", o->tolerance,
                    "Absolute tolerance of the witness refinement (world units, > 0); default: 0.01 times the smaller "
                    "sampling radius");
    cmd->add_option("--relative-tolerance", o->relative_tolerance, "Relative tolerance of the witness refinement (>= 0, default 0)");
    cmd->add_option("--budget-us", o->budget_us,
                    "Time budget per pose in microseconds (>= 0; default 0: none); the answer then depends on the "
                    "machine's speed");
    cmd->add_option("--max-node-pairs", o->max_node_pairs,
                    "Budget per pose on the node pairs of the closest-pair walk (deterministic; default 0: none)");
    cmd->add_flag("--certified-lower-bound", o->certified_lower_bound,
                  "Certify each pose's lower_bound: point pair distances minus the points' domain radii (holds "
                  "whatever the fit; 13-27 % more time) instead of minus r(P) + 2 sigma per surface");
    cmd->add_flag("--penetration", o->penetration, "For intersecting poses, also measure the penetration depth (depth)");
    add_object_settings(cmd, o->object, false);
    cmd->add_option("--kernel", o->kernel, kernel_option_help())->check(CLI::IsMember(kernel_names()));
    cmd->add_option("--kernel-object", o->kernel_object,
                    "The moving object's kernel alone, overriding --kernel for it: auto, geodesic or euclidean (e.g. "
                    "geodesic for a part with sharp edges, whose edges it rounds less, beside a lean scene)")
        ->check(CLI::IsMember(kernel_names()));
    cmd->add_option("--seed", o->seed, "Seed of the queries (default 24301 = 0x5eed; pose i gets pair_seed(seed, i))");
    cmd->add_option("--threads", o->threads, "Worker threads (default 0: all available); the answers do not depend on it");
    cmd->add_flag("--orthonormalize", o->orthonormalize,
                  "Use the nearest rotation of each pose's 3x3 part instead of refusing one that is off by more than "
                  "1e-5 on R^T R - I; prints how far it moved");
    cmd->add_flag("--json", o->json, "Print one JSON object, the result's fields named as in C++ (NaN and inf: null)");
    cmd->add_option("--png", o->png, "Draw the clearance profile (clearance against the pose index, the margin) into this PNG file");
    cmd->callback([o] { run_clearance(*o); });
}

} // namespace pccd_tool
