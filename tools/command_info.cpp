// pccd info FILE [--json]: what a point file holds and the figures of its cloud (points, bounding
// box, mean spacing, and the preprocessed object with the library's defaults: graph, CPSP map,
// bandwidth, normals and the time of each stage). Later stages add their figures to the same JSON
// object. Given a prepared object file (pccd prepare, an object's save()), its kind and format
// version and the loaded object's figures instead.
#include "commands.h"
#include "progress.h"

#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Hierarchy/Sphere_covering.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/object_file_info.h>
#include <PCCD/Proximity_graph/graph_components.h>

#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace pccd_tool {
namespace {

using PCCD::testing::Clock;
using PCCD::testing::ms_since;

nlohmann::json vector_json(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

double median_of(const Eigen::VectorXd& v) { return PCCD::testing::upper_median({v.data(), v.data() + v.size()}); }

/// A prepared object file: its kind and format version, and the loaded object's figures.
template <class Object>
nlohmann::json describe_prepared(const std::string& path, const PCCD::Object_file_info& file)
{
    nlohmann::json out;
    out["file"] = path;
    out["prepared"] = {{"kernel", PCCD::to_string(file.kind)},
                       {"format_version", file.version},
                       {"bytes", std::filesystem::file_size(path)}};
    const auto start = Clock::now();
    const Object object = Object::load(path);
    out["timings_ms"]["load"] = ms_since(start);
    out["points"] = object.size();
    const PCCD::Point_cloud<>& cloud = object.cloud();
    out["bbox"] = {{"min", vector_json(cloud.bbox().min())}, {"max", vector_json(cloud.bbox().max())}};
    out["mean_spacing"] = cloud.mean_spacing();
    out["sampling_radius"] = object.sampling_radius();
    out["bandwidth"] = object.bandwidth();
    out["theta_eps"] = object.weight().threshold();
    out["surface_fit"] = PCCD::to_string(object.surface().fit());
    out["noise"] = {{"sigma", object.noise_estimate()}};
    out["outliers"] = {{"count", object.scan().outliers.size()}, {"input_points", object.scan().input_points}};
    const PCCD::Point_cloud_hierarchy& h = object.hierarchy();
    out["hierarchy"] = {{"depth", h.height()},
                        {"nodes", h.nodes().size()},
                        {"leaf_size", h.leaf_size()},
                        {"volume", PCCD::to_string(h.volume())}};
    return out;
}

nlohmann::json describe_file(const std::string& path)
{
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error)) {
        const PCCD::Object_file_info file = PCCD::object_file_info(path);
        if (file.kind == PCCD::Object_file_kind::geodesic)
            return describe_prepared<PCCD::Point_cloud_object<>>(path, file);
        if (file.kind == PCCD::Object_file_kind::euclidean)
            return describe_prepared<PCCD::Euclidean_point_cloud_object<>>(path, file);
    }
    nlohmann::json out;
    out["file"] = path;
    auto start = Clock::now();
    const PCCD::Point_data data = PCCD::IO::read_points(path);
    out["timings_ms"]["read"] = ms_since(start);
    out["points"] = data.points.size();
    out["normals"] = {{"from_file", data.has_normals()}};
    if (data.points.size() < 2) {
        start = Clock::now();
        const PCCD::Point_cloud<> cloud(data.points);
        out["timings_ms"]["kd_tree"] = ms_since(start);
        out["bbox"] = {{"min", vector_json(cloud.bbox().min())}, {"max", vector_json(cloud.bbox().max())}};
        out["mean_spacing"] = nullptr; // undefined for a single point
        return out;
    }
    // The object exactly as collide and eval preprocess it (library defaults: r-SIG, CPSP map bounded
    // at the kernel's support radius, default bandwidth), the file's normals, if any, as hints that
    // orient the surface's normals where they are not zero.
    const PCCD::Point_cloud_object_options options;
    const PCCD::Point_cloud_object<> object(data, with_progress(options, path)); // progress on a terminal
    const PCCD::Point_cloud<>& cloud = object.cloud();
    const PCCD::Preprocessing_times& t = object.timings();
    out["timings_ms"]["kd_tree"] = t.kd_tree;
    out["bbox"] = {{"min", vector_json(cloud.bbox().min())}, {"max", vector_json(cloud.bbox().max())}};
    start = Clock::now();
    const double mean_spacing = cloud.mean_spacing();
    out["mean_spacing"] = mean_spacing;
    out["timings_ms"]["mean_spacing"] = ms_since(start);
    out["timings_ms"]["sampling_radius"] = t.sampling_radius;
    out["sampling_radius"] = object.sampling_radius();
    out["timings_ms"]["graph"] = t.graph;
    const PCCD::Proximity_graph& graph = object.graph();
    out["graph"] = {{"kind", PCCD::to_string(graph.kind(), graph.parameter())},
                    {"r", graph.parameter()},
                    {"edges", graph.num_edges()},
                    {"virtual_edges", graph.num_virtual_edges()},
                    {"components", PCCD::graph_components(graph).count}};
    out["timings_ms"]["cpsp"] = t.cpsp;
    out["cpsp"] = {{"entries", object.cpsp().num_entries()}, {"bytes", object.cpsp().memory_bytes()}};
    out["bandwidth"] = object.bandwidth();
    out["eta"] = options.bandwidth.eta;
    out["theta_eps"] = object.theta_eps();
    out["surface_fit"] = PCCD::to_string(object.surface().fit());
    out["timings_ms"]["normals"] = t.normals;
    out["timings_ms"]["hierarchy"] = t.hierarchy;
    const PCCD::Orientation_report& orientation = object.orientation();
    out["normals"]["flipped"] = orientation.flipped;
    out["normals"]["components"] = orientation.components;
    out["normals"]["unoriented"] = orientation.unoriented;
    out["normals"]["hints_used"] = orientation.hints_used;
    out["normals"]["hints_ignored"] = orientation.hints_ignored;
    out["normals"]["unhinted_components"] = orientation.unhinted_components;
    // The cloud as a scan: noise estimate, isolated outliers left out, the surface's domain.
    out["noise"] = {{"sigma", object.noise_estimate()}, {"sigma_in_spacings", object.noise_estimate() / mean_spacing}};
    out["outliers"] = {{"count", object.scan().outliers.size()}, {"input_points", object.scan().input_points}};
    if (object.domain_radii().size() > 0)
        out["domain"] = {{"median_radius", median_of(object.domain_radii())}};
    out["timings_ms"]["outliers_domain"] = t.outliers;
    const PCCD::Point_cloud_hierarchy& h = object.hierarchy();
    std::size_t leaves = 0;
    for (const auto& node : h.nodes()) leaves += node.is_leaf() ? 1 : 0;
    const auto covering_start = Clock::now();
    const PCCD::Sphere_covering covering(h);
    const double covering_ms = ms_since(covering_start);
    // Covering radii of the root and, as a typical figure, the median over the leaves' parents.
    std::vector<double> parent_radii;
    for (PCCD::Point_cloud_hierarchy::Index i = 0; i < h.nodes().size(); ++i)
        if (!h.node(i).is_leaf() && h.node(h.left(i)).is_leaf()) parent_radii.push_back(covering.radius(i));
    std::sort(parent_radii.begin(), parent_radii.end());
    out["hierarchy"] = {{"depth", h.height()},
                        {"nodes", h.nodes().size()},
                        {"leaves", leaves},
                        {"leaf_size", h.leaf_size()},
                        {"volume", PCCD::to_string(h.volume())},
                        {"build_ms", t.hierarchy},
                        {"reaches", h.has_reach()},
                        {"largest_reach", h.root().reach},
                        {"bytes", h.memory_bytes()},
                        {"covering", {{"subsample", covering.subsample()},
                                      {"root_radius", covering.radius(0)},
                                      {"median_radius_above_leaves", parent_radii.empty() ? 0.0 : parent_radii[parent_radii.size() / 2]},
                                      {"build_ms", covering_ms}}}};
    return out;
}

