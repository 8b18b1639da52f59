// PCCD/Hierarchy/internal/Point_cloud_hierarchy_build.h -- the build of a Point_cloud_hierarchy
// (doc/algorithms.md "Point cloud hierarchy"): median splits in place (the halves of large nodes in
// parallel), layout checks, the point order, boxes, reaches, slabs and spheres of the nodes. The
// out-of-line private members of the class; included at the end of
// PCCD/Hierarchy/Point_cloud_hierarchy.h (not self-contained: the class comes first there).
#pragma once

namespace PCCD {

inline void Point_cloud_hierarchy::build_tree(const Eigen::Matrix3Xd& points)
{
    const Index n = Index(points.cols());
    std::vector<std::pair<Index, std::size_t>> memo;
    m_nodes.assign(predicted_nodes(n, memo), Node{});
    bool complete = true;
    build_in_place(points, 0, n, 0, parallel_depth, memo, complete);
    if (complete) return;
    std::iota(m_order.begin(), m_order.end(), Index(0));
    m_nodes.clear();
    build(points, 0, n, m_nodes);
    m_nodes.shrink_to_fit();
}

inline std::size_t Point_cloud_hierarchy::predicted_nodes(Index count, std::vector<std::pair<Index, std::size_t>>& memo) const
{
    if (count <= m_leaf_size) return 1;
    for (const auto& [c, nodes] : memo)
        if (c == count) return nodes;
    const std::size_t nodes = 1 + predicted_nodes(count / 2, memo) + predicted_nodes(count - count / 2, memo);
    memo.emplace_back(count, nodes);
    return nodes;
}

inline void Point_cloud_hierarchy::build_in_place(const Eigen::Matrix3Xd& points, Index first, Index last, std::size_t id, int depth,
                        const std::vector<std::pair<Index, std::size_t>>& memo, bool& complete)
{
    Node& node = m_nodes[id];
    const Index middle = split(points, first, last, node);
    if (middle == last) {
        if (node.count > m_leaf_size) complete = false; // coincident points: not the predicted shape
        return;
    }
    const Index left_count = middle - first;
    std::size_t left_nodes = 1;
    if (left_count > m_leaf_size)
        for (const auto& [c, nodes] : memo)
            if (c == left_count) left_nodes = nodes;
    node.right = Index(id + 1 + left_nodes);
    const auto left = [&] { build_in_place(points, first, middle, id + 1, depth - 1, memo, complete); };
    bool right_complete = true;
    const auto right = [&] { build_in_place(points, middle, last, node.right, depth - 1, memo, right_complete); };
    if (depth > 0 && last - first > parallel_points) {
        internal::parallel_invoke(left, right);
    } else {
        left();
        right();
    }
    if (!right_complete) complete = false;
}

inline Point_cloud_hierarchy::Index Point_cloud_hierarchy::build(const Eigen::Matrix3Xd& points, Index first, Index last, std::vector<Node>& nodes)
{
    const Index id = Index(nodes.size());
    nodes.push_back(Node{});
    Node node;
    const Index middle = split(points, first, last, node);
    nodes[id] = node;
    if (middle == last) return id;
    build(points, first, middle, nodes);
    nodes[id].right = build(points, middle, last, nodes);
    return id;
}

inline Point_cloud_hierarchy::Index Point_cloud_hierarchy::split(const Eigen::Matrix3Xd& points, Index first, Index last, Node& node)
{
    Eigen::AlignedBox3d box;
    for (Index k = first; k < last; ++k) box.extend(points.col(m_order[k]));
    node.box = box;
    node.first = first;
    node.count = last - first;
    if (std::size_t(last - first) <= m_leaf_size) return last;
    Eigen::Index axis = 0;
    box.sizes().maxCoeff(&axis);
    if (!(box.sizes()(axis) > 0.0)) return last; // all points coincide: one leaf, whatever its size
    const Index middle = first + (last - first) / 2;
    // Ties broken by index so that the tree does not depend on the standard library's algorithm.
    std::nth_element(m_order.begin() + first, m_order.begin() + middle, m_order.begin() + last,
                     [&](Index a, Index b) {
                         const double ca = points(axis, a), cb = points(axis, b);
                         return ca < cb || (ca == cb && a < b);
                     });
    return middle;
}

inline void Point_cloud_hierarchy::check_layout(const Layout& layout, std::size_t n)
{
    const auto fail = [](auto&&... what) {
        throw Invalid_input(internal::concat("point cloud hierarchy layout: ", what...));
    };
    if (layout.order.size() != n) fail(layout.order.size(), " indices in the order for ", n, " points");
    std::vector<bool> seen(n, false);
    for (const Index k : layout.order) {
        if (k >= n || seen[k]) fail("the order is not a permutation of the points (index ", k, ")");
        seen[k] = true;
    }
    const std::size_t m = layout.counts.size();
    if (m == 0 || layout.rights.size() != m) fail(m, " node counts and ", layout.rights.size(), " right children");
    if (layout.counts[0] != n) fail("the root holds ", layout.counts[0], " of ", n, " points");
    if (int(layout.volume) > int(Bounding_volume::sphere)) fail("unknown bounding volume ", int(layout.volume));
    if (layout.leaf_size == 0) fail("leaf_size 0");
    // end[i]: one past the last node of i's subtree; nodes are depth-first, children after parents.
    std::vector<std::size_t> end(m);
    for (std::size_t i = m; i-- > 0;) {
        const Index r = layout.rights[i], c = layout.counts[i];
        if (r == no_child) {
            end[i] = i + 1;
            continue;
        }
        if (!(r > i + 1 && r < m) || end[i + 1] != r)
            fail("node ", i, ": right child ", r, " is not where its left subtree ends");
        if (c <= layout.leaf_size || layout.counts[i + 1] != c / 2 || layout.counts[r] != c - c / 2)
            fail("node ", i, " of ", c, " points is not split at its median");
        end[i] = end[r];
    }
    if (end[0] != m) fail(m - end[0], " nodes outside the tree");
}

inline void Point_cloud_hierarchy::order_points(const Eigen::Matrix3Xd& coordinates, const Eigen::VectorXd& reach)
{
    const std::size_t n = m_order.size();
    m_ordered.resize(4, Eigen::Index(n));
    for (std::size_t k = 0; k < n; ++k) {
        m_ordered.col(Eigen::Index(k)).head<3>() = coordinates.col(m_order[k]);
        m_ordered(3, Eigen::Index(k)) = reach.size() == 0 ? 0.0 : reach(m_order[k]);
    }
}

inline void Point_cloud_hierarchy::node_boxes()
{
    for (std::size_t i = m_nodes.size(); i-- > 0;) {
        Node& node = m_nodes[i];
        if (node.is_leaf()) {
            const auto block = m_ordered.middleCols(node.first, node.count).template topRows<3>();
            node.box = Eigen::AlignedBox3d(block.rowwise().minCoeff(), block.rowwise().maxCoeff());
        } else {
            node.box = m_nodes[left(Index(i))].box.merged(m_nodes[node.right].box);
        }
    }
}

inline void Point_cloud_hierarchy::node_reaches()
{
    for (std::size_t i = m_nodes.size(); i-- > 0;) {
        Node& node = m_nodes[i];
        node.reach = node.is_leaf() ? m_ordered.row(3).segment(node.first, node.count).maxCoeff()
                                    : std::max(m_nodes[left(Index(i))].reach, m_nodes[node.right].reach);
    }
}

inline void Point_cloud_hierarchy::finish()
{
    node_reaches();
    if (m_volume == Bounding_volume::box_and_slab) compute_slabs();
    if (m_volume == Bounding_volume::sphere) compute_spheres();
}

inline void Point_cloud_hierarchy::compute_slabs()
{
    slab_subtree(0, m_nodes.front().box.center(), parallel_depth);
}

inline Point_cloud_hierarchy::Moments Point_cloud_hierarchy::slab_subtree(Index i, const Eigen::Vector3d& origin, int depth)
{
    Node& node = m_nodes[i];
    Moments m;
    if (node.is_leaf()) {
        for (Index k = node.first; k < node.first + node.count; ++k) {
            const Eigen::Vector3d p = m_ordered.col(k).head<3>() - origin;
            m.sum += p;
            m.squares += p * p.transpose();
        }
    } else {
        Moments a, b;
        const auto left_half = [&] { a = slab_subtree(left(i), origin, depth - 1); };
        const auto right_half = [&] { b = slab_subtree(node.right, origin, depth - 1); };
        if (depth > 0 && node.count > parallel_points) {
            internal::parallel_invoke(left_half, right_half);
        } else {
            left_half();
            right_half();
        }
        m.sum = a.sum + b.sum;
        m.squares = a.squares + b.squares;
    }
    const Eigen::Vector3d mean = m.sum / double(node.count);
    const Eigen::Matrix3d covariance = m.squares / double(node.count) - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    Eigen::Vector3d normal = solver.eigenvectors().col(0);
    if (solver.info() != Eigen::Success || !internal::all_finite(normal) || !(normal.norm() > 0.5)) return m;
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
    return m;
}

inline void Point_cloud_hierarchy::compute_spheres()
{
    m_spheres.assign(m_nodes.size(), Sphere{});
    internal::parallel_for_ranges(m_nodes.size(), 256, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const Node& node = m_nodes[i];
            const Sphere a = sphere_of_points(node, centroid(node)), b = sphere_of_points(node, node.box.center());
            m_spheres[i] = a.radius <= b.radius ? a : b;
        }
    });
}

