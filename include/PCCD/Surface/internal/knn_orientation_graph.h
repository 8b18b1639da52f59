// PCCD/Surface/internal/knn_orientation_graph.h -- the lean graph the normals of a lean object are
// oriented over (doc/manual/surface.md, "The lean object: the Euclidean kernel for large scans"):
// the symmetric k-nearest-neighbour graph as a bare compressed sparse row graph (32-bit indices,
// no edge lengths or flags, both directions of every pair, a pair found from both ends stored
// twice), filled from the k-NN lists by counting. It holds 4 (N + 1) + 8 k N bytes and needs 4 k N
// more while it is built (a Proximity_graph of the same points holds about twice that and needs
// about 490 bytes per point to build); orient_normals() reads only its structure.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/transform_iterator.hpp>

#include <PCCD/Error.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/internal/parallel.h>

namespace PCCD::internal {

/// A PointGraph of 32-bit vertices without edge properties.
using Orientation_graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, boost::no_property,
                                                             boost::no_property, std::uint32_t, std::uint32_t>;

/// Edge e of the symmetric graph over the k-NN lists `lists` (k per point, point i's at i k): for
/// e < k N the pair (i, lists[e]) with i = e / k, else the reverse of edge e - k N.
struct Knn_pair {
    const std::uint32_t* lists = nullptr;
    std::size_t k = 1, half = 0;
    std::pair<std::uint32_t, std::uint32_t> operator()(std::size_t e) const
    {
        if (e < half) return {std::uint32_t(e / k), lists[e]};
        e -= half;
        return {lists[e], std::uint32_t(e / k)};
    }
};

/// The symmetric k-NN graph of `cloud`: each point joined both ways to its k nearest other points
/// (ties by index). The k-NN queries run in parallel on `threads` (unset: all) when TBB is on; the
/// result does not depend on it. The graph is filled by two counting passes over the lists (no
/// sort, no edge array): the lists and the graph are alive together, 4 k N + 4 (N + 1) + 8 k N bytes.
/// \throws Invalid_input if k is 0 or 2 k N does not fit 32 bits.
template <class K>
Orientation_graph knn_orientation_graph(const Point_cloud<K>& cloud, unsigned k, std::optional<unsigned> threads)
{
    if (k == 0) throw Invalid_input("orientation graph: k must be >= 1, got 0");
    const std::size_t n = cloud.size();
    const std::size_t kk = std::max<std::size_t>(1, std::min<std::size_t>(k, n - 1));
    const std::size_t half = n * kk;
    if (2 * half >= std::size_t(UINT32_MAX))
        throw Invalid_input(internal::concat("orientation graph: ", n, " points with k = ", kk,
                                             " make more than 2^32 edges"));
    std::vector<std::uint32_t> lists(half);
    with_threads(threads, [&] {
        Per_thread<std::vector<typename Point_cloud<K>::Neighbor>> buffers;
        parallel_for_ranges(n, 1024, [&](std::size_t begin, std::size_t end) {
            auto& found = buffers.local();
            for (std::size_t i = begin; i < end; ++i) {
                cloud.k_nearest(cloud.position(std::uint32_t(i)), kk + 1, found);
                std::size_t m = 0;
                for (const auto& nb : found)
                    if (nb.index != i && m < kk) lists[i * kk + m++] = nb.index;
                // Fewer than k others (more than k coincident copies): the point itself fills in.
                for (; m < kk; ++m) lists[i * kk + m] = std::uint32_t(i);
            }
        });
    });
    const Knn_pair pair{lists.data(), kk, half};
    const auto first = boost::make_transform_iterator(boost::counting_iterator<std::size_t>(0), pair);
    const auto last = boost::make_transform_iterator(boost::counting_iterator<std::size_t>(2 * half), pair);
    return Orientation_graph(boost::edges_are_unsorted_multi_pass, first, last, n);
}

} // namespace PCCD::internal
