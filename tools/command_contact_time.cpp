// pccd contact-time A B [--from-a 12 numbers] [--to-a 12 numbers] [--from-b 12 numbers] [--to-b 12 numbers]
//   [--motion linear|screw] [--centre-a x,y,z] [--centre-b x,y,z] [--orthonormalize] [--normalize]
//   [--tolerance D] [--time-accuracy D] [--near-step S] [--max-steps N] [--seed S] [--json]
//   [--png F [--png-time T]] [--cases FILE]:
// the first time in [0, 1] at which two point clouds moving rigidly come into contact
// (PCCD::time_of_contact), with its bracket, the contact point and normal, the counters and the
// wall time; --png draws the objects at the contact time. Each object is preprocessed once (point
// files make geodesic objects) or loaded from a prepared object file (as its kind); with
// --cases every row of a CSV file of four poses is answered with the same preprocessed objects.
// Implements doc/manual/continuous.md, "CLI and Python".
#include "commands.h"
#include "intersection_support.h"
#include "parse_number.h"
#include "pose_cases.h"
#include "render_objects.h"
#include "transform_options.h"

#include <PCCD/Continuous/Contact_time_names.h>
#include <PCCD/Continuous/Contact_time_options.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>
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

struct Contact_time_cli_options {
    std::string file_a;
    std::string file_b;
    std::vector<std::string> from_a;
    std::vector<std::string> to_a;
    std::vector<std::string> from_b;
    std::vector<std::string> to_b;
    std::string motion = "linear";
    std::vector<std::string> centre_a;
    std::vector<std::string> centre_b;
    bool normalize = false;
    bool orthonormalize = false;
    std::string tolerance;     // empty: 0
    std::string time_accuracy; // empty: automatic
    std::string near_step;     // empty: 0.5
    std::size_t max_steps = PCCD::Contact_time_options{}.max_steps;
    std::uint64_t seed = PCCD::Intersection_options{}.seed;
    bool json = false;
    std::string png;
    std::string png_time; // empty: the contact time (t_low without contact)
    std::string cases;
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

/// The library's options from the command line, checked before any work (and by the library's own
/// rule, PCCD::internal::check_options).
PCCD::Contact_time_options contact_time_options(const Contact_time_cli_options& o)
{
    PCCD::Contact_time_options options;
    options.distance.intersection.seed = o.seed;
    if (!o.tolerance.empty()) options.tolerance = option_number(o.tolerance, "--tolerance", false);
    if (!o.time_accuracy.empty()) options.time_accuracy = option_number(o.time_accuracy, "--time-accuracy", true);
    if (!o.near_step.empty()) {
        options.near_step = parse_finite_number(o.near_step, "--near-step");
        if (!(options.near_step > 0.0 && options.near_step <= 4.0))
            throw PCCD::Invalid_input("--near-step " + o.near_step + ": must be in (0, 4]");
    }
    if (o.max_steps == 0) throw PCCD::Invalid_input("--max-steps 0: must be >= 1");
    options.max_steps = o.max_steps;
    PCCD::internal::check_options(options, "pccd contact-time");
    return options;
}

/// --centre-a / --centre-b: three finite numbers (one "x,y,z" argument or three), the local origin
/// when absent.
Eigen::Vector3d centre_option(const std::vector<std::string>& arguments, const std::string& option)
{
    if (arguments.empty()) return Eigen::Vector3d::Zero();
    std::string joined;
    for (const std::string& a : arguments) joined += a + ' ';
    const std::vector<std::string> fields = split_fields(joined);
    if (fields.size() != 3)
        throw PCCD::Invalid_input(option + " expects 3 numbers x,y,z (a point in the object's own frame), got " +
                                  std::to_string(fields.size()));
    Eigen::Vector3d c;
    for (int k = 0; k < 3; ++k) c(k) = parse_finite_number(fields[std::size_t(k)], option);
    return c;
}

/// The motion of one object, linear or screw, from its start and end poses.
struct Motion {
    std::optional<PCCD::Linear_motion> linear;
    std::optional<PCCD::Screw_motion> screw;

