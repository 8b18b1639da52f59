// pccd info FILE [--json]: what a point file holds and the figures of its cloud (points, bounding
// box, mean spacing, preprocessing times). Later stages add their figures to the same JSON object.
#include "commands.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/Point_cloud.h>

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
    out["normals"] = data.has_normals();

    start = Clock::now();
    const PCCD::Point_cloud<> cloud(data.points);
    out["timings_ms"]["kd_tree"] = ms_since(start);
    out["bbox"] = {{"min", vector_json(cloud.bbox().min())}, {"max", vector_json(cloud.bbox().max())}};
    if (cloud.size() >= 2) {
        start = Clock::now();
        out["mean_spacing"] = cloud.mean_spacing();
        out["timings_ms"]["mean_spacing"] = ms_since(start);
    } else {
        out["mean_spacing"] = nullptr; // undefined for a single point
    }
    return out;
}

void print_text(const nlohmann::json& info)
{
    std::cout << std::setprecision(6);
    std::cout << "file          " << info["file"].get<std::string>() << '\n'
              << "points        " << info["points"] << (info["normals"].get<bool>() ? " (with normals)" : "") << '\n'
              << "bbox min      " << info["bbox"]["min"].dump() << '\n'
              << "bbox max      " << info["bbox"]["max"].dump() << '\n'
              << "mean spacing  " << info["mean_spacing"] << '\n';
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
