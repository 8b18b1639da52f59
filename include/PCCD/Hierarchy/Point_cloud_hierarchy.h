// PCCD/Hierarchy/Point_cloud_hierarchy.h -- a static bounding-volume hierarchy over the points of a
// cloud (doc/algorithms.md "Point cloud hierarchy"): axis-aligned boxes built top-down by median
// splits of the longest side, leaves of a few points, logarithmic height; each node's points are
// also bounded by a slab normal to their direction of least spread, thin on a surface patch. Each
// point may carry a reach (how far from it its surface can be defined, doc/manual/hierarchy.md) and
// each node the largest reach of its points; the points and reaches are also stored in hierarchy
// order, so that a leaf's data is contiguous. The bounding volume its node-pair tests use is chosen
// per hierarchy (Bounding_volume: box and slab, box alone, or sphere; doc/manual/hierarchy.md
// "Bounding volumes"). The intersection queries use it to restrict their work to the parts of two
// objects that can touch (overlapping_leaves.h, reach_traversal.h). The build runs in parallel on
// TBB; a built tree can be refitted over new positions of the same points (the hierarchy of a
// deforming cloud, doc/manual/kinetic.md "Deforming point clouds") and rebuilt from its Layout
// (how an object file stores it).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy_options.h>
#include <PCCD/internal/finite.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// A static bounding-volume tree over the points of a cloud.
///
/// Node 0 is the root; nodes are stored in depth-first order, so an inner node's left child follows
/// it directly. A node covers the points order()[first, first + count). The tree is balanced
/// (median splits: a left child holds half its parent's points, rounded down): its height is
/// ceil(log2(N / leaf_size)) + 1 at most.
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
        /// False for a node of a refitted tree, or of a tree whose volume is not box_and_slab.
        bool has_slab() const { return std::isfinite(slab_min); }
    };

    /// A ball holding a node's points (Bounding_volume::sphere).
    struct Sphere {
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        double radius = 0.0;
    };

    /// The shape of a tree without its geometry: the point order and, per node in depth-first order,
    /// its point count and right child (no_child for a leaf), with the options it was built with.
    /// With the same points it determines the whole hierarchy (boxes, reaches, slabs, spheres):
    /// an object file stores it (doc/manual/surface.md, save and load).
    struct Layout {
        std::vector<Index> order;
        std::vector<Index> counts;
        std::vector<Index> rights;
        std::size_t leaf_size = 8;
        Bounding_volume volume = Bounding_volume::box_and_slab;
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
    ///         that is not finite or < 0, or options.threads is 0 or above 4096.
    /// Complexity: O(N log N) time, in parallel over subtrees and nodes with TBB; O(N) space.
    template <class Derived>
    Point_cloud_hierarchy(const Eigen::MatrixBase<Derived>& points, const Eigen::VectorXd& reach,
                          const Point_cloud_hierarchy_options& options = {})
    {
        m_leaf_size = options.leaf_size;
        m_volume = options.volume;
        m_has_reach = reach.size() != 0;
        const auto build_all = [&](const Eigen::Matrix3Xd& coordinates) {
            m_order.resize(std::size_t(coordinates.cols()));
            std::iota(m_order.begin(), m_order.end(), Index(0));
            internal::with_threads(options.threads, [&] {
                build_tree(coordinates);
                order_points(coordinates, reach);
                finish();
            });
        };
        // Points of doubles are read where they are; others are converted (one copy).
        if constexpr (std::is_same_v<Derived, Eigen::Matrix3Xd>) {
            check_points(points.derived(), reach, options.leaf_size, options.threads);
            build_all(points.derived());
        } else {
            build_all(checked_points(points, reach, options.leaf_size, options.threads));
        }
    }

    /// The hierarchy `layout` describes (as layout() returned it, e.g. read from a file) over the
    /// 3 x N `points` it was built on, with a reach per point as in the constructor above: the same
    /// tree, boxes, reaches, slabs and spheres as that build, without its splits. Every geometric
    /// quantity is recomputed from the points, so a layout cannot make a volume miss its points.
    /// \throws Invalid_input if the layout is not that of a median-split tree over N points (the
    ///         order a permutation of 0..N-1, each inner node's left child holding half its points
    ///         rounded down, its right child the rest, the nodes in depth-first order, no leaf above
    ///         leaf_size points unless they coincide), or as the constructor above.
    /// Complexity: O(N log N) time (the slabs or spheres), in parallel with TBB; O(N) space.
    template <class Derived>
    Point_cloud_hierarchy(const Layout& layout, const Eigen::MatrixBase<Derived>& points, const Eigen::VectorXd& reach,
                          std::optional<unsigned> threads = std::nullopt)
    {
        const Eigen::Matrix3Xd coordinates = checked_points(points, reach, layout.leaf_size, threads);
        m_leaf_size = layout.leaf_size;
        m_volume = layout.volume;
        m_has_reach = reach.size() != 0;
        check_layout(layout, std::size_t(coordinates.cols()));
        m_order = layout.order;
        m_nodes.resize(layout.counts.size());
        // Ranges top-down (a parent precedes its children); boxes bottom-up from the ordered points.
        m_nodes[0].count = Index(coordinates.cols());
        for (std::size_t i = 0; i < m_nodes.size(); ++i) {
            Node& node = m_nodes[i];
            node.right = layout.rights[i];
            if (node.is_leaf()) continue;
            Node& l = m_nodes[i + 1];
            Node& r = m_nodes[node.right];
            l.first = node.first, l.count = node.count / 2;
            r.first = node.first + l.count, r.count = node.count - l.count;
        }
        internal::with_threads(threads, [&] {
            order_points(coordinates, reach);
            node_boxes();
            for (std::size_t i = 0; i < m_nodes.size(); ++i) {
                const Node& node = m_nodes[i];
                if (node.is_leaf() && node.count > m_leaf_size && node.box.sizes().maxCoeff() > 0.0)
                    throw Invalid_input(internal::concat("point cloud hierarchy layout: leaf ", i, " holds ", node.count,
                                                         " points that do not coincide (leaf size ", m_leaf_size, ")"));
            }
            finish();
        });
    }

    /// The tree of `topology` (same nodes, same point order, same leaf size) over new positions of
    /// the same points: every box is recomputed tight over its node's points at `points` (3 x N,
    /// point i in column i) and every reach from `reach` (empty: the hierarchy has no reaches). This
    /// is the bottom-up refit a deforming cloud uses instead of a rebuild
    /// (doc/manual/kinetic.md, "Deforming point clouds"): the boxes stay exact, only their
    /// tightness depends on how far the points moved relative to each other since `topology` was
    /// built. The refitted nodes have no slabs (Node::slab_normal zero): recomputing them would
    /// cost O(N log N) per refit. A sphere tree gets new spheres: a leaf's from its points, an inner
    /// node's the smallest ball holding its children's (looser than a build's, still O(N)).
    /// \throws Invalid_input if `topology` is empty, the number of points differs from its size, a
    ///         coordinate is not finite, or `reach` is neither empty nor of size N or holds a value
    ///         that is not finite or < 0.
    /// Complexity: O(N) time and space.
    template <class Derived>
    Point_cloud_hierarchy(const Point_cloud_hierarchy& topology, const Eigen::MatrixBase<Derived>& points,
                          const Eigen::VectorXd& reach)
        : m_nodes(topology.m_nodes), m_order(topology.m_order), m_leaf_size(topology.m_leaf_size),
          m_volume(topology.m_volume), m_has_reach(reach.size() != 0)
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
        for (Node& node : m_nodes) {
            // The topology's slabs bound the old positions only; a refitted tree has none.
            node.slab_normal.setZero();
            node.slab_min = -std::numeric_limits<double>::infinity();
            node.slab_max = std::numeric_limits<double>::infinity();
        }
        node_boxes();
        node_reaches();
        if (m_volume == Bounding_volume::sphere) {
            m_spheres.resize(m_nodes.size());
            for (std::size_t i = m_nodes.size(); i-- > 0;) {
                const Node& node = m_nodes[i];
                m_spheres[i] = node.is_leaf() ? sphere_of_points(node, centroid(node))
                                              : enclosing(m_spheres[i + 1], m_spheres[node.right]);
            }
        }
    }

    /// \name Access
    /// @{
    const std::vector<Node>& nodes() const { return m_nodes; }
    const Node& node(Index i) const { return m_nodes[i]; }
    /// Whether node i is a leaf (the walks of traversal.h read the tree through is_leaf, left, right).
    bool is_leaf(Index i) const { return m_nodes[i].is_leaf(); }
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
    /// The bounding volume of the node-pair tests.
    Bounding_volume volume() const { return m_volume; }
    /// True when every node has a sphere (volume() == Bounding_volume::sphere).
    bool has_spheres() const { return !m_spheres.empty(); }
    /// The bounding sphere of node i (local coordinates). \pre has_spheres()
    const Sphere& sphere(Index i) const { return m_spheres[i]; }
    /// The tree's shape, from which the constructor taking a Layout rebuilds it over the same points.
    Layout layout() const
    {
        Layout l{.order = m_order, .counts = {}, .rights = {}, .leaf_size = m_leaf_size, .volume = m_volume};
        l.counts.reserve(m_nodes.size());
        l.rights.reserve(m_nodes.size());
        for (const Node& node : m_nodes) l.counts.push_back(node.count), l.rights.push_back(node.right);
        return l;
    }
    std::size_t size() const { return m_order.size(); }
    /// True when the hierarchy was built with reaches (otherwise every reach is 0).
    bool has_reach() const { return m_has_reach; }
    bool empty() const { return m_nodes.empty(); }
    std::size_t leaf_size() const { return m_leaf_size; }
    /// Number of levels (1 for a single leaf).
    std::size_t height() const { return m_nodes.empty() ? 0 : height_of_tree(); }
    std::size_t memory_bytes() const
    {
        return m_nodes.capacity() * sizeof(Node) + m_order.capacity() * sizeof(Index) +
               std::size_t(m_ordered.size()) * sizeof(double) + m_spheres.capacity() * sizeof(Sphere);
    }
    /// @}

