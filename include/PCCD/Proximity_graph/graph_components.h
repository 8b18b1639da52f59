// PCCD/Proximity_graph/graph_components.h -- connected components of a proximity graph, with or
// without its virtual edges (doc/algorithms.md, "Long edges and virtual edges": the surface sees
// the graph without virtual edges; normal orientation propagates per component). Works on any
// ProximityGraph model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <type_traits>
#include <vector>

#include <boost/graph/graph_traits.hpp>

#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/concepts/ProximityGraph.h>

namespace PCCD {

/// The connected components of a graph.
struct Graph_components {
    /// Number of components (isolated vertices count as components).
    std::size_t count = 0;
    /// label[v] in [0, count): components are numbered in the order of their smallest vertex.
    std::vector<std::uint32_t> label;
};

/// Computes the connected components of `g`, ignoring virtual edges unless `include_virtual`.
///
/// \tparam Graph a model of ProximityGraph (any weight map; only the structure is read). Directed
///         models must store both directions of every edge.
/// \tparam VirtualMap a model of EdgeFlagMap (PCCD::No_virtual_edges for graphs without the mark).
/// Complexity: O(E α(N)) (union-find). Thread safety: reads `g` only.
template <class Graph, class VirtualMap = No_virtual_edges>
    requires EdgeFlagMap<VirtualMap, Graph> && (!std::is_same_v<Graph, Proximity_graph>)
Graph_components graph_components(const Graph& g, const VirtualMap& is_virtual = {}, bool include_virtual = false)
{
    const std::size_t n = num_vertices(g);
    std::vector<std::uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    };
    for (auto [v, v_end] = vertices(g); v != v_end; ++v)
        for (auto [e, e_end] = out_edges(*v, g); e != e_end; ++e) {
            if (!include_virtual && get(is_virtual, *e)) continue;
            const std::uint32_t a = find(std::uint32_t(source(*e, g)));
            const std::uint32_t b = find(std::uint32_t(target(*e, g)));
            // Linking the larger root under the smaller keeps every root the smallest of its set.
            if (a < b) parent[b] = a;
            else if (b < a) parent[a] = b;
        }
    Graph_components result;
    result.label.resize(n);
    for (std::uint32_t v = 0; v < n; ++v) {
        const std::uint32_t root = find(v);
        result.label[v] = (root == v) ? std::uint32_t(result.count++) : result.label[root];
    }
    return result;
}

/// The components of a Proximity_graph, ignoring virtual edges unless `include_virtual`.
inline Graph_components graph_components(const Proximity_graph& graph, bool include_virtual = false)
{
    return graph_components(graph.graph(), graph.virtual_map(), include_virtual);
}

} // namespace PCCD
