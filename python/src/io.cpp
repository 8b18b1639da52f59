// python/src/io.cpp -- pccd.read_points and pccd.write_points: PCCD's PLY, OFF and XYZ/PWN readers
// and writers (doc/manual/io.md) with numpy arrays; every unusable file raises OSError with PCCD's
// message naming the file and the problem.
#include "pccd_python.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/IO/write_points.h>

#include <PCCD/Error.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace pccd_python {

namespace {

py::array rows_to_array(const std::vector<Eigen::Vector3d>& rows)
{
    py::array_t<double> a({py::ssize_t(rows.size()), py::ssize_t(3)});
    auto out = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (int j = 0; j < 3; ++j) out(py::ssize_t(i), j) = rows[i](j);
    return a;
}

std::vector<Eigen::Vector3d> array_to_rows(const Row_array& a)
{
    std::vector<Eigen::Vector3d> rows(a.rows);
    for (std::size_t i = 0; i < a.rows; ++i) rows[i] = Eigen::Vector3d(a.at(i, 0), a.at(i, 1), a.at(i, 2));
    return rows;
}

const char* read_points_doc = R"doc(Read the points (and normals) of a PLY, OFF or XYZ/PWN file.

The format is chosen by the extension (``.ply``, ``.off``, ``.xyz``, ``.pwn``, any case). For an
OFF or PLY mesh the vertices are the points.

Parameters
----------
path : str, bytes or os.PathLike
    The file to read.

Returns
-------
points : numpy.ndarray
    (N, 3) float64 array of the points, in file order (N >= 1).
normals : numpy.ndarray or None
    (N, 3) float64 array of the normals as stored in the file (not normalized), or None when the
    file has none.

Raises
------
OSError
    The file is missing, a directory, unreadable, empty, truncated or malformed, or holds a NaN or
    infinite coordinate; the message starts with the file name and names the problem.
TypeError
    `path` is not a str, bytes or os.PathLike (None included).

Examples
--------
>>> points, normals = pccd.read_points("bunny00.off")
>>> points.shape
(37706, 3)
)doc";

const char* write_points_doc = R"doc(Write points (and normals) to a PLY, OFF or XYZ file.

The format is chosen by the extension. Coordinates are written with 17 significant digits, so
that every float64 reads back exactly.

Parameters
----------
path : str, bytes or os.PathLike
    The file to write (replaced if it exists).
points : array_like
    (N, 3) array of float32 or float64 numbers.
normals : array_like, optional
    (N, 3) array, one normal per point.
binary : bool, optional
    Binary little-endian PLY (``.ply`` only). Default False.

Raises
------
ValueError
    An array of the wrong shape or type, no points, a NaN or infinite value, or normals not
    one per point.
OSError
    The file cannot be written, or its extension names no supported format.
)doc";

} // namespace

void add_io(py::module_& m)
{
    m.def(
        "read_points",
        [](const py::object& path) {
            const std::string file = path_argument(path, "read_points", "path");
            if (std::filesystem::is_directory(file))
                throw PCCD::File_error(file, "is a directory, not a point file (.ply, .off, .xyz or .pwn)");
            PCCD::Point_data data;
            {
                py::gil_scoped_release release;
                data = PCCD::IO::read_points(file);
            }
            py::object normals = data.has_normals() ? py::object(rows_to_array(data.normals)) : py::object(py::none());
            return py::make_tuple(rows_to_array(data.points), normals);
        },
        py::arg("path"), read_points_doc);
    m.def(
        "write_points",
        [](const py::object& path, const py::object& points, const py::object& normals, bool binary) {
            const std::string file = path_argument(path, "write_points", "path");
            PCCD::Point_data data;
            data.points = array_to_rows(row_array(points, "points"));
            if (!normals.is_none()) {
                data.normals = array_to_rows(row_array(normals, "normals"));
                if (data.normals.size() != data.points.size())
                    throw py::value_error("normals: " + std::to_string(data.normals.size()) + " normals for " +
                                          std::to_string(data.points.size()) + " points (need one per point)");
            }
            py::gil_scoped_release release;
            PCCD::IO::write_points(file, data, PCCD::IO::Write_options{.binary = binary});
        },
        py::arg("path"), py::arg("points"), py::arg("normals") = py::none(), py::kw_only(), py::arg("binary") = false,
        write_points_doc);
}

} // namespace pccd_python
