// Meshes with known geometry for the tests of PCCD/Exact/: a subdivided icosahedron (a sphere or an
// ellipsoid with its vertices on the smooth surface) and an axis-aligned box, both outward oriented.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/IO/Triangle_mesh_data.h>

namespace pccd_test {

/// A subdivided icosahedron with its vertices on the unit sphere, outward oriented, then scaled by
/// `axes` (an ellipsoid when they differ) and moved to `centre`.
inline PCCD::Triangle_mesh_data icosphere(int subdivisions, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero(),
                                         double radius = 1.0, const Eigen::Vector3d& axes = Eigen::Vector3d::Ones())
{
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Eigen::Vector3d& p : v) p.normalize();
    std::vector<std::array<std::uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
        const auto middle = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            v.push_back((v[a] + v[b]).normalized());
            const auto index = std::uint32_t(v.size() - 1);
            midpoint.emplace(key, index);
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& tri : f) {
            const std::uint32_t ab = middle(tri[0], tri[1]), bc = middle(tri[1], tri[2]), ca = middle(tri[2], tri[0]);
            next.push_back({tri[0], ab, ca});
            next.push_back({tri[1], bc, ab});
            next.push_back({tri[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        f = std::move(next);
    }
    PCCD::Triangle_mesh_data mesh;
    for (const Eigen::Vector3d& p : v) mesh.vertices.push_back(centre + radius * p.cwiseProduct(axes));
    mesh.triangles = f;
    return mesh;
}

/// The axis-aligned box centre +- half (12 triangles, outward oriented).
inline PCCD::Triangle_mesh_data box_mesh(const Eigen::Vector3d& centre, const Eigen::Vector3d& half)
{
    PCCD::Triangle_mesh_data mesh;
    for (int i = 0; i < 8; ++i)
        mesh.vertices.push_back(centre + Eigen::Vector3d((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                                                         (i & 4) ? half.z() : -half.z()));
    // Vertex i has bit 0 = +x, bit 1 = +y, bit 2 = +z; two triangles per face, counter-clockwise seen
    // from outside.
    mesh.triangles = {{0, 2, 3}, {0, 3, 1},  // z-
                      {4, 5, 7}, {4, 7, 6},  // z+
                      {0, 1, 5}, {0, 5, 4},  // y-
                      {2, 6, 7}, {2, 7, 3},  // y+
                      {0, 4, 6}, {0, 6, 2},  // x-
                      {1, 3, 7}, {1, 7, 5}}; // x+
    return mesh;
}

} // namespace pccd_test
