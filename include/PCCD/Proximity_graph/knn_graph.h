// PCCD/Proximity_graph/knn_graph.h -- the symmetric k-nearest-neighbour graph over a point cloud
// (doc/algorithms.md, "Proximity graphs and geodesic distance"), the simplest proximity graph,
// built with one kd-tree query per point, in parallel when TBB is available.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
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

/// Builds the symmetric k-NN graph of `cloud`: i and j are joined when j is among the k nearest
/// other positions of i or i among those of j (ties broken by index); then long edges are marked
/// virtual (mark_long_edges()). Coincident points are handled as in sphere_of_influence_graph():
/// the graph is built over distinct positions and each copy is joined to its representative by a
/// zero-length edge.
///
/// \tparam K a model of PointCloudKernel.
/// \throws Invalid_input if `options.k` is 0 or the long-edge factor is not > 0.
/// Complexity: O(N k log N) expected. Thread safety: reads `cloud` only.
template <PointCloudKernel K>
Proximity_graph knn_graph(const Point_cloud<K>& cloud, const Knn_graph_options& options = {})
{
    using FT = typename K::FT;
    if (options.k == 0) throw Invalid_input("k-NN graph: k must be >= 1, got 0");
    internal::check(options.long_edges);
    const auto distinct = internal::find_distinct_positions(cloud);
    const Kd_tree<FT>& tree = internal::distinct_tree(cloud, distinct);
    const auto& c = tree.coordinates();
    const std::vector<std::uint32_t> order = internal::spatial_order(c);
    std::vector<internal::Found_edge> edges;
    internal::with_threads(options.threads, [&] {
        edges = internal::gather_edges<FT>(tree.size(), order, [&](std::uint32_t u, auto& nn, auto& found) {
            tree.k_nearest(c.col(Eigen::Index(u)), std::size_t(options.k) + 1, nn);
            for (const auto& nb : nn)
                if (nb.index != u)
                    found.push_back({internal::original_index(distinct, u), internal::original_index(distinct, nb.index),
                                     float(internal::point_distance(c, u, nb.index))});
        });
    });
    return internal::finish_graph(std::uint32_t(cloud.size()), edges, distinct.representative, options.long_edges,
                                  Graph_kind::knn, options.k);
}

} // namespace PCCD
