// PCCD/concepts/ProximityGraph.h -- concept of the graphs PCCD walks for geodesic distances and
// shortest paths (doc/algorithms.md, "Proximity graphs and geodesic distance"): Boost.Graph models
// with an edge weight map.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>

#include <boost/graph/graph_concepts.hpp>
#include <boost/graph/graph_traits.hpp>

namespace PCCD {

/// \concept PointGraph
/// A Boost.Graph model over the points of a cloud (vertex `i` is point `i`), without weights: what
/// the walks that need only the adjacency use (orient_normals()).
///
/// Requirements, for `const G& g`, a vertex `v` and an edge `e`:
/// - `boost::graph_traits<G>::traversal_category` converts to both
///   `boost::vertex_list_graph_tag` and `boost::incidence_graph_tag`;
/// - the vertex descriptor is an integral type (vertex `i` is point `i`);
/// - `num_vertices(g)`, `vertices(g)`, `out_edges(v, g)`, `out_degree(v, g)`, `source(e, g)`,
///   `target(e, g)` as in BGL's VertexListGraph and IncidenceGraph concepts.
///
/// Models: every ProximityGraph's graph type.
template <class G>
concept PointGraph = requires(const G& g, typename boost::graph_traits<G>::vertex_descriptor v,
                              typename boost::graph_traits<G>::edge_descriptor e) {
    requires std::is_convertible_v<typename boost::graph_traits<G>::traversal_category, boost::vertex_list_graph_tag>;
    requires std::is_convertible_v<typename boost::graph_traits<G>::traversal_category, boost::incidence_graph_tag>;
    requires std::integral<typename boost::graph_traits<G>::vertex_descriptor>;
    { num_vertices(g) } -> std::convertible_to<std::size_t>;
    vertices(g);
    out_edges(v, g);
    { out_degree(v, g) } -> std::convertible_to<std::size_t>;
    { source(e, g) } -> std::convertible_to<typename boost::graph_traits<G>::vertex_descriptor>;
    { target(e, g) } -> std::convertible_to<typename boost::graph_traits<G>::vertex_descriptor>;
};

/// \concept ProximityGraph
/// A PointGraph with edge lengths: the graphs PCCD walks for geodesic distances and shortest paths.
///
/// Requirements: `G` models PointGraph, and for an edge `e` and `const WeightMap& w`, `get(w, e)`
/// returns the edge's length, convertible to double (a readable property map).
///
/// Edges are undirected: a directed model must store both directions of every edge with the same
/// length (as PCCD::Proximity_graph::Graph does), an undirectedS model stores each edge once. Lengths
/// are >= 0 and, for the A* of Paths_on_the_fly, not shorter than the Euclidean distance of the ends.
///
/// Models: boost::compressed_sparse_row_graph<boost::directedS, ...> (PCCD's default storage,
/// PCCD::Proximity_graph::Graph with Proximity_graph::Length_map) and
/// boost::adjacency_list<vecS, vecS, ...>, each with its weight map.
template <class G, class WeightMap>
concept ProximityGraph = PointGraph<G> && requires(typename boost::graph_traits<G>::edge_descriptor e, const WeightMap& w) {
    { get(w, e) } -> std::convertible_to<double>;
};

/// \concept EdgeFlagMap
/// A readable property map from the edges of graph `G` to a flag, used for the "virtual" mark of
/// long edges (doc/algorithms.md, "Long edges and virtual edges").
///
/// Requirement, for `const M& m` and an edge `e` of `G`: `get(m, e)` is convertible to bool.
///
/// Models: the bundled-member map `get(&Proximity_edge::is_virtual, g)` of PCCD's default graph,
/// PCCD::No_virtual_edges (every edge is real; the default for user graphs), and any Boost
/// property map over edges with a bool value (e.g. an adjacency_list's bundled or interior bool
/// property).
template <class M, class G>
concept EdgeFlagMap = requires(const M& m, typename boost::graph_traits<G>::edge_descriptor e) {
    { get(m, e) } -> std::convertible_to<bool>;
};

/// \concept WritableEdgeFlagMap
/// An EdgeFlagMap that can also be written: where mark_long_edges() records which edges are long.
///
/// Requirements: `M` models EdgeFlagMap for `G`, and for `M& m`, an edge `e` of `G` and a bool
/// `b`, `put(m, e, b)` sets the flag of `e` (a writable property map; copies of `m` write to the
/// same storage, since the map is taken by value).
///
/// Models: the bundled-member map `get(&Proximity_edge::is_virtual, g)` of PCCD's default graph,
/// and any Boost read-write property map over edges with a bool value.
template <class M, class G>
concept WritableEdgeFlagMap = EdgeFlagMap<M, G> && requires(M& m, typename boost::graph_traits<G>::edge_descriptor e, bool b) {
    put(m, e, b);
};

} // namespace PCCD
