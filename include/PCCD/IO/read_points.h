// PCCD/IO/read_points.h -- reads a point cloud (points and, if present, normals) from a PLY, OFF or
// XYZ/PWN file, checked by PCCD so that every unusable file throws PCCD::File_error naming the
// problem. Binary PLY and XYZ/PWN files are read by PCCD in chunks straight into the result
// (PCCD/IO/internal/read_ply_binary.h, read_xyz.h); ascii PLY and OFF files are read whole, checked
// (check_ply.h, check_off.h), then read by CGAL's readers. Implements the reading of points of
// doc/manual/io.md (format table, "Functions", "Normals are read as stored", "Meshes as points",
// "Errors", "How it works").
#pragma once

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/internal/check_off.h>
#include <PCCD/IO/internal/check_ply.h>
#include <PCCD/IO/internal/read_helpers.h>
#include <PCCD/IO/internal/read_ply_binary.h>
#include <PCCD/IO/internal/read_xyz.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace PCCD::IO {

/// Reads the points of the file `path` in the given format; for an OFF or PLY file that holds a
/// mesh, the vertices are the points (the faces are checked, then ignored).
///
/// - PLY: ascii, binary little or big endian; the `vertex` element must have `x`, `y`, `z` of type
///   float or double, and has normals if it also has `nx`, `ny`, `nz`.
/// - OFF: ascii `OFF`, `COFF`, `NOFF` (normals) or `CNOFF`; one vertex per line.
/// - XYZ/PWN: one point per line, `x y z` or `x y z nx ny nz` (the same on every line), `#`
///   comments, and an optional point count alone on the first line.
///
/// \returns the points and, when the file has them, one normal per point (else `normals` is empty).
/// \throws File_error when the file cannot be used. The message starts with `path` and names the
///         problem: missing/unreadable, empty, "bad header" (wrong magic, malformed or negative
///         counts), "truncated" (fewer vertices or faces than the header declares), "malformed
///         number" (with the line), a NaN or infinite coordinate (with the vertex or point index, and
///         the line for ascii), "no points", "inconsistent normals", a face vertex "out of range",
///         "unexpected data" after the declared content, "unsupported" variants.
/// Complexity: O(file size). Memory: a binary PLY or an XYZ/PWN file is read in chunks of about
/// 1 MiB into the result, which is reserved once (from the header's vertex count for PLY, checked
/// against the file size first); an ascii PLY or an OFF file is held in memory while it is read.
inline Point_data read_points(const std::string& path, Format format)
{
    if (format == Format::xyz) return internal::read_xyz_points(path);
    if (format == Format::ply)
        if (std::optional<Point_data> data = internal::read_binary_ply_points(path)) return std::move(*data);

    using Kernel = CGAL::Simple_cartesian<double>;
    using Point_3 = Kernel::Point_3;
    using Vector_3 = Kernel::Vector_3;
    using Point_with_normal = std::pair<Point_3, Vector_3>;

    std::string text = internal::load_file(path);
    std::vector<Point_3> points;
    std::vector<Vector_3> normals;
    std::size_t expected = 0;
    bool has_normals = false;

    const auto read_with_normals = [&](auto&& reader) {
        std::vector<Point_with_normal> items;
        const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                            .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>());
        const bool ok = reader(std::back_inserter(items), np);
        points.reserve(items.size());
        for (const Point_with_normal& item : items) {
            points.push_back(item.first);
            if (has_normals) normals.push_back(item.second);
        }
        return ok;
    };

    bool ok = false;
    switch (format) {
    case Format::off: {
        const internal::Off_summary summary = internal::check_off(path, text);
        expected = summary.vertices;
        has_normals = summary.normals;
        internal::prepare_ascii_for_cgal(text);
        std::istringstream in(std::move(text));
        std::vector<std::vector<std::size_t>> polygons;
        ok = CGAL::IO::read_OFF(in, points, polygons,
                                CGAL::parameters::vertex_normal_output_iterator(std::back_inserter(normals))
                                    .verbose(false));
        break;
    }
    case Format::ply: {
        const internal::Ply_summary summary = internal::check_ply(path, text, false);
        expected = summary.vertices;
        has_normals = summary.normals;
        if (!summary.binary) internal::prepare_ascii_for_cgal(text);
        std::istringstream in(std::move(text), std::ios::in | std::ios::binary);
        ok = read_with_normals([&](auto out, const auto& np) { return CGAL::IO::read_PLY(in, out, np); });
        break;
    }
    case Format::xyz: // read above
        break;
    }
    if (!ok) internal::cgal_disagrees(path, format, "it returned false");
    if (points.size() != expected || normals.size() != (has_normals ? expected : 0))
        internal::cgal_disagrees(path, format,
                                 internal::concat("it read ", points.size(), " points and ", normals.size(),
                                                  " normals, PCCD counted ", expected, has_normals ? " of each" : " points"));

    Point_data data;
    data.points.reserve(points.size());
    for (const Point_3& p : points) data.points.emplace_back(p.x(), p.y(), p.z());
    data.normals.reserve(normals.size());
    for (const Vector_3& n : normals) data.normals.emplace_back(n.x(), n.y(), n.z());
    return data;
}

/// Reads the points of the file `path` in the format named by its extension (case-insensitive):
/// `.ply`, `.off`, `.xyz` or `.pwn`. Throws File_error "unknown extension" for any other.
/// See read_points(const std::string&, Format).
inline Point_data read_points(const std::string& path)
{
    return read_points(path, internal::format_for_reading(path, false));
}

} // namespace PCCD::IO
