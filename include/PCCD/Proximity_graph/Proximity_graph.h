// PCCD/Proximity_graph/Proximity_graph.h -- PCCD's default graph storage (doc/algorithms.md,
// "Proximity graphs and geodesic distance"): a compact static Boost.Graph model
// (boost::compressed_sparse_row_graph with 32-bit vertices) whose edges carry their length and a
// "virtual" flag, plus what it was built as (k-NN graph, SIG, r-SIG). The builders are knn_graph()
// and sphere_of_influence_graph(); every algorithm that reads a graph also accepts any other model
// of ProximityGraph.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <PCCD/Error.h>
#include <PCCD/Proximity_graph/graph_options.h>
#include <PCCD/concepts/ProximityGraph.h>

namespace PCCD {

/// The bundled property of an edge of Proximity_graph.
struct Proximity_edge {
    /// Euclidean length of the edge (the distance between its two points).
    float length = 0.f;
    /// True when the long-edge test (mark_long_edges()) found the edge too long: it is excluded from
    /// the surface's geodesic distances but may still be walked by the interpolation search.
    bool is_virtual = false;
    friend bool operator==(const Proximity_edge&, const Proximity_edge&) = default;
};

/// "knn", "sig" or "r-sig" (the name used by the pccd tool).
inline std::string to_string(Graph_kind kind, unsigned parameter)
{
    if (kind == Graph_kind::knn) return "knn";
    return parameter == 1 ? "sig" : "r-sig";
}

/// A readable edge-flag map saying that no edge is virtual: the default virtual-edge map for graphs
/// that carry no such mark. Models EdgeFlagMap for every graph.
struct No_virtual_edges {
    using category = boost::readable_property_map_tag;
    using value_type = bool;
    using reference = bool;
    template <class Edge>
    friend bool get(const No_virtual_edges&, const Edge&)
    {
        return false;
    }
};

/// A proximity graph over the N points of a cloud, stored as a compressed sparse row graph.
///
/// Vertex `i` is point `i`. Edges are undirected and stored once in each direction, so
/// `out_edges(v, graph())` lists every neighbour of `v`, sorted by index, and num_edges() counts each
/// undirected edge once. Memory: 8 bytes per vertex plus 12 bytes per stored direction of an edge.
///
/// The graph is immutable once built. Thread safety: all member functions are const and safe to call
/// concurrently.
class Proximity_graph {
public:
    /// The Boost.Graph model: a directed CSR graph holding both directions of every edge.
    using Graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Proximity_edge,
                                                     boost::no_property, std::uint32_t, std::uint64_t>;
    using vertex_descriptor = boost::graph_traits<Graph>::vertex_descriptor;
    using edge_descriptor = boost::graph_traits<Graph>::edge_descriptor;
    /// Readable map edge -> length (float), a model of the weight map of ProximityGraph.
    using Length_map = boost::property_map<Graph, float Proximity_edge::*>::const_type;
    /// Readable map edge -> virtual flag, a model of EdgeFlagMap.
    using Virtual_map = boost::property_map<Graph, bool Proximity_edge::*>::const_type;

    /// An empty graph (no vertices).
    Proximity_graph() = default;

    /// Wraps a CSR graph built elsewhere (the builders and the file reader use it).
    /// \pre `graph` is symmetric: for every edge (u, v) it holds (v, u) with the same property.
    /// `parameter` is k for Graph_kind::knn and r for Graph_kind::sphere_of_influence.
    Proximity_graph(Graph graph, Graph_kind kind, unsigned parameter)
        : m_graph(std::move(graph)), m_kind(kind), m_parameter(parameter)
    {
        for (std::uint64_t e = 0; e < m_graph.m_forward.m_column.size(); ++e)
            if (m_graph[edge_at(e)].is_virtual) ++m_virtual_directed;
    }

