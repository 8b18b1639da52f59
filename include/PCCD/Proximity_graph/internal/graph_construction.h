// PCCD/Proximity_graph/internal/graph_construction.h -- the machinery shared by knn_graph() and
// sphere_of_influence_graph() (doc/algorithms.md, "Sphere-of-influence graphs"): grouping
// coincident points, a kd-tree over the distinct positions, and the assembly of a symmetric CSR
// graph from a list of undirected edges.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Kd_tree.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Proximity_graph/prune_long_edges.h>
#include <PCCD/internal/parallel.h>
#include <PCCD/internal/spatial_order.h>

namespace PCCD::internal {

/// Euclidean distance between columns `a` and `b`, in double. The graph builders and their tests
/// use this one formula so that edge tests agree to the last bit.
template <class Coordinates>
inline double point_distance(const Coordinates& c, std::uint32_t a, std::uint32_t b)
{
    const double dx = double(c(0, a)) - double(c(0, b));
    const double dy = double(c(1, a)) - double(c(1, b));
    const double dz = double(c(2, a)) - double(c(2, b));
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}


/// An undirected edge found by a builder, between two original point indices.
struct Found_edge {
    std::uint32_t a, b;
    float length;
};

/// The distinct positions of a cloud. Coincident points (equal coordinates) form a group whose
/// representative is its smallest index; graphs are defined over the representatives and every other
/// member of a group is joined to its representative by one zero-length edge.
template <class FT>
struct Distinct_positions {
    using Coordinates = Eigen::Matrix<FT, 3, Eigen::Dynamic>;
    /// representative[i]: the smallest index at the position of point i.
    std::vector<std::uint32_t> representative;
    /// The representatives in increasing order (== 0..N-1 when there are no coincident points).
    std::vector<std::uint32_t> unique;
    /// A kd-tree over the representatives' positions (only when some points coincide); its index k
    /// is point unique[k].
    std::unique_ptr<Kd_tree<FT>> own_tree;

    bool has_duplicates() const { return own_tree != nullptr; }
};

/// Graph edge lengths (and CPSP distances) are stored as float: a cloud whose bounding box
/// diagonal exceeds float's range would give infinite lengths and no usable geometry.
template <class K>
void check_extent_fits_float(const Point_cloud<K>& cloud)
{
    const double diagonal = (cloud.bbox().max() - cloud.bbox().min()).template cast<double>().norm();
    if (std::isgreater(diagonal, double(std::numeric_limits<float>::max()) / 4.0))
        throw Invalid_input(concat("proximity graph: the cloud's extent (bounding box diagonal ", diagonal,
                                   ") is beyond the float range of edge lengths; rescale the cloud, e.g. with "
                                   "PCCD::normalize_to_unit_cube"));
}

template <class K>
Distinct_positions<typename K::FT> find_distinct_positions(const Point_cloud<K>& cloud)
{
    check_extent_fits_float(cloud);
    using FT = typename K::FT;
    const auto& c = cloud.coordinates();
    const auto n = static_cast<std::uint32_t>(cloud.size());
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
        for (int d = 0; d < 3; ++d)
            if (c(d, a) != c(d, b)) return c(d, a) < c(d, b);
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    Distinct_positions<FT> result;
    result.representative.resize(n);
    bool duplicates = false;
    for (std::size_t s = 0; s < n;) {
        std::size_t t = s + 1;
        while (t < n && c.col(order[t]) == c.col(order[s])) ++t;
        // order is sorted by index inside a group, so order[s] is the smallest index.
        for (std::size_t u = s; u < t; ++u) result.representative[order[u]] = order[s];
        duplicates = duplicates || t - s > 1;
        s = t;
    }
    result.unique.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i)
        if (result.representative[i] == i) result.unique.push_back(i);
    if (duplicates) {
        typename Distinct_positions<FT>::Coordinates u(3, Eigen::Index(result.unique.size()));
        for (std::size_t k = 0; k < result.unique.size(); ++k) u.col(Eigen::Index(k)) = c.col(result.unique[k]);
        result.own_tree = std::make_unique<Kd_tree<FT>>(std::move(u));
    }
    return result;
}

/// The kd-tree to query for distinct positions: the cloud's own, or the one over representatives.
template <class K>
const Kd_tree<typename K::FT>& distinct_tree(const Point_cloud<K>& cloud, const Distinct_positions<typename K::FT>& d)
{
    return d.has_duplicates() ? *d.own_tree : cloud.kd_tree();
}