inline Eigen::Vector3d Point_cloud_hierarchy::centroid(const Node& node) const
{
    return m_ordered.middleCols(node.first, node.count).template topRows<3>().rowwise().mean();
}

inline Point_cloud_hierarchy::Sphere Point_cloud_hierarchy::sphere_of_points(const Node& node, const Eigen::Vector3d& centre) const
{
    double largest = 0.0;
    for (Index k = node.first; k < node.first + node.count; ++k)
        largest = std::max(largest, (m_ordered.col(k).head<3>() - centre).squaredNorm());
    // A few ulps more, so that rounding in a distance computed elsewhere cannot put a point outside.
    return {centre, std::sqrt(largest) * (1.0 + 8.0 * std::numeric_limits<double>::epsilon())};
}

inline Point_cloud_hierarchy::Sphere Point_cloud_hierarchy::enclosing(const Sphere& a, const Sphere& b)
{
    const Eigen::Vector3d d = b.centre - a.centre;
    const double distance = d.norm();
    if (distance + b.radius <= a.radius) return a;
    if (distance + a.radius <= b.radius) return b;
    const double radius = 0.5 * (distance + a.radius + b.radius);
    // Rounding: the radius is grown by a few ulps of the scale so that both balls stay inside.
    const double scale = distance + a.radius + b.radius + a.centre.cwiseAbs().maxCoeff();
    return {a.centre + ((radius - a.radius) / distance) * d, radius + 4.0 * std::numeric_limits<double>::epsilon() * scale};
}

inline std::size_t Point_cloud_hierarchy::height_of_tree() const
{
    std::vector<std::size_t> heights(m_nodes.size(), 1);
    for (std::size_t i = m_nodes.size(); i-- > 0;)
        if (!m_nodes[i].is_leaf()) heights[i] = 1 + std::max(heights[left(Index(i))], heights[right(Index(i))]);
    return heights.front();
}

} // namespace PCCD
