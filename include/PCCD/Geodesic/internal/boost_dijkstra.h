// PCCD/Geodesic/internal/boost_dijkstra.h -- the CPSP map's alternative bounded search
// (Bounded_dijkstra::boost, doc/manual/graphs.md "The CPSP map"): BGL's Dijkstra without colour
// map over the per-thread workspace, with a combine function that saturates to +infinity beyond
// the bound so that the search stops by itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>

#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <PCCD/Geodesic/internal/dijkstra_workspace.h>

namespace PCCD::internal {

/// Read-write property map over one member of the workspace's vertex records (for BGL).
template <class T, T Dijkstra_workspace::Vertex_state::*member>
struct Workspace_map {
    using category = boost::read_write_property_map_tag;
    using value_type = T;
    using reference = T&;
    using key_type = std::size_t;
    Dijkstra_workspace* ws;
    friend T get(const Workspace_map& m, std::size_t v) { return m.ws->state[v].*member; }
    friend void put(const Workspace_map& m, std::size_t v, T value) { m.ws->state[v].*member = value; }
};

/// Edge weight for BGL's Dijkstra: the length, or +infinity for an excluded virtual edge.
template <class Graph, class LengthMap, class VirtualMap>
struct Bounded_weight_map {
    using category = boost::readable_property_map_tag;
    using value_type = double;
    using reference = double;
    using key_type = typename boost::graph_traits<Graph>::edge_descriptor;
    LengthMap length;
    VirtualMap is_virtual;
    bool use_virtual;
    friend double get(const Bounded_weight_map& m, const key_type& e)
    {
        return (!m.use_virtual && get(m.is_virtual, e)) ? std::numeric_limits<double>::infinity()
                                                        : double(get(m.length, e));
    }
};

template <class Graph, class LengthMap, class VirtualMap>
void boost_bounded_dijkstra(const Graph& g, const LengthMap& length, const VirtualMap& is_virtual, bool use_virtual,
                            double bound, std::uint32_t source, Dijkstra_workspace& ws, Cpsp_list& out)
{
    using Vertex = typename boost::graph_traits<Graph>::vertex_descriptor;
    const auto first = std::uint32_t(out.targets.size());
    struct Visitor : boost::default_dijkstra_visitor {
        Dijkstra_workspace* ws;
        Cpsp_list* out;
        std::uint32_t first;
        void discover_vertex(Vertex v, const Graph&) const { ws->touched.push_back(std::uint32_t(v)); }
        void examine_vertex(Vertex u, const Graph&) const
        {
            const auto uu = std::uint32_t(u);
            auto& su = ws->state[uu];
            su.position = std::uint32_t(out->targets.size()) - first;
            out->targets.push_back(uu);
            out->distances.push_back(float(su.distance));
            out->predecessors.push_back(ws->state[su.parent].position);
        }
    };
    Visitor visitor;
    visitor.ws = &ws;
    visitor.out = &out;
    visitor.first = first;
    ws.state[source].distance = 0.0;
    ws.state[source].parent = source;
    const auto identity = boost::typed_identity_property_map<Vertex>();
    using State = Dijkstra_workspace::Vertex_state;
    const Bounded_weight_map<Graph, LengthMap, VirtualMap> weight{length, is_virtual, use_virtual};
    // Saturating at the bound: a candidate beyond it is +infinity, never relaxed, never queued.
    auto combine = [bound](double a, double b) {
        const double sum = a + b;
        return sum <= bound ? sum : std::numeric_limits<double>::infinity();
    };
    boost::dijkstra_shortest_paths_no_color_map_no_init(
        g, Vertex(source), Workspace_map<std::uint32_t, &State::parent>{&ws},
        Workspace_map<double, &State::distance>{&ws}, weight, identity, std::less<double>(),
        combine, std::numeric_limits<double>::infinity(), 0.0, visitor);
}

} // namespace PCCD::internal
