// PCCD/make_point_cloud_object.h -- a preprocessed Point_cloud_object straight from the 3 x N
// coordinate matrices that PCCD's samplers and most Eigen code produce (sample_triangle_mesh()
// gives in Triangle_mesh_sample::points), with or without normals, as a function whose kernel defaults and
// whose result type `auto` can hold: it calls Point_cloud_object's matrix constructors.
// doc/manual/surface.md, "One call: Point_cloud_object".
#pragma once

#include <Eigen/Core>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Point_cloud_object_options.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

/// Point_cloud_object<K>(points, options): the preprocessed object of the points in the columns of
/// `points`.
/// \tparam K a model of PointCloudKernel (default: Eigen_kernel<double>).
/// \throws Invalid_input as that constructor does (too few points, a coordinate that is not
///         finite, invalid options).
template <PointCloudKernel K = Eigen_kernel<double>>
Point_cloud_object<K> make_point_cloud_object(const Eigen::Matrix3Xd& points,
                                              const Point_cloud_object_options& options = {})
{
    return Point_cloud_object<K>(points, options);
}

/// Point_cloud_object<K>(points, normals, options): as above, with one normal per point (column i
/// of `normals` for column i of `points`), used as hints that decide the sign of the object's
/// normals (zero or non-finite columns count as missing).
/// \throws Invalid_input when `normals` does not have one column per point, and as above.
template <PointCloudKernel K = Eigen_kernel<double>>
Point_cloud_object<K> make_point_cloud_object(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                              const Point_cloud_object_options& options = {})
{
    return Point_cloud_object<K>(points, normals, options);
}

} // namespace PCCD
