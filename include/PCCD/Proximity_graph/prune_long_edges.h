// PCCD/Proximity_graph/prune_long_edges.h -- the long-edge outlier test of doc/algorithms.md, "Long
// edges and virtual edges" (WSCG05 §3.2 and §4.5): edges far longer than the local edge scale are
// marked *virtual* rather than removed. The surface ignores virtual edges for its geodesic
// distances; the interpolation search may still walk them to bridge holes and boundaries.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <PCCD/Error.h>
#include <PCCD/Proximity_graph/graph_options.h>
#include <PCCD/concepts/ProximityGraph.h>

namespace PCCD {

namespace internal {

inline void check(const Long_edge_options& options)
{
    if (!std::isgreater(options.factor, 0.0))
        throw Invalid_input(internal::concat("long-edge factor must be > 0, got ", options.factor));
}

/// Median of the positive values in `values` (reordered); 0 when there is none.
inline double median_of_positive(std::vector<double>& values)
{
    const auto positive_end = std::partition(values.begin(), values.end(), [](double x) { return x > 0.0; });
    const auto count = positive_end - values.begin();
    if (count == 0) return 0.0;
    const auto middle = values.begin() + count / 2;
    std::nth_element(values.begin(), middle, positive_end);
    if (count % 2 == 1) return *middle;
    const double upper = *middle;
    const double lower = *std::max_element(values.begin(), middle);
    return 0.5 * (lower + upper);
}

} // namespace internal

/// Marks the long edges of `g` as virtual and the others as real: `put(is_virtual, e, flag)` for
/// every out-edge `e` of every vertex, with the test of Long_edge_options::factor (symmetric in the
/// two ends, so both stored directions of an edge get the same flag).
///
/// \tparam Graph a model of ProximityGraph with `LengthMap`; undirected, or directed with both
///         directions of every edge stored (as Proximity_graph::Graph).
/// \tparam LengthMap readable edge -> length map.
/// \tparam VirtualMap a model of WritableEdgeFlagMap (e.g. `get(&Proximity_edge::is_virtual, g)`).
/// \returns the number of undirected edges marked virtual (edges counted from their smaller end;
///          self-loops never count).
/// \throws Invalid_input if the factor is not > 0.
/// Complexity: O(E) expected (two passes of nth_element over the adjacency lists). Thread safety:
/// reads `g`; writes `is_virtual`, so no other thread may use that map meanwhile.
template <class Graph, class LengthMap, class VirtualMap>
    requires ProximityGraph<Graph, LengthMap> && WritableEdgeFlagMap<VirtualMap, Graph>
std::size_t mark_long_edges(const Graph& g, const LengthMap& length, VirtualMap is_virtual,
                            const Long_edge_options& options = {})
{
    internal::check(options);
    const std::size_t n = num_vertices(g);
    std::vector<double> own(n, 0.0), scale(n, 0.0);
    std::vector<double> values;
    for (auto [v, v_end] = vertices(g); v != v_end; ++v) {
        values.clear();
        for (auto [e, e_end] = out_edges(*v, g); e != e_end; ++e) values.push_back(double(get(length, *e)));
        own[std::size_t(*v)] = internal::median_of_positive(values);
    }
    for (auto [v, v_end] = vertices(g); v != v_end; ++v) {
        values.assign(1, own[std::size_t(*v)]);
        for (auto [e, e_end] = out_edges(*v, g); e != e_end; ++e) values.push_back(own[std::size_t(target(*e, g))]);
        scale[std::size_t(*v)] = internal::median_of_positive(values);
    }
    std::size_t marked = 0;
    for (auto [v, v_end] = vertices(g); v != v_end; ++v)
        for (auto [e, e_end] = out_edges(*v, g); e != e_end; ++e) {
            const auto u = std::size_t(source(*e, g));
            const auto w = std::size_t(target(*e, g));
            const bool is_long = double(get(length, *e)) > options.factor * std::min(scale[u], scale[w]);
            put(is_virtual, *e, is_long);
            if (is_long && u < w) ++marked;
        }
    return marked;
}

} // namespace PCCD