    PCCD::Rigid_transform_3<double> pose(double t) const { return linear ? linear->pose(t) : screw->pose(t); }
};

Motion make_motion(const std::string& kind, const PCCD::Rigid_transform_3<double>& from,
                   const PCCD::Rigid_transform_3<double>& to, const Eigen::Vector3d& centre)
{
    Motion m;
    if (kind == "linear")
        m.linear.emplace(from, to, centre);
    else
        m.screw.emplace(from, to);
    return m;
}

/// PCCD::time_of_contact with the two motions (both linear or both screw).
template <class A, class B>
PCCD::Contact_time_result contact_time(const A& a, const Motion& ma, const B& b, const Motion& mb,
                                       const PCCD::Contact_time_options& options)
{
    if (ma.linear) return PCCD::time_of_contact(a, *ma.linear, b, *mb.linear, options);
    return PCCD::time_of_contact(a, *ma.screw, b, *mb.screw, options);
}

/// A pose as its 12 numbers, the 3x4 matrix [R | t] row by row.
nlohmann::ordered_json pose_json(const PCCD::Rigid_transform_3<double>& p)
{
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) out.push_back(p.rotation()(i, j));
        out.push_back(p.translation()(i));
    }
    return out;
}

/// The fields of Contact_time_result under their C++ names (NaN: null).
nlohmann::ordered_json result_json(const PCCD::Contact_time_result& r)
{
    nlohmann::ordered_json j;
    j["status"] = PCCD::to_string(r.status);
    j["t"] = r.t;
    j["t_low"] = r.t_low;
    j["t_high"] = r.t_high;
    j["point"] = vector_json(r.point);
    j["normal"] = vector_json(r.normal);
    nlohmann::ordered_json counters = nlohmann::ordered_json::object();
    PCCD::for_each_counter(r.counters, [&](const char* name, std::size_t value) { counters[name] = value; });
    j["counters"] = std::move(counters);
    return j;
}

std::string number_text(double x)
{
    if (std::isnan(x)) return "nan";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", x);
    return buffer;
}

std::string vector_text(const Eigen::Vector3d& v)
{
    if (!v.allFinite()) return "none";
    return "[" + number_text(v.x()) + ", " + number_text(v.y()) + ", " + number_text(v.z()) + "]";
}

/// Markers at the positions of an object's local point `c` at `n` times of its motion.
pccd_render::Marker_layer path_layer(const Motion& m, const Eigen::Vector3d& c, double radius, pccd_render::Rgb colour)
{
    constexpr Eigen::Index n = 65;
    pccd_render::Marker_layer layer;
    layer.points.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i) layer.points.col(i) = m.pose(double(i) / double(n - 1)).transform_point(c);
    layer.radius = radius;
    layer.colour = colour;
    return layer;
}

/// The poses of a motion given by options: A at t = 0 and 1, B at t = 0 and 1.
struct Option_poses {
    PCCD::Rigid_transform_3<double> from_a, to_a, from_b, to_b;
};

