// PCCD/Geodesic/internal/cpsp_build.h -- building the CPSP map's flat arrays (doc/manual/graphs.md,
// "The CPSP map"): one bounded Dijkstra per source, run in breadth-first order by blocks (in
// parallel with TBB), then the lists scattered into point order behind one offset per point.
#pragma once

#include <algorithm>
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

/// The lists of every source of `g` bounded at `bound`, by blocks of cpsp_block_size sources taken
/// in `order` (source k of the search is vertex order[k]); `hand_written` picks the routine.
template <class Graph, class LengthMap, class VirtualMap>
std::vector<Cpsp_block> search_cpsp_blocks(const Graph& g, const LengthMap& length, const VirtualMap& is_virtual,
                                           bool use_virtual, bool hand_written, double bound, std::optional<unsigned> threads,
                                           const std::vector<std::uint32_t>& order)
{
    const std::size_t n = num_vertices(g);
    // The type get(length, e) gives (ProximityGraph asks no property_traits of the map).
    using Edge = typename boost::graph_traits<Graph>::edge_descriptor;
    using Length = std::conditional_t<
        std::is_same_v<std::remove_cvref_t<decltype(get(length, std::declval<Edge>()))>, float>, float, double>;
    Compact_graph<Length> compact;
    if (hand_written) compact = make_compact_graph<Length>(g, length, is_virtual, use_virtual, order);
    std::vector<Cpsp_block> blocks;
    blocks.reserve((n + cpsp_block_size - 1) / cpsp_block_size);
    Per_thread<Dijkstra_workspace> workspaces;
    with_threads(threads, [&] {
        ordered_blocks(
            n, cpsp_block_size,
            [&](std::size_t begin, std::size_t end) {
                Dijkstra_workspace& ws = workspaces.local();
                ws.prepare(n);
                Cpsp_block block;
                block.sizes.reserve(end - begin);
                for (std::size_t k = begin; k < end; ++k) {
                    const std::size_t before = block.lists.targets.size();
                    // The compact graph numbers vertices in breadth-first order: source k there is
                    // order[k] here.
                    if (hand_written)
                        hand_written_bounded_dijkstra(compact, bound, std::uint32_t(k), ws, block.lists);
                    else
                        boost_bounded_dijkstra(g, length, is_virtual, use_virtual, bound, order[k], ws, block.lists);
                    ws.reset();
                    block.sizes.push_back(block.lists.targets.size() - before);
                }
                // The lists grew by doubling: without the slack, all blocks together take no more
                // than the final arrays (the peak memory of the build is both at once).
                block.lists.targets.shrink_to_fit();
                block.lists.distances.shrink_to_fit();
                block.lists.predecessors.shrink_to_fit();
                return block;
            },
            [&](Cpsp_block block) { blocks.push_back(std::move(block)); });
    });
    return blocks;
}

/// One array of the blocks' lists scattered into point order (block b's i-th list is point
/// order[b * block size + i]); each block's part is released as soon as copied.
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
        std::vector<T>().swap(from); // release as soon as copied
    }
    return out;
}

/// The blocks' lists scattered into point order, one array at a time, so that the peak memory is
/// the blocks plus one array (not plus all three).
inline Cpsp_arrays scatter_cpsp_blocks(std::vector<Cpsp_block>& blocks, const std::vector<std::uint32_t>& order)
{
    const std::size_t n = order.size();
    Cpsp_arrays a;
    a.offsets.assign(n + 1, 0);
    for (std::size_t b = 0; b < blocks.size(); ++b)
        for (std::size_t i = 0; i < blocks[b].sizes.size(); ++i)
            a.offsets[std::size_t(order[b * cpsp_block_size + i]) + 1] = blocks[b].sizes[i];
    for (std::size_t p = 0; p < n; ++p) a.offsets[p + 1] += a.offsets[p];
    a.targets = scatter_cpsp_array(blocks, order, a.offsets, &Cpsp_list::targets);
    a.distances = scatter_cpsp_array(blocks, order, a.offsets, &Cpsp_list::distances);
    a.predecessors = scatter_cpsp_array(blocks, order, a.offsets, &Cpsp_list::predecessors);
    blocks.clear();
    return a;
}

/// The CPSP arrays of `g`: every vertex's list of the vertices within `bound`, nearest first.
template <class Graph, class LengthMap, class VirtualMap>
Cpsp_arrays build_cpsp_arrays(const Graph& g, const LengthMap& length, const VirtualMap& is_virtual,
                              bool use_virtual, bool hand_written, double bound, std::optional<unsigned> threads)
{
    // Sources run in breadth-first order (for cache locality) by blocks; the lists are then
    // scattered into point order.
    const std::vector<std::uint32_t> order = breadth_first_order(g);
    std::vector<Cpsp_block> blocks =
        search_cpsp_blocks(g, length, is_virtual, use_virtual, hand_written, bound, threads, order);
    return scatter_cpsp_blocks(blocks, order);
}

} // namespace PCCD::internal