    /// \name Access
    /// @{
    const Graph& graph() const { return m_graph; }
    Length_map length_map() const { return get(&Proximity_edge::length, m_graph); }
    Virtual_map virtual_map() const { return get(&Proximity_edge::is_virtual, m_graph); }
    Graph_kind kind() const { return m_kind; }
    /// k for a k-NN graph, r for an r-SIG.
    unsigned parameter() const { return m_parameter; }
    std::size_t num_vertices() const { return boost::num_vertices(m_graph); }
    /// Number of undirected edges (each stored twice).
    std::size_t num_edges() const { return boost::num_edges(m_graph) / 2; }
    /// Number of undirected edges marked virtual.
    std::size_t num_virtual_edges() const { return m_virtual_directed / 2; }
    /// Heap bytes held by the graph (row offsets, targets, edge properties).
    std::size_t memory_bytes() const
    {
        return m_graph.m_forward.m_rowstart.size() * sizeof(std::uint64_t) +
               boost::num_edges(m_graph) * (sizeof(std::uint32_t) + sizeof(Proximity_edge));
    }
    /// The CSR row offsets (N + 1 entries) and the targets of the stored edge directions, in order.
    const std::vector<std::uint64_t>& row_offsets() const { return m_graph.m_forward.m_rowstart; }
    const std::vector<std::uint32_t>& targets() const { return m_graph.m_forward.m_column; }
    /// The property of the `e`-th stored edge direction (0 <= e < 2 num_edges()).
    const Proximity_edge& edge_property(std::uint64_t e) const { return m_graph[edge_at(e)]; }
    /// @}

    friend bool operator==(const Proximity_graph& a, const Proximity_graph& b)
    {
        if (a.m_kind != b.m_kind || a.m_parameter != b.m_parameter || a.row_offsets() != b.row_offsets() ||
            a.targets() != b.targets())
            return false;
        for (std::uint64_t e = 0; e < a.targets().size(); ++e)
            if (!(a.edge_property(e) == b.edge_property(e))) return false;
        return true;
    }

private:
    edge_descriptor edge_at(std::uint64_t e) const
    {
        // The CSR edge descriptor is (source, index); properties are looked up by index only.
        return edge_descriptor(0, e);
    }

    Graph m_graph;
    Graph_kind m_kind = Graph_kind::sphere_of_influence;
    unsigned m_parameter = 0;
    std::size_t m_virtual_directed = 0;
};

namespace internal {

/// Input iterator over the (source, target) pairs of CSR arrays, in order (for the CSR graph's
/// edges_are_sorted constructor).
class Csr_edge_iterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = std::pair<std::uint32_t, std::uint32_t>;
    using difference_type = std::ptrdiff_t;
    using pointer = const value_type*;
    using reference = const value_type&;

    Csr_edge_iterator(const std::vector<std::uint64_t>& rows, const std::vector<std::uint32_t>& targets,
                      std::uint64_t edge)
        : m_rows(&rows), m_targets(&targets), m_edge(edge)
    {
        skip_empty_rows();
    }
    const value_type& operator*() const { return m_current; }
    const value_type* operator->() const { return &m_current; }
    Csr_edge_iterator& operator++()
    {
        ++m_edge;
        skip_empty_rows();
        return *this;
    }
    Csr_edge_iterator operator++(int)
    {
        Csr_edge_iterator old = *this;
        ++*this;
        return old;
    }
    friend bool operator==(const Csr_edge_iterator& a, const Csr_edge_iterator& b) { return a.m_edge == b.m_edge; }

private:
    void skip_empty_rows()
    {
        while (m_row + 1 < m_rows->size() && (*m_rows)[m_row + 1] <= m_edge) ++m_row;
        if (m_edge < m_targets->size()) m_current = {m_row, (*m_targets)[m_edge]};
    }
    const std::vector<std::uint64_t>* m_rows;
    const std::vector<std::uint32_t>* m_targets;
    std::uint64_t m_edge;
    std::uint32_t m_row = 0;
    value_type m_current = {0, 0};
};

/// Builds the CSR graph from row offsets (N + 1 entries), targets and edge properties.
/// \pre rows.front() == 0, rows nondecreasing, rows.back() == targets.size() == properties.size().
inline Proximity_graph::Graph make_csr_graph(const std::vector<std::uint64_t>& rows,
                                             const std::vector<std::uint32_t>& targets,
                                             const std::vector<Proximity_edge>& properties)
{
    const auto n = static_cast<std::uint32_t>(rows.size() - 1);
    return Proximity_graph::Graph(boost::edges_are_sorted, Csr_edge_iterator(rows, targets, 0),
                                  Csr_edge_iterator(rows, targets, targets.size()), properties.begin(), n,
                                  targets.size());
}

} // namespace internal
} // namespace PCCD
