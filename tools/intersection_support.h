// tools/intersection_support.h -- what `pccd collide`, `pccd distance` and `pccd bench` share:
// reading an object from a file (optionally normalized into [-1, 1]^3, doc/manual/sampling.md) and
// preprocessing it, or loading it from a prepared object file (`pccd prepare`, cli_collide.md,
// "Prepared objects"), choosing the leaf intersector by name (doc/manual/intersection.md, the leaf
// intersector policies), running one timed query, and the query's counters as JSON and CSV. It
// implements the command line of doc/manual/cli_collide.md.
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/object_file_info.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sharp_feature_options.h>

#include <PCCD/testing/timing.h>

#include "progress.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace pccd_tool {

using PCCD::testing::Clock;
using PCCD::testing::ms_since;
using PCCD::testing::us_since;

/// The methods of the --method option: the two leaf intersector policies, by their name().
/// The names of --hierarchy (Intersection_options::traversal).
inline const std::vector<std::string>& traversal_names()
{
    static const std::vector<std::string> names{"flat", "depth-first", "likelihood"};
    return names;
}

/// The traversal named `name` (one of traversal_names()).
inline PCCD::Traversal traversal_from_name(const std::string& name)
{
    if (name == "flat") return PCCD::Traversal::flat;
    if (name == "depth-first") return PCCD::Traversal::depth_first;
    if (name == "likelihood") return PCCD::Traversal::likelihood;
    throw PCCD::Invalid_input("--hierarchy must be flat, depth-first or likelihood, not \"" + name + "\"");
}

/// Query options from the command line's --seed, --hierarchy and --budget-us (0: no time limit).
inline PCCD::Intersection_options query_options(std::uint64_t seed, const std::string& hierarchy, double budget_us)
{
    PCCD::Intersection_options options{.seed = seed, .traversal = traversal_from_name(hierarchy)};
    if (budget_us != 0.0) options.max_time_us = budget_us;
    return options;
}

/// The names of --volume (Point_cloud_hierarchy_options::volume).
inline const std::vector<std::string>& volume_names()
{
    static const std::vector<std::string> names{"box_and_slab", "box", "sphere"};
    return names;
}

/// The bounding volume named `name` (one of volume_names()).
inline PCCD::Bounding_volume volume_from_name(const std::string& name)
{
    if (const auto v = PCCD::bounding_volume_from_string(name)) return *v;
    throw PCCD::Invalid_input("--volume must be box_and_slab, box or sphere, not \"" + name + "\"");
}

inline const std::vector<std::string>& method_names()
{
    static const std::vector<std::string> names{PCCD::Interpolation_search::name(), PCCD::Randomized_sampling::name()};
    return names;
}

/// Whether the paths `a` and `b` name the same file (then it is read and preprocessed once).
inline bool same_file(const std::string& a, const std::string& b)
{
    std::error_code error;
    return a == b || std::filesystem::equivalent(a, b, error);
}

/// Points (and normals, when given) ready for preprocessing.
using Object_points = PCCD::Point_data;

/// Centres and scales `points` into [-1, 1]^3 in place (normals keep their direction: the
/// similarity has no rotation and a positive scale).
inline void normalize_points(std::vector<Eigen::Vector3d>& points)
{
    const PCCD::Similarity_3 similarity = PCCD::compute_unit_cube_normalization(points);
    for (Eigen::Vector3d& p : points) p = similarity.transform_point(p);
}

/// The points of a PLY, OFF or XYZ file (an OFF or PLY mesh gives its vertices), normalized into
/// [-1, 1]^3 when asked.
inline Object_points read_object_points(const std::string& path, bool normalize)
{
    PCCD::Point_data data = PCCD::IO::read_points(path);
    if (normalize) normalize_points(data.points);
    return {std::move(data.points), std::move(data.normals)};
}

