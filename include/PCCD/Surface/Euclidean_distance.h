// PCCD/Surface/Euclidean_distance.h -- the Euclidean distance policy of the implicit surface
// (doc/algorithms.md, "Euclidean and geodesic distance"): the neighbours of a query are found by a
// kd-tree radius query.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

/// d(x, p) = |x - p|, enumerated by kd-tree radius queries on the cloud. Models SurfaceDistance.
///
/// \tparam K a model of PointCloudKernel (the kernel of the cloud).
///
/// A cheap view: it holds a shared handle on the immutable cloud. Both enumerations cost one kd-tree
/// radius query, O(log N + k) expected for k neighbours (plus sorting them), and use a per-thread
/// scratch buffer, so they are safe to call from several threads at once.
template <PointCloudKernel K = Eigen_kernel<double>>
class Euclidean_distance {
public:
    using Kernel = K;
    using FT = typename K::FT;

    explicit Euclidean_distance(Point_cloud<K> cloud) : m_cloud(std::move(cloud)) {}

    std::size_t size() const { return m_cloud.size(); }
    Eigen::Vector3d position(std::uint32_t i) const { return m_cloud.position(i).template cast<double>(); }
    /// Unbounded: any radius is answered exactly.
    double max_radius() const { return std::numeric_limits<double>::infinity(); }
    const Point_cloud<K>& cloud() const { return m_cloud; }

    /// Visits every point within Euclidean distance `radius` of point `i` (i itself included).
    template <class Visitor>
    void for_each_neighbor_of_point(std::uint32_t i, double radius, Visitor&& visitor) const
    {
        for_each_neighbor(position(i), radius, visitor);
    }

    /// Visits every point within Euclidean distance `radius` of `x`, nearest first; returns the
    /// nearest one (std::nullopt when none is within `radius`).
    template <class Visitor>
    std::optional<std::uint32_t> for_each_neighbor(const Eigen::Vector3d& x, double radius, Visitor&& visitor) const
    {
        thread_local std::vector<Neighbor<FT>> found;
        m_cloud.within_radius(x.template cast<FT>(), FT(radius), found);
        if (found.empty()) return std::nullopt;
        for (const auto& neighbor : found) visitor(neighbor.index, std::sqrt(double(neighbor.squared_distance)));
        return found.front().index;
    }

private:
    Point_cloud<K> m_cloud;
};

} // namespace PCCD
