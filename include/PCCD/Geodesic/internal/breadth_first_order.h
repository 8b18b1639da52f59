// PCCD/Geodesic/internal/breadth_first_order.h -- the numbering of the graph copy the CPSP map's
// searches run on, and their order when the points' own order is not local (doc/manual/graphs.md,
// "The CPSP map"): the graph's vertices breadth-first, component by component, so that a search,
// and consecutive searches, touch mostly the same memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <boost/graph/graph_traits.hpp>

namespace PCCD::internal {

/// The vertices of `g` in breadth-first order, component by component from the smallest
/// unvisited vertex. Running the per-source searches in this order makes consecutive searches
/// touch mostly the same vertices, so their scratch entries and adjacency rows stay in cache (on a
/// randomly numbered cloud this made the CPSP map several times faster, doc/benchmarks.md).
template <class Graph>
std::vector<std::uint32_t> breadth_first_order(const Graph& g)
{
    using Vertex = typename boost::graph_traits<Graph>::vertex_descriptor;
    const std::size_t n = num_vertices(g);
    std::vector<std::uint32_t> order;
    order.reserve(n);
    std::vector<bool> seen(n, false);
    for (std::size_t root = 0; root < n; ++root) {
        if (seen[root]) continue;
        seen[root] = true;
        std::size_t head = order.size();
        order.push_back(std::uint32_t(root));
        for (; head < order.size(); ++head)
            for (auto [e, e_end] = out_edges(Vertex(order[head]), g); e != e_end; ++e) {
                const auto v = std::size_t(target(*e, g));
                if (!seen[v]) {
                    seen[v] = true;
                    order.push_back(std::uint32_t(v));
                }
            }
    }
    return order;
}

} // namespace PCCD::internal
