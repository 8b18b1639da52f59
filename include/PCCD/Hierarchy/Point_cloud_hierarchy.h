// PCCD/Hierarchy/Point_cloud_hierarchy.h -- a static bounding-volume hierarchy over the points of a
// cloud (doc/algorithms.md "Point cloud hierarchy"): axis-aligned boxes built top-down by median
// splits of the longest side, leaves of a few points, logarithmic height; each node's points are
// also bounded by a slab normal to their direction of least spread, thin on a surface patch. Each
// point may carry a reach (how far from it its surface can be defined, doc/manual/hierarchy.md) and
// each node the largest reach of its points; the points and reaches are also stored in hierarchy
// order, so that a leaf's data is contiguous. The intersection queries use it to restrict their
// work to the parts of two objects that can touch (overlapping_leaves.h, reach_traversal.h). A
// built tree can be refitted over new positions of the same points (the hierarchy of a deforming
// cloud, doc/manual/kinetic.md "Deforming point clouds").
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
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// Options of Point_cloud_hierarchy.
struct Point_cloud_hierarchy_options {
    /// Largest number of points in a leaf (>= 1). Default 8: leaves about two sampling radii wide, so
    /// that the leaf pairs of two touching objects hug their contact region; measured faster than 16
    /// and 32 for first-hit queries (doc/benchmarks.md "Point cloud hierarchy").
    std::size_t leaf_size = 8;
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
        /// The largest reach of the node's points (0 when the hierarchy was built without reaches).
        double reach = 0.0;
        /// A slab holding the node's points: every point p satisfies slab_min <= slab_normal . p <=
        /// slab_max. The normal is the direction of least spread of the points (their covariance's
        /// smallest eigenvector), so on a surface patch the slab is thin where the box is not; box
        /// and slab together bound the points. A refitted tree has no slabs: a zero normal and an
        /// infinite interval, which holds every point.
        Eigen::Vector3d slab_normal = Eigen::Vector3d::Zero();
        double slab_min = -std::numeric_limits<double>::infinity();
        double slab_max = std::numeric_limits<double>::infinity();

        bool is_leaf() const { return right == no_child; }
        /// False for a node of a refitted tree (no slab).
        bool has_slab() const { return std::isfinite(slab_min); }
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
        : Point_cloud_hierarchy(points, Eigen::VectorXd(), options)
    {
    }

    /// Builds the hierarchy of the 3 x N `points` with a reach per point (`reach(i)` for point i,
    /// finite and >= 0; empty: every reach is 0). Node::reach is the largest reach of a node's points.
    /// \throws Invalid_input as above, or if `reach` is neither empty nor of size N, or holds a value
    ///         that is not finite or < 0.
    template <class Derived>
    Point_cloud_hierarchy(const Eigen::MatrixBase<Derived>& points, const Eigen::VectorXd& reach,
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
        if (reach.size() != 0 && std::size_t(reach.size()) != n)
            throw Invalid_input(internal::concat("point cloud hierarchy: ", reach.size(), " reaches for ", n, " points"));
        for (Eigen::Index i = 0; i < reach.size(); ++i)
            if (!(std::isfinite(reach(i)) && reach(i) >= 0.0))
                throw Invalid_input(internal::concat("point cloud hierarchy: the reach of point ", i, " (", reach(i),
                                                     ") must be finite and >= 0"));
        m_leaf_size = options.leaf_size;
        m_has_reach = reach.size() != 0;
        m_order.resize(n);
        std::iota(m_order.begin(), m_order.end(), Index(0));
        m_nodes.reserve(2 * (n / m_leaf_size + 1));
        build(coordinates, 0, Index(n));
        // Points and reaches in hierarchy order; node reaches bottom-up (children follow parents).
        m_ordered.resize(4, Eigen::Index(n));
        for (std::size_t k = 0; k < n; ++k) {
            m_ordered.col(Eigen::Index(k)).head<3>() = coordinates.col(m_order[k]);
            m_ordered(3, Eigen::Index(k)) = reach.size() == 0 ? 0.0 : reach(m_order[k]);
        }
        for (std::size_t i = m_nodes.size(); i-- > 0;) {
            Node& node = m_nodes[i];
            node.reach = node.is_leaf() ? m_ordered.row(3).segment(node.first, node.count).maxCoeff()
                                        : std::max(m_nodes[left(Index(i))].reach, m_nodes[node.right].reach);
        }
        compute_slabs();
    }