/// A preprocessed object (Point_cloud_object, or the lean Euclidean_point_cloud_object) and the wall
/// time its preprocessing took, or its loading when it came from a prepared object file (`loaded`).
template <class Object = PCCD::Point_cloud_object<>>
struct Prepared_object {
    Object object;
    double preprocess_ms;
    bool loaded = false;
};

/// The name of an object's kernel in the outputs: "geodesic" or "euclidean".
template <class Object>
constexpr const char* kernel_name()
{
    return PCCD::GeodesicCollisionObject<Object> ? "geodesic" : "euclidean";
}

/// A prepared object as the JSON outputs report it: file, points, kernel, surface fit, the
/// hierarchy's leaf size, sampling radius, preprocessing time.
template <class Object>
nlohmann::ordered_json object_json(const std::string& file, const Prepared_object<Object>& prepared)
{
    return {{"file", file},
            {"points", prepared.object.size()},
            {"kernel", kernel_name<Object>()},
            {"surface_fit", PCCD::to_string(prepared.object.surface().fit())},
            {"leaf_size", prepared.object.hierarchy().leaf_size()},
            {"sampling_radius", prepared.object.sampling_radius()},
            {"preprocess_ms", prepared.preprocess_ms},
            {"prepared_file", prepared.loaded}};
}

/// One object's line of the commands' text summaries, from its object_json(): "A: file, N points,
/// K kernel, r(P) x, preprocessed in T ms" (or "loaded from a prepared object file in T ms").
inline void print_object_line(const char* name, const nlohmann::ordered_json& o)
{
    std::printf("%s: %s, %zu points, %s kernel, r(P) %.5g, %s in %.1f ms\n", name, o["file"].get<std::string>().c_str(),
                o["points"].get<std::size_t>(), o["kernel"].get<std::string>().c_str(),
                o["sampling_radius"].get<double>(),
                o["prepared_file"].get<bool>() ? "loaded from a prepared object file" : "preprocessed",
                o["preprocess_ms"].get<double>());
}

/// `--kernel`: which object the points make. auto: the lean object (Euclidean kernel) when the
/// cloud that decides (the object's own; `pccd world`: the largest file) has at least
/// `lean_from_points` points, the geodesic one otherwise.
inline constexpr std::size_t lean_from_points = 1000000;
inline bool use_lean_kernel(const std::string& kernel, std::size_t points)
{
    if (kernel == "euclidean") return true;
    if (kernel == "geodesic") return false;
    return points >= lean_from_points;
}

/// One object argument of a command: the points of a point file, or a prepared object file
/// (`pccd prepare`, or an object's save() in C++ or Python), which is loaded instead of preprocessed
/// and whose kind fixes the object's kernel.
struct Object_input {
    std::string file;
    PCCD::Object_file_kind prepared = PCCD::Object_file_kind::none;
    std::uint64_t prepared_points = 0;
    Object_points points; // empty for a prepared object file

    bool is_prepared() const { return prepared != PCCD::Object_file_kind::none; }
    /// A prepared file's kernel ("geodesic" or "euclidean"), else `kernel` (the commands without a
    /// --kernel option: "geodesic").
    std::string kernel_or(const std::string& kernel) const { return is_prepared() ? PCCD::to_string(prepared) : kernel; }
    /// The number of points (a prepared file's, from its opening).
    std::size_t size() const { return is_prepared() ? std::size_t(prepared_points) : points.points.size(); }
};

/// What PCCD::object_file_info() tells of the command argument `path`; kind none, without opening
/// it, when it is not a regular file (missing or a directory: the point readers then say so).
inline PCCD::Object_file_info prepared_file_info(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return {};
    return PCCD::object_file_info(path);
}

