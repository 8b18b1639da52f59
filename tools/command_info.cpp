// pccd info FILE [--json]: what a point file holds and the figures of its cloud (points, bounding
// box, mean spacing, preprocessing times). Later stages add their figures to the same JSON object.
#include "commands.h"

#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/Surface/orient_normals.h>
#include <PCCD/sampling_radius.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace pccd_tool {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

nlohmann::json vector_json(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json describe_file(const std::string& path)
{
    nlohmann::json out;
    out["file"] = path;
    auto start = Clock::now();
    const PCCD::Point_data data = PCCD::IO::read_points(path);
    out["timings_ms"]["read"] = ms_since(start);
    out["points"] = data.points.size();
    out["normals"] = {{"from_file", data.has_normals()}};

    start = Clock::now();
    const PCCD::Point_cloud<> cloud(data.points);
    out["timings_ms"]["kd_tree"] = ms_since(start);
    out["bbox"] = {{"min", vector_json(cloud.bbox().min())}, {"max", vector_json(cloud.bbox().max())}};
    if (cloud.size() >= 2) {
        start = Clock::now();
        out["mean_spacing"] = cloud.mean_spacing();
        out["timings_ms"]["mean_spacing"] = ms_since(start);
        // Geodesic preprocessing with the library defaults (r-SIG, CPSP bound eta r(P)).
        start = Clock::now();
        const double radius = PCCD::sampling_radius(cloud);
        out["timings_ms"]["sampling_radius"] = ms_since(start);
        out["sampling_radius"] = radius;
        start = Clock::now();
        const PCCD::Proximity_graph graph = PCCD::sphere_of_influence_graph(cloud);
        out["timings_ms"]["graph"] = ms_since(start);
        out["graph"] = {{"kind", PCCD::to_string(graph.kind(), graph.parameter())},
                        {"r", graph.parameter()},
                        {"edges", graph.num_edges()},
                        {"virtual_edges", graph.num_virtual_edges()},
                        {"components", PCCD::graph_components(graph).count}};
        start = Clock::now();
        const PCCD::Close_pairs_shortest_paths cpsp(graph, radius);
        out["timings_ms"]["cpsp"] = ms_since(start);
        out["cpsp"] = {{"entries", cpsp.num_entries()}, {"bytes", cpsp.memory_bytes()}};
        // Implicit surface (ALGORITHMS.md section 1): default bandwidth, normals oriented like the
        // file's when it has them, else over the graph.
        const PCCD::Bandwidth_options bandwidth;
        const PCCD::Gaussian_weight weight = PCCD::gaussian_weight(radius, bandwidth);
        out["bandwidth"] = weight.bandwidth();
        out["eta"] = bandwidth.eta;
        out["theta_eps"] = weight.threshold();
        start = Clock::now();
        // A non-owning handle on the local map (aliasing constructor with an empty owner).
        const std::shared_ptr<const PCCD::Close_pairs_shortest_paths> map(std::shared_ptr<void>(), &cpsp);
        PCCD::Normal_estimate estimate = PCCD::estimate_normals(PCCD::Geodesic_distance<>(cloud, map), weight);
        PCCD::Orientation_report orientation;
        if (data.has_normals()) {
            Eigen::Matrix3Xd given(3, Eigen::Index(data.normals.size()));
            for (std::size_t i = 0; i < data.normals.size(); ++i) given.col(Eigen::Index(i)) = data.normals[i];
            orientation = PCCD::orient_normals_like(estimate.normals, given);
        } else {
            orientation = PCCD::orient_normals(graph, cloud.coordinates(), estimate.normals);
        }
        out["timings_ms"]["normals"] = ms_since(start);
        out["normals"]["flipped"] = orientation.flipped;
        out["normals"]["components"] = orientation.components;
        out["normals"]["unoriented"] = orientation.unoriented;
    } else {
        out["mean_spacing"] = nullptr; // undefined for a single point
    }
    return out;
}

void print_text(const nlohmann::json& info)
{
    std::cout << std::setprecision(6);
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
                  << "normals       " << info["normals"].dump() << '\n';
    for (const auto& [name, ms] : info["timings_ms"].items())
        std::cout << "time " << std::left << std::setw(9) << name << ms.get<double>() << " ms\n";
}

} // namespace

void register_info(CLI::App& app)
{
    auto* cmd = app.add_subcommand("info", "Describe a point file (PLY, OFF, XYZ): points, bounding box, mean spacing");
    auto file = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Point cloud or mesh file (.ply, .off, .xyz, .pwn)")->required();
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
