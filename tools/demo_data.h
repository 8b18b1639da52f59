// tools/demo_data.h -- the built-in data of the pccd tool: the scanned Stanford bunny of Debian's
// libcgal-demo package when it is available, otherwise PCCD's procedural torus (the embedded
// default). Both are normalized into [-1, 1]^3 (doc/manual/sampling.md) and sampled by area.
#pragma once

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Torus_shape.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>

#ifndef PCCD_DATA_DIR
#define PCCD_DATA_DIR ""
#endif

namespace pccd_tool {

/// A sampled demo object: its points and normals in [-1, 1]^3, the area of its surface, and where
/// it came from.
struct Demo_object {
    std::string name;
    std::string source;
    Eigen::Matrix3Xd points;
    Eigen::Matrix3Xd normals;
    double area = 0.0;
};

/// The directory holding libcgal-demo's meshes: $PCCD_DATA_DIR if set, else the one found at build
/// time; empty when neither exists.
inline std::string data_directory()
{
    if (const char* env = std::getenv("PCCD_DATA_DIR"); env != nullptr && *env != '\0') return env;
    return PCCD_DATA_DIR;
}

/// `n` points sampled uniformly by area from the bunny (or the torus fallback), seeded.
inline Demo_object load_demo_object(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    const std::string dir = data_directory();
    const std::filesystem::path bunny = std::filesystem::path(dir) / "bunny00.off";
    if (!dir.empty() && std::filesystem::exists(bunny)) {
        PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(bunny.string());
        const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
        for (auto& v : mesh.vertices) v = normalization.transform_point(v);
        const PCCD::Triangle_mesh_sample sample = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, engine);
        double area = 0.0;
        for (const auto& t : mesh.triangles)
            area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
        return {"bunny", "scanned mesh " + bunny.string() + " (Debian package libcgal-demo)", sample.points,
                sample.normals, area};
    }
    const PCCD::testing::Torus_shape torus(0.7, 0.3);
    const PCCD::testing::Surface_sample sample = torus.sample(n, engine);
    return {"torus",
            "embedded default: procedural torus R = 0.7, r = 0.3 (libcgal-demo's scanned meshes not found; "
            "install the Debian package libcgal-demo or set PCCD_DATA_DIR)",
            sample.points, sample.normals, torus.area()};
}

} // namespace pccd_tool
