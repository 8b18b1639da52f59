// PCCD/Geodesic/Close_pairs_shortest_paths.h -- the close-pairs shortest-paths (CPSP) map of
// ALGORITHMS.md section 2 (PBG04, WSCG05 §3.2): for every point, the points reachable in the
// proximity graph within the kernel's support radius eta * r(P) (section 1), sorted by geodesic
// distance, with the predecessor that rebuilds each shortest path. Also the Stored_paths path policy
// and the annulus search of the root bracketing (section 6.1).
//
// Storage is flat: one 64-bit offset per point, then per entry a 32-bit point id, a float distance
// and the 32-bit position of its predecessor in the same list (12 bytes per entry).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <PCCD/Error.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/concepts/ProximityGraph.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// Which bounded single-source shortest-path routine builds the CPSP map. Both give the same
/// distances; among equally short paths they may pick different predecessors.
enum class Bounded_dijkstra : std::uint8_t {
    /// PCCD's own Dijkstra: the searched edges are first read through the BGL interface into flat
    /// arrays with vertices renumbered in breadth-first order (for memory locality), then searched
    /// with a 4-ary heap (lazy deletion) and per-thread scratch reset only where touched. The
    /// default: the faster of the two (doc/benchmarks.md).
    hand_written = 0,
    /// boost::dijkstra_shortest_paths_no_color_map_no_init with a combine function that saturates
    /// to +infinity beyond the bound, so vertices past the support radius are never queued and the
    /// search stops by itself.
    boost = 1,
};

/// Options of the CPSP map.
struct Cpsp_options {
    /// eta: the search bound in units of the sampling radius r(P); the bound is eta * r(P), the
    /// support of the Gaussian kernel with h = eta r / sqrt(-ln theta_eps) (ALGORITHMS.md section 1).
    /// Default 3, the implicit surface's default eta (chosen by measurement, doc/manual/surface.md).
    /// Must be > 0.
    double support = 3.0;
    /// Walk virtual edges too. Default false: the surface's geodesic distances ignore them.
    bool use_virtual_edges = false;
    /// The bounded Dijkstra implementation (default: the faster, hand-written one).
    Bounded_dijkstra algorithm = Bounded_dijkstra::hand_written;
    /// Worker threads; 0 (default) uses all available. Ignored without TBB. The result does not
    /// depend on it.
    unsigned threads = 0;
};

namespace internal {

/// First index i in [0, n) with !(a[i] < key) (lower bound) or, if `upper`, with a[i] > key, by
/// interpolation search over the sorted array `a`, alternating with bisection so that the worst
/// case stays O(log n) while uniform-like data take O(log log n) probes.
inline std::size_t interpolation_bound(const float* a, std::size_t n, double key, bool upper)
{
    auto before = [&](float value) { return upper ? double(value) <= key : double(value) < key; };
    std::size_t lo = 0, hi = n;
    for (bool bisect = false; lo < hi; bisect = !bisect) {
        if (!before(a[lo])) return lo;
        if (before(a[hi - 1])) return hi;
        // Now a[lo] is before the key and a[hi - 1] is not, so lo < hi - 1 and a[lo] < a[hi - 1].
        std::size_t probe;
        if (bisect) {
            probe = lo + (hi - 1 - lo) / 2;
        } else {
            const double fraction = (key - double(a[lo])) / (double(a[hi - 1]) - double(a[lo]));
            probe = lo + std::size_t(std::clamp(fraction, 0.0, 1.0) * double(hi - 1 - lo));
        }
        probe = std::clamp(probe, lo + 1, hi - 1);
        if (before(a[probe])) lo = probe + 1;
        else hi = probe;
    }
    return lo;
}

/// One source's list while it is being built.
struct Cpsp_list {
    std::vector<std::uint32_t> targets;
    std::vector<float> distances;
    std::vector<std::uint32_t> predecessors;
};

/// A 4-ary min-heap of (distance, vertex), ties broken by vertex; shallower than a binary heap, so
/// fewer comparisons and cache lines per pop (measured faster than std::push_heap/pop_heap here).
class Quaternary_heap {
public:
    using Item = std::pair<double, std::uint32_t>;
    bool empty() const { return m_items.empty(); }
    void clear() { m_items.clear(); }
    void push(Item item)
    {
        std::size_t i = m_items.size();
        m_items.push_back(item);
        while (i > 0) {
            const std::size_t parent = (i - 1) / 4;
            if (!(item < m_items[parent])) break;
            m_items[i] = m_items[parent];
            i = parent;
        }
        m_items[i] = item;
    }
    Item pop()
    {
        const Item top = m_items.front();
        const Item last = m_items.back();
        m_items.pop_back();
        const std::size_t n = m_items.size();
        if (n == 0) return top;
        std::size_t i = 0;
        for (;;) {
            const std::size_t child = 4 * i + 1;
            if (child >= n) break;
            std::size_t best = child;
            const std::size_t end = std::min(child + 4, n);
            for (std::size_t c = child + 1; c < end; ++c)
                if (m_items[c] < m_items[best]) best = c;
            if (!(m_items[best] < last)) break;
            m_items[i] = m_items[best];
            i = best;
        }
        m_items[i] = last;
        return top;
    }

private:
    std::vector<Item> m_items;
};

/// Per-thread scratch of the bounded Dijkstra: one record per vertex (one cache line touched per
/// visited vertex), reset only where touched.
struct Dijkstra_workspace {
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    struct Vertex_state {
        double distance = std::numeric_limits<double>::infinity();
        std::uint32_t position = none; // position in the current list once settled
        std::uint32_t parent = 0;      // hand-written: position of the parent; boost: parent vertex
    };
    std::vector<Vertex_state> state;
    std::vector<std::uint32_t> touched;
    Quaternary_heap heap; // hand-written: the queue (lazy deletion of superseded entries)