    /// The tree of `topology` (same nodes, same point order, same leaf size) over new positions of
    /// the same points: every box is recomputed tight over its node's points at `points` (3 x N,
    /// point i in column i) and every reach from `reach` (empty: the hierarchy has no reaches). This
    /// is the bottom-up refit a deforming cloud uses instead of a rebuild
    /// (doc/manual/kinetic.md, "Deforming point clouds"): the boxes stay exact, only their
    /// tightness depends on how far the points moved relative to each other since `topology` was
    /// built. The refitted nodes have no slabs (Node::slab_normal zero): recomputing them would
    /// cost O(N log N) per refit.
    /// \throws Invalid_input if `topology` is empty, the number of points differs from its size, a
    ///         coordinate is not finite, or `reach` is neither empty nor of size N or holds a value
    ///         that is not finite or < 0.
    /// Complexity: O(N) time and space.
    template <class Derived>
    Point_cloud_hierarchy(const Point_cloud_hierarchy& topology, const Eigen::MatrixBase<Derived>& points,
                          const Eigen::VectorXd& reach)
        : m_nodes(topology.m_nodes), m_order(topology.m_order), m_leaf_size(topology.m_leaf_size),
          m_has_reach(reach.size() != 0)
    {
        if (topology.empty()) throw Invalid_input("point cloud hierarchy: refit of an empty hierarchy");
        if (points.rows() != 3 || std::size_t(points.cols()) != m_order.size())
            throw Invalid_input(internal::concat("point cloud hierarchy: refit with ", points.cols(),
                                                 " points of a hierarchy over ", m_order.size()));
        if (reach.size() != 0 && std::size_t(reach.size()) != m_order.size())
            throw Invalid_input(internal::concat("point cloud hierarchy: ", reach.size(), " reaches for ",
                                                 m_order.size(), " points"));
        const std::size_t n = m_order.size();
        m_ordered.resize(4, Eigen::Index(n));
        for (std::size_t k = 0; k < n; ++k) {
            const Index i = m_order[k];
            m_ordered.col(Eigen::Index(k)).head<3>() = points.col(Eigen::Index(i)).template cast<double>();
            if (!internal::all_finite(m_ordered.col(Eigen::Index(k)).head<3>()))
                throw Invalid_input(internal::concat("point cloud hierarchy: point ", i, " is not finite"));
            const double r = reach.size() == 0 ? 0.0 : reach(Eigen::Index(i));
            if (!(std::isfinite(r) && r >= 0.0))
                throw Invalid_input(internal::concat("point cloud hierarchy: the reach of point ", i, " (", r,
                                                     ") must be finite and >= 0"));
            m_ordered(3, Eigen::Index(k)) = r;
        }
        // Children follow their parents in depth-first order: a backward sweep sees children first.
        for (std::size_t i = m_nodes.size(); i-- > 0;) {
            Node& node = m_nodes[i];
            // The topology's slabs bound the old positions only; a refitted tree has none.
            node.slab_normal.setZero();
            node.slab_min = -std::numeric_limits<double>::infinity();
            node.slab_max = std::numeric_limits<double>::infinity();
            if (node.is_leaf()) {
                const auto block = m_ordered.middleCols(node.first, node.count);
                node.box = Eigen::AlignedBox3d(block.topRows<3>().rowwise().minCoeff(),
                                               block.topRows<3>().rowwise().maxCoeff());
                node.reach = block.row(3).maxCoeff();
            } else {
                const Node& a = m_nodes[left(Index(i))];
                const Node& b = m_nodes[node.right];
                node.box = a.box.merged(b.box);
                node.reach = std::max(a.reach, b.reach);
            }
        }
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
    /// Position (rows 0-2, the cloud's local frame) and reach (row 3) of the k-th point in
    /// hierarchy order, i.e. of point order()[k]: a node's points are the columns [first, first + count).
    const Eigen::Matrix4Xd& ordered_points() const { return m_ordered; }
    std::size_t size() const { return m_order.size(); }
    /// True when the hierarchy was built with reaches (otherwise every reach is 0).
    bool has_reach() const { return m_has_reach; }
    bool empty() const { return m_nodes.empty(); }
    std::size_t leaf_size() const { return m_leaf_size; }
    /// Number of levels (1 for a single leaf).
    std::size_t height() const { return m_nodes.empty() ? 0 : height_of(0); }
    std::size_t memory_bytes() const
    {
        return m_nodes.capacity() * sizeof(Node) + m_order.capacity() * sizeof(Index) +
               std::size_t(m_ordered.size()) * sizeof(double);
    }
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

    /// The slab of every node: the points' second moments are summed bottom-up (relative to the
    /// root box's centre), the normal is their covariance's smallest eigenvector, and the interval
    /// is taken over the node's points. O(N log N).
    void compute_slabs()
    {
        const Eigen::Vector3d origin = m_nodes.front().box.center();
        struct Moments {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            Eigen::Matrix3d squares = Eigen::Matrix3d::Zero();
        };
        std::vector<Moments> moments(m_nodes.size());
        for (std::size_t i = m_nodes.size(); i-- > 0;) {
            const Node& node = m_nodes[i];
            Moments& m = moments[i];
            if (node.is_leaf()) {
                for (Index k = node.first; k < node.first + node.count; ++k) {
                    const Eigen::Vector3d p = m_ordered.col(k).head<3>() - origin;
                    m.sum += p;
                    m.squares += p * p.transpose();
                }
            } else {
                const Moments& a = moments[left(Index(i))];
                const Moments& b = moments[node.right];
                m.sum = a.sum + b.sum;
                m.squares = a.squares + b.squares;
            }
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        for (std::size_t i = 0; i < m_nodes.size(); ++i) {
            Node& node = m_nodes[i];
            const Eigen::Vector3d mean = moments[i].sum / double(node.count);
            const Eigen::Matrix3d covariance = moments[i].squares / double(node.count) - mean * mean.transpose();
            solver.computeDirect(covariance);
            Eigen::Vector3d normal = solver.eigenvectors().col(0);
            if (solver.info() != Eigen::Success || !internal::all_finite(normal) || !(normal.norm() > 0.5)) continue;
            normal.normalize();
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (Index k = node.first; k < node.first + node.count; ++k) {
                const double d = normal.dot(m_ordered.col(k).head<3>());
                lo = std::min(lo, d);
                hi = std::max(hi, d);
            }
            node.slab_normal = normal;
            node.slab_min = lo;
            node.slab_max = hi;
        }
    }

    std::size_t height_of(Index i) const
    {
        if (m_nodes[i].is_leaf()) return 1;
        return 1 + std::max(height_of(left(i)), height_of(right(i)));
    }

    std::vector<Node> m_nodes;
    std::vector<Index> m_order;
    Eigen::Matrix4Xd m_ordered;
    std::size_t m_leaf_size = 8;
    bool m_has_reach = false;
};

} // namespace PCCD
