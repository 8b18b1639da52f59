// pccd distance A B [--transform-a 12 numbers] [--transform-b 12 numbers] [--orthonormalize] [--normalize]
//   [--penetration] [--max-distance D] [--tolerance T] [--relative-tolerance R] [--budget-us T] [--max-node-pairs N]
//   [--certified-lower-bound]
//   [--seed S] [--margin M | --contacts [--max-contacts N]] [--json] [--png F] [--cases FILE]:
// how far apart two posed point clouds are (PCCD::distance: the distance between their implicit
// surfaces, an honest interval around it, the witness points and normals, and with --penetration
// the penetration depths of intersecting poses), whether they come closer than a margin
// (PCCD::within_distance, --margin), or their contact regions (PCCD::contacts, --contacts), with
// the query's counters and wall time; --png draws the objects and the witness segment. Each object
// is preprocessed once; with --cases every row of a CSV file of pose pairs is answered with the
// same preprocessed objects. Implements doc/manual/proximity-cli-python.md, "pccd distance".
#include "commands.h"
#include "intersection_support.h"
#include "parse_number.h"
#include "pose_cases.h"
#include "render_objects.h"
#include "transform_options.h"

#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Proximity/contacts.h>
#include <PCCD/Proximity/distance.h>
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

struct Distance_cli_options {
    std::string file_a;
    std::string file_b;
    std::vector<std::string> transform_a;
    std::vector<std::string> transform_b;
    bool normalize = false;
    bool orthonormalize = false;
    bool penetration = false;
    std::string max_distance;       // empty: no limit
    std::string tolerance;          // empty: automatic
    std::string relative_tolerance; // empty: 0
    std::string budget_us;          // empty or 0: none
    std::size_t max_node_pairs = 0; // 0: none
    bool certified_lower_bound = false;
    std::string margin;             // set: within_distance
    bool contacts = false;
    std::size_t max_contacts = PCCD::Distance_options{}.max_contacts;
    std::uint64_t seed = PCCD::Intersection_options{}.seed;
    bool json = false;
    std::string png;
    std::string cases;
    std::string kernel = "auto"; // auto, geodesic or euclidean
    std::string kernel_a, kernel_b; // empty: as --kernel
    Object_settings object;
};

/// The number an option was given, checked: finite, and >= 0 (or > 0 when `positive`).
double option_number(const std::string& text, const std::string& option, bool positive)
{
    const double value = parse_finite_number(text, option);
    if (positive ? !(value > 0.0) : !(value >= 0.0))
        throw PCCD::Invalid_input(option + " " + text + ": must be " + (positive ? "> 0" : ">= 0"));
    return value;
}

/// The library's options from the command line, checked before any work (the library's own rule,
/// PCCD::internal::check_options, runs too: nothing it would refuse reaches the preprocessing).
PCCD::Distance_options distance_options(const Distance_cli_options& o)
{
    PCCD::Distance_options options;
    options.penetration = o.penetration;
    options.intersection.seed = o.seed;
    if (!o.max_distance.empty()) options.max_distance = option_number(o.max_distance, "--max-distance", false);
    if (!o.tolerance.empty()) options.absolute_tolerance = option_number(o.tolerance, "--tolerance", true);
    if (!o.relative_tolerance.empty())
        options.relative_tolerance = option_number(o.relative_tolerance, "--relative-tolerance", false);
    if (!o.budget_us.empty()) {
        const double us = option_number(o.budget_us, "--budget-us", false);
        if (us != 0.0) options.max_time_us = us; // 0: no budget, as for pccd collide
    }
    if (o.max_node_pairs != 0) options.max_node_pairs = o.max_node_pairs;
    options.certified_lower_bound = o.certified_lower_bound;
    if (o.max_contacts == 0) throw PCCD::Invalid_input("--max-contacts 0: must be >= 1");
    options.max_contacts = o.max_contacts;
    PCCD::internal::check_options(options, "pccd distance");
    return options;
}