/// The query (or the cases) on A and B preprocessed (or loaded) into an `A` and a `B`, and its output.
template <class A, class B>
void run_contact_time_with(const Contact_time_cli_options& o, const PCCD::Contact_time_options& options,
                           const Eigen::Vector3d& centre_a, const Eigen::Vector3d& centre_b,
                           const std::optional<double>& png_time, const std::optional<std::vector<Motion_case>>& cases,
                           const Option_poses& poses, const Two_clouds& clouds)
{
    const auto& [from_a, to_a, from_b, to_b] = poses;
    const Prepared_pair<A, B> objects = prepare_pair<A, B>(clouds, o.object);
    const Prepared_object<A>& a = objects.a;
    const Prepared_object<B>& b = objects.b;
    const bool same = objects.shared;
    const double preprocess_ms = objects.preprocess_ms();

    if (cases) {
        std::printf("case,status,t,t_low,t_high,query_us\n");
        for (std::size_t i = 0; i < cases->size(); ++i) {
            const Motion_case& c = (*cases)[i];
            const Motion ma = make_motion(o.motion, c.from_a, c.to_a, centre_a);
            const Motion mb = make_motion(o.motion, c.from_b, c.to_b, centre_b);
            const Clock::time_point start = Clock::now();
            const PCCD::Contact_time_result r = contact_time(a.object, ma, b.object, mb, options);
            const double us = us_since(start);
            std::printf("%zu,%s,%.17g,%.17g,%.17g,%.1f\n", i + 1, PCCD::to_string(r.status), r.t, r.t_low, r.t_high, us);
        }
        std::fflush(stdout);
        std::fprintf(stderr, "pccd contact-time: %zu cases; preprocessing took %.1f ms\n", cases->size(), preprocess_ms);
        return;
    }

    const Motion ma = make_motion(o.motion, from_a, to_a, centre_a);
    const Motion mb = make_motion(o.motion, from_b, to_b, centre_b);
    const Clock::time_point start = Clock::now();
    const PCCD::Contact_time_result result = contact_time(a.object, ma, b.object, mb, options);
    const double query_us = us_since(start);

    nlohmann::ordered_json r;
    r["a"] = object_json(o.file_a, a);
    r["b"] = object_json(o.file_b, b);
    r["same_object"] = same;
    r["normalize"] = o.normalize;
    r["motion"] = o.motion;
    r["from_a"] = pose_json(from_a);
    r["to_a"] = pose_json(to_a);
    r["from_b"] = pose_json(from_b);
    r["to_b"] = pose_json(to_b);
    r["centre_a"] = o.motion == "linear" ? vector_json(centre_a) : nullptr;
    r["centre_b"] = o.motion == "linear" ? vector_json(centre_b) : nullptr;
    r["seed"] = o.seed;
    r["tolerance"] = options.tolerance;
    r["time_accuracy"] = options.time_accuracy ? nlohmann::ordered_json(*options.time_accuracy) : nullptr;
    r["near_step"] = options.near_step;
    r["max_steps"] = options.max_steps;
    r["query_us"] = query_us;
    r.update(result_json(result));
    r["preprocess_ms"] = preprocess_ms;
    r["png"] = nullptr;
    r["png_time"] = nullptr;
    bool drew_point = false;
    if (!o.png.empty()) {
        // At the contact time; without contact where the query stopped (1 for no_contact).
        const double t = png_time ? *png_time : result.status == PCCD::Contact_time_status::contact ? result.t : result.t_low;
        pccd_render::Scene scene;
        scene.clouds.push_back(cloud_layer(a.object, ma.pose(t), pccd_render::colour_a));
        scene.clouds.push_back(cloud_layer(b.object, mb.pose(t), pccd_render::colour_b));
        const double radius = 0.5 * std::min(scene.clouds[0].splat_radius, scene.clouds[1].splat_radius);
        // The paths of the box centres over [0, 1], darker than the clouds.
        const auto centre = [](const auto& object) {
            return Eigen::Vector3d(object.hierarchy().root().box.center());
        };
        scene.markers.push_back(path_layer(ma, centre(a.object), 0.5 * radius, {30, 70, 140}));
        scene.markers.push_back(path_layer(mb, centre(b.object), 0.5 * radius, {170, 120, 20}));
        if (result.point.allFinite() && (!png_time || *png_time == result.t)) {
            pccd_render::Marker_layer layer;
            layer.points = result.point;
            layer.radius = 3.0 * radius;
            scene.markers.push_back(std::move(layer));
            drew_point = true;
        }
        render_to_png(scene, std::nullopt, 800, 600, o.png);
        r["png"] = std::filesystem::absolute(o.png).string();
        r["png_time"] = t;
    }
    if (o.json) {
        std::cout << r.dump(2) << '\n';
        return;
    }
    print_object_line("A", r["a"]);
    if (same)
        std::printf("B: the same object as A\n");
    else
        print_object_line("B", r["b"]);
    std::printf("motion %s, tolerance %s, seed %llu%s\n", o.motion.c_str(), number_text(options.tolerance).c_str(),
                static_cast<unsigned long long>(o.seed), o.normalize ? ", normalized into [-1,1]^3" : "");
    std::printf("status: %s\n", PCCD::to_string(result.status));
    std::printf("t: %s\nt_low: %s\nt_high: %s\n", number_text(result.t).c_str(), number_text(result.t_low).c_str(),
                number_text(result.t_high).c_str());
    std::printf("point: %s\nnormal: %s\n", vector_text(result.point).c_str(), vector_text(result.normal).c_str());
    std::printf("counters:");
    PCCD::for_each_counter(result.counters, [](const char* name, std::size_t value) { std::printf(" %s %zu", name, value); });
    std::printf("\nquery_us: %.1f\n", query_us);
    if (!r["png"].is_null())
        std::printf("wrote %s: A blue, B gold at t = %s, their paths darker%s\n", r["png"].get<std::string>().c_str(),
                    number_text(r["png_time"].get<double>()).c_str(),
                    drew_point ? ", the contact point red" : "");
}

