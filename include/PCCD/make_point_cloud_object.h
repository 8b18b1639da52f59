// PCCD/make_point_cloud_object.h -- a preprocessed Point_cloud_object straight from the 3 x N
// coordinate matrices that PCCD's samplers and most Eigen code produce (Surface_sample::points,
// Triangle_mesh_sample::points), with or without normals: no range of items, no point map.
// doc/manual/surface.md, "One call: Point_cloud_object".
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Error.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Point_cloud_object_options.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

namespace internal {

/// Readable property map from a column index to that column of a 3 x N matrix, as a 3D point.
struct Matrix_column_map {
    const Eigen::Matrix3Xd* matrix;
    friend Eigen::Vector3d get(const Matrix_column_map& m, std::size_t i) { return m.matrix->col(Eigen::Index(i)); }
};

inline std::vector<std::size_t> column_indices(const Eigen::Matrix3Xd& points)
{
    std::vector<std::size_t> items(std::size_t(points.cols()));
    std::iota(items.begin(), items.end(), std::size_t(0));
    return items;
}

} // namespace internal

/// The preprocessed object of the points in the columns of `points`, as the constructor
/// Point_cloud_object(items, point_map, options) builds it.
/// \tparam K a model of PointCloudKernel (default: Eigen_kernel<double>).
/// \throws Invalid_input as that constructor does (too few points, a coordinate that is not
///         finite, invalid options).
template <PointCloudKernel K = Eigen_kernel<double>>
Point_cloud_object<K> make_point_cloud_object(const Eigen::Matrix3Xd& points,
                                              const Point_cloud_object_options& options = {})
{
    return Point_cloud_object<K>(internal::column_indices(points), internal::Matrix_column_map{&points}, options);
}

/// As above, with one normal per point (column i of `normals` for column i of `points`), used as
/// hints that decide the sign of the object's normals (zero or non-finite columns count as missing),
/// as the constructor with a normal map does.
/// \throws Invalid_input when `normals` does not have one column per point, and as above.
template <PointCloudKernel K = Eigen_kernel<double>>
Point_cloud_object<K> make_point_cloud_object(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                              const Point_cloud_object_options& options = {})
{
    if (normals.cols() != points.cols())
        throw Invalid_input(internal::concat("make_point_cloud_object: ", normals.cols(), " normals for ", points.cols(),
                                             " points (need one per point)"));
    return Point_cloud_object<K>(internal::column_indices(points), internal::Matrix_column_map{&points},
                                 internal::Matrix_column_map{&normals}, options);
}

} // namespace PCCD
