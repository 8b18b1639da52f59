// PCCD/IO/Triangle_mesh_data.h -- the plain data a mesh file holds: vertices and triangles as
// index triples. Filled by PCCD::IO::read_triangle_mesh, written by PCCD::IO::write_triangle_mesh,
// and taken by Exact_mesh. Implements the mesh data of doc/manual/io.md; its name is
// PCCD::Triangle_mesh_data, and PCCD::IO::Triangle_mesh_data names the same type (doc/manual/io.md,
// "Namespaces"). This header does not include CGAL.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace PCCD {

/// A triangle soup: vertices and triangles given by three 0-based indices into `vertices`.
struct Triangle_mesh_data {
    /// The vertices, in file order.
    std::vector<Eigen::Vector3d> vertices;
    /// The triangles, each a triple of indices into `vertices`. Polygons of the file with more than
    /// three vertices appear here as fans (see read_triangle_mesh).
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

namespace IO {
/// The same type as PCCD::Triangle_mesh_data, so that the whole I/O interface is found in PCCD::IO.
using PCCD::Triangle_mesh_data;
} // namespace IO

} // namespace PCCD