/// Reads the object argument `path`: a prepared object file is only recognized here (by its
/// magic), a point file is read (and normalized into [-1, 1]^3 when asked).
/// \throws PCCD::Invalid_input when asked to normalize a prepared object file (its points are fixed:
///         prepare it with --normalize); PCCD::File_error as PCCD::IO::read_points.
inline Object_input read_object_input(const std::string& path, bool normalize)
{
    const PCCD::Object_file_info info = prepared_file_info(path);
    if (info.kind != PCCD::Object_file_kind::none) {
        if (normalize)
            throw PCCD::Invalid_input(path + ": a prepared object file cannot be normalized (--normalize): its points "
                                             "are fixed; prepare it from its point file with --normalize");
        return {path, info.kind, info.points, {}};
    }
    return {path, PCCD::Object_file_kind::none, 0, read_object_points(path, normalize)};
}

/// The two object files of a query command, each read once: `b` is empty when both name the same
/// file (`same`), which the command then preprocesses (or loads) once.
struct Two_clouds {
    bool same = false;
    Object_input a;
    std::optional<Object_input> b;

    const Object_input& input_b() const { return b ? *b : a; }
};

inline Two_clouds read_two_clouds(const std::string& file_a, const std::string& file_b, bool normalize)
{
    Two_clouds clouds;
    clouds.same = same_file(file_a, file_b);
    clouds.a = read_object_input(file_a, normalize);
    if (!clouds.same) clouds.b = read_object_input(file_b, normalize);
    return clouds;
}

/// Calls `run` with a tag of the object type `kernel` chooses for a cloud of `points` points (for
/// `auto`, the number that decides): `run(std::type_identity<PCCD::Euclidean_point_cloud_object<>>{})`
/// or the same with `PCCD::Point_cloud_object<>`.
template <class Run>
void with_kernel(const std::string& kernel, std::size_t points, Run&& run)
{
    if (use_lean_kernel(kernel, points))
        run(std::type_identity<PCCD::Euclidean_point_cloud_object<>>{});
    else
        run(std::type_identity<PCCD::Point_cloud_object<>>{});
}

/// The kernel of a prepared object file of kind `prepared` (none: a point file, `kernel` decides),
/// checked against the kernel asked for it (`kernel`: auto agrees with either).
/// \throws PCCD::Invalid_input, naming `file`, when `kernel` names the other kind.
inline std::string kernel_of_input(const std::string& kernel, PCCD::Object_file_kind prepared, const std::string& file)
{
    if (prepared == PCCD::Object_file_kind::none) return kernel;
    const std::string kind = PCCD::to_string(prepared);
    if (kernel != "auto" && kernel != kind)
        throw PCCD::Invalid_input(file + ": a prepared object file of the " + kind + " kernel, asked for as " + kernel +
                                  ": prepare it again with --kernel " + kernel + ", or leave the kernel to the file");
    return kind;
}

/// The two objects' kernels: a prepared object file's own (an explicit other kernel is refused,
/// kernel_of_input), else each object's own option (`kernel_a`, `kernel_b`; empty: not given)
/// or else `kernel`, with `auto` decided by that object's own number of points, so that a small
/// part beside a large scan keeps the geodesic kernel, which rounds its edges less
/// (doc/benchmarks.md, "From the command line"). Calls `run(std::type_identity<A>{},
/// std::type_identity<B>{})` with the two object types.
template <class Run>
void with_kernels(const std::string& kernel, const std::string& kernel_a, const std::string& kernel_b,
                  const Two_clouds& clouds, Run&& run)
{
    const Object_input& a = clouds.a;
    const Object_input& b = clouds.input_b();
    const std::string chosen_a = kernel_of_input(kernel_a.empty() ? kernel : kernel_a, a.prepared, a.file);
    const std::string chosen_b = kernel_of_input(kernel_b.empty() ? kernel : kernel_b, b.prepared, b.file);
    with_kernel(chosen_a, a.size(), [&]<class A>(std::type_identity<A> tag_a) {
        with_kernel(chosen_b, b.size(), [&]<class B>(std::type_identity<B> tag_b) { run(tag_a, tag_b); });
    });
}