/// The counters of a proximity query by name, in the library's order (PCCD::for_each_counter),
/// then those of the intersection query it ran, prefixed "intersection_" (unless the library's
/// list names them already).
std::vector<std::pair<std::string, std::size_t>> distance_counters(const PCCD::Distance_counters& counters)
{
    std::vector<std::pair<std::string, std::size_t>> out;
    bool has_intersection = false;
    PCCD::for_each_counter(counters, [&](const char* name, std::size_t value) {
        out.emplace_back(name, value);
        has_intersection = has_intersection || std::string(name).starts_with("intersection_");
    });
    if (!has_intersection)
        PCCD::for_each_counter(counters.intersection, [&](const char* name, std::size_t value) {
            out.emplace_back(std::string("intersection_") + name, value);
        });
    return out;
}

nlohmann::ordered_json counters_json(const PCCD::Distance_counters& counters)
{
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& [name, value] : distance_counters(counters)) out[name] = value;
    return out;
}

nlohmann::ordered_json result_json(const PCCD::Distance_result& r)
{
    nlohmann::ordered_json j;
    j["status"] = PCCD::to_string(r.status);
    j["distance"] = r.distance; // NaN and +infinity: null
    j["lower_bound"] = r.lower_bound;
    j["upper_bound"] = r.upper_bound;
    j["point_a"] = vector_json(r.point_a);
    j["point_b"] = vector_json(r.point_b);
    j["normal_a"] = vector_json(r.normal_a);
    j["normal_b"] = vector_json(r.normal_b);
    j["depth"] = r.depth;
    j["depth_a"] = r.depth_a;
    j["depth_b"] = r.depth_b;
    j["contact_normal"] = vector_json(r.contact_normal);
    j["counters"] = counters_json(r.counters);
    nlohmann::ordered_json points = nlohmann::ordered_json::array();
    for (const PCCD::Intersection_point& p : r.intersection_points) points.push_back(vector_json(p.position));
    j["intersection_points"] = std::move(points);
    return j;
}

nlohmann::ordered_json result_json(const PCCD::Clearance_result& r)
{
    nlohmann::ordered_json j;
    j["within"] = r.within;
    j["status"] = PCCD::to_string(r.status);
    j["margin"] = r.margin;
    j["lower_bound"] = r.lower_bound;
    j["upper_bound"] = r.upper_bound;
    j["point_a"] = vector_json(r.point_a);
    j["point_b"] = vector_json(r.point_b);
    j["counters"] = counters_json(r.counters);
    return j;
}

nlohmann::ordered_json result_json(const PCCD::Contact_result& r)
{
    nlohmann::ordered_json j;
    j["status"] = PCCD::to_string(r.status);
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const PCCD::Contact& c : r.contacts)
        list.push_back({{"position", vector_json(c.position)},
                        {"normal", vector_json(c.normal)},
                        {"depth", c.depth},
                        {"point_a", vector_json(c.point_a)},
                        {"point_b", vector_json(c.point_b)},
                        {"points_inside", c.points_inside}});
    j["contacts"] = std::move(list);
    j["regions"] = r.regions;
    j["counters"] = counters_json(r.counters);
    return j;
}

/// One value of the text summary: a number with 9 significant digits, nan or inf as such.
std::string text_value(const nlohmann::ordered_json& v)
{
    if (v.is_null()) return "none";
    if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
    if (v.is_number_float()) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.9g", v.get<double>());
        return buffer;
    }
    if (v.is_array()) {
        std::string out = "[";
        for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + text_value(v[i]);
        return out + "]";
    }
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