void run_contact_time(const Contact_time_cli_options& o)
{
    // Everything is read and checked before the (slow) preprocessing.
    if (o.motion != "linear" && o.motion != "screw")
        throw PCCD::Invalid_input("--motion must be linear or screw, not \"" + o.motion + "\"");
    if (o.motion == "screw" && (!o.centre_a.empty() || !o.centre_b.empty()))
        throw PCCD::Invalid_input(std::string(o.centre_a.empty() ? "--centre-b" : "--centre-a") +
                                  " applies to --motion linear only (a screw motion turns about its own axis)");
    const PCCD::Contact_time_options options = contact_time_options(o);
    const Eigen::Vector3d centre_a = centre_option(o.centre_a, "--centre-a");
    const Eigen::Vector3d centre_b = centre_option(o.centre_b, "--centre-b");
    std::optional<double> png_time;
    if (!o.png_time.empty()) {
        png_time = parse_finite_number(o.png_time, "--png-time");
        if (!(*png_time >= 0.0 && *png_time <= 1.0))
            throw PCCD::Invalid_input("--png-time " + o.png_time + ": the time must be in [0, 1]");
    }
    std::optional<std::vector<Motion_case>> cases;
    PCCD::Rigid_transform_3<double> from_a, to_a, from_b, to_b;
    if (!o.cases.empty())
        cases = read_motion_cases(o.cases, o.orthonormalize);
    else {
        from_a = option_transform(o.from_a, "--from-a", o.orthonormalize);
        to_a = option_transform(o.to_a, "--to-a", o.orthonormalize);
        from_b = option_transform(o.from_b, "--from-b", o.orthonormalize);
        to_b = option_transform(o.to_b, "--to-b", o.orthonormalize);
    }
    // Point files make geodesic objects; a prepared object file (pccd prepare) is loaded as its kind.
    const Two_clouds clouds = read_two_clouds(o.file_a, o.file_b, o.normalize);
    with_kernels("", clouds.a.kernel_or("geodesic"), clouds.input_b().kernel_or("geodesic"), clouds,
                 [&]<class A, class B>(std::type_identity<A>, std::type_identity<B>) {
                     run_contact_time_with<A, B>(o, options, centre_a, centre_b, png_time, cases, {from_a, to_a, from_b, to_b},
                                                 clouds);
                 });
}

} // namespace

