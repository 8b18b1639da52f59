// pccd eval FILE --at "x y z" [--at ...] [--kernel geodesic|euclidean] [--json]: the implicit
// surface of a point file at given points (doc/algorithms.md, "The implicit surface"): f, n(x),
// a(x), or why f is undefined there. Preprocessing uses Point_cloud_object's defaults; the file's normals, when it has
// them, are hints that orient the surface's normals (zero ones count as missing).
#include "commands.h"
#include "progress.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/Point_cloud_object.h>

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace pccd_tool {
namespace {

Eigen::Vector3d parse_point(const std::string& text)
{
    std::istringstream in(text);
    Eigen::Vector3d p;
    std::string rest;
    if (!(in >> p.x() >> p.y() >> p.z()) || (in >> rest) || !p.allFinite())
        throw PCCD::Invalid_input("--at expects three finite numbers \"x y z\", got \"" + text + "\"");
    return p;
}

nlohmann::json vector_or_null(const Eigen::Vector3d& v)
{
    if (!v.allFinite()) return nullptr;
    return nlohmann::json::array({v.x(), v.y(), v.z()});
}

nlohmann::json evaluation_json(const Eigen::Vector3d& x, const PCCD::Surface_evaluation& e)
{
    nlohmann::json out;
    out["at"] = vector_or_null(x);
    out["status"] = PCCD::to_string(e.status);
    out["f"] = e.defined() ? nlohmann::json(e.value) : nlohmann::json(nullptr);
    out["n"] = vector_or_null(e.normal);
    out["a"] = vector_or_null(e.centroid);
    out["neighbors"] = e.neighbor_count;
    out["nearest"] = e.nearest == PCCD::Surface_evaluation::no_point ? nlohmann::json(nullptr) : nlohmann::json(e.nearest);
    return out;
}

void print_text(const nlohmann::json& result)
{
    std::cout << std::setprecision(9);
    std::cout << "file " << result["file"].get<std::string>() << ", kernel " << result["kernel"].get<std::string>()
              << ", bandwidth " << result["bandwidth"].get<double>() << '\n';
    for (const auto& e : result["evaluations"]) {
        std::cout << "at " << e["at"].dump() << ": ";
        if (e["f"].is_null())
            std::cout << "f undefined (" << e["status"].get<std::string>() << ")\n";
        else
            std::cout << "f = " << e["f"].get<double>() << "  n = " << e["n"].dump() << "  a = " << e["a"].dump()
                      << '\n';
    }
}

} // namespace

void register_eval(CLI::App& app)
{
    auto* cmd = app.add_subcommand("eval", "Evaluate the implicit surface f of a point file at given points");
    auto file = std::make_shared<std::string>();
    auto at = std::make_shared<std::vector<std::string>>();
    auto kernel = std::make_shared<std::string>("geodesic");
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "Point cloud or mesh file (.ply, .off, .xyz, .pwn)")->required();
    cmd->add_option("--at", *at, "A query point \"x y z\" (repeatable)")->required();
    cmd->add_option("--kernel", *kernel, "Distance of the kernel: geodesic (default) or euclidean")
        ->check(CLI::IsMember({"geodesic", "euclidean"}));
    cmd->add_flag("--json", *json, "Print one JSON object instead of text");
    cmd->callback([file, at, kernel, json] {
        std::vector<Eigen::Vector3d> points;
        for (const std::string& text : *at) points.push_back(parse_point(text));
        const PCCD::Point_data data = PCCD::IO::read_points(*file);
        // The file's normals, if any, are hints; progress on stderr when it is a terminal.
        const PCCD::Point_cloud_object<> object(data, with_progress({}, *file));
        nlohmann::json result;
        result["file"] = *file;
        result["kernel"] = *kernel;
        result["bandwidth"] = object.bandwidth();
        result["eta"] = object.eta();
        result["theta_eps"] = object.theta_eps();
        for (const Eigen::Vector3d& x : points) {
            const auto e = *kernel == "euclidean" ? object.euclidean_surface().evaluate(x) : object.surface().evaluate(x);
            result["evaluations"].push_back(evaluation_json(x, e));
        }
        if (*json)
            std::cout << result.dump(2) << '\n';
        else
            print_text(result);
    });
}

} // namespace pccd_tool
