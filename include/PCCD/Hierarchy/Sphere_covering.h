// PCCD/Hierarchy/Sphere_covering.h -- per-node subsamples and sphere coverings of a point cloud
// hierarchy (doc/manual/hierarchy.md, "Subsamples and sphere coverings"): every node keeps up to K
// of its points, chosen by farthest-point sampling, and one radius such that the balls of that
// radius around them cover all the node's points. The radius is measured over the node's points,
// not assumed; the surface patch the points sample lies within that radius plus the cloud's
// sampling radius r(P) of the subsample. The queries do not use the coverings yet; `pccd info`
// reports them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// Subsamples and covering radii of the nodes of a Point_cloud_hierarchy.
///
/// For node i: centres(i) are up to `subsample` columns of the hierarchy's ordered_points() in the
/// node's range, the first the point nearest the node's box centre, each next one the point
/// farthest from those chosen (farthest-point sampling); radius(i) is the largest distance from a
/// point of the node to its nearest centre, so every point of the node lies within radius(i) of a
/// centre. A node with at most `subsample` points keeps them all (radius 0).
///
/// Immutable after construction; const members are safe to call concurrently. Refers to no data of
/// the hierarchy after construction (the centres are column indices into its ordered points).
class Sphere_covering {
public:
    using Index = Point_cloud_hierarchy::Index;

    /// Builds the coverings of every node of `hierarchy` with up to `subsample` centres each.
    /// \throws Invalid_input if subsample is 0 or above 255.
    /// Complexity: O(N K log N) time for N points, K = subsample, in parallel over nodes with TBB;
    /// O(nodes K) space.
    explicit Sphere_covering(const Point_cloud_hierarchy& hierarchy, std::size_t subsample = 8,
                             std::optional<unsigned> threads = std::nullopt)
        : m_subsample(subsample)
    {
        if (subsample == 0 || subsample > 255)
            throw Invalid_input(internal::concat("sphere covering: subsample ", subsample, " must be in [1, 255]"));
        const std::size_t nodes = hierarchy.nodes().size();
        m_centres.assign(nodes * subsample, 0);
        m_counts.assign(nodes, 0);
        m_radii.assign(nodes, 0.0);
        internal::with_threads(threads, [&] {
            internal::parallel_for_ranges(nodes, 64, [&](std::size_t begin, std::size_t end) {
                std::vector<double> nearest;
                for (std::size_t i = begin; i < end; ++i) cover(hierarchy, Index(i), nearest);
            });
        });
    }

    /// The centres of node i: columns of the hierarchy's ordered_points().
    std::span<const Index> centres(Index i) const { return {m_centres.data() + std::size_t(i) * m_subsample, m_counts[i]}; }
    /// The covering radius of node i.
    double radius(Index i) const { return m_radii[i]; }
    std::size_t subsample() const { return m_subsample; }
    std::size_t size() const { return m_radii.size(); }
    std::size_t memory_bytes() const
    {
        return m_centres.capacity() * sizeof(Index) + m_counts.capacity() + m_radii.capacity() * sizeof(double);
    }

private:
    void cover(const Point_cloud_hierarchy& h, Index i, std::vector<double>& nearest)
    {
        const auto& node = h.node(i);
        const Eigen::Matrix4Xd& p = h.ordered_points();
        Index* centres = m_centres.data() + std::size_t(i) * m_subsample;
        const Eigen::Vector3d middle = node.box.center();
        // The first centre: the point nearest the box centre (ties: the first in order).
        Index first = node.first;
        double best = std::numeric_limits<double>::infinity();
        for (Index k = node.first; k < node.first + node.count; ++k) {
            const double d = (p.col(k).head<3>() - middle).squaredNorm();
            if (d < best) best = d, first = k;
        }
        nearest.assign(node.count, std::numeric_limits<double>::infinity());
        std::uint8_t count = 0;
        Index next = first;
        for (;;) {
            centres[count++] = next;
            const Eigen::Vector3d c = p.col(next).head<3>();
            double farthest = -1.0;
            for (Index k = 0; k < node.count; ++k) {
                double& d = nearest[k];
                d = std::min(d, (p.col(node.first + k).head<3>() - c).squaredNorm());
                if (d > farthest) farthest = d, next = node.first + k;
            }
            if (count == m_subsample || !(farthest > 0.0)) {
                m_radii[i] = std::sqrt(std::max(farthest, 0.0));
                break;
            }
        }
        m_counts[i] = count;
    }

    std::size_t m_subsample;
    std::vector<Index> m_centres;
    std::vector<std::uint8_t> m_counts;
    std::vector<double> m_radii;
};

} // namespace PCCD
