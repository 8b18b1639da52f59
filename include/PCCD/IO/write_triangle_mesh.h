// PCCD/IO/write_triangle_mesh.h -- writes a triangle mesh to an OFF or PLY (ascii or binary) file
// through CGAL's polygon soup writers. What it writes, read_triangle_mesh reads back exactly.
// Implements the writing of meshes of doc/manual/io.md ("Functions", "Round trips are exact",
// "Errors").
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/IO/internal/finite_checks.h>
#include <PCCD/IO/internal/write_helpers.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/io.h>
#include <CGAL/Simple_cartesian.h>

#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace PCCD::IO {

/// Writes `mesh` to the file `path` in the given format (Format::off or Format::ply), replacing
/// the file. OFF: ascii, 17 significant digits by default. PLY: `double` vertex coordinates and an
/// `int` `vertex_indices` list per face; ascii, or binary little endian when `options.binary`.
///
/// \throws Invalid_input (with the function and the path in the message) if the mesh has no
///         vertex or no triangle, a NaN or infinite coordinate, a triangle index out of range (the
///         message names the triangle), for Format::xyz, or for bad options (binary OFF, precision
///         outside [1, 17]).
/// \throws File_error if the file cannot be opened for writing or written completely.
inline void write_triangle_mesh(const std::string& path, const Triangle_mesh_data& mesh, Format format,
                                const Write_options& options = {})
{
    using internal::concat;
    using Point_3 = CGAL::Simple_cartesian<double>::Point_3;

    const std::string where = concat("write_triangle_mesh(", path, "): ");
    if (format == Format::xyz) throw Invalid_input(where + "an XYZ file cannot hold a triangle mesh");
    internal::check_write_options("write_triangle_mesh", path, format, options);
    if (mesh.vertices.empty()) throw Invalid_input(where + "the mesh has no vertex");
    if (mesh.triangles.empty()) throw Invalid_input(where + "the mesh has no triangle");
    if (mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw Invalid_input(concat(where, mesh.vertices.size(), " vertices: OFF and PLY files index at most 2^31 - 1"));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!internal::is_finite(mesh.vertices[i]))
            throw Invalid_input(concat(where, "vertex ", i, " has a NaN or infinite coordinate"));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (const std::uint32_t v : mesh.triangles[t])
            if (v >= mesh.vertices.size())
                throw Invalid_input(concat(where, "triangle ", t, " references vertex ", v, ", out of range (the mesh has ",
                                           mesh.vertices.size(), " vertices)"));

    std::vector<Point_3> points;
    points.reserve(mesh.vertices.size());
    for (const Eigen::Vector3d& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());

    std::ofstream out = internal::open_for_writing(path, options.binary);
    CGAL::IO::set_mode(out, options.binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    const auto np = CGAL::parameters::stream_precision(options.precision);
    const bool ok = format == Format::off ? CGAL::IO::write_OFF(out, points, mesh.triangles, np)
                                          : CGAL::IO::write_PLY(out, points, mesh.triangles, np);
    internal::finish_writing(path, out, ok);
}

/// Writes `mesh` to the file `path` in the format named by its extension (case-insensitive):
/// `.off` or `.ply`; throws File_error "unknown extension" for any other.
/// See write_triangle_mesh(const std::string&, const Triangle_mesh_data&, Format, const Write_options&).
inline void write_triangle_mesh(const std::string& path, const Triangle_mesh_data& mesh,
                                const Write_options& options = {})
{
    write_triangle_mesh(path, mesh, internal::format_for_writing(path, true), options);
}

} // namespace PCCD::IO