void print_text(const nlohmann::json& info)
{
    std::cout << std::setprecision(6);
    if (info.contains("prepared")) {
        const nlohmann::json& p = info["prepared"];
        std::cout << "file          " << info["file"].get<std::string>() << " (a prepared "
                  << p["kernel"].get<std::string>() << " object file, format version " << p["format_version"] << ", "
                  << p["bytes"] << " bytes)\n"
                  << "points        " << info["points"] << '\n'
                  << "bbox min      " << info["bbox"]["min"].dump() << '\n'
                  << "bbox max      " << info["bbox"]["max"].dump() << '\n'
                  << "mean spacing  " << info["mean_spacing"] << '\n'
                  << "sampling r    " << info["sampling_radius"] << '\n'
                  << "bandwidth     " << info["bandwidth"] << " (theta_eps " << info["theta_eps"] << ")\n"
                  << "surface fit   " << info["surface_fit"].get<std::string>() << '\n'
                  << "noise         " << info["noise"]["sigma"] << '\n'
                  << "outliers      " << info["outliers"]["count"] << " of " << info["outliers"]["input_points"]
                  << " points left out\n"
                  << "hierarchy     " << info["hierarchy"].dump() << '\n'
                  << "time load     " << info["timings_ms"]["load"].get<double>() << " ms\n";
        return;
    }
    std::cout << "file          " << info["file"].get<std::string>() << '\n'
              << "points        " << info["points"] << (info["normals"]["from_file"].get<bool>() ? " (with normals)" : "")
              << '\n'
              << "bbox min      " << info["bbox"]["min"].dump() << '\n'
              << "bbox max      " << info["bbox"]["max"].dump() << '\n'
              << "mean spacing  " << info["mean_spacing"] << '\n';
    if (info.contains("graph"))
        std::cout << "sampling r    " << info["sampling_radius"] << '\n'
                  << "graph         " << info["graph"].dump() << '\n'
                  << "cpsp          " << info["cpsp"].dump() << '\n'
                  << "bandwidth     " << info["bandwidth"] << " (eta " << info["eta"] << ", theta_eps "
                  << info["theta_eps"] << ")\n"
                  << "surface fit   " << info["surface_fit"].get<std::string>() << '\n'
                  << "normals       " << info["normals"].dump() << '\n'
                  << "noise         " << info["noise"]["sigma"] << " (" << info["noise"]["sigma_in_spacings"]
                  << " mean spacings)\n"
                  << "outliers      " << info["outliers"]["count"] << " of " << info["outliers"]["input_points"]
                  << " points left out\n"
                  << "hierarchy     " << info["hierarchy"].dump() << '\n';
    for (const auto& [name, ms] : info["timings_ms"].items())
        std::cout << std::left << std::setw(20) << ("time " + name) << ' ' << ms.get<double>() << " ms\n";
}

} // namespace

void register_info(CLI::App& app)
{
    auto* cmd = app.add_subcommand("info", "Describe a point file (PLY, OFF, XYZ): points, bounding box, mean spacing; or a "
                                           "prepared object file (pccd prepare): its kind and the loaded object's figures");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Point cloud or mesh file (.ply, .off, .xyz, .pwn), or a prepared object file")
        ->required();
    cmd->add_flag("--json", *json, "Print one JSON object instead of text");
    cmd->callback([file, json] {
        const nlohmann::json info = describe_file(*file);
        if (*json)
            std::cout << info.dump(2) << '\n';
        else
            print_text(info);
    });
}

} // namespace pccd_tool