/// The names `--kernel` and the per-object kernel options accept.
inline const std::vector<std::string>& kernel_names()
{
    static const std::vector<std::string> names{"auto", "geodesic", "euclidean"};
    return names;
}

/// The help text of `--kernel`, one for every command that takes it.
inline const char* kernel_option_help()
{
    return "The objects' surface kernel: geodesic (Point_cloud_object), euclidean (the lean "
           "Euclidean_point_cloud_object, about a fifth of the memory) or auto (default: euclidean for an "
           "object of 10^6 points or more, each object by its own size)";
}

/// Adds --kernel-a and --kernel-b (each object's kernel, overriding --kernel for it) to a command.
inline void add_object_kernels(CLI::App* cmd, std::string& kernel_a, std::string& kernel_b)
{
    cmd->add_option("--kernel-a", kernel_a,
                    "A's kernel alone, overriding --kernel for it: auto, geodesic or euclidean (e.g. geodesic for a "
                    "part with sharp edges beside a lean scan)")
        ->check(CLI::IsMember(kernel_names()));
    cmd->add_option("--kernel-b", kernel_b, "B's kernel alone, as --kernel-a")->check(CLI::IsMember(kernel_names()));
}

/// A vector as a JSON array of three numbers; null when an entry is NaN or infinite (an answer
/// that has no such point or direction).
inline nlohmann::ordered_json vector_json(const Eigen::Vector3d& v)
{
    if (!v.allFinite()) return nullptr;
    return {v.x(), v.y(), v.z()};
}

/// What the query commands let the user choose of the objects' preprocessing
/// (doc/manual/cli_collide.md, "Preprocessing options"): the hierarchy's bounding volume
/// (`--volume`, on the commands that take it) and leaf size (`--leaf-size`), and the surface
/// (`--surface default|sharp`: the library's defaults or PCCD::sharp_feature_options()).
struct Object_settings {
    /// A name of volume_names(), or empty: the library's default (box_and_slab), and a prepared
    /// object file's own.
    std::string volume;
    /// A whole number >= 1, or "auto".
    std::string leaf_size = "auto";
    std::string surface = "default";
};

/// `--leaf-size auto` keeps the library's leaf size (8) below this many points of an object and
/// uses auto_large_leaf_size from here: with leaves of 8, median splits of 10^7 points leave 4.8
/// points per leaf; leaves of 10 leave 9.5 and answer first-hit queries 8 % faster
/// (doc/benchmarks.md, "The leaf size").
inline constexpr std::size_t auto_large_leaf_from_points = 1000000;
inline constexpr std::size_t auto_large_leaf_size = 10;

/// What --leaf-size accepts besides "auto": a whole number >= 1 of at most 9 digits, or nullopt.
inline std::optional<std::size_t> parse_leaf_size(const std::string& text)
{
    const bool digits = !text.empty() && text.size() <= 9 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const std::size_t value = digits ? std::stoul(text) : 0;
    return value >= 1 ? std::optional<std::size_t>(value) : std::nullopt;
}

/// The leaf size `settings` choose for an object of `points` points.
/// \throws PCCD::Invalid_input when --leaf-size is neither "auto" nor a whole number >= 1.
inline std::size_t leaf_size_for(const Object_settings& settings, std::size_t points)
{
    if (settings.leaf_size == "auto")
        return points >= auto_large_leaf_from_points ? auto_large_leaf_size
                                                     : PCCD::Point_cloud_hierarchy_options{}.leaf_size;
    if (const auto value = parse_leaf_size(settings.leaf_size)) return *value;
    throw PCCD::Invalid_input("--leaf-size must be auto or a whole number >= 1, not \"" + settings.leaf_size + "\"");
}