    void prepare(std::size_t n)
    {
        if (state.size() != n) state.assign(n, Vertex_state());
    }
    void reset()
    {
        for (std::uint32_t v : touched) state[v] = Vertex_state();
        touched.clear();
    }
};

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

/// Edge weight for BGL's Dijkstra: the length, or +infinity for an excluded virtual edge.
template <class LengthMap, class VirtualMap>
struct Bounded_weight_map {
    using category = boost::readable_property_map_tag;
    using value_type = double;
    using reference = double;
    using key_type = typename boost::property_traits<LengthMap>::key_type;
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
    const Bounded_weight_map<LengthMap, VirtualMap> weight{length, is_virtual, use_virtual};
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

} // namespace internal

/// The CPSP map of a proximity graph: for every point p, the list of points q with geodesic
/// (shortest-path) distance g(p, q) <= bound = support * r(P), sorted by g, starting with p itself
/// at distance 0, each with the position of its predecessor on a shortest path from p.
///
/// Distances are accumulated in double along the graph's edge lengths and stored as floats; the
/// lists are sorted by the double distances (ties in the order the search settled them), so they are
/// non-decreasing in the stored floats too.
///
/// Thread safety: immutable after construction; all queries are const and safe to run concurrently.
class Close_pairs_shortest_paths {
public:
    using Index = std::uint32_t;
    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

    /// An empty map.
    Close_pairs_shortest_paths() = default;