/// Original index of kd-tree result index `k` of distinct_tree().
template <class FT>
std::uint32_t original_index(const Distinct_positions<FT>& d, std::uint32_t k)
{
    return d.has_duplicates() ? d.unique[k] : k;
}

/// Assembles the symmetric CSR graph over `n` vertices from undirected edges (a != b; an edge may be
/// listed twice, once from each end, and is then kept once), plus a zero-length edge from every
/// non-representative point to its representative. Rows are sorted by target. O(E log E / N + N).
inline Proximity_graph::Graph assemble_graph(std::uint32_t n, const std::vector<Found_edge>& edges,
                                             const std::vector<std::uint32_t>& representative)
{
    std::vector<std::uint64_t> rows(std::size_t(n) + 1, 0);
    for (const Found_edge& e : edges) {
        ++rows[e.a + 1];
        ++rows[e.b + 1];
    }
    for (std::uint32_t i = 0; i < n; ++i)
        if (representative[i] != i) {
            ++rows[i + 1];
            ++rows[representative[i] + 1];
        }
    std::partial_sum(rows.begin(), rows.end(), rows.begin());
    struct Slot {
        std::uint32_t target;
        float length;
    };
    std::vector<Slot> slots(rows.back());
    std::vector<std::uint64_t> fill(rows.begin(), rows.end() - 1);
    for (const Found_edge& e : edges) {
        slots[fill[e.a]++] = Slot{e.b, e.length};
        slots[fill[e.b]++] = Slot{e.a, e.length};
    }
    for (std::uint32_t i = 0; i < n; ++i)
        if (representative[i] != i) {
            slots[fill[i]++] = Slot{representative[i], 0.f};
            slots[fill[representative[i]]++] = Slot{i, 0.f};
        }
    std::vector<std::uint64_t> compact(std::size_t(n) + 1, 0);
    std::vector<std::uint32_t> targets;
    std::vector<Proximity_edge> properties;
    // Sort each row and drop repeated targets (an edge listed from both ends), in place.
    std::uint64_t out = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        auto first = slots.begin() + std::ptrdiff_t(rows[i]);
        auto last = slots.begin() + std::ptrdiff_t(rows[i + 1]);
        std::sort(first, last, [](const Slot& x, const Slot& y) { return x.target < y.target; });
        for (auto it = first; it != last; ++it)
            if (it == first || it->target != (it - 1)->target) slots[out++] = *it;
        compact[i + 1] = out;
    }
    targets.resize(out);
    properties.resize(out);
    for (std::uint64_t e = 0; e < out; ++e) {
        targets[e] = slots[e].target;
        properties[e] = Proximity_edge{slots[e].length, false};
    }
    slots = {};
    return make_csr_graph(compact, targets, properties);
}

/// The edges found from every distinct position of a cloud: `find_from(u, neighbors, found)` appends
/// to `found` the edges it finds from distinct position u (a kd-tree index), with `neighbors` a
/// scratch vector reused within a block. Positions are visited in spatial order `order` by blocks of
/// 4096, in parallel when TBB is available; the edges come back in block order, so the result does
/// not depend on the number of threads.
template <class FT, class FindFrom>
std::vector<Found_edge> gather_edges(std::size_t m, const std::vector<std::uint32_t>& order, const FindFrom& find_from)
{
    std::vector<Found_edge> edges;
    ordered_blocks(
        m, 4096,
        [&](std::size_t begin, std::size_t end) {
            std::vector<Found_edge> found;
            std::vector<Neighbor<FT>> neighbors;
            for (std::size_t i = begin; i < end; ++i) find_from(order[i], neighbors, found);
            return found;
        },
        [&](std::vector<Found_edge> found) { edges.insert(edges.end(), found.begin(), found.end()); });
    return edges;
}

/// The proximity graph of kind `kind` (parameter `parameter`) over the `n` points of a cloud from the
/// edges found among its distinct positions (assemble_graph(), which `edges` is released after),
/// with its long edges marked virtual (mark_long_edges()).
inline Proximity_graph finish_graph(std::uint32_t n, std::vector<Found_edge>& edges,
                                    const std::vector<std::uint32_t>& representative, const Long_edge_options& long_edges,
                                    Graph_kind kind, unsigned parameter)
{
    auto graph = assemble_graph(n, edges, representative);
    edges = {};
    mark_long_edges(graph, get(&Proximity_edge::length, std::as_const(graph)), get(&Proximity_edge::is_virtual, graph),
                    long_edges);
    return Proximity_graph(std::move(graph), kind, parameter);
}

} // namespace PCCD::internal