/// The text summary: one "name: value" line per result field (nan and inf where the JSON has
/// null), the proximity counters on one line, those of the intersection query on the next.
void print_summary(const nlohmann::ordered_json& r, const nlohmann::ordered_json& result,
                   const std::vector<std::pair<std::string, double>>& raw_numbers)
{
    print_object_line("A", r["a"]);
    if (r["same_object"].get<bool>())
        std::printf("B: the same object as A\n");
    else
        print_object_line("B", r["b"]);
    std::printf("query %s, seed %llu%s\n", r["query"].get<std::string>().c_str(),
                static_cast<unsigned long long>(r["seed"].get<std::uint64_t>()),
                r["normalize"].get<bool>() ? ", normalized into [-1,1]^3" : "");
    for (const auto& [name, value] : result.items()) {
        if (name == "counters" || name == "contacts" || name == "intersection_points") continue;
        const auto raw = std::find_if(raw_numbers.begin(), raw_numbers.end(), [&](const auto& p) { return p.first == name; });
        if (raw != raw_numbers.end() && !std::isfinite(raw->second)) // null in the JSON: say which
            std::printf("%s: %s\n", name.c_str(), std::isnan(raw->second) ? "nan" : raw->second > 0 ? "inf" : "-inf");
        else if (value.is_null())
            std::printf("%s: nan\n", name.c_str());
        else
            std::printf("%s: %s\n", name.c_str(), text_value(value).c_str());
    }
    if (result.contains("contacts")) {
        std::size_t i = 0;
        for (const auto& c : result["contacts"])
            std::printf("contact %zu: position %s, normal %s, depth %s, points_inside %zu\n", ++i,
                        text_value(c["position"]).c_str(), text_value(c["normal"]).c_str(),
                        text_value(c["depth"]).c_str(), c["points_inside"].get<std::size_t>());
    }
    if (result.contains("intersection_points") && !result["intersection_points"].empty())
        std::printf("intersection_points: %s\n", text_value(result["intersection_points"][0]).c_str());
    std::printf("counters:");
    for (const auto& [name, value] : result["counters"].items())
        if (!name.starts_with("intersection_")) std::printf(" %s %zu", name.c_str(), value.get<std::size_t>());
    std::printf("\nintersection counters:");
    for (const auto& [name, value] : result["counters"].items())
        if (name.starts_with("intersection_"))
            std::printf(" %s %zu", name.substr(std::string("intersection_").size()).c_str(), value.get<std::size_t>());
    std::printf("\nquery_us: %.1f\n", r["query_us"].get<double>());
}

/// Markers along the segment from `p` to `q` (both ends included), about `spacing` apart.
pccd_render::Marker_layer segment_layer(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double spacing, double radius)
{
    const double length = (q - p).norm();
    const Eigen::Index n = std::clamp<Eigen::Index>(Eigen::Index(std::ceil(length / spacing)) + 1, 2, 2000);
    pccd_render::Marker_layer layer;
    layer.points.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i) layer.points.col(i) = p + (q - p) * (double(i) / double(n - 1));
    layer.radius = radius;
    return layer;
}

