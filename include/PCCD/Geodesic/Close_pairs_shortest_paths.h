// PCCD/Geodesic/Close_pairs_shortest_paths.h -- the close-pairs shortest-paths (CPSP) map of
// doc/manual/graphs.md ("The CPSP map"; PBG04, WSCG05 §3.2): for every point, the points reachable
// in the proximity graph within the kernel's support radius eta * r(P), sorted by geodesic
// distance, with the predecessor that rebuilds each shortest path, and the annulus search of the
// root bracketing. The bounded Dijkstra routines that build it are in Geodesic/internal/; the path
// policy reading it is Stored_paths (Geodesic/Stored_paths.h).
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

#include <boost/graph/graph_traits.hpp>

#include <PCCD/Error.h>
#include <PCCD/Geodesic/internal/cpsp_build.h>
#include <PCCD/Geodesic/internal/interpolation_bound.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/concepts/ProximityGraph.h>

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
    /// support of the Gaussian kernel with h = eta r / sqrt(-ln theta_eps) (doc/manual/surface.md).
    /// Default 3, the implicit surface's default eta (chosen by measurement, doc/manual/surface.md).
    /// Must be > 0.
    double support = 3.0;
    /// Walk virtual edges too. Default false: the surface's geodesic distances ignore them.
    bool use_virtual_edges = false;
    /// The bounded Dijkstra implementation (default: the faster, hand-written one).
    Bounded_dijkstra algorithm = Bounded_dijkstra::hand_written;
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

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
        internal::Cpsp_arrays arrays =
            internal::build_cpsp_arrays(g, length, is_virtual, options.use_virtual_edges,
                                        options.algorithm == Bounded_dijkstra::hand_written, bound(), options.threads);
        m_offsets = std::move(arrays.offsets);
        m_targets = std::move(arrays.targets);
        m_distances = std::move(arrays.distances);
        m_predecessors = std::move(arrays.predecessors);
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

} // namespace PCCD
