// PCCD/Kd_tree.h -- exact k-nearest-neighbour and radius queries over a flat 3 x N coordinate
// store, the spatial index under every Point_cloud (doc/algorithms.md, "Proximity graphs and
// geodesic distance" and "Sampling radius and sphere coverings" need k-NN for the graphs, the
// sampling radius and evaluation at arbitrary points).
//
// Backed by nanoflann (chosen over CGAL's Kd_tree by benchmark/kd_tree_benchmark.cpp, figures in
// doc/benchmarks.md). Results are sorted by (squared distance, index), so ties come out in a fixed
// order and every query is deterministic.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <nanoflann.hpp>

#include <PCCD/Error.h>
#include <PCCD/internal/cell_grid.h>
#include <PCCD/internal/finite.h>
#include <PCCD/internal/removal.h>

namespace PCCD {

/// One query result: a point index and its squared Euclidean distance to the query.
template <class FT>
struct Neighbor {
    std::uint32_t index;
    FT squared_distance;
    friend bool operator==(const Neighbor&, const Neighbor&) = default;
};

namespace internal {

template <class FT>
bool neighbor_less(const Neighbor<FT>& a, const Neighbor<FT>& b)
{
    return a.squared_distance < b.squared_distance ||
           (a.squared_distance == b.squared_distance && a.index < b.index);
}

// A bound slightly above d2. nanoflann offers a point only when its distance is strictly below
// worstDist(), and prunes a subtree when an incrementally computed (rounded) lower bound exceeds
// worstDist(); a relative slack of a few ulps makes sure that points tied with the bound are still
// offered. The result sets then decide exactly.
template <class FT>
FT with_slack(FT d2)
{
    return d2 + d2 * (16 * std::numeric_limits<FT>::epsilon()) + std::numeric_limits<FT>::min();
}

// nanoflann result set keeping the k smallest (squared distance, index) pairs in lexicographic
// order: points tied with the k-th distance are offered too (with_slack) and win by index.
template <class FT>
class Knn_result_set {
public:
    Knn_result_set(Neighbor<FT>* data, std::size_t capacity) : m_data(data), m_capacity(capacity) {}
    std::size_t size() const { return m_count; }
    bool full() const { return m_count == m_capacity; }
    FT worstDist() const
    {
        return full() ? with_slack(m_data[m_count - 1].squared_distance) : std::numeric_limits<FT>::infinity();
    }
    template <class Index>
    bool addPoint(FT d2, Index index)
    {
        const Neighbor<FT> candidate{static_cast<std::uint32_t>(index), d2};
        if (full() && !neighbor_less(candidate, m_data[m_count - 1])) return true;
        std::size_t i = full() ? m_count - 1 : m_count++;
        for (; i > 0 && neighbor_less(candidate, m_data[i - 1]); --i) m_data[i] = m_data[i - 1];
        m_data[i] = candidate;
        return true;
    }

private:
    Neighbor<FT>* m_data;
    std::size_t m_capacity;
    std::size_t m_count = 0;
};

// nanoflann result set collecting every point with squared distance <= bound (unsorted).
template <class FT>
class Radius_result_set {
public:
    Radius_result_set(std::vector<Neighbor<FT>>& out, FT bound) : m_out(out), m_bound(bound) {}
    std::size_t size() const { return m_out.size(); }
    bool full() const { return true; }
    FT worstDist() const { return with_slack(m_bound); }
    template <class Index>
    bool addPoint(FT d2, Index index)
    {
        if (d2 <= m_bound) m_out.push_back(Neighbor<FT>{static_cast<std::uint32_t>(index), d2});
        return true;
    }

private:
    std::vector<Neighbor<FT>>& m_out;
    FT m_bound;
};

} // namespace internal

/// Exact kd-tree over the columns of a 3 x N matrix.
/// \tparam FT float or double.
/// The tree keeps its own copy of the coordinates. Queries are const and safe for concurrent readers.
template <class FT>
class Kd_tree {
public:
    using Coordinates = Eigen::Matrix<FT, 3, Eigen::Dynamic>;
    using Vector_3 = Eigen::Matrix<FT, 3, 1>;
    using Index = std::uint32_t;
    using Result = Neighbor<FT>;

    /// Default leaf size (points per leaf), chosen by benchmark/kd_tree_benchmark.cpp.
    static constexpr std::size_t default_leaf_size = 10;