/// The preprocessing options `settings` choose for an object of `points` points.
/// \throws PCCD::Invalid_input on a bad --volume, --leaf-size or --surface.
inline PCCD::Point_cloud_object_options object_options(const Object_settings& settings, std::size_t points)
{
    PCCD::Point_cloud_object_options options;
    if (settings.surface == "sharp")
        options = PCCD::sharp_feature_options(options);
    else if (settings.surface != "default")
        throw PCCD::Invalid_input("--surface must be default or sharp, not \"" + settings.surface + "\"");
    if (!settings.volume.empty()) options.hierarchy.volume = volume_from_name(settings.volume);
    options.hierarchy.leaf_size = leaf_size_for(settings, points);
    return options;
}

/// Adds --leaf-size and --surface (and --volume when `with_volume`) to a command.
inline void add_object_settings(CLI::App* cmd, Object_settings& settings, bool with_volume)
{
    if (with_volume)
        cmd->add_option("--volume", settings.volume,
                        "Bounding volume of the hierarchies' node tests: box_and_slab (default; a prepared object "
                        "file's own), box or sphere")
            ->check(CLI::IsMember(volume_names()));
    cmd->add_option("--leaf-size", settings.leaf_size,
                    "Largest number of points in a hierarchy leaf: a whole number >= 1, or auto (default: 8, and 10 "
                    "for an object of 10^6 points or more; a prepared object file's own)")
        ->check(CLI::Validator(
            [](std::string& text) {
                return text == "auto" || parse_leaf_size(text)
                           ? std::string()
                           : "must be auto or a whole number >= 1, not \"" + text + "\"";
            },
            "auto|N"));
    cmd->add_option("--surface", settings.surface,
                    "The implicit surface: default (the sphere fit) or sharp (the sharp-feature options for CAD parts: "
                    "IMLS fit, theta_eps 3e-5, robust normal refit)")
        ->check(CLI::IsMember({"default", "sharp"}));
}

/// Preprocesses the points with the options `settings` choose (Point_cloud_object's defaults
/// unless told otherwise); normals, when present, are hints that orient the object's normals (as
/// `pccd eval` does).
/// `input` given as an rvalue is handed to the object, which may free it early (the lean object
/// frees the points once it holds its copy: `pccd prepare`).
/// \throws PCCD::Invalid_input, naming `name`, when no point has a normal: the points are too few
///         or too degenerate (e.g. all on one line) to make a surface, and every query would answer
///         "separate" without looking; and as object_options() on bad settings.
template <class Object = PCCD::Point_cloud_object<>, class Points>
    requires std::same_as<std::remove_cvref_t<Points>, Object_points>
Prepared_object<Object> prepare_object(Points&& input, const std::string& name, const Object_settings& settings = {})
{
    const Clock::time_point start = Clock::now();
    const std::size_t points = input.points.size();
    Object object(std::forward<Points>(input), with_progress(object_options(settings, points), name));
    if (object.orientation().unoriented == object.size())
        throw PCCD::Invalid_input(name + ": no point has a surface normal: its " + std::to_string(object.size()) +
                                  " points are too few or too degenerate (e.g. all on one line) to make a surface");
    return {std::move(object), ms_since(start)};
}

/// Loads the prepared object file `input.file` as an `Object` (its kind, kernel_of_input()). Its
/// hierarchy is the one it stores unless --leaf-size or --volume asks for another (then built with
/// those, leaf_size_for() the file's number of points); its surface is the one it was prepared
/// with.
/// \throws PCCD::Invalid_input when --surface sharp is asked of a file prepared with another fit;
///         PCCD::File_error as the object's load().
template <class Object>
Prepared_object<Object> load_prepared_object(const Object_input& input, const Object_settings& settings)
{
    const Clock::time_point start = Clock::now();
    const bool stored_hierarchy = settings.leaf_size == "auto" && settings.volume.empty();
    Object object = stored_hierarchy ? Object::load(input.file)
                                     : Object::load(input.file, object_options(settings, input.size()).hierarchy);
    const double ms = ms_since(start);
    if (settings.surface == "sharp" && object.surface().fit() != PCCD::sharp_feature_options().surface_fit)
        throw PCCD::Invalid_input(input.file + ": --surface sharp asked of a prepared object file whose surface fit is " +
                                  PCCD::to_string(object.surface().fit()) +
                                  ": a prepared file keeps its surface; prepare it with --surface sharp");
    return {std::move(object), ms, true};
}

