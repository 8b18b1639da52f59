// make_cli_data DIR: writes the small inputs of the pccd CLI tests into DIR -- a sampled unit
// sphere (sphere.xyz, 2000 points, no normals), a sampled torus with its exact normals
// (torus.ply, 2000 points) and a triangulated torus mesh (torus_mesh.off, 32 x 16 quads), all
// procedural and seeded, so that the tests need no external data.
#include <PCCD/IO/write_points.h>
#include <PCCD/IO/write_triangle_mesh.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <numbers>

namespace {

PCCD::Point_data to_point_data(const PCCD::testing::Surface_sample& sample, bool with_normals)
{
    PCCD::Point_data data;
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) {
        data.points.push_back(sample.points.col(i));
        if (with_normals) data.normals.push_back(sample.normals.col(i));
    }
    return data;
}

PCCD::Triangle_mesh_data torus_mesh(double major, double minor, std::uint32_t nu, std::uint32_t nv)
{
    PCCD::Triangle_mesh_data mesh;
    for (std::uint32_t i = 0; i < nu; ++i)
        for (std::uint32_t j = 0; j < nv; ++j) {
            const double u = 2.0 * std::numbers::pi * i / nu, v = 2.0 * std::numbers::pi * j / nv;
            const double w = major + minor * std::cos(v);
            mesh.vertices.emplace_back(w * std::cos(u), w * std::sin(u), minor * std::sin(v));
        }
    const auto index = [&](std::uint32_t i, std::uint32_t j) { return (i % nu) * nv + (j % nv); };
    for (std::uint32_t i = 0; i < nu; ++i)
        for (std::uint32_t j = 0; j < nv; ++j) {
            mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
            mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return mesh;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: make_cli_data DIR\n";
        return 2;
    }
    const std::filesystem::path dir(argv[1]);
    std::filesystem::create_directories(dir);
    PCCD::Random_engine engine(7);
    const PCCD::testing::Sphere_shape sphere(Eigen::Vector3d::Zero(), 1.0);
    PCCD::IO::write_points((dir / "sphere.xyz").string(), to_point_data(sphere.sample(2000, engine), false));
    const PCCD::testing::Torus_shape torus(0.7, 0.3);
    PCCD::IO::write_points((dir / "torus.ply").string(), to_point_data(torus.sample(2000, engine), true));
    PCCD::IO::write_triangle_mesh((dir / "torus_mesh.off").string(), torus_mesh(0.7, 0.3, 32, 16));
    std::cout << "wrote sphere.xyz, torus.ply, torus_mesh.off to " << dir.string() << '\n';
    return 0;
}
