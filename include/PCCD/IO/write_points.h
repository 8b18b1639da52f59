// PCCD/IO/write_points.h -- writes a point cloud (points and, if present, normals) to a PLY (ascii or
// binary), OFF or XYZ/PWN file through CGAL's writers. What it writes, read_points reads back
// exactly (17 significant digits in ascii, the bits of the doubles in binary PLY). Implements the
// writing of points of doc/manual/io.md ("Functions", "Round trips are exact", "Errors").
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/internal/finite_checks.h>
#include <PCCD/IO/internal/write_helpers.h>

#include <CGAL/IO/io.h>
#include <CGAL/IO/write_off_points.h>
#include <CGAL/IO/write_ply_points.h>
#include <CGAL/IO/write_xyz_points.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace PCCD::IO {

/// Writes `data` to the file `path` in the given format, replacing the file.
///
/// - PLY: `vertex` element with `double` properties x, y, z (and nx, ny, nz with normals); ascii,
///   or binary little endian when `options.binary`.
/// - OFF: `OFF` header, or `NOFF` with normals (x y z nx ny nz per line); no faces.
/// - XYZ/PWN: one point per line, `x y z` or `x y z nx ny nz`.
///
/// \throws Invalid_input (with the function and the path in the message) if `data.points` is empty,
///         if `data.normals` is neither empty nor of the size of `data.points`, if a coordinate or
///         normal is NaN or infinite (the message names the index), or for bad options (binary for
///         OFF or XYZ, precision outside [1, 17]).
/// \throws File_error if the file cannot be opened for writing or written completely.
inline void write_points(const std::string& path, const Point_data& data, Format format,
                         const Write_options& options = {})
{
    using internal::concat;
    using Kernel = CGAL::Simple_cartesian<double>;
    using Point_with_normal = std::pair<Kernel::Point_3, Kernel::Vector_3>;

    internal::check_write_options("write_points", path, format, options);
    const std::string where = concat("write_points(", path, "): ");
    if (data.points.empty()) throw Invalid_input(where + "no points to write");
    if (!data.normals.empty() && data.normals.size() != data.points.size())
        throw Invalid_input(concat(where, "inconsistent normals: ", data.normals.size(), " normals for ",
                                   data.points.size(), " points"));
    for (std::size_t i = 0; i < data.points.size(); ++i)
        if (!internal::is_finite(data.points[i])) throw Invalid_input(concat(where, "point ", i, " has a NaN or infinite coordinate"));
    for (std::size_t i = 0; i < data.normals.size(); ++i)
        if (!internal::is_finite(data.normals[i])) throw Invalid_input(concat(where, "the normal of point ", i, " is NaN or infinite"));

    std::vector<Point_with_normal> items;
    items.reserve(data.points.size());
    for (std::size_t i = 0; i < data.points.size(); ++i) {
        const Eigen::Vector3d& p = data.points[i];
        const Eigen::Vector3d n = data.normals.empty() ? Eigen::Vector3d::Zero() : data.normals[i];
        items.emplace_back(Kernel::Point_3(p.x(), p.y(), p.z()), Kernel::Vector_3(n.x(), n.y(), n.z()));
    }

    std::ofstream out = internal::open_for_writing(path, options.binary);
    CGAL::IO::set_mode(out, options.binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    const auto write = [&](const auto& np) {
        switch (format) {
        case Format::ply: return CGAL::IO::write_PLY(out, items, np);
        case Format::off: return CGAL::IO::write_OFF(out, items, np);
        case Format::xyz: return CGAL::IO::write_XYZ(out, items, np);
        }
        return false;
    };
    const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                        .stream_precision(options.precision);
    const bool ok = data.normals.empty()
                        ? write(np)
                        : write(np.normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
    internal::finish_writing(path, out, ok);
}

/// Writes `data` to the file `path` in the format named by its extension (case-insensitive):
/// `.ply`, `.off`, `.xyz` or `.pwn`; throws File_error "unknown extension" for any other.
/// See write_points(const std::string&, const Point_data&, Format, const Write_options&).
inline void write_points(const std::string& path, const Point_data& data, const Write_options& options = {})
{
    write_points(path, data, internal::format_for_writing(path, false), options);
}

} // namespace PCCD::IO
