// PCCD/Kinetic/internal/AABB_tree_build.h -- the one static top-down build of Kinetic_AABB_tree and
// Refit_AABB_tree (doc/manual/kinetic.md, "Building and advancing": "a median split of the
// primitives' centroids"; Refit_AABB_tree's rebuild uses it at every frame): median split of
// primitive centroids along the longest side of their box, a binary tree with one primitive per
// leaf and height ceil(log2 n), in O(n log n); plus the node type and the walks both trees share.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Kinetic/internal/Primitive_slots.h>

namespace PCCD::internal {

inline constexpr std::uint32_t no_node = std::numeric_limits<std::uint32_t>::max();

/// One node of a binary AABB tree: a leaf holds one primitive, an inner node two children.
struct AABB_node {
    std::uint32_t parent = no_node;
    std::uint32_t left = no_node;  ///< no_node for a leaf
    std::uint32_t right = no_node;
    std::uint32_t primitive = no_node; ///< the primitive of a leaf
    bool is_leaf() const { return left == no_node; }
};

/// Builds the tree over `primitives` (ids into `centroids`) into `nodes` (appended, pre-order, so a
/// parent precedes its children); returns the root, or no_node when `primitives` is empty.
/// Ties between equal centroids are broken by primitive id, so the result is deterministic.
inline std::uint32_t build_median_split(std::vector<std::uint32_t> primitives, const std::vector<Eigen::Vector3d>& centroids,
                                        std::vector<AABB_node>& nodes)
{
    if (primitives.empty()) return no_node;
    struct Task {
        std::size_t begin, end;
        std::uint32_t parent;
        bool is_left;
    };
    std::vector<Task> stack{{0, primitives.size(), no_node, true}};
    std::uint32_t root = no_node;
    while (!stack.empty()) {
        const Task task = stack.back();
        stack.pop_back();
        const auto index = std::uint32_t(nodes.size());
        nodes.push_back({});
        nodes[index].parent = task.parent;
        if (task.parent == no_node)
            root = index;
        else if (task.is_left)
            nodes[task.parent].left = index;
        else
            nodes[task.parent].right = index;
        if (task.end - task.begin == 1) {
            nodes[index].primitive = primitives[task.begin];
            continue;
        }
        Eigen::AlignedBox3d box;
        for (std::size_t i = task.begin; i < task.end; ++i) box.extend(centroids[primitives[i]]);
        int axis = 0;
        box.sizes().maxCoeff(&axis);
        const std::size_t mid = task.begin + (task.end - task.begin) / 2;
        std::nth_element(primitives.begin() + std::ptrdiff_t(task.begin), primitives.begin() + std::ptrdiff_t(mid),
                         primitives.begin() + std::ptrdiff_t(task.end), [&](std::uint32_t a, std::uint32_t b) {
                             const double ca = centroids[a][axis], cb = centroids[b][axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        // Right pushed first so the left subtree is built first and directly follows its parent.
        stack.push_back({mid, task.end, index, false});
        stack.push_back({task.begin, mid, index, true});
    }
    return root;
}

/// Builds the tree over the live primitives of `primitives` into `nodes` (appended) with
/// build_median_split; returns the root. The centroid of primitive i, the mean of `position(v)`
/// over its vertices v, goes to centroids[i] (resized to the slots' capacity).
template <class P, class Position>
std::uint32_t build_over_live_primitives(const Primitive_slots<P>& primitives, Position&& position,
                                         std::vector<Eigen::Vector3d>& centroids, std::vector<AABB_node>& nodes)
{
    std::vector<std::uint32_t> ids;
    ids.reserve(primitives.live_count());
    centroids.resize(primitives.capacity());
    for (std::uint32_t i = 0; i < std::uint32_t(primitives.capacity()); ++i) {
        if (!primitives.contains(i)) continue;
        ids.push_back(i);
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < P::vertex_count; ++k) c += position(std::uint32_t(primitives[i].vertex(k)));
        centroids[i] = c / double(P::vertex_count);
    }
    return build_median_split(std::move(ids), centroids, nodes);
}

/// A node array read as a tree by the walks of PCCD/Hierarchy/traversal.h.
struct AABB_node_array {
    const std::vector<AABB_node>& nodes;
    bool is_leaf(std::uint32_t n) const { return nodes[n].is_leaf(); }
    std::uint32_t left(std::uint32_t n) const { return nodes[n].left; }
    std::uint32_t right(std::uint32_t n) const { return nodes[n].right; }
};

/// Nodes of the subtree of `root` in post-order (children before parents): the reverse of a
/// pre-order walk that takes the right child first.
inline void postorder(const std::vector<AABB_node>& nodes, std::uint32_t root, std::vector<std::uint32_t>& out)
{
    out.clear();
    if (root == no_node) return;
    struct Traits {
        std::vector<std::uint32_t>& out;
        bool go_further() const { return true; }
        bool enter(std::uint32_t n)
        {
            out.push_back(n);
            return true;
        }
        void leaf(std::uint32_t) {}
        bool left_first(std::uint32_t) const { return false; }
    } traits{out};
    traverse(AABB_node_array{nodes}, root, traits);
    std::reverse(out.begin(), out.end());
}

/// Height of the subtree of `root` (a single leaf has height 0; an empty tree -1): children's
/// heights before their parents', in post-order.
inline int height(const std::vector<AABB_node>& nodes, std::uint32_t root)
{
    if (root == no_node) return -1;
    std::vector<std::uint32_t> order;
    postorder(nodes, root, order);
    std::vector<int> heights(nodes.size(), 0);
    for (const std::uint32_t n : order)
        if (!nodes[n].is_leaf()) heights[n] = 1 + std::max(heights[nodes[n].left], heights[nodes[n].right]);
    return heights[root];
}

} // namespace PCCD::internal
