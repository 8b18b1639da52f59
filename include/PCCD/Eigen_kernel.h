// PCCD/Eigen_kernel.h -- PCCD's own minimal kernel on Eigen fixed-size vectors, a model of
// PointCloudKernel for users who do not use CGAL. Point_3 and Vector_3 are Eigen::Matrix<FT,3,1>.
#pragma once

#include <concepts>

#include <Eigen/Core>

namespace PCCD {

/// Minimal kernel over Eigen 3-vectors. \tparam FT_ `float` or `double`.
/// Models PointCloudKernel. Stateless; safe to share between threads.
template <std::floating_point FT_>
struct Eigen_kernel {
    using FT = FT_;
    using Point_3 = Eigen::Matrix<FT, 3, 1>;
    using Vector_3 = Eigen::Matrix<FT, 3, 1>;

    struct Construct_point_3 {
        Point_3 operator()(FT x, FT y, FT z) const { return Point_3(x, y, z); }
    };
    struct Compute_x_3 {
        FT operator()(const Point_3& p) const { return p.x(); }
    };
    struct Compute_y_3 {
        FT operator()(const Point_3& p) const { return p.y(); }
    };
    struct Compute_z_3 {
        FT operator()(const Point_3& p) const { return p.z(); }
    };
    struct Compute_squared_distance_3 {
        FT operator()(const Point_3& p, const Point_3& q) const { return (p - q).squaredNorm(); }
    };

    Construct_point_3 construct_point_3_object() const { return {}; }
    Compute_x_3 compute_x_3_object() const { return {}; }
    Compute_y_3 compute_y_3_object() const { return {}; }
    Compute_z_3 compute_z_3_object() const { return {}; }
    Compute_squared_distance_3 compute_squared_distance_3_object() const { return {}; }
};

} // namespace PCCD