/// The query (or the cases) on the points of A and B, preprocessed into an `A` and a `B` (once when
/// both name the same file with the same kernel), and its output.
template <class A, class B>
void run_distance_with(const Distance_cli_options& o, const PCCD::Distance_options& options,
                       const std::optional<double>& margin, const Query_poses& poses, const Two_clouds& clouds)
{
    const auto& [cases, pose_a, pose_b] = poses;
    const Prepared_pair<A, B> objects = prepare_pair<A, B>(clouds, o.object);
    const Prepared_object<A>& a = objects.a;
    const Prepared_object<B>& b = objects.b;
    const bool same = objects.shared;
    const double preprocess_ms = objects.preprocess_ms();

    if (cases) {
        std::printf("case,status,distance,lower_bound,upper_bound,query_us\n");
        for (std::size_t i = 0; i < cases->size(); ++i) {
            const Pose_case& c = (*cases)[i];
            const Clock::time_point start = Clock::now();
            const PCCD::Distance_result r = PCCD::distance(a.object, c.pose_a, b.object, c.pose_b, options);
            const double us = us_since(start);
            std::printf("%zu,%s,%.17g,%.17g,%.17g,%.1f\n", i + 1, PCCD::to_string(r.status), r.distance, r.lower_bound,
                        r.upper_bound, us);
        }
        std::fflush(stdout);
        std::fprintf(stderr, "pccd distance: %zu cases; preprocessing took %.1f ms\n", cases->size(), preprocess_ms);
        return;
    }

    nlohmann::ordered_json r;
    r["a"] = object_json(o.file_a, a);
    r["b"] = object_json(o.file_b, b);
    r["same_object"] = same;
    r["normalize"] = o.normalize;
    r["query"] = margin ? "within_distance" : o.contacts ? "contacts" : "distance";
    r["seed"] = o.seed;
    r["penetration"] = options.penetration;
    r["max_distance"] = options.max_distance ? nlohmann::ordered_json(*options.max_distance) : nullptr;
    r["absolute_tolerance"] = options.absolute_tolerance ? nlohmann::ordered_json(*options.absolute_tolerance) : nullptr;
    r["relative_tolerance"] = options.relative_tolerance;
    r["certified_lower_bound"] = options.certified_lower_bound;

    // The query, its JSON, the numbers that JSON shows as null, and the segment to draw.
    nlohmann::ordered_json result;
    std::vector<std::pair<std::string, double>> raw_numbers;
    std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segment;
    std::vector<PCCD::Intersection_point> curve;
    std::vector<Eigen::Vector3d> contact_points;
    const Clock::time_point start = Clock::now();
    if (margin) {
        const PCCD::Clearance_result c = PCCD::within_distance(a.object, pose_a, b.object, pose_b, *margin, options);
        r["query_us"] = us_since(start);
        result = result_json(c);
        raw_numbers = {{"lower_bound", c.lower_bound}, {"upper_bound", c.upper_bound}};
        if (c.point_a.allFinite() && c.point_b.allFinite()) segment.emplace(c.point_a, c.point_b);
    } else if (o.contacts) {
        const PCCD::Contact_result c = PCCD::contacts(a.object, pose_a, b.object, pose_b, options);
        r["query_us"] = us_since(start);
        result = result_json(c);
        for (const PCCD::Contact& k : c.contacts)
            for (const Eigen::Vector3d& p : {k.position, k.point_a, k.point_b})
                if (p.allFinite()) contact_points.push_back(p);
    } else {
        const PCCD::Distance_result d = PCCD::distance(a.object, pose_a, b.object, pose_b, options);
        r["query_us"] = us_since(start);
        result = result_json(d);
        raw_numbers = {{"distance", d.distance}, {"lower_bound", d.lower_bound}, {"upper_bound", d.upper_bound},
                       {"depth", d.depth},       {"depth_a", d.depth_a},         {"depth_b", d.depth_b}};
        if (d.point_a.allFinite() && d.point_b.allFinite()) segment.emplace(d.point_a, d.point_b);
        curve = d.intersection_points;
    }
    r.update(result);
    r["preprocess_ms"] = preprocess_ms;
    r["png"] = nullptr;
    if (!o.png.empty()) {
        pccd_render::Scene scene;
        scene.clouds.push_back(cloud_layer(a.object, pose_a, pccd_render::colour_a));
        scene.clouds.push_back(cloud_layer(b.object, pose_b, pccd_render::colour_b));
        const double radius = 0.5 * std::min(scene.clouds[0].splat_radius, scene.clouds[1].splat_radius);
        if (segment) scene.markers.push_back(segment_layer(segment->first, segment->second, radius, radius));
        if (!curve.empty()) scene.markers.push_back(curve_layer(curve, radius));
        if (!contact_points.empty()) {
            pccd_render::Marker_layer layer;
            layer.points.resize(3, Eigen::Index(contact_points.size()));
            for (std::size_t i = 0; i < contact_points.size(); ++i) layer.points.col(Eigen::Index(i)) = contact_points[i];
            layer.radius = 2.0 * radius;
            scene.markers.push_back(std::move(layer));
        }
        render_to_png(scene, std::nullopt, 800, 600, o.png);
        r["png"] = std::filesystem::absolute(o.png).string();
    }
    if (o.json) {
        std::cout << r.dump(2) << '\n';
        return;
    }
    print_summary(r, result, raw_numbers);
    if (!r["png"].is_null()) {
        const char* drawn = segment ? "the witness segment red"
                            : !curve.empty() ? "the intersection point red"
                            : !contact_points.empty() ? "the contacts red"
                                                      : "no witness (none found)";
        std::printf("wrote %s: A blue, B gold, %s\n", r["png"].get<std::string>().c_str(), drawn);
    }
}

void run_distance(const Distance_cli_options& o)
{
    // Everything is read and checked before the (slow) preprocessing.
    const PCCD::Distance_options options = distance_options(o);
    std::optional<double> margin;
    if (!o.margin.empty()) margin = option_number(o.margin, "--margin", false);
    const Query_poses poses = read_query_poses(o.cases, o.transform_a, o.transform_b, o.orthonormalize);
    const Two_clouds clouds = read_two_clouds(o.file_a, o.file_b, o.normalize);
    with_kernels(o.kernel, o.kernel_a, o.kernel_b, clouds, [&]<class A, class B>(std::type_identity<A>, std::type_identity<B>) {
        run_distance_with<A, B>(o, options, margin, poses, clouds);
    });
}

} // namespace