/// An object from a command's argument: loaded when it is a prepared object file, preprocessed
/// from its points otherwise (prepare_object()).
template <class Object>
Prepared_object<Object> make_object(const Object_input& input, const Object_settings& settings)
{
    if (input.is_prepared()) return load_prepared_object<Object>(input, settings);
    return prepare_object<Object>(input.points, input.file, settings);
}

/// Two objects preprocessed for a query: `shared` when both name the same file and take the same
/// kernel, which is then preprocessed once (b a copy of a, sharing its data).
template <class A, class B>
struct Prepared_pair {
    Prepared_object<A> a;
    Prepared_object<B> b;
    bool shared = false;

    /// The preprocessing time of the objects built (once when shared).
    double preprocess_ms() const { return a.preprocess_ms + (shared ? 0.0 : b.preprocess_ms); }
};

/// Preprocesses (or loads, make_object()) the two objects into an A and a B (see Prepared_pair);
/// the same file under two kernels is preprocessed twice.
template <class A, class B>
Prepared_pair<A, B> prepare_pair(const Two_clouds& clouds, const Object_settings& settings)
{
    Prepared_object<A> a = make_object<A>(clouds.a, settings);
    if constexpr (std::is_same_v<A, B>) {
        if (clouds.same) {
            Prepared_object<B> b = a;
            return {std::move(a), std::move(b), true};
        }
    }
    Prepared_object<B> b = make_object<B>(clouds.input_b(), settings);
    return {std::move(a), std::move(b), false};
}

/// The answer of one query and its wall time (steady_clock, microseconds).
struct Timed_result {
    PCCD::Intersection_result result;
    double query_us;
};

/// One query: do_intersect (first_hit) or intersection_points, with the policy named `method`.
template <class A, class B>
Timed_result run_timed_query(const A& a, const PCCD::Rigid_transform_3<double>& pose_a, const B& b,
                             const PCCD::Rigid_transform_3<double>& pose_b, const PCCD::Intersection_options& options,
                             const std::string& method, bool first_hit)
{
    const auto query = [&](const auto& policy) {
        const Clock::time_point start = Clock::now();
        PCCD::Intersection_result result = first_hit ? PCCD::do_intersect(a, pose_a, b, pose_b, options, policy)
                                                     : PCCD::intersection_points(a, pose_a, b, pose_b, options, policy);
        const double us = us_since(start);
        return Timed_result{std::move(result), us};
    };
    if (method == PCCD::Randomized_sampling::name()) return query(PCCD::Randomized_sampling{});
    if (method == PCCD::Interpolation_search::name()) return query(PCCD::Interpolation_search{});
    throw PCCD::Invalid_input("unknown method \"" + method + "\" (expected isearch or rst)");
}

/// The names of the counters, in the order of PCCD::for_each_counter (the library's one list).
inline const std::vector<std::string>& counter_names()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        PCCD::for_each_counter(PCCD::Intersection_counters{}, [&](const char* name, std::size_t) { out.emplace_back(name); });
        return out;
    }();
    return names;
}

/// The counters' values, in the order of counter_names().
inline std::vector<std::size_t> counter_values(const PCCD::Intersection_counters& c)
{
    std::vector<std::size_t> values;
    PCCD::for_each_counter(c, [&](const char*, std::size_t value) { values.push_back(value); });
    return values;
}

/// Adds every counter to `out` under its name.
template <class Json>
void add_counters(Json& out, const PCCD::Intersection_counters& counters)
{
    PCCD::for_each_counter(counters, [&](const char* name, std::size_t value) { out[name] = value; });
}

} // namespace pccd_tool