    /// Builds the tree. O(N log N).
    /// \pre `coordinates.cols() < 2^32 - 1` and all coordinates finite (Point_cloud checks this).
    explicit Kd_tree(Coordinates coordinates, std::size_t leaf_size = default_leaf_size)
        : m_impl(std::make_unique<Impl>(std::move(coordinates), leaf_size))
    {
    }

    /// The tree of the points left when the points `removed` (sorted indices, each once) are taken
    /// out, the others keeping their order (point i becomes i minus the number removed before it).
    /// No rebuild: the removed points are dropped from their leaves and the others renumbered, in
    /// one pass over the leaves; the inner nodes keep their cuts, which still separate the points
    /// left, so every query answers exactly as on a tree built afresh on them (results are unique:
    /// ties go by index). This tree is moved from. O(N), against O(N log N) for a build (removing
    /// the 20 outliers of a 10^7-point scan this way took its outlier stage from 9.7 to 8.3 s).
    /// \throws Invalid_input if `removed` is not sorted, repeats an index or holds one >= size().
    Kd_tree without(const std::vector<Index>& removed) &&
    {
        const std::size_t n = size();
        const std::vector<Index> renumbered = internal::renumber_without(n, removed, "kd-tree");
        constexpr Index gone = internal::removed_point;
        const Index next_index = Index(n - removed.size());
        Kd_tree result(std::move(*this));
        Impl& impl = *result.m_impl;
        Coordinates kept(3, Eigen::Index(next_index));
        for (std::size_t i = 0; i < n; ++i)
            if (renumbered[i] != gone) kept.col(Eigen::Index(renumbered[i])) = impl.coords.col(Eigen::Index(i));
        impl.coords = std::move(kept); // the dataset refers to this member, which stays in place
        Index_type& index = impl.index;
        if (index.root_node) {
            // Each leaf keeps its points left, renumbered, at the front of its range.
            std::vector<typename Index_type::NodePtr> stack{index.root_node};
            while (!stack.empty()) {
                const typename Index_type::NodePtr node = stack.back();
                stack.pop_back();
                if (node->child1 || node->child2) {
                    if (node->child1) stack.push_back(node->child1);
                    if (node->child2) stack.push_back(node->child2);
                    continue;
                }
                auto& leaf = node->node_type.lr;
                auto write = leaf.left;
                for (auto i = leaf.left; i < leaf.right; ++i)
                    if (const Index to = renumbered[index.vAcc[i]]; to != gone) index.vAcc[write++] = to;
                leaf.right = write;
            }
        }
        index.m_size = next_index;
        index.m_size_at_index_build = next_index;
        impl.grid.reset(); // its indices are the old ones; lay_cell_grid() lays one anew
        return result;
    }

    /// Lays a grid of cubic cells of side `cell` over the points (replacing any grid laid before),
    /// which then answers within_radius() for every query whose ball meets at most 27 cells (radii
    /// up to `cell`; up to 8 cells for radii up to cell / 2): the same points and distances as the
    /// tree, found by a few independent hash look-ups instead of a descent of the tree
    /// (doc/benchmarks.md, "Radius queries from a cell grid"). Other queries stay with the tree.
    /// Memory: 4 bytes per point and up to 43 bytes per non-empty cell. Returns false, laying none, when
    /// `cell` is not finite and normal (>= the smallest normal double) or the points' box spans
    /// 2^21 - 1 cells or more along an axis.
    /// Not thread safe: lay the grid before the tree is shared. O(N) expected.
    bool lay_cell_grid(double cell)
    {
        m_impl->grid.reset();
        if (!internal::Cell_grid<FT>::fits(m_impl->coords, cell)) return false;
        m_impl->grid.emplace(m_impl->coords, cell);
        return true;
    }

    /// The side of the cells of the grid lay_cell_grid() laid, if any.
    std::optional<double> cell_grid_side() const
    {
        return m_impl->grid ? std::optional<double>(m_impl->grid->cell()) : std::nullopt;
    }

    std::size_t size() const { return static_cast<std::size_t>(m_impl->coords.cols()); }
    const Coordinates& coordinates() const { return m_impl->coords; }
    /// Heap bytes held by the tree: its copy of the coordinates (3 N FT), the index's permutation
    /// of the points (N 32-bit indices), its nodes (nanoflann's pool, with its unused tails) and
    /// the cell grid, if one was laid.
    std::size_t memory_bytes() const
    {
        return static_cast<std::size_t>(m_impl->coords.size()) * sizeof(FT) + m_impl->index.usedMemory(m_impl->index) +
               (m_impl->grid ? m_impl->grid->memory_bytes() : 0);
    }

