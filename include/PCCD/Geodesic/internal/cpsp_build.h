// PCCD/Geodesic/internal/cpsp_build.h -- building the CPSP map's flat arrays (doc/manual/graphs.md,
// "The CPSP map"): one bounded Dijkstra per source on a copy of the graph renumbered breadth-first,
// by blocks of sources (in parallel with TBB): in point order, each block's lists appended to the
// final arrays as it arrives, when the points are in a local order; otherwise breadth-first, the
// lists scattered into point order at the end; one offset per point.
#pragma once

#include <algorithm>
#include <cmath>
#include <new>
#include <numeric>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/graph/graph_traits.hpp>

#include <PCCD/Geodesic/internal/boost_dijkstra.h>
#include <PCCD/Geodesic/internal/breadth_first_order.h>
#include <PCCD/Geodesic/internal/dijkstra_workspace.h>
#include <PCCD/Geodesic/internal/hand_written_dijkstra.h>
#include <PCCD/internal/parallel.h>

namespace PCCD::internal {

/// The flat arrays of a CPSP map: list p is entries [offsets[p], offsets[p + 1]).
struct Cpsp_arrays {
    std::vector<std::uint64_t> offsets;
    std::vector<std::uint32_t> targets;
    std::vector<float> distances;
    std::vector<std::uint32_t> predecessors;
};

/// The lists of a block of consecutive sources (in search order), one after the other.
struct Cpsp_block {
    Cpsp_list lists;
    std::vector<std::uint64_t> sizes;
};

/// Sources per block of the parallel build.
inline constexpr std::size_t cpsp_block_size = 512;

/// The lists of sources k in [begin, end), one after the other, with their sizes: source k is point
/// `order[k]` (point k when `order` is empty); `rank[p]`: point p's vertex in the compact graph
/// (hand-written searches).
template <class Graph, class LengthMap, class VirtualMap, class Length>
Cpsp_block search_cpsp_sources(const Graph& g, const LengthMap& length, const VirtualMap& is_virtual, bool use_virtual,
                               const Compact_graph<Length>* compact, const std::vector<std::uint32_t>& rank,
                               const std::vector<std::uint32_t>& order, double bound, std::size_t begin,
                               std::size_t end, Dijkstra_workspace& ws)
{
    ws.prepare(num_vertices(g));
    Cpsp_block block;
    block.sizes.reserve(end - begin);
    for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t p = order.empty() ? std::uint32_t(k) : order[k];
        const std::size_t before = block.lists.targets.size();
        if (compact)
            hand_written_bounded_dijkstra(*compact, bound, rank[p], ws, block.lists);
        else
            boost_bounded_dijkstra(g, length, is_virtual, use_virtual, bound, p, ws, block.lists);
        ws.reset();
        block.sizes.push_back(block.lists.targets.size() - before);
    }
    return block;
}

/// One array of blocks of lists in search order scattered into point order (block b's i-th list
/// is point order[b * block size + i]); each block's part is released as soon as copied.
template <class T>
std::vector<T> scatter_cpsp_array(std::vector<Cpsp_block>& blocks, const std::vector<std::uint32_t>& order,
                                  const std::vector<std::uint64_t>& offsets, std::vector<T> Cpsp_list::*member)
{
    std::vector<T> out(offsets.back());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        std::vector<T>& from = blocks[b].lists.*member;
        std::size_t at = 0;
        for (std::size_t i = 0; i < blocks[b].sizes.size(); ++i) {
            const std::size_t size = blocks[b].sizes[i];
            std::copy_n(from.begin() + std::ptrdiff_t(at), size,
                        out.begin() + std::ptrdiff_t(offsets[order[b * cpsp_block_size + i]]));
            at += size;
        }
        std::vector<T>().swap(from);
    }
    return out;
}

/// Whether consecutive points lie close in the breadth-first numbering (mean rank step below N/8),
/// as in a cloud stored in spatial order: then searches taken in point order stay in cache.
inline bool point_order_is_local(const std::vector<std::uint32_t>& rank)
{
    if (rank.size() < 2) return true;
    double steps = 0.0;
    for (std::size_t p = 1; p < rank.size(); ++p) steps += std::abs(double(rank[p]) - double(rank[p - 1]));
    return steps / double(rank.size() - 1) < double(rank.size()) / 8.0;
}

/// Room for the arrays' entries: 1.5 times the mean list size of 64 sources spread over the
/// points (deterministic), times N. Reserved memory is only address space until it is written, so
/// the slack costs no resident memory, while the lists are appended without a reallocation (whose
/// copy would hold the arrays twice) unless the estimate falls short.
template <class Search>
void reserve_cpsp_arrays(Cpsp_arrays& a, std::size_t n, const Search& search_one)
{
    const std::size_t probes = std::min<std::size_t>(n, 64);
    std::size_t entries = 0;
    for (std::size_t k = 0; k < probes; ++k) entries += search_one(k * n / probes);
    const double per_source = probes == 0 ? 0.0 : double(entries) / double(probes);
    const std::size_t room = std::size_t(std::ceil(1.5 * per_source * double(n))) + 4096;
    try {
        a.targets.reserve(room);
        a.distances.reserve(room);
        a.predecessors.reserve(room);
    } catch (const std::bad_alloc&) { // no such address space: grow as needed
    }
}