void register_contact_time(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "contact-time", "When two point clouds moving rigidly over t in [0, 1] first come into contact: the time, "
                        "its bracket, the contact point and normal (continuous collision detection)");
    auto o = std::make_shared<Contact_time_cli_options>();
    cmd->add_option("A", o->file_a, "First point file (.ply, .off, .xyz, .pwn; a mesh gives its vertices)")->required();
    cmd->add_option("B", o->file_b, "Second point file (may be the same as A: preprocessed once)")->required();
    const char* pose_help = ": 12 numbers, the 3x4 matrix [R | t] row by row, as --transform-a of pccd distance "
                            "(default: identity)";
    auto* fa = cmd->add_option("--from-a", o->from_a, std::string("Pose of A at t = 0") + pose_help)->expected(1, 12);
    auto* ta = cmd->add_option("--to-a", o->to_a, std::string("Pose of A at t = 1") + pose_help)->expected(1, 12);
    auto* fb = cmd->add_option("--from-b", o->from_b, std::string("Pose of B at t = 0") + pose_help)->expected(1, 12);
    auto* tb = cmd->add_option("--to-b", o->to_b, std::string("Pose of B at t = 1") + pose_help)->expected(1, 12);
    cmd->add_option("--motion", o->motion,
                    "linear (default: a centre moves on a straight line, the rotation turns about it by slerp; "
                    "PCCD::Linear_motion) or screw (the constant screw from the start to the end pose; "
                    "PCCD::Screw_motion); both objects move so");
    cmd->add_option("--centre-a", o->centre_a,
                    "With --motion linear: the point of A (its own frame) that moves on a straight line, x,y,z "
                    "(default: the origin)")
        ->expected(1, 3);
    cmd->add_option("--centre-b", o->centre_b, "The same for B")->expected(1, 3);
    cmd->add_flag("--orthonormalize", o->orthonormalize,
                  "Use the nearest rotation of each pose's 3x3 part instead of refusing one that is off by more than "
                  "1e-5 on R^T R - I; prints how far it moved");
    cmd->add_flag("--normalize", o->normalize,
                  "Centre and scale each object into [-1,1]^3 (bounding box) before preprocessing");
    cmd->add_option("--tolerance", o->tolerance,
                    "Surfaces closer than this are in contact (world units, >= 0; default 0: they intersect)");
    cmd->add_option("--time-accuracy", o->time_accuracy,
                    "Narrow the contact's bracket until no point moves farther than this within it (world units, "
                    "> 0; default: the library's, a fraction of the smaller sampling radius)");
    cmd->add_option("--near-step", o->near_step,
                    "Sub-step of the contact checks near contact, in sampling radii (in (0, 4], default 0.5)");
    cmd->add_option("--max-steps", o->max_steps, "Budget of steps; then the answer is undecided (default 100000)");
    cmd->add_option("--seed", o->seed, "Seed of the contact checks (default 24301 = 0x5eed)");
    add_object_settings(cmd, o->object, false);
    auto* json = cmd->add_flag("--json", o->json,
                               "Print one JSON object, the result's fields named as in C++ (NaN: null)");
    auto* png = cmd->add_option("--png", o->png,
                                "Draw the objects at the contact time (A blue, B gold), their paths and the contact "
                                "point (red) into this PNG file");
    cmd->add_option("--png-time", o->png_time, "With --png: draw at this time in [0, 1] instead")->needs(png);
    cmd->add_option("--cases", o->cases,
                    "CSV of motions, 48 numbers a row (A at t = 0, A at t = 1, B at t = 0, B at t = 1; 3x4 "
                    "row-major each); prints case,status,t,t_low,t_high,query_us")
        ->excludes(fa)
        ->excludes(ta)
        ->excludes(fb)
        ->excludes(tb)
        ->excludes(json)
        ->excludes(png);
    cmd->callback([o] { run_contact_time(*o); });
}

} // namespace pccd_tool
