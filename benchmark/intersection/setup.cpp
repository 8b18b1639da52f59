// benchmark/intersection/setup.cpp -- reading and sampling the bunny, preprocessing the cloud.
#include "setup.h"

#include <PCCD/testing/timing.h>

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

namespace pccd_bench::intersection {

using PCCD::testing::Clock;
using PCCD::testing::ms_since;

std::optional<PCCD::Triangle_mesh_data> read_bunny()
{
    const std::filesystem::path path = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    if (std::string(PCCD_DATA_DIR).empty() || !std::filesystem::exists(path)) return std::nullopt;
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);
    return mesh;
}

std::vector<Eigen::Vector3d> cloud_points(const PCCD::Triangle_mesh_data& mesh, std::size_t n, std::uint64_t seed)
{
    if (n == 0) return {mesh.vertices.begin(), mesh.vertices.end()};
    PCCD::Random_engine engine(seed);
    const PCCD::Triangle_mesh_sample sample = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, engine);
    std::vector<Eigen::Vector3d> points(std::size_t(sample.points.cols()));
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points[std::size_t(i)] = sample.points.col(i);
    return points;
}

Prepared prepare(const std::vector<Eigen::Vector3d>& points)
{
    const auto start = Clock::now();
    PCCD::Point_cloud_object<> object(points);
    return {std::move(object), ms_since(start)};
}

void print_setup(const Bunny_setup& bunny, const Prepared& prepared, const Arguments& args)
{
    const PCCD::Point_cloud_object<>& object = prepared.object;
    std::printf("bunny: %zu vertices, %zu triangles; cloud N = %zu (%s), mean spacing %.5f, r(P) = %.5f, "
                "preprocessing %.0f ms; %zu rotation pairs per distance, seed %llu, median of %d runs per query\n",
                bunny.mesh.vertices.size(), bunny.mesh.triangles.size(), object.size(),
                args.points == 0 ? "mesh vertices" : "resampled mesh", object.cloud().mean_spacing(),
                object.sampling_radius(), prepared.preprocess_ms, args.rotations, (unsigned long long)args.seed,
                args.repetitions);
}

} // namespace pccd_bench::intersection
