// pccd collide A B [--transform-a 12 numbers] [--transform-b 12 numbers] [--orthonormalize] [--normalize]
//   [--method isearch|rst] [--mode first|all] [--seed S] [--out points.ply] [--json] [--cases FILE]:
// whether two point clouds, each posed by a rigid transform, intersect (do_intersect, --mode first)
// or where (intersection_points, --mode all), with the query's counters and wall time
// (doc/algorithms.md, "Randomized sampling" and "Interpolation search"); --png draws the query.
// Each object is preprocessed once; with --cases every row of a
// CSV file of pose pairs is answered with the same preprocessed objects.
#include "commands.h"
#include "intersection_support.h"
#include "pose_cases.h"
#include "render_objects.h"
#include "transform_options.h"

#include <PCCD/IO/write_points.h>
#include <PCCD/Rigid_transform_3.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace pccd_tool {
namespace {

struct Collide_options {
    std::string file_a;
    std::string file_b;
    std::vector<std::string> transform_a;
    std::vector<std::string> transform_b;
    bool normalize = false;
    bool orthonormalize = false;
    std::string method = "isearch";
    std::string mode = "first";
    std::uint64_t seed = PCCD::Intersection_options{}.seed;
    std::string out;
    bool json = false;
    std::string cases;
    std::string hierarchy = "likelihood";
    double budget_us = 0.0;
    Object_settings object;
    std::string png;
    std::string kernel = "auto"; // auto, geodesic or euclidean
    std::string kernel_a, kernel_b; // empty: as --kernel
};

void print_summary(const nlohmann::ordered_json& r)
{
    print_object_line("A", r["a"]);
    if (r["same_object"].get<bool>())
        std::printf("B: the same object as A\n");
    else
        print_object_line("B", r["b"]);
    std::printf("method %s, mode %s, seed %llu%s\n", r["method"].get<std::string>().c_str(),
                r["mode"].get<std::string>().c_str(), static_cast<unsigned long long>(r["seed"].get<std::uint64_t>()),
                r["normalize"].get<bool>() ? ", normalized into [-1,1]^3" : "");
    if (r["intersects"].get<bool>())
        std::printf("answer: intersecting, %zu point%s\n", r["points"].get<std::size_t>(),
                    r["points"].get<std::size_t>() == 1 ? "" : "s");
    else
        std::printf("answer: no intersection (%s)\n", r["status"].get<std::string>().c_str());
    std::printf("query: %.1f us, %zu f evaluations\n", r["query_us"].get<double>(), r["f_evaluations"].get<std::size_t>());
    std::printf("counters:");
    for (std::size_t i = 1; i < counter_names().size(); ++i)
        std::printf(" %s %zu", counter_names()[i].c_str(), r[counter_names()[i]].get<std::size_t>());
    std::printf("\n");
    if (r.contains("first_point")) std::printf("first point: %s\n", r["first_point"].dump().c_str());
}

/// The query (or the cases) on the points of A and B, preprocessed into an `A` and a `B` (once when
/// both name the same file with the same kernel), and its output.
template <class A, class B>
void run_collide_with(const Collide_options& o, const PCCD::Intersection_options& query_options,
                      const Query_poses& poses, const Two_clouds& clouds)
{
    const bool first_hit = o.mode == "first";
    const auto& [cases, pose_a, pose_b] = poses;
    const Prepared_pair<A, B> objects = prepare_pair<A, B>(clouds, o.object);
    const Prepared_object<A>& a = objects.a;
    const Prepared_object<B>& b = objects.b;
    const bool same = objects.shared;
    const double preprocess_ms = objects.preprocess_ms();

    if (cases) {
        std::printf("case,intersects,f_evaluations,query_us,points\n");
        for (std::size_t i = 0; i < cases->size(); ++i) {
            const Pose_case& c = (*cases)[i];
            const Timed_result t =
                run_timed_query(a.object, c.pose_a, b.object, c.pose_b, query_options, o.method, first_hit);
            std::printf("%zu,%d,%zu,%.1f,%zu\n", i + 1, t.result.intersects ? 1 : 0, t.result.counters.f_evaluations,
                        t.query_us, t.result.points.size());
        }
        std::fflush(stdout);
        std::fprintf(stderr, "pccd collide: %zu cases, %s, mode %s; preprocessing took %.1f ms\n", cases->size(),
                     o.method.c_str(), o.mode.c_str(), preprocess_ms);
        return;
    }

    const Timed_result t = run_timed_query(a.object, pose_a, b.object, pose_b, query_options, o.method, first_hit);
    nlohmann::ordered_json r;
    r["a"] = object_json(o.file_a, a);
    r["b"] = object_json(o.file_b, b);
    r["same_object"] = same;
    r["normalize"] = o.normalize;
    r["method"] = o.method;
    r["mode"] = o.mode;
    r["seed"] = o.seed;
    r["intersects"] = t.result.intersects;
    r["status"] = PCCD::to_string(t.result.status);
    r["points"] = t.result.points.size();
    add_counters(r, t.result.counters);
    r["closest_estimate"] = t.result.closest_estimate; // inf: null
    r["query_us"] = t.query_us;
    r["preprocess_ms"] = preprocess_ms;
    if (!t.result.points.empty()) {
        const Eigen::Vector3d& p = t.result.points.front().position;
        r["first_point"] = {p.x(), p.y(), p.z()};
    }
    r["out"] = nullptr;
    if (!o.out.empty()) {
        if (t.result.points.empty()) {
            std::fprintf(stderr, "pccd collide: no intersection points; %s not written\n", o.out.c_str());
        } else {
            PCCD::Point_data data;
            for (const PCCD::Intersection_point& p : t.result.points) data.points.push_back(p.position);
            PCCD::IO::write_points(o.out, data);
            r["out"] = o.out;
        }
    }
    r["png"] = nullptr;
    if (!o.png.empty()) {
        pccd_render::Scene scene;
        scene.clouds.push_back(cloud_layer(a.object, pose_a, pccd_render::colour_a));
        scene.clouds.push_back(cloud_layer(b.object, pose_b, pccd_render::colour_b));
        scene.markers.push_back(curve_layer(t.result.points, 0.5 * scene.clouds.front().splat_radius));
        render_to_png(scene, std::nullopt, 800, 600, o.png);
        r["png"] = std::filesystem::absolute(o.png).string();
    }
    if (o.json)
        std::cout << r.dump(2) << '\n';
    else {
        print_summary(r);
        if (!r["out"].is_null()) std::printf("wrote %zu points to %s\n", t.result.points.size(), o.out.c_str());
        if (!r["png"].is_null())
            std::printf("wrote %s: A blue, B gold, %zu intersection point%s red\n", r["png"].get<std::string>().c_str(),
                        t.result.points.size(), t.result.points.size() == 1 ? "" : "s");
    }
}

void run_collide(const Collide_options& o)
{
    const PCCD::Intersection_options query_options = pccd_tool::query_options(o.seed, o.hierarchy, o.budget_us);
    // Everything is read and checked before the (slow) preprocessing.
    const Query_poses poses = read_query_poses(o.cases, o.transform_a, o.transform_b, o.orthonormalize);
    const Two_clouds clouds = read_two_clouds(o.file_a, o.file_b, o.normalize);
    with_kernels(o.kernel, o.kernel_a, o.kernel_b, clouds, [&]<class A, class B>(std::type_identity<A>, std::type_identity<B>) {
        run_collide_with<A, B>(o, query_options, poses, clouds);
    });
}

} // namespace