/// The CPSP arrays of `g`: every vertex's list of the vertices within `bound`, nearest first.
/// The searches run on a copy of the graph renumbered breadth-first, so that each touches nearby
/// memory. When the points' own order is local (a cloud in spatial order), the sources are taken in
/// point order and each block of lists is appended to the final arrays as it arrives: the arrays are
/// held once. Otherwise (e.g. points in random order, where consecutive searches in point order
/// would each start cold: 1.8x slower at 10^6 points) the sources are taken breadth-first and the
/// blocks are scattered into point order at the end, holding the lists twice for a moment.
template <class Graph, class LengthMap, class VirtualMap>
Cpsp_arrays build_cpsp_arrays(const Graph& g, const LengthMap& length, const VirtualMap& is_virtual,
                              bool use_virtual, bool hand_written, double bound, std::optional<unsigned> threads)
{
    const std::size_t n = num_vertices(g);
    // The type get(length, e) gives (ProximityGraph asks no property_traits of the map).
    using Edge = typename boost::graph_traits<Graph>::edge_descriptor;
    using Length = std::conditional_t<
        std::is_same_v<std::remove_cvref_t<decltype(get(length, std::declval<Edge>()))>, float>, float, double>;
    std::vector<std::uint32_t> order = breadth_first_order(g);
    std::vector<std::uint32_t> rank(n);
    for (std::size_t k = 0; k < n; ++k) rank[order[k]] = std::uint32_t(k);
    Compact_graph<Length> compact;
    if (hand_written) compact = make_compact_graph<Length>(g, length, is_virtual, use_virtual, order);
    const Compact_graph<Length>* searched = hand_written ? &compact : nullptr;
    const bool in_point_order = point_order_is_local(rank);
    if (in_point_order) order.clear(); // source k is point k
    const auto search = [&](std::size_t begin, std::size_t end, Dijkstra_workspace& ws) {
        return search_cpsp_sources(g, length, is_virtual, use_virtual, searched, rank, order, bound, begin, end, ws);
    };

    Cpsp_arrays a;
    a.offsets.assign(n + 1, 0);
    std::vector<Cpsp_block> blocks; // breadth-first sources only
    if (in_point_order) {
        Dijkstra_workspace ws;
        reserve_cpsp_arrays(a, n, [&](std::size_t p) { return search(p, p + 1, ws).lists.targets.size(); });
    } else {
        blocks.reserve((n + cpsp_block_size - 1) / cpsp_block_size);
    }
    Per_thread<Dijkstra_workspace> workspaces;
    std::size_t next = 0; // point order: the first source of the next block to arrive
    with_threads(threads, [&] {
        ordered_blocks(
            n, cpsp_block_size,
            [&](std::size_t begin, std::size_t end) {
                Cpsp_block block = search(begin, end, workspaces.local());
                if (!in_point_order) { // held until the end: without the lists' growth slack
                    block.lists.targets.shrink_to_fit();
                    block.lists.distances.shrink_to_fit();
                    block.lists.predecessors.shrink_to_fit();
                }
                return block;
            },
            [&](Cpsp_block block) {
                if (!in_point_order) {
                    blocks.push_back(std::move(block));
                    return;
                }
                a.targets.insert(a.targets.end(), block.lists.targets.begin(), block.lists.targets.end());
                a.distances.insert(a.distances.end(), block.lists.distances.begin(), block.lists.distances.end());
                a.predecessors.insert(a.predecessors.end(), block.lists.predecessors.begin(),
                                      block.lists.predecessors.end());
                for (const std::uint64_t size : block.sizes) {
                    a.offsets[next + 1] = a.offsets[next] + size;
                    ++next;
                }
            });
    });
    compact = Compact_graph<Length>(); // the searches are done: free the copy before the arrays are assembled
    std::vector<std::uint32_t>().swap(rank);
    if (in_point_order) return a;
    for (std::size_t b = 0; b < blocks.size(); ++b)
        for (std::size_t i = 0; i < blocks[b].sizes.size(); ++i)
            a.offsets[std::size_t(order[b * cpsp_block_size + i]) + 1] = blocks[b].sizes[i];
    for (std::size_t p = 0; p < n; ++p) a.offsets[p + 1] += a.offsets[p];
    // One array at a time: the peak is the blocks plus one array, not plus all three.
    a.targets = scatter_cpsp_array(blocks, order, a.offsets, &Cpsp_list::targets);
    a.distances = scatter_cpsp_array(blocks, order, a.offsets, &Cpsp_list::distances);
    a.predecessors = scatter_cpsp_array(blocks, order, a.offsets, &Cpsp_list::predecessors);
    return a;
}

} // namespace PCCD::internal