    /// Runs a Dijkstra bounded at `options.support * sampling_radius` from every vertex of `g`.
    ///
    /// \tparam Graph a model of ProximityGraph with `LengthMap` (vertex i is point i); directed models
    ///         must store both directions of every edge.
    /// \tparam VirtualMap a model of EdgeFlagMap; virtual edges are skipped unless
    ///         `options.use_virtual_edges`.
    /// \pre edge lengths are >= 0 (geodesic lengths of a proximity graph).
    /// \throws Invalid_input if `sampling_radius` or `options.support` is not finite and > 0, or if
    ///         the graph has 2^32 - 1 vertices or more.
    /// Complexity: O(N m log m) for m the mean list length (constant for bounded support, so O(N));
    /// memory 8 + 12 m bytes per point. Parallel over sources with TBB.
    template <class Graph, class LengthMap, class VirtualMap = No_virtual_edges>
        requires(!std::is_same_v<Graph, Proximity_graph>) && ProximityGraph<Graph, LengthMap> &&
                EdgeFlagMap<VirtualMap, Graph>
    Close_pairs_shortest_paths(const Graph& g, const LengthMap& length, double sampling_radius,
                               const Cpsp_options& options = {}, const VirtualMap& is_virtual = {})
        : m_sampling_radius(sampling_radius), m_support(options.support)
    {
        if (!(std::isfinite(sampling_radius) && sampling_radius > 0.0))
            throw Invalid_input(internal::concat("CPSP map: the sampling radius must be finite and > 0, got ",
                                                 sampling_radius));
        if (!(std::isfinite(options.support) && options.support > 0.0))
            throw Invalid_input(
                internal::concat("CPSP map: the support factor eta must be finite and > 0, got ", options.support));
        const std::size_t n = num_vertices(g);
        if (n >= std::size_t(std::numeric_limits<Index>::max()))
            throw Invalid_input(internal::concat("CPSP map: the graph has ", n, " vertices; at most 2^32 - 2"));
        const double bound = this->bound();
        // Sources run in breadth-first order (for cache locality) by blocks; the lists are then
        // scattered into point order.
        const std::vector<Index> order = internal::breadth_first_order(g);
        using Length = std::conditional_t<
            std::is_same_v<std::remove_cvref_t<typename boost::property_traits<LengthMap>::value_type>, float>, float,
            double>;
        internal::Compact_graph<Length> compact;
        if (options.algorithm == Bounded_dijkstra::hand_written)
            compact = internal::make_compact_graph<Length>(g, length, is_virtual, options.use_virtual_edges, order);
        constexpr std::size_t block_size = 512;
        struct Block {
            internal::Cpsp_list lists;
            std::vector<std::uint64_t> sizes;
        };
        std::vector<Block> blocks;
        blocks.reserve((n + block_size - 1) / block_size);
        internal::Per_thread<internal::Dijkstra_workspace> workspaces;
        internal::with_threads(options.threads, [&] {
            internal::ordered_blocks(
                n, block_size,
                [&](std::size_t begin, std::size_t end) {
                    internal::Dijkstra_workspace& ws = workspaces.local();
                    ws.prepare(n);
                    Block block;
                    block.sizes.reserve(end - begin);
                    for (std::size_t k = begin; k < end; ++k) {
                        const std::size_t before = block.lists.targets.size();
                        // The compact graph numbers vertices in breadth-first order: source k there
                        // is order[k] here.
                        if (options.algorithm == Bounded_dijkstra::hand_written)
                            internal::hand_written_bounded_dijkstra(compact, bound, Index(k), ws, block.lists);
                        else
                            internal::boost_bounded_dijkstra(g, length, is_virtual, options.use_virtual_edges, bound,
                                                             order[k], ws, block.lists);
                        ws.reset();
                        block.sizes.push_back(block.lists.targets.size() - before);
                    }
                    return block;
                },
                [&](Block block) { blocks.push_back(std::move(block)); });
        });
        compact = {};
        m_offsets.assign(n + 1, 0);
        for (std::size_t b = 0; b < blocks.size(); ++b)
            for (std::size_t i = 0; i < blocks[b].sizes.size(); ++i)
                m_offsets[std::size_t(order[b * block_size + i]) + 1] = blocks[b].sizes[i];
        for (std::size_t p = 0; p < n; ++p) m_offsets[p + 1] += m_offsets[p];
        m_targets.resize(m_offsets[n]);
        m_distances.resize(m_offsets[n]);
        m_predecessors.resize(m_offsets[n]);
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            const internal::Cpsp_list& lists = blocks[b].lists;
            std::size_t from = 0;
            for (std::size_t i = 0; i < blocks[b].sizes.size(); ++i) {
                const std::size_t size = blocks[b].sizes[i];
                const std::uint64_t to = m_offsets[order[b * block_size + i]];
                std::copy_n(lists.targets.begin() + std::ptrdiff_t(from), size, m_targets.begin() + std::ptrdiff_t(to));
                std::copy_n(lists.distances.begin() + std::ptrdiff_t(from), size,
                            m_distances.begin() + std::ptrdiff_t(to));
                std::copy_n(lists.predecessors.begin() + std::ptrdiff_t(from), size,
                            m_predecessors.begin() + std::ptrdiff_t(to));
                from += size;
            }
            blocks[b] = Block(); // release as soon as copied
        }
    }

    /// The CPSP map of PCCD's default graph, over its non-virtual edges unless
    /// `options.use_virtual_edges`.
    Close_pairs_shortest_paths(const Proximity_graph& graph, double sampling_radius, const Cpsp_options& options = {})
        : Close_pairs_shortest_paths(graph.graph(), graph.length_map(), sampling_radius, options, graph.virtual_map())
    {
    }

    /// Takes stored arrays (used by the file reader, which validates them first).
    /// \pre offsets.front() == 0, offsets non-decreasing, offsets.back() == size of the other three
    ///      arrays; every list starts with its own point at distance 0, distances are non-decreasing
    ///      inside a list and predecessors point to earlier-or-equal positions of the same list.
    Close_pairs_shortest_paths(double sampling_radius, double support, std::vector<std::uint64_t> offsets,
                               std::vector<Index> targets, std::vector<float> distances,
                               std::vector<Index> predecessors)
        : m_sampling_radius(sampling_radius), m_support(support), m_offsets(std::move(offsets)),
          m_targets(std::move(targets)), m_distances(std::move(distances)), m_predecessors(std::move(predecessors))
    {
    }

