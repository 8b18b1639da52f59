// PCCD/Kd_tree.h -- exact k-nearest-neighbour and radius queries over a flat 3 x N coordinate store,
// the spatial index under every Point_cloud (ALGORITHMS.md sections 2-3 need k-NN for the graphs,
// the sampling radius and evaluation at arbitrary points).
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
#include <vector>

#include <Eigen/Core>
#include <nanoflann.hpp>

#include <PCCD/Error.h>

namespace PCCD {

/// One query result: a point index and its squared Euclidean distance to the query.
template <class FT>
struct Neighbor {
    std::uint32_t index;
    FT squared_distance;
    friend bool operator==(const Neighbor&, const Neighbor&) = default;
};

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

    std::size_t size() const { return static_cast<std::size_t>(m_impl->coords.cols()); }
    const Coordinates& coordinates() const { return m_impl->coords; }

    /// The `k` nearest points to `query` (fewer if the tree holds fewer), sorted by
    /// (squared distance, index), written into `out` (cleared first). O(k log N) expected.
    void k_nearest(const Vector_3& query, std::size_t k, std::vector<Result>& out) const
    {
        out.clear();
        if (size() == 0 || k == 0) return;
        k = std::min(k, size());
        // Ask for one more so that a tie at the k-th place can be broken by index.
        std::size_t asked = std::min(k + 1, size());
        std::vector<Index> indices(asked);
        std::vector<FT> distances(asked);
        for (;;) {
            const std::size_t found =
                m_impl->index.knnSearch(query.data(), asked, indices.data(), distances.data());
            out.resize(found);
            for (std::size_t i = 0; i < found; ++i) out[i] = Result{indices[i], distances[i]};
            sort_results(out);
            // A tie across the cut: make sure every point at the k-th distance is seen, then cut.
            if (found <= k || out.back().squared_distance > out[k - 1].squared_distance || asked == size()) break;
            asked = std::min(2 * asked, size());
            indices.resize(asked);
            distances.resize(asked);
        }
        if (out.size() > k) out.resize(k);
    }

    /// Convenience overload returning a new vector.
    std::vector<Result> k_nearest(const Vector_3& query, std::size_t k) const
    {
        std::vector<Result> out;
        k_nearest(query, k, out);
        return out;
    }

    /// The nearest point to `query`. \pre the tree is not empty.
    Result nearest(const Vector_3& query) const
    {
        PCCD_precondition_msg(size() > 0, "nearest-point query on an empty kd-tree");
        std::vector<Result> out;
        k_nearest(query, 1, out);
        return out.front();
    }

    /// All points within distance `radius` of `query` (distance <= radius), sorted by
    /// (squared distance, index), written into `out` (cleared first).
    void within_radius(const Vector_3& query, FT radius, std::vector<Result>& out) const
    {
        PCCD_precondition_msg(radius >= FT(0), "radius query with a negative radius");
        out.clear();
        if (size() == 0) return;
        std::vector<std::pair<Index, FT>> matches;
        nanoflann::SearchParams params;
        params.sorted = false;
        // nanoflann keeps points with squared distance < bound; nudge the bound up by one ulp so
        // points exactly on the sphere are included, then filter exactly.
        const FT bound = radius * radius;
        m_impl->index.radiusSearch(query.data(), std::nextafter(bound, std::numeric_limits<FT>::max()), matches,
                                   params);
        out.reserve(matches.size());
        for (const auto& [index, d2] : matches)
            if (d2 <= bound) out.push_back(Result{index, d2});
        sort_results(out);
    }

    /// Convenience overload returning a new vector.
    std::vector<Result> within_radius(const Vector_3& query, FT radius) const
    {
        std::vector<Result> out;
        within_radius(query, radius, out);
        return out;
    }

private:
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

    static void sort_results(std::vector<Result>& results)
    {
        std::sort(results.begin(), results.end(), [](const Result& a, const Result& b) {
            return a.squared_distance < b.squared_distance ||
                   (a.squared_distance == b.squared_distance && a.index < b.index);
        });
    }

    std::unique_ptr<Impl> m_impl;
};

} // namespace PCCD
