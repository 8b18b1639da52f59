// PCCD/Proximity_graph/sphere_of_influence_graph.h -- the sphere-of-influence graph (SIG) and its
// r-SIG generalization over a point cloud (doc/algorithms.md, "Sphere-of-influence graphs", WSCG05
// §3.2), built in O(N log N) expected time with kd-tree queries, in parallel when TBB is available.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Proximity_graph/graph_options.h>
#include <PCCD/Proximity_graph/internal/graph_construction.h>
#include <PCCD/Proximity_graph/prune_long_edges.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// Builds the r-SIG of `cloud`: points i and j are joined when |p_i - p_j| <= d_i + d_j, d_i the
/// distance of p_i to its r-th nearest neighbour; then long edges are marked virtual
/// (mark_long_edges()).
///
/// Coincident points: the definition degenerates for them (a duplicate's nearest neighbour is at
/// distance 0), so the graph is defined over *distinct positions*. Each group of coincident points
/// is represented by its smallest index; d_i and the SIG edges are computed among representatives
/// (d_i is the distance to the r-th nearest *other position*, or to the farthest one when there
/// are fewer than r), and every other member of a group gets a single zero-length edge to its
/// representative. Geodesic distances are thus the same for all copies, and the graph stays linear
/// in size however many copies there are.
///
/// Distances are computed in double from the cloud's coordinates; stored lengths are floats.
///
/// \tparam K a model of PointCloudKernel.
/// \throws Invalid_input if `options.r` is 0 or the long-edge factor is not > 0.
/// Complexity: O(N log N) expected (one k-NN and one radius-2 d_i query per point); memory of the
/// result 8 + 12 * (directed edges) bytes per point. Thread safety: reads `cloud` only.
template <PointCloudKernel K>
Proximity_graph sphere_of_influence_graph(const Point_cloud<K>& cloud,
                                          const Sphere_of_influence_graph_options& options = {})
{
    using FT = typename K::FT;
    if (options.r == 0) throw Invalid_input("sphere-of-influence graph: r must be >= 1, got 0");
    internal::check(options.long_edges);
    const auto distinct = internal::find_distinct_positions(cloud);
    const Kd_tree<FT>& tree = internal::distinct_tree(cloud, distinct);
    const auto& c = tree.coordinates();
    const std::size_t m = tree.size();
    const std::vector<std::uint32_t> order = internal::spatial_order(c);
    std::vector<double> radius(m, 0.0);
    std::vector<internal::Found_edge> edges;
    internal::with_threads(options.threads, [&] {
        internal::parallel_for_ranges(m, 1024, [&](std::size_t begin, std::size_t end) {
            std::vector<Neighbor<FT>> nn;
            for (std::size_t i = begin; i < end; ++i) {
                const std::uint32_t k = order[i];
                // The query point itself comes first (distance 0, and positions are distinct), so
                // the last of the r + 1 nearest is the r-th nearest other position.
                tree.k_nearest(c.col(Eigen::Index(k)), std::size_t(options.r) + 1, nn);
                radius[k] = internal::point_distance(c, k, nn.back().index);
            }
        });
        // Edge (u, v) is reported by its end with the larger radius (the smaller index on a tie):
        // |p_u - p_v| <= d_u + d_v <= 2 d_u, so a radius-2 d_u query from that end finds it.
        edges = internal::gather_edges<FT>(m, order, [&](std::uint32_t k, auto& near, auto& found) {
            const double du = radius[k];
            if (du == 0.0) return;
            // A small margin so that the kd-tree's own rounding cannot drop a boundary edge; the
            // exact test below decides.
            tree.within_radius(c.col(Eigen::Index(k)), FT(2.0 * du * (1.0 + 1e-6)), near);
            for (const auto& nb : near) {
                const std::uint32_t v = nb.index;
                const double dv = radius[v];
                if (v == k || dv > du || (dv == du && v < k)) continue;
                const double length = internal::point_distance(c, k, v);
                if (length <= du + dv)
                    found.push_back({internal::original_index(distinct, k), internal::original_index(distinct, v),
                                     float(length)});
            }
        });
    });
    radius = {};
    return internal::finish_graph(std::uint32_t(cloud.size()), edges, distinct.representative, options.long_edges,
                                  Graph_kind::sphere_of_influence, options.r);
}

} // namespace PCCD