    /// \name Size and parameters
    /// @{
    /// Number of points (lists).
    std::size_t size() const { return m_offsets.empty() ? 0 : m_offsets.size() - 1; }
    /// Total number of entries over all lists (each list includes its own point).
    std::size_t num_entries() const { return m_targets.size(); }
    double sampling_radius() const { return m_sampling_radius; }
    /// eta, the bound in units of the sampling radius.
    double support() const { return m_support; }
    /// The search bound, support() * sampling_radius().
    double bound() const { return m_support * m_sampling_radius; }
    /// Heap bytes held by the map.
    std::size_t memory_bytes() const
    {
        return m_offsets.size() * sizeof(std::uint64_t) + m_targets.size() * sizeof(Index) +
               m_distances.size() * sizeof(float) + m_predecessors.size() * sizeof(Index);
    }
    /// @}

    /// \name The list of point p (\pre p < size())
    /// @{
    /// The points within the bound, nearest first (entry 0 is p itself).
    std::span<const Index> targets(Index p) const { return slice(m_targets, p); }
    /// Their geodesic distances from p, non-decreasing.
    std::span<const float> distances(Index p) const { return slice(m_distances, p); }
    /// For each entry, the entry position of its predecessor on the stored shortest path (0 for p).
    std::span<const Index> predecessors(Index p) const { return slice(m_predecessors, p); }
    /// The entry position of q in p's list, or npos when q is beyond the bound. O(list length).
    std::size_t find(Index p, Index q) const
    {
        const auto t = targets(p);
        const auto it = std::find(t.begin(), t.end(), q);
        return it == t.end() ? npos : std::size_t(it - t.begin());
    }
    /// The shortest path from p to the target of `entry`, both included, written to `path` (cleared
    /// first). Consecutive points are joined by graph edges whose lengths sum to distances(p)[entry].
    /// \pre entry < targets(p).size(). O(path length).
    void path(Index p, std::size_t entry, std::vector<Index>& path) const
    {
        PCCD_precondition_msg(p < size() && entry < targets(p).size(), "CPSP path: entry out of range");
        const auto t = targets(p);
        const auto pred = predecessors(p);
        path.clear();
        for (;;) {
            path.push_back(t[entry]);
            if (entry == 0) break;
            entry = pred[entry];
        }
        std::reverse(path.begin(), path.end());
    }
    /// The entries of p's list whose distance lies in the annulus [d0, d1], as a half-open range of
    /// entry positions [first, last) (empty when d1 < d0). Found by interpolation search over the
    /// sorted distances: O(log log m) probes on evenly spread distances, O(log m) at worst.
    std::pair<std::size_t, std::size_t> annulus(Index p, double d0, double d1) const
    {
        const auto d = distances(p);
        const std::size_t first = internal::interpolation_bound(d.data(), d.size(), d0, false);
        if (d1 < d0) return {first, first};
        return {first, internal::interpolation_bound(d.data(), d.size(), d1, true)};
    }
    /// @}

    /// \name Raw arrays (serialization)
    /// @{
    const std::vector<std::uint64_t>& offsets() const { return m_offsets; }
    const std::vector<Index>& all_targets() const { return m_targets; }
    const std::vector<float>& all_distances() const { return m_distances; }
    const std::vector<Index>& all_predecessors() const { return m_predecessors; }
    /// @}

    friend bool operator==(const Close_pairs_shortest_paths&, const Close_pairs_shortest_paths&) = default;

private:
    template <class T>
    std::span<const T> slice(const std::vector<T>& v, Index p) const
    {
        PCCD_debug_precondition(p < size());
        return std::span<const T>(v.data() + m_offsets[p], std::size_t(m_offsets[p + 1] - m_offsets[p]));
    }

    double m_sampling_radius = 0.0;
    double m_support = 0.0;
    std::vector<std::uint64_t> m_offsets;
    std::vector<Index> m_targets;
    std::vector<float> m_distances;
    std::vector<Index> m_predecessors;
};

/// Path policy reading the shortest paths stored in a CPSP map (ALGORITHMS.md section 2). Models
/// PathSource. Cheap to copy; refers to the map, which must outlive it.
class Stored_paths {
public:
    using Index = std::uint32_t;
    explicit Stored_paths(const Close_pairs_shortest_paths& map) : m_map(&map) {}

    /// Writes the stored shortest path from `from` to `to` (both included) into `path` and returns
    /// true, or returns false (path cleared) when `to` is beyond the CPSP bound of `from`.
    /// O(list length + path length). Thread-safe.
    bool path(Index from, Index to, std::vector<Index>& path) const
    {
        const std::size_t entry = m_map->find(from, to);
        if (entry == Close_pairs_shortest_paths::npos) {
            path.clear();
            return false;
        }
        m_map->path(from, entry, path);
        return true;
    }

private:
    const Close_pairs_shortest_paths* m_map;
};

} // namespace PCCD
