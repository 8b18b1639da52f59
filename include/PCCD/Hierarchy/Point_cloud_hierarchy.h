// PCCD/Hierarchy/Point_cloud_hierarchy.h -- a static bounding-volume hierarchy over the points of a
// cloud (ALGORITHMS.md section 4, first part): axis-aligned boxes built top-down by median splits of
// the longest side, leaves of a few points, logarithmic height. The intersection queries use it to
// restrict their work to the parts of two objects that can touch (overlapping_leaves.h). The
// per-node subsamples and sphere coverings of section 4 are not stored yet.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// Options of Point_cloud_hierarchy.
struct Point_cloud_hierarchy_options {
    /// Largest number of points in a leaf (>= 1). Default 16: leaves a few sampling radii wide, so
    /// that the leaf pairs of two touching objects hug their contact region (doc/manual/intersection.md).
    std::size_t leaf_size = 16;
};

/// A static AABB tree over the points of a cloud.
///
/// Node 0 is the root; nodes are stored in depth-first order, so an inner node's left child follows
/// it directly. A node covers the points order()[first, first + count). The tree is balanced
/// (median splits): its height is ceil(log2(N / leaf_size)) + 1 at most.
///
/// Immutable after construction; all member functions are const and safe to call concurrently.
class Point_cloud_hierarchy {
public:
    using Index = std::uint32_t;
    static constexpr Index no_child = 0;

    struct Node {
        /// The tight bounding box of the node's points (local coordinates of the cloud).
        Eigen::AlignedBox3d box;
        /// Range of the node's points in order().
        Index first = 0;
        Index count = 0;
        /// Index of the right child; no_child for a leaf. The left child is the next node.
        Index right = no_child;

        bool is_leaf() const { return right == no_child; }
    };

    /// An empty hierarchy.
    Point_cloud_hierarchy() = default;

    /// Builds the hierarchy of the 3 x N `points` (any Eigen expression with 3 rows).
    /// \throws Invalid_input if there are no points, a coordinate is not finite, leaf_size is 0, or
    ///         N >= 2^32 - 1.
    /// Complexity: O(N log N) time, O(N) space.
    template <class Derived>
    explicit Point_cloud_hierarchy(const Eigen::MatrixBase<Derived>& points,
                                   const Point_cloud_hierarchy_options& options = {})
    {
        static_assert(Derived::RowsAtCompileTime == 3 || Derived::RowsAtCompileTime == Eigen::Dynamic,
                      "Point_cloud_hierarchy needs a 3 x N matrix of points");
        if (points.rows() != 3) throw Invalid_input("point cloud hierarchy: the points must be a 3 x N matrix");
        const std::size_t n = std::size_t(points.cols());
        if (n == 0) throw Invalid_input("point cloud hierarchy: the cloud is empty");
        if (n >= std::size_t(std::numeric_limits<Index>::max()))
            throw Invalid_input("point cloud hierarchy: too many points (at most 2^32 - 2)");
        if (options.leaf_size == 0) throw Invalid_input("point cloud hierarchy: leaf_size must be >= 1");
        const Eigen::Matrix3Xd coordinates = points.template cast<double>();
        for (Eigen::Index i = 0; i < coordinates.cols(); ++i)
            if (!internal::all_finite(coordinates.col(i)))
                throw Invalid_input(internal::concat("point cloud hierarchy: point ", i, " is not finite"));
        m_leaf_size = options.leaf_size;
        m_order.resize(n);
        std::iota(m_order.begin(), m_order.end(), Index(0));
        m_nodes.reserve(2 * (n / m_leaf_size + 1));
        build(coordinates, 0, Index(n));
    }

    /// \name Access
    /// @{
    const std::vector<Node>& nodes() const { return m_nodes; }
    const Node& node(Index i) const { return m_nodes[i]; }
    const Node& root() const { return m_nodes.front(); }
    Index left(Index i) const { return i + 1; }
    Index right(Index i) const { return m_nodes[i].right; }
    /// Point indices, grouped by leaf.
    const std::vector<Index>& order() const { return m_order; }
    /// The point indices of node i.
    std::span<const Index> points_of(Index i) const
    {
        const Node& node = m_nodes[i];
        return {m_order.data() + node.first, node.count};
    }
    std::size_t size() const { return m_order.size(); }
    bool empty() const { return m_nodes.empty(); }
    std::size_t leaf_size() const { return m_leaf_size; }
    /// Number of levels (1 for a single leaf).
    std::size_t height() const { return m_nodes.empty() ? 0 : height_of(0); }
    std::size_t memory_bytes() const { return m_nodes.capacity() * sizeof(Node) + m_order.capacity() * sizeof(Index); }
    /// @}

private:
    Index build(const Eigen::Matrix3Xd& points, Index first, Index last)
    {
        const Index id = Index(m_nodes.size());
        m_nodes.push_back(Node{});
        Eigen::AlignedBox3d box;
        for (Index k = first; k < last; ++k) box.extend(points.col(m_order[k]));
        m_nodes[id].box = box;
        m_nodes[id].first = first;
        m_nodes[id].count = last - first;
        if (std::size_t(last - first) <= m_leaf_size) return id;
        Eigen::Index axis = 0;
        box.sizes().maxCoeff(&axis);
        if (!(box.sizes()(axis) > 0.0)) return id; // all points coincide: one leaf, whatever its size
        const Index middle = first + (last - first) / 2;
        // Ties broken by index so that the tree does not depend on the standard library's algorithm.
        std::nth_element(m_order.begin() + first, m_order.begin() + middle, m_order.begin() + last,
                         [&](Index a, Index b) {
                             const double ca = points(axis, a), cb = points(axis, b);
                             return ca < cb || (ca == cb && a < b);
                         });
        build(points, first, middle);
        m_nodes[id].right = build(points, middle, last);
        return id;
    }

    std::size_t height_of(Index i) const
    {
        if (m_nodes[i].is_leaf()) return 1;
        return 1 + std::max(height_of(left(i)), height_of(right(i)));
    }

    std::vector<Node> m_nodes;
    std::vector<Index> m_order;
    std::size_t m_leaf_size = 16;
};

} // namespace PCCD
