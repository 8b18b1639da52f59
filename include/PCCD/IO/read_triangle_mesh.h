// PCCD/IO/read_triangle_mesh.h -- reads a triangle mesh (vertices and index triples) from an OFF or
// PLY file through CGAL's polygon soup readers, after PCCD's own check of the format (PCCD/IO/
// internal/check_off.h, check_ply.h), so that every unusable file throws PCCD::File_error naming
// the problem. Implements the reading of meshes of doc/manual/io.md ("Functions", "Polygons",
// "Errors").
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/IO/internal/check_off.h>
#include <PCCD/IO/internal/check_ply.h>
#include <PCCD/IO/internal/read_helpers.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace PCCD::IO {

/// Reads the triangle mesh of the file `path` in the given format (Format::off or Format::ply).
///
/// Every face must have at least 3 vertices, all in range. A polygon with k > 3 vertices
/// (v0, v1, ..., vk-1) becomes the fan of k - 2 triangles (v0, vi, vi+1), i = 1 .. k-2, in order:
/// exact for convex polygons (all a well-formed OFF or PLY file holds in practice), not a
/// triangulation of a non-convex one. Vertices no face uses are kept. OFF: ascii OFF, COFF, NOFF,
/// CNOFF (normals and colors are ignored). PLY: ascii or binary; the `face` element needs a
/// `vertex_indices` (or `vertex_index`) list of int or uint.
///
/// \throws File_error when the file cannot be used, with the messages of read_points, plus "no
///         faces" when the file holds none, "out of range" for a face index >= the vertex count
///         (the message names the face and, for ascii, the line). Format::xyz throws File_error
///         (an XYZ file holds no faces).
/// Complexity: O(file size); the file is held in memory while it is read.
inline Triangle_mesh_data read_triangle_mesh(const std::string& path, Format format)
{
    using Point_3 = CGAL::Simple_cartesian<double>::Point_3;

    if (format == Format::xyz) internal::fail(path, "unsupported format: an XYZ file holds no triangle mesh");
    std::string text = internal::load_file(path);
    std::vector<Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    std::size_t vertices = 0, faces = 0;
    const auto check_vertex_count = [&] {
        if (vertices > std::numeric_limits<std::uint32_t>::max())
            internal::fail(path, internal::concat("unsupported: ", vertices, " vertices, PCCD indexes at most 2^32 - 1"));
    };
    bool ok = false;
    if (format == Format::off) {
        const internal::Off_summary summary = internal::check_off(path, text);
        if (summary.faces == 0)
            internal::fail(path, "no faces: the header declares 0 faces (a point cloud? read it with PCCD::IO::read_points)");
        vertices = summary.vertices;
        faces = summary.faces;
        check_vertex_count();
        internal::prepare_ascii_for_cgal(text);
        std::istringstream in(std::move(text));
        ok = CGAL::IO::read_OFF(in, points, polygons, CGAL::parameters::verbose(false));
    } else {
        const internal::Ply_summary summary = internal::check_ply(path, text, true);
        vertices = summary.vertices;
        faces = summary.faces;
        check_vertex_count();
        if (!summary.binary) internal::prepare_ascii_for_cgal(text);
        std::istringstream in(std::move(text), std::ios::in | std::ios::binary);
        ok = CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false));
    }
    if (!ok) internal::cgal_disagrees(path, format, "it returned false");
    if (points.size() != vertices || polygons.size() != faces)
        internal::cgal_disagrees(path, format,
                                 internal::concat("it read ", points.size(), " vertices and ", polygons.size(),
                                                  " faces, the header declares ", vertices, " and ", faces));

    Triangle_mesh_data mesh;
    mesh.vertices.reserve(points.size());
    for (const Point_3& p : points) mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    mesh.triangles.reserve(polygons.size());
    for (std::size_t f = 0; f < polygons.size(); ++f) {
        const std::vector<std::size_t>& polygon = polygons[f];
        if (polygon.size() < 3)
            internal::cgal_disagrees(path, format, internal::concat("face ", f, " has ", polygon.size(), " vertices"));
        for (const std::size_t v : polygon)
            if (v >= points.size())
                internal::cgal_disagrees(path, format, internal::concat("face ", f, " references vertex ", v));
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
            mesh.triangles.push_back({static_cast<std::uint32_t>(polygon[0]), static_cast<std::uint32_t>(polygon[i]),
                                      static_cast<std::uint32_t>(polygon[i + 1])});
    }
    return mesh;
}

/// Reads the triangle mesh of the file `path` in the format named by its extension
/// (case-insensitive): `.off` or `.ply`. Throws File_error "unknown extension" for any other.
/// See read_triangle_mesh(const std::string&, Format).
inline Triangle_mesh_data read_triangle_mesh(const std::string& path)
{
    return read_triangle_mesh(path, internal::format_for_reading(path, true));
}

} // namespace PCCD::IO
