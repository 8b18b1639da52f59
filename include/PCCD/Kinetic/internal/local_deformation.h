// PCCD/Kinetic/internal/local_deformation.h -- how a deforming cloud has moved near each point
// against its rest pose (doc/algorithms.md, "Deforming point clouds"): the stretch of the edges of
// the proximity graph, and the rest normal carried to the current pose by the local deformation
// gradient (which orients the re-fitted normals whatever rotation the motion made).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Proximity_graph/Proximity_graph.h>

namespace PCCD::internal {

/// Rest length of every stored edge direction of `graph` (CSR order) over the 3 x N `rest`
/// positions; 0 for virtual edges (which are never measured).
template <class Points>
std::vector<double> rest_edge_lengths(const Proximity_graph& graph, const Points& rest)
{
    const auto& rows = graph.row_offsets();
    const auto& targets = graph.targets();
    std::vector<double> lengths(targets.size(), 0.0);
    for (std::size_t u = 0; u + 1 < rows.size(); ++u)
        for (std::uint64_t e = rows[u]; e < rows[u + 1]; ++e)
            if (!graph.edge_property(e).is_virtual)
                lengths[e] = (rest.col(Eigen::Index(targets[e])) - rest.col(Eigen::Index(u))).template cast<double>().norm();
    return lengths;
}

/// current / rest length of the edges of point u: their smallest, largest and mean (1, 1, 1 when u
/// has no measured edge: only virtual ones, or only of rest length 0).
struct Point_stretch {
    double min = 1.0;
    double max = 1.0;
    double mean = 1.0;
    std::uint32_t worst = 0; ///< the other end of the edge farthest from length-preserving
    std::size_t measured = 0; ///< edges measured
};

template <class Points>
Point_stretch point_stretch(const Proximity_graph& graph, const std::vector<double>& rest_lengths,
                            const Points& current, std::uint32_t u)
{
    const auto& rows = graph.row_offsets();
    const auto& targets = graph.targets();
    Point_stretch s;
    double sum = 0.0, worst = 0.0;
    std::size_t count = 0;
    for (std::uint64_t e = rows[u]; e < rows[u + 1]; ++e) {
        if (!(rest_lengths[e] > 0.0)) continue;
        const double ratio =
            (current.col(Eigen::Index(targets[e])) - current.col(Eigen::Index(u))).template cast<double>().norm() /
            rest_lengths[e];
        if (count == 0) s.min = s.max = ratio;
        s.min = std::min(s.min, ratio);
        s.max = std::max(s.max, ratio);
        // Distance from isometry on a ratio scale: a halving is as far as a doubling.
        const double off = ratio >= 1.0 ? ratio : 1.0 / std::max(ratio, 1e-300);
        if (count == 0 || off > worst) {
            worst = off;
            s.worst = targets[e];
        }
        sum += ratio;
        ++count;
    }
    if (count > 0) s.mean = sum / double(count);
    s.measured = count;
    return s;
}

/// Sums of the least-squares fit of the local deformation gradient at a point: the 3 x 3 map F
/// minimizing sum |F u_j - v_j|^2, u_j the rest offset of neighbour j in the frame (t1, t2, n) of
/// the rest normal n, v_j its current offset. Where the rest offsets are (nearly) coplanar the
/// normal column of F is undetermined and only the tangent columns are fitted (3 x 2 map).
struct Deformation_sums {
    Eigen::Matrix3d uu = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d vu = Eigen::Matrix3d::Zero();

    void add(const Eigen::Vector3d& u, const Eigen::Vector3d& v)
    {
        uu += u * u.transpose();
        vu += v * u.transpose();
    }

    /// The rest normal carried by F: (F t1) x (F t2), unit length (for the identity map and for
    /// rotations, exactly the rest normal moved, to rounding); nullopt when the rest offsets do not
    /// span the tangent plane or F collapses it.
    std::optional<Eigen::Vector3d> transported_normal() const
    {
        const Eigen::Matrix2d tangent = uu.topLeftCorner<2, 2>();
        const double det = tangent.determinant();
        const double scale = tangent.trace();
        if (!(det > 1e-12 * scale * scale)) return std::nullopt;
        Eigen::Matrix<double, 3, 2> columns;
        // The spread of the normal offsets left after the tangent fit (Schur complement).
        const Eigen::Vector2d cross = uu.block<2, 1>(0, 2);
        const double normal_spread = uu(2, 2) - cross.dot(tangent.inverse() * cross);
        if (normal_spread > 1e-8 * scale) {
            columns = (vu * uu.inverse()).leftCols<2>();
        } else {
            columns = vu.leftCols<2>() * tangent.inverse();
        }
        const Eigen::Vector3d n = columns.col(0).cross(columns.col(1));
        const double length = n.norm();
        if (!(length > 0.0 && std::isfinite(length))) return std::nullopt;
        return n / length;
    }
};

/// An orthonormal tangent basis (t1, t2) of the unit normal n, with t1 x t2 = n.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> tangent_basis(const Eigen::Vector3d& n)
{
    const Eigen::Vector3d helper = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d t1 = n.cross(helper).normalized();
    return {t1, n.cross(t1)};
}

} // namespace PCCD::internal