    /// The `k` nearest points to `query` (fewer if the tree holds fewer), sorted by
    /// (squared distance, index), written into `out` (cleared first). O(k log N) expected.
    /// Among points at the same distance the smaller indices win, so the answer is unique.
    /// \throws Invalid_input if `query` has a NaN or infinite coordinate.
    void k_nearest(const Vector_3& query, std::size_t k, std::vector<Result>& out) const
    {
        check_query(query);
        out.clear();
        k = std::min(k, size());
        if (k == 0) return;
        out.resize(k);
        internal::Knn_result_set<FT> results(out.data(), k);
        m_impl->index.findNeighbors(results, query.data(), nanoflann::SearchParams());
        out.resize(results.size());
    }

    /// Convenience overload returning a new vector.
    std::vector<Result> k_nearest(const Vector_3& query, std::size_t k) const
    {
        std::vector<Result> out;
        k_nearest(query, k, out);
        return out;
    }

    /// The nearest point to `query`. \pre the tree is not empty.
    /// \throws Invalid_input if `query` has a NaN or infinite coordinate.
    Result nearest(const Vector_3& query) const
    {
        PCCD_precondition_msg(size() > 0, "nearest-point query on an empty kd-tree");
        std::vector<Result> out;
        k_nearest(query, 1, out);
        return out.front();
    }

    /// All points within distance `radius` of `query` (squared distance <= radius^2), sorted by
    /// (squared distance, index), written into `out` (cleared first). From the cell grid when one
    /// is laid and the ball meets few of its cells (lay_cell_grid()), from the tree otherwise: the
    /// same answer either way.
    /// \throws Invalid_input if `query` has a NaN or infinite coordinate.
    void within_radius(const Vector_3& query, FT radius, std::vector<Result>& out) const
    {
        check_query(query);
        // A quiet comparison: `radius >= 0` would raise FE_INVALID (a trap in Debug test builds) on NaN.
        PCCD_precondition_msg(std::isgreaterequal(radius, FT(0)), "radius query with a negative or NaN radius");
        out.clear();
        if (size() == 0) return;
        if (!m_impl->grid || !m_impl->grid->within_radius(m_impl->coords, query, radius, out)) {
            internal::Radius_result_set<FT> results(out, radius * radius);
            m_impl->index.findNeighbors(results, query.data(), nanoflann::SearchParams());
        }
        // A lambda, not the function's address: the sort inlines it (through a function pointer
        // the comparisons were a tenth of a profile of a 10^7-point object's preprocessing).
        std::sort(out.begin(), out.end(), [](const Result& a, const Result& b) { return internal::neighbor_less(a, b); });
    }

    /// Convenience overload returning a new vector.
    std::vector<Result> within_radius(const Vector_3& query, FT radius) const
    {
        std::vector<Result> out;
        within_radius(query, radius, out);
        return out;
    }

private:
    // Without this a NaN query point makes every distance comparison false: k_nearest then
    // returned nothing (and nearest() read an empty vector) instead of failing clearly.
    static void check_query(const Vector_3& query)
    {
        if (!internal::all_finite(query))
            throw Invalid_input(internal::concat("kd-tree query at a non-finite point (", query.x(), ", ", query.y(), ", ",
                                                 query.z(), ")"));
    }

    struct Dataset {
        const Coordinates* coords;
        std::size_t kdtree_get_point_count() const { return static_cast<std::size_t>(coords->cols()); }
        FT kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*coords)(Eigen::Index(dim), Eigen::Index(i)); }
        template <class Box>
        bool kdtree_get_bbox(Box&) const
        {
            return false;
        }
    };
    using Index_type =
        nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<FT, Dataset, FT, Index>, Dataset, 3, Index>;

    // Held behind a pointer: nanoflann keeps a reference to the dataset, which must not move.
    struct Impl {
        Coordinates coords;
        Dataset dataset;
        Index_type index;
        std::optional<internal::Cell_grid<FT>> grid;
        Impl(Coordinates c, std::size_t leaf_size)
            : coords(std::move(c)),
              dataset{&coords},
              index(3, dataset, nanoflann::KDTreeSingleIndexAdaptorParams(leaf_size))
        {
            PCCD_precondition_msg(coords.cols() < Eigen::Index(std::numeric_limits<Index>::max()),
                                  "a kd-tree holds fewer than 2^32 - 1 points");
            if (coords.cols() > 0) index.buildIndex();
        }
    };

    std::unique_ptr<Impl> m_impl;
};

} // namespace PCCD
