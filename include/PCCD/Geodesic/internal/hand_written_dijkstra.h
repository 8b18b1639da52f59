// PCCD/Geodesic/internal/hand_written_dijkstra.h -- PCCD's own bounded Dijkstra, the default
// routine of the CPSP map (Bounded_dijkstra::hand_written, doc/manual/graphs.md "The CPSP map"):
// the searched edges copied into a compact CSR graph renumbered breadth-first, then one search per
// source with a 4-ary heap (lazy deletion) that never queues a vertex beyond the bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <boost/graph/graph_traits.hpp>

#include <PCCD/Geodesic/internal/dijkstra_workspace.h>

namespace PCCD::internal {

/// The graph the hand-written Dijkstra walks: the searched edges of the input graph copied into
/// flat CSR arrays, with vertices renumbered in breadth-first order so that a search touches
/// mostly neighbouring memory. `Length` is float when the input's lengths are floats (as in
/// Proximity_graph), double otherwise, so distances are the same sums as on the input graph.
template <class Length>
struct Compact_graph {
    std::vector<std::uint64_t> rows;
    std::vector<std::uint32_t> targets;
    std::vector<Length> lengths;
    std::vector<std::uint32_t> original; // original[new id] = vertex of the input graph
};

template <class Length, class Graph, class LengthMap, class VirtualMap>
Compact_graph<Length> make_compact_graph(const Graph& g, const LengthMap& length, const VirtualMap& is_virtual,
                                         bool use_virtual, std::vector<std::uint32_t> order)
{
    using Vertex = typename boost::graph_traits<Graph>::vertex_descriptor;
    const std::size_t n = order.size();
    std::vector<std::uint32_t> rank(n);
    for (std::size_t k = 0; k < n; ++k) rank[order[k]] = std::uint32_t(k);
    Compact_graph<Length> c;
    c.rows.reserve(n + 1);
    c.rows.push_back(0);
    for (std::size_t k = 0; k < n; ++k) {
        for (auto [e, e_end] = out_edges(Vertex(order[k]), g); e != e_end; ++e) {
            if (!use_virtual && get(is_virtual, *e)) continue;
            c.targets.push_back(rank[std::size_t(target(*e, g))]);
            c.lengths.push_back(Length(get(length, *e)));
        }
        c.rows.push_back(c.targets.size());
    }
    c.original = std::move(order);
    return c;
}

template <class Length>
void hand_written_bounded_dijkstra(const Compact_graph<Length>& g, double bound, std::uint32_t source,
                                   Dijkstra_workspace& ws, Cpsp_list& out)
{
    auto& heap = ws.heap;
    heap.clear();
    ws.state[source].distance = 0.0;
    ws.state[source].parent = 0;
    ws.touched.push_back(source);
    heap.push({0.0, source});
    const auto first = std::uint32_t(out.targets.size());
    while (!heap.empty()) {
        const auto [d, u] = heap.pop();
        auto& su = ws.state[u];
        if (su.position != Dijkstra_workspace::none) continue; // a stale, longer entry
        const auto position = std::uint32_t(out.targets.size()) - first;
        su.position = position;
        out.targets.push_back(g.original[u]);
        out.distances.push_back(float(d));
        out.predecessors.push_back(su.parent);
        for (std::uint64_t e = g.rows[u]; e < g.rows[u + 1]; ++e) {
            const std::uint32_t v = g.targets[e];
            const double candidate = d + double(g.lengths[e]);
            auto& sv = ws.state[v];
            if (candidate <= bound && candidate < sv.distance) {
                if (sv.distance == std::numeric_limits<double>::infinity()) ws.touched.push_back(v);
                sv.distance = candidate;
                sv.parent = position;
                heap.push({candidate, v});
            }
        }
    }
}

} // namespace PCCD::internal