void register_collide(CLI::App& app)
{
    auto* cmd = app.add_subcommand(
        "collide", "Whether (and where) two point clouds intersect, each posed by a rigid transform");
    auto o = std::make_shared<Collide_options>();
    cmd->add_option("A", o->file_a, "First point file (.ply, .off, .xyz, .pwn; a mesh gives its vertices)")->required();
    cmd->add_option("B", o->file_b, "Second point file (may be the same as A: preprocessed once)")->required();
    auto* ta = cmd->add_option("--transform-a", o->transform_a,
                               "Pose of A: 12 numbers, the 3x4 matrix [R | t] row by row (default: identity)")
                   ->expected(1, 12);
    auto* tb = cmd->add_option("--transform-b", o->transform_b, "Pose of B, as --transform-a")->expected(1, 12);
    cmd->add_flag("--orthonormalize", o->orthonormalize,
                  "Use the nearest rotation of each --transform's 3x3 part (polar factor) instead of refusing one "
                  "that is off by more than 1e-5 on R^T R - I; prints how far it moved");
    cmd->add_flag("--normalize", o->normalize,
                  "Centre and scale each object into [-1,1]^3 (bounding box) before preprocessing");
    cmd->add_option("--method", o->method, "Leaf intersector: isearch (interpolation search, default) or rst")
        ->check(CLI::IsMember(method_names()));
    cmd->add_option("--mode", o->mode, "first: stop at the first intersection (do_intersect, default); "
                                       "all: points on the intersection curves (intersection_points)")
        ->check(CLI::IsMember({"first", "all"}));
    cmd->add_option("--seed", o->seed, "Seed of the query (default 24301 = 0x5eed)");
    cmd->add_option("--hierarchy", o->hierarchy,
                    "How the hierarchies are walked: likelihood (default), depth-first, or flat (the published "
                    "method, for comparison)")
        ->check(CLI::IsMember(traversal_names()));
    cmd->add_option("--budget-us", o->budget_us,
                    "Time budget per query in microseconds (time-critical: status undecided when it runs out "
                    "first; default 0: none)")
        ->check(CLI::NonNegativeNumber);
    add_object_settings(cmd, o->object, true);
    cmd->add_option("--kernel", o->kernel, kernel_option_help())->check(CLI::IsMember(kernel_names()));
    add_object_kernels(cmd, o->kernel_a, o->kernel_b);
    auto* out = cmd->add_option("--out", o->out, "Write the intersection points to this file (.ply, .off, .xyz)");
    auto* json = cmd->add_flag("--json", o->json, "Print one JSON object instead of text");
    auto* png = cmd->add_option("--png", o->png,
                                "Draw the posed objects (A blue, B gold) and the points found (red) into this PNG file");
    cmd->add_option("--cases", o->cases,
                    "CSV of pose pairs, 24 numbers a row (T_A then T_B, 3x4 row-major); prints "
                    "case,intersects,f_evaluations,query_us,points")
        ->excludes(ta)
        ->excludes(tb)
        ->excludes(out)
        ->excludes(json)
        ->excludes(png);
    cmd->callback([o] { run_collide(*o); });
}

} // namespace pccd_tool