void register_distance(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "distance", "How far apart two posed point clouds are: the distance between their implicit surfaces, "
                    "witness points, penetration depth, clearance and contacts");
    auto o = std::make_shared<Distance_cli_options>();
    cmd->add_option("A", o->file_a, "First point file (.ply, .off, .xyz, .pwn; a mesh gives its vertices)")->required();
    cmd->add_option("B", o->file_b, "Second point file (may be the same as A: preprocessed once)")->required();
    auto* ta = cmd->add_option("--transform-a", o->transform_a,
                               "Pose of A: 12 numbers, the 3x4 matrix [R | t] row by row (default: identity)")
                   ->expected(1, 12);
    auto* tb = cmd->add_option("--transform-b", o->transform_b, "Pose of B, as --transform-a")->expected(1, 12);
    cmd->add_flag("--orthonormalize", o->orthonormalize,
                  "Use the nearest rotation of each --transform's 3x3 part instead of refusing one that is off by "
                  "more than 1e-5 on R^T R - I; prints how far it moved");
    cmd->add_flag("--normalize", o->normalize,
                  "Centre and scale each object into [-1,1]^3 (bounding box) before preprocessing");
    cmd->add_flag("--penetration", o->penetration,
                  "For intersecting poses, also measure the penetration depths (depth, depth_a, depth_b) and the "
                  "contact normal");
    cmd->add_option("--max-distance", o->max_distance,
                    "Farther apart than D (world units, >= 0): report only that (distance inf) when no point pair comes "
                    "within D plus the surfaces' radii (one that does is refined and its distance reported); default: no "
                    "limit");
    cmd->add_option("--tolerance", o->tolerance,
                    "Absolute tolerance of the witness refinement (world units, > 0); default: 0.01 times the smaller "
                    "sampling radius");
    cmd->add_option("--relative-tolerance", o->relative_tolerance,
                    "Relative tolerance of the witness refinement (>= 0, default 0)");
    cmd->add_option("--budget-us", o->budget_us,
                    "Time budget per query in microseconds (>= 0; default 0: none); the answer then depends on the "
                    "machine's speed");
    cmd->add_option("--max-node-pairs", o->max_node_pairs,
                    "Budget on the node pairs of the closest-pair walk (deterministic; default 0: none); the "
                    "interval [lower_bound, upper_bound] narrows as it grows");
    cmd->add_flag("--certified-lower-bound", o->certified_lower_bound,
                  "Certify lower_bound: point pair distances minus the points' domain radii (holds whatever the fit; "
                  "13-27 % more time) instead of minus r(P) + 2 sigma per surface");
    auto* margin = cmd->add_option("--margin", o->margin,
                                   "Answer within_distance instead: whether the surfaces come closer than M (>= 0)");
    auto* contacts = cmd->add_flag("--contacts", o->contacts,
                                   "Answer contacts instead: the contact regions of intersecting poses, deepest first");
    cmd->add_option("--max-contacts", o->max_contacts, "With --contacts: the most regions returned (default 8)");
    margin->excludes(contacts);
    cmd->add_option("--seed", o->seed, "Seed of the query (default 24301 = 0x5eed)");
    add_object_settings(cmd, o->object, false);
    cmd->add_option("--kernel", o->kernel, kernel_option_help())->check(CLI::IsMember(kernel_names()));
    add_object_kernels(cmd, o->kernel_a, o->kernel_b);
    auto* json = cmd->add_flag("--json", o->json,
                               "Print one JSON object, the result's fields named as in C++ (NaN and inf: null)");
    auto* png = cmd->add_option("--png", o->png,
                                "Draw the posed objects (A blue, B gold) and the witness segment (red) into this PNG file");
    cmd->add_option("--cases", o->cases,
                    "CSV of pose pairs, 24 numbers a row (T_A then T_B, 3x4 row-major); prints "
                    "case,status,distance,lower_bound,upper_bound,query_us")
        ->excludes(ta)
        ->excludes(tb)
        ->excludes(json)
        ->excludes(png)
        ->excludes(margin)
        ->excludes(contacts);
    cmd->callback([o] { run_distance(*o); });
}

} // namespace pccd_tool
