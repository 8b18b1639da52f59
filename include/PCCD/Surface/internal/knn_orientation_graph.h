// PCCD/Surface/internal/knn_orientation_graph.h -- the lean graph the normals of a lean object are
// oriented over (doc/manual/surface.md, "The lean object: the Euclidean kernel for large scans"):
// the symmetric k-nearest-neighbour graph as a bare compressed sparse row graph (32-bit indices,
// no edge lengths or flags, both directions of every pair, each pair once each way), filled from
// the k-NN lists by counting, from a cloud or from the lists of its local spacing. It holds at most
// 4 (N + 1) + 8 k N bytes (about 5.5 k N on scans, where most pairs are on both lists) and needs
// the 4 k N of the lists while it is built (a Proximity_graph of the same points holds about twice
// that and needs about 490 bytes per point to build); orient_normals() reads only its structure.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/filter_iterator.hpp>
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

/// Whether edge e of Knn_pair is kept: every edge (i, j) of a list, and the reverse (j, i) only
/// when i is not on j's list (which then holds the edge (j, i) already): each pair once per
/// direction.
struct Knn_pair_kept {
    const std::uint32_t* lists = nullptr;
    std::size_t k = 1, half = 0;
    bool operator()(std::size_t e) const
    {
        if (e < half) return true;
        e -= half;
        const std::uint32_t i = std::uint32_t(e / k);
        const std::uint32_t* list_j = lists + std::size_t(lists[e]) * k;
        return std::find(list_j, list_j + k, i) == list_j + k;
    }
};

/// The symmetric graph of the k-NN lists `lists` of n points (k per point, point i's at i k): each
/// point joined both ways to the points on its list, a pair on both lists once each way. The graph
/// is filled by two counting passes over the lists (no sort, no edge array): the lists and the
/// graph are alive together, 4 k N + 4 (N + 1) + at most 8 k N bytes.
/// \throws Invalid_input if the lists do not hold k per point, or 2 k N does not fit 32 bits.
inline Orientation_graph knn_orientation_graph(const std::vector<std::uint32_t>& lists, std::size_t k, std::size_t n)
{
    const std::size_t half = n * k;
    if (k == 0 || lists.size() != half)
        throw Invalid_input(internal::concat("orientation graph: ", lists.size(), " list entries for ", n,
                                             " points with k = ", k));
    if (2 * half >= std::size_t(UINT32_MAX))
        throw Invalid_input(internal::concat("orientation graph: ", n, " points with k = ", k,
                                             " make more than 2^32 edges"));
    const Knn_pair pair{lists.data(), k, half};
    const Knn_pair_kept keep{lists.data(), k, half};
    const auto kept = [&](std::size_t e) {
        return boost::make_filter_iterator(keep, boost::counting_iterator<std::size_t>(e),
                                           boost::counting_iterator<std::size_t>(2 * half));
    };
    const auto first = boost::make_transform_iterator(kept(0), pair);
    const auto last = boost::make_transform_iterator(kept(2 * half), pair);
    return Orientation_graph(boost::edges_are_unsorted_multi_pass, first, last, n);
}

/// The number of neighbours per point of knn_orientation_graph(cloud, k, threads): k, at most N - 1
/// and at least 1.
inline std::size_t orientation_graph_k(unsigned k, std::size_t n)
{
    return std::max<std::size_t>(1, std::min<std::size_t>(k, n - 1));
}

/// The symmetric k-NN graph of `cloud`: each point joined both ways to its k nearest other points
/// (ties by index), a pair that is on both lists once each way. The k-NN queries run in parallel on
/// `threads` (unset: all) when TBB is on; the result does not depend on it. The same graph as
/// knn_orientation_graph(lists, k, N) of the lists of local_spacing(cloud, k, true).
/// \throws Invalid_input if k is 0 or 2 k N does not fit 32 bits.
template <class K>
Orientation_graph knn_orientation_graph(const Point_cloud<K>& cloud, unsigned k, std::optional<unsigned> threads)
{
    if (k == 0) throw Invalid_input("orientation graph: k must be >= 1, got 0");
    const std::size_t n = cloud.size();
    const std::size_t kk = orientation_graph_k(k, n);
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
    return knn_orientation_graph(lists, kk, n);
}

} // namespace PCCD::internal
