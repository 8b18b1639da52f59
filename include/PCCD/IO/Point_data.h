// PCCD/IO/Point_data.h -- the plain data a point file holds: points and, when the file has them,
// one normal per point. Filled by PCCD::IO::read_points, written by PCCD::IO::write_points, and
// taken by Point_cloud_object. Implements the point data of doc/manual/io.md; its name is
// PCCD::Point_data, and PCCD::IO::Point_data names the same type (doc/manual/io.md, "Namespaces").
// This header does not include CGAL.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace PCCD {

/// Points read from, or to be written to, a point file (PLY, OFF, XYZ/PWN).
struct Point_data {
    /// The points, in file order. Never empty after a successful read.
    std::vector<Eigen::Vector3d> points;
    /// One normal per point (same order), or empty when the file has no normals. Normals are stored
    /// as the file gives them: they are not normalized.
    std::vector<Eigen::Vector3d> normals;

    bool has_normals() const noexcept { return !normals.empty(); }
};

namespace IO {
/// The same type as PCCD::Point_data, so that the whole I/O interface is found in PCCD::IO.
using PCCD::Point_data;
} // namespace IO

} // namespace PCCD