private:
    /// Nodes of more points than this build their halves in parallel (down to parallel_depth levels).
    static constexpr Index parallel_points = 1u << 14;
    static constexpr int parallel_depth = 8;

    /// The points as doubles, checked with the reaches and options (see the constructors).
    template <class Derived>
    static Eigen::Matrix3Xd checked_points(const Eigen::MatrixBase<Derived>& points, const Eigen::VectorXd& reach,
                                           std::size_t leaf_size, const std::optional<unsigned>& threads)
    {
        static_assert(Derived::RowsAtCompileTime == 3 || Derived::RowsAtCompileTime == Eigen::Dynamic,
                      "Point_cloud_hierarchy needs a 3 x N matrix of points");
        if (points.rows() != 3) throw Invalid_input("point cloud hierarchy: the points must be a 3 x N matrix");
        if (points.cols() == 0) throw Invalid_input("point cloud hierarchy: the cloud is empty");
        Eigen::Matrix3Xd coordinates = points.template cast<double>();
        check_points(coordinates, reach, leaf_size, threads);
        return coordinates;
    }

    /// The checks of checked_points() on points of doubles, read in place.
    static void check_points(const Eigen::Matrix3Xd& coordinates, const Eigen::VectorXd& reach, std::size_t leaf_size,
                             const std::optional<unsigned>& threads)
    {
        const std::size_t n = std::size_t(coordinates.cols());
        if (n == 0) throw Invalid_input("point cloud hierarchy: the cloud is empty");
        if (n >= std::size_t(std::numeric_limits<Index>::max()))
            throw Invalid_input("point cloud hierarchy: too many points (at most 2^32 - 2)");
        if (leaf_size == 0) throw Invalid_input("point cloud hierarchy: leaf_size must be >= 1");
        internal::check_threads(threads, "point cloud hierarchy: threads");
        for (Eigen::Index i = 0; i < coordinates.cols(); ++i)
            if (!internal::all_finite(coordinates.col(i)))
                throw Invalid_input(internal::concat("point cloud hierarchy: point ", i, " is not finite"));
        if (reach.size() != 0 && std::size_t(reach.size()) != n)
            throw Invalid_input(internal::concat("point cloud hierarchy: ", reach.size(), " reaches for ", n, " points"));
        for (Eigen::Index i = 0; i < reach.size(); ++i)
            if (!(std::isfinite(reach(i)) && reach(i) >= 0.0))
                throw Invalid_input(internal::concat("point cloud hierarchy: the reach of point ", i, " (", reach(i),
                                                     ") must be finite and >= 0"));
    }

    /// Builds the tree into m_nodes. The median splits fix every subtree's size from its point count
    /// alone (predicted_nodes), unless a node of more than leaf_size points that all coincide stops as
    /// a leaf; so the nodes are first built in place, the two halves of a node above
    /// parallel_points points in parallel, into an array of the predicted size. If such a leaf
    /// turns up, the tree is built again sequentially from the original order (the same tree either
    /// way; no copies of the node array in the common case).
    void build_tree(const Eigen::Matrix3Xd& points);

    /// The number of nodes of a subtree of `count` points whose points never all coincide.
    std::size_t predicted_nodes(Index count, std::vector<std::pair<Index, std::size_t>>& memo) const;

    /// Builds the subtree over m_order[first, last) as node `id` of m_nodes and the nodes after it
    /// (their places predicted). Sets `complete` to false at a leaf the prediction did not foresee
    /// (the rest of the build is then wasted and redone). `memo` is only read (filled by
    /// build_tree()). Only the nodes of one subtree write its `complete`, one after another (a node
    /// writes it after its children's tasks have joined; a right half has its own flag).
    void build_in_place(const Eigen::Matrix3Xd& points, Index first, Index last, std::size_t id, int depth,
                        const std::vector<std::pair<Index, std::size_t>>& memo, bool& complete);

    /// Appends the subtree over m_order[first, last) to `nodes` (absolute indices). Returns its root.
    Index build(const Eigen::Matrix3Xd& points, Index first, Index last, std::vector<Node>& nodes);

    /// Sets `node`'s range and box over m_order[first, last) and, unless it is a leaf (at most
    /// leaf_size points, or all coincide), splits the range at its median along the box's longest
    /// side. Returns the start of the right half (`last` for a leaf).
    Index split(const Eigen::Matrix3Xd& points, Index first, Index last, Node& node);

    /// Throws unless `layout` is that of a median-split tree over n points (see its constructor).
    static void check_layout(const Layout& layout, std::size_t n);

    /// Points and reaches in hierarchy order (checked already).
    void order_points(const Eigen::Matrix3Xd& coordinates, const Eigen::VectorXd& reach);

    /// Every node's tight box from the ordered points, bottom-up (children follow their parents in
    /// depth-first order, so a backward sweep sees children first).
    void node_boxes();

    /// Every node's largest reach, bottom-up.
    void node_reaches();

    /// Node reaches, and the slabs or spheres the volume asks for (the points ordered, the boxes set).
    void finish();

    /// The slab of every node: the points' second moments are summed bottom-up (relative to the
    /// root box's centre), the normal is their covariance's smallest eigenvector, and the interval
    /// is taken over the node's points. O(N log N) time, O(height) moments alive at once, in
    /// parallel over subtrees.
    void compute_slabs();
    /// The first and second moments of a node's points about the root box's centre.
    struct Moments {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        Eigen::Matrix3d squares = Eigen::Matrix3d::Zero();
    };
    /// Sets the slabs of the subtree of node i (post-order: a node's moments are its children's sum,
    /// so only those along the path are alive) and returns node i's moments; halves of more than
    /// parallel_points points in parallel, down to `depth` levels.
    Moments slab_subtree(Index i, const Eigen::Vector3d& origin, int depth);

    /// The sphere of every node: centred at the centroid of its points or at its box centre,
    /// whichever gives the smaller ball holding them. O(N log N), in parallel over nodes.
    void compute_spheres();

    Eigen::Vector3d centroid(const Node& node) const;

    /// The smallest ball centred at `centre` that holds the node's points.
    Sphere sphere_of_points(const Node& node, const Eigen::Vector3d& centre) const;

    /// The smallest ball holding the balls a and b.
    static Sphere enclosing(const Sphere& a, const Sphere& b);

    /// The tree's height: nodes are stored in depth-first order (children after their parent), so
    /// one pass from the last node to the root sees both children before the parent.
    std::size_t height_of_tree() const;

    std::vector<Node> m_nodes;
    std::vector<Index> m_order;
    Eigen::Matrix4Xd m_ordered;
    std::vector<Sphere> m_spheres;
    std::size_t m_leaf_size = 8;
    Bounding_volume m_volume = Bounding_volume::box_and_slab;
    bool m_has_reach = false;
};

} // namespace PCCD

#include <PCCD/Hierarchy/internal/Point_cloud_hierarchy_build.h>
