// PCCD/Surface/Geodesic_distance.h -- the geodesic distance policy of the implicit surface
// (doc/algorithms.md, "Euclidean and geodesic distance"): d(x, p) = |x - p*| + g(p*, p), p* the
// cloud point nearest to x and g the shortest-path length in the proximity graph, read from the
// close-pairs shortest-path (CPSP) map. At a cloud point the neighbours are its CPSP list: no
// kd-tree query at all.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

#include <Eigen/Core>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

/// d(x, p) = |x - p*| + g(p*, p), with g from a Close_pairs_shortest_paths map. Models
/// SurfaceDistance. Points that the graph does not connect to p* within the map's bound are not
/// neighbours at all: this is what stops the surface from bleeding across thin gaps.
///
/// \tparam K a model of PointCloudKernel (the kernel of the cloud).
///
/// max_radius() is the map's bound: the surface's kernel support must not exceed it. The distances
/// are the map's (stored as float). d is discontinuous where p* changes (on the boundaries of the
/// cloud's Voronoi cells), by at most the difference of the graph distances of neighbouring points.
///
/// A cheap view sharing the immutable cloud and map. Thread safety: const, safe to call concurrently.
template <PointCloudKernel K = Eigen_kernel<double>>
class Geodesic_distance {
public:
    using Kernel = K;
    using FT = typename K::FT;
    using Map = Close_pairs_shortest_paths;

    /// \throws Invalid_input if `map` is null or does not have one list per cloud point.
    Geodesic_distance(Point_cloud<K> cloud, std::shared_ptr<const Map> map)
        : m_cloud(std::move(cloud)), m_map(std::move(map))
    {
        if (!m_map) throw Invalid_input("geodesic distance: no CPSP map given");
        if (m_map->size() != m_cloud.size())
            throw Invalid_input(internal::concat("geodesic distance: the CPSP map has ", m_map->size(),
                                                 " lists for a cloud of ", m_cloud.size(), " points"));
    }

    std::size_t size() const { return m_cloud.size(); }
    Eigen::Vector3d position(std::uint32_t i) const { return m_cloud.position(i).template cast<double>(); }
    /// The map's bound: its lists hold every point within this geodesic distance.
    double max_radius() const { return m_map->bound(); }
    const Point_cloud<K>& cloud() const { return m_cloud; }
    const Map& map() const { return *m_map; }
    /// The shared map itself (a deforming cloud keeps its rest map over moved points).
    const std::shared_ptr<const Map>& shared_map() const { return m_map; }

    /// Visits the entries of i's CPSP list with g(p_i, p_j) <= radius, nearest first. O(k), no
    /// kd-tree query.
    template <class Visitor>
    void for_each_neighbor_of_point(std::uint32_t i, double radius, Visitor&& visitor) const
    {
        const auto targets = m_map->targets(i);
        const auto distances = m_map->distances(i);
        for (std::size_t k = 0; k < targets.size(); ++k) {
            const double g = double(distances[k]);
            if (g > radius) break;
            visitor(targets[k], g);
        }
    }

    /// Finds p* (one kd-tree nearest-neighbour query), then visits p*'s list with
    /// |x - p*| + g(p*, p_j) <= radius. Returns p*, or std::nullopt when |x - p*| > radius.
    template <class Visitor>
    std::optional<std::uint32_t> for_each_neighbor(const Eigen::Vector3d& x, double radius, Visitor&& visitor) const
    {
        const auto nearest = m_cloud.nearest(x.template cast<FT>());
        const double offset = std::sqrt(double(nearest.squared_distance));
        if (!(offset <= radius)) return std::nullopt;
        for_each_neighbor_of_point(nearest.index, radius - offset,
                                   [&](std::uint32_t j, double g) { visitor(j, offset + g); });
        return nearest.index;
    }

private:
    Point_cloud<K> m_cloud;
    std::shared_ptr<const Map> m_map;
};

} // namespace PCCD
