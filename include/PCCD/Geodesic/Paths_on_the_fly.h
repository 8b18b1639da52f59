// PCCD/Geodesic/Paths_on_the_fly.h -- shortest paths computed at query time instead of stored
// (doc/manual/graphs.md, "Paths without storage"; WSCG05 Algorithm 2): the Paths_on_the_fly path
// policy, which keeps nothing beyond the graph and the point coordinates.
//
// WSCG05's Algorithm 2 is a best-first search from p1 whose priority is the geodesic distance to
// p2, read from a CPSP map that stores distances. PCCD's version needs no stored distance at all:
// it is an A* search whose priority is g(p1, x) + |x - p2|. The Euclidean distance never exceeds the
// geodesic one (edge lengths are Euclidean), so the heuristic is consistent and the path returned
// is a true shortest path, of the same length as the CPSP map's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <boost/graph/graph_traits.hpp>

#include <PCCD/Error.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/concepts/PathSource.h>
#include <PCCD/concepts/ProximityGraph.h>
#include <PCCD/concepts/PointCloudKernel.h>

namespace PCCD {

/// Options of Paths_on_the_fly.
struct Paths_on_the_fly_options {
    /// Walk virtual edges too. Default false (the same paths as a CPSP map built with defaults);
    /// the interpolation search may turn it on to bridge holes (WSCG05 §4.5).
    bool use_virtual_edges = false;
    /// Give up on paths longer than this (e.g. the CPSP bound eta * r(P)); default +infinity. With a
    /// finite bound a query costs O(m log m) for the m points within it; without one an unreachable
    /// target costs a search of its whole component. Must be > 0 (NaN is rejected).
    double bound = std::numeric_limits<double>::infinity();
};

/// Path policy computing each shortest path at query time by an A* search (see the header comment).
/// Models PathSource.
///
/// \tparam Graph a model of ProximityGraph with `LengthMap`, whose vertex i is point i of the
///         coordinates; directed models must store both directions of every edge.
/// \tparam VirtualMap a model of EdgeFlagMap.
/// \tparam FT the coordinate type.
/// \pre every edge length is at least the Euclidean distance between its ends, up to float
///      rounding (true of every PCCD graph), so that the A* estimate is a lower bound.
/// Refers to the graph, maps and coordinates, which must outlive it. Thread safety: path() is const
/// and allocates its own scratch, so concurrent queries are safe.
template <class Graph, class LengthMap, class VirtualMap = No_virtual_edges, class FT = double>
    requires ProximityGraph<Graph, LengthMap> && EdgeFlagMap<VirtualMap, Graph>
class Paths_on_the_fly {
public:
    using Index = std::uint32_t;
    using Coordinates = Eigen::Matrix<FT, 3, Eigen::Dynamic>;

    /// \throws Invalid_input if the bound is not > 0 or the coordinates do not match the graph.
    Paths_on_the_fly(const Graph& g, const LengthMap& length, const Coordinates& coordinates,
                     const Paths_on_the_fly_options& options = {}, const VirtualMap& is_virtual = {})
        : m_graph(&g), m_length(length), m_is_virtual(is_virtual), m_coordinates(&coordinates), m_options(options)
    {
        if (!std::isgreater(options.bound, 0.0))
            throw Invalid_input(internal::concat("paths on the fly: the bound must be > 0, got ", options.bound));
        if (std::size_t(coordinates.cols()) != std::size_t(num_vertices(g)))
            throw Invalid_input(internal::concat("paths on the fly: ", coordinates.cols(), " points but the graph has ",
                                                 num_vertices(g), " vertices"));
    }

    /// Writes a shortest path from `from` to `to` (both included) into `path` and returns true, or
    /// returns false with `path` empty when `to` is not reachable within the bound.
    /// Complexity: O(m log m), m the number of points whose g + Euclidean estimate stays below the
    /// path length (a thin ellipse-like region around the path).
    bool path(Index from, Index to, std::vector<Index>& path) const
    {
        using Vertex = typename boost::graph_traits<Graph>::vertex_descriptor;
        path.clear();
        struct State {
            double distance;
            Index parent;
            bool settled;
        };
        std::unordered_map<Index, State> states;
        using Item = std::pair<double, Index>; // (distance + heuristic, vertex)
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
        states[from] = State{0.0, from, false};
        open.push({heuristic(from, to), from});
        while (!open.empty()) {
            const Index u = open.top().second;
            open.pop();
            State& su = states[u];
            if (su.settled) continue;
            su.settled = true;
            if (u == to) {
                for (Index v = to;; v = states[v].parent) {
                    path.push_back(v);
                    if (v == from) break;
                }
                std::reverse(path.begin(), path.end());
                return true;
            }
            const double du = su.distance;
            for (auto [e, e_end] = out_edges(Vertex(u), *m_graph); e != e_end; ++e) {
                if (!m_options.use_virtual_edges && get(m_is_virtual, *e)) continue;
                const auto v = Index(target(*e, *m_graph));
                const double candidate = du + double(get(m_length, *e));
                const double estimate = candidate + heuristic(v, to);
                if (estimate > m_options.bound) continue;
                auto [it, inserted] = states.try_emplace(v, State{candidate, u, false});
                if (!inserted) {
                    if (it->second.settled || candidate >= it->second.distance) continue;
                    it->second.distance = candidate;
                    it->second.parent = u;
                }
                open.push({estimate, v});
            }
        }
        return false;
    }

private:
    double heuristic(Index a, Index b) const
    {
        // Stored edge lengths are rounded (to float in Proximity_graph); shrinking the Euclidean
        // estimate by far more than that rounding keeps it a lower bound of every path length.
        const auto& c = *m_coordinates;
        const double dx = double(c(0, a)) - double(c(0, b));
        const double dy = double(c(1, a)) - double(c(1, b));
        const double dz = double(c(2, a)) - double(c(2, b));
        return (1.0 - 1e-6) * std::sqrt(dx * dx + dy * dy + dz * dz);
    }

    const Graph* m_graph;
    LengthMap m_length;
    VirtualMap m_is_virtual;
    const Coordinates* m_coordinates;
    Paths_on_the_fly_options m_options;
};

/// Paths_on_the_fly over PCCD's default graph and the cloud it was built from.
template <PointCloudKernel K>
Paths_on_the_fly<Proximity_graph::Graph, Proximity_graph::Length_map, Proximity_graph::Virtual_map, typename K::FT>
paths_on_the_fly(const Proximity_graph& graph, const Point_cloud<K>& cloud, const Paths_on_the_fly_options& options = {})
{
    return {graph.graph(), graph.length_map(), cloud.coordinates(), options, graph.virtual_map()};
}

} // namespace PCCD
