// PCCD/Hierarchy/traversal.h -- the one depth-first walk over a bounding-volume tree, or over two
// trees at once, that every hierarchy query of PCCD runs (doc/algorithms.md "Point cloud
// hierarchy"; doc/manual/hierarchy.md "Traversals"). A query is a traits class: it tests nodes (or
// node pairs), acts at leaves (or leaf pairs), chooses which children come first and may stop the
// walk, the way CGAL's AABB_tree::traversal(query, traits) separates the walk from what it is for.
// The point queries (within_reach, nearest_point), the reach traversal of two objects, the
// overlapping leaves of the flat traversal and the kinetic and refit trees' overlap, range and ray
// queries are traits of these two functions.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>
#include <cstdint>
#include <utility>
#include <vector>

namespace PCCD {

/// \concept WalkableTree
/// A binary tree the walks can descend, its nodes named by indices of the unsigned integer type
/// `Node`: for `const T& t` and a node `n`, `t.is_leaf(n)`, and for an inner node `t.left(n)` and
/// `t.right(n)`, its two children. The walks never ask anything else of the tree; the traits read
/// the nodes' volumes. Models: Point_cloud_hierarchy, Refit_AABB_tree and Kinetic_AABB_tree's
/// query view (std::uint32_t nodes).
template <class T, class Node>
concept WalkableTree = std::unsigned_integral<Node> && requires(const T& t, Node n) {
    { t.is_leaf(n) } -> std::convertible_to<bool>;
    { t.left(n) } -> std::convertible_to<Node>;
    { t.right(n) } -> std::convertible_to<Node>;
};

/// \concept TreeWalkTraits
/// What a query tells traverse(tree, root, traits) (`Index` the tree's node index):
/// - `traits.go_further()`: false stops the walk (e.g. after a first hit), checked before each node;
/// - `traits.enter(i)`: the node test; false prunes i's subtree;
/// - `traits.leaf(i)`: the leaf action, for every leaf whose test passed;
/// - `traits.left_first(i)`: for an inner node that passed, true to visit its left subtree first
///   (e.g. the child nearer the query).
template <class Traits, class Index>
concept TreeWalkTraits = requires(Traits& traits, Index i) {
    { traits.go_further() } -> std::convertible_to<bool>;
    { traits.enter(i) } -> std::convertible_to<bool>;
    traits.leaf(i);
    { traits.left_first(i) } -> std::convertible_to<bool>;
};

/// How a pair walk goes on from a node pair that passed its test (TreePairWalkTraits::split).
enum class Pair_split : std::uint8_t {
    leaves, ///< report the pair to the traits' leaf_pair() (both are leaves, or the query stops here)
    first,  ///< replace it by (each child of the first node, the second node)
    second, ///< replace it by (the first node, each child of the second node)
    both,   ///< replace it by the four pairs of children at once
};

/// \concept TreePairWalkTraits
/// What a query tells traverse(first, root_first, second, root_second, traits):
/// - `traits.go_further()`: false stops the walk, checked before each node pair;
/// - `traits.enter(i, j)`: the node-pair test; false prunes the pair;
/// - `traits.split(i, j)`: for a pair that passed, a Pair_split: report it as a leaf pair or which
///   nodes to open (the traits know which nodes are leaves; a leaf must not be opened);
/// - `traits.leaf_pair(i, j)`: the action for a pair split() reports;
/// - `traits.first_left_first(i, j)`, `traits.second_left_first(i, j)`: when node i of the first
///   tree (j of the second) is opened in pair (i, j), true to visit its left child first.
/// Children of both nodes (Pair_split::both) are visited as (near, near), (near, far), (far, near),
/// (far, far), "near" being the child each order puts first.
template <class Traits, class Index>
concept TreePairWalkTraits = requires(Traits& traits, Index i, Index j) {
    { traits.go_further() } -> std::convertible_to<bool>;
    { traits.enter(i, j) } -> std::convertible_to<bool>;
    { traits.split(i, j) } -> std::convertible_to<Pair_split>;
    traits.leaf_pair(i, j);
    { traits.first_left_first(i, j) } -> std::convertible_to<bool>;
    { traits.second_left_first(i, j) } -> std::convertible_to<bool>;
};

namespace internal {

/// A LIFO stack that keeps its first N items in place (no allocation for the balanced trees of
/// PCCD: a depth-first walk holds at most a few pending siblings per level) and spills to the heap
/// beyond them (a degenerate tree of any depth).
template <class T, int N>
class Walk_stack {
public:
    bool empty() const { return m_top == 0 && m_spilled.empty(); }
    /// The number of items held.
    std::size_t size() const { return std::size_t(m_top) + m_spilled.size(); }
    void push(const T& item)
    {
        if (m_top < N)
            m_items[m_top++] = item;
        else
            m_spilled.push_back(item);
    }
    T pop()
    {
        if (!m_spilled.empty()) {
            const T item = m_spilled.back();
            m_spilled.pop_back();
            return item;
        }
        return m_items[--m_top];
    }

private:
    T m_items[N];
    int m_top = 0;
    std::vector<T> m_spilled;
};

} // namespace internal

/// What a walk did.
struct Walk_counters {
    /// Nodes (or node pairs) tested.
    std::size_t tested = 0;
    /// Nodes (or node pairs) still waiting when go_further() stopped the walk (0 when it ran to
    /// its end).
    std::size_t pending = 0;
};

/// Walks `tree` depth first from node `root`: each node whose enter() passes is a leaf (leaf()) or
/// has its children visited, the one left_first() names first. Stops when go_further() is false.
/// Deterministic. Complexity: O(nodes tested), each at most once; O(height) extra space,
/// allocation-free up to height 64. Thread safety: the walk itself shares nothing.
template <class Tree, class Index, class Traits>
    requires WalkableTree<Tree, Index> && TreeWalkTraits<Traits, Index>
Walk_counters traverse(const Tree& tree, Index root, Traits& traits)
{
    Walk_counters counters;
    internal::Walk_stack<Index, 64> stack;
    stack.push(root);
    while (!stack.empty()) {
        if (!traits.go_further()) {
            counters.pending = stack.size();
            break;
        }
        const Index i = stack.pop();
        ++counters.tested;
        if (!traits.enter(i)) continue;
        if (tree.is_leaf(i)) {
            traits.leaf(i);
            continue;
        }
        const Index l = tree.left(i), r = tree.right(i);
        if (traits.left_first(i)) {
            stack.push(r);
            stack.push(l);
        } else {
            stack.push(l);
            stack.push(r);
        }
    }
    return counters;
}

/// Walks two trees at once, depth first from the pair (root_first, root_second): each pair whose
/// enter() passes is reported (leaf_pair()) or opened as split() says, children in the orders the
/// traits choose. Stops when go_further() is false. The two trees may be the same object (pairs of
/// its subtrees). Deterministic. Complexity: O(node pairs tested), each at most once; O(height)
/// extra space, allocation-free up to 64 levels. Thread safety: the walk itself shares nothing.
template <class First, class Second, class Index, class Traits>
    requires WalkableTree<First, Index> && WalkableTree<Second, Index> && TreePairWalkTraits<Traits, Index>
Walk_counters traverse(const First& first, Index root_first, const Second& second, std::type_identity_t<Index> root_second,
                       Traits& traits)
{
    Walk_counters counters;
    struct Pending { // trivially constructible: the stack's fixed part costs nothing to set up
        Index i, j;
    };
    internal::Walk_stack<Pending, 192> stack;
    stack.push({root_first, root_second});
    while (!stack.empty()) {
        if (!traits.go_further()) {
            counters.pending = stack.size();
            break;
        }
        const auto [i, j] = stack.pop();
        ++counters.tested;
        if (!traits.enter(i, j)) continue;
        switch (traits.split(i, j)) {
        case Pair_split::leaves: traits.leaf_pair(i, j); break;
        case Pair_split::first: {
            Index near = first.left(i), far = first.right(i);
            if (!traits.first_left_first(i, j)) std::swap(near, far);
            stack.push({far, j});
            stack.push({near, j});
            break;
        }
        case Pair_split::second: {
            Index near = second.left(j), far = second.right(j);
            if (!traits.second_left_first(i, j)) std::swap(near, far);
            stack.push({i, far});
            stack.push({i, near});
            break;
        }
        case Pair_split::both: {
            Index fa[2] = {first.left(i), first.right(i)}, se[2] = {second.left(j), second.right(j)};
            if (!traits.first_left_first(i, j)) std::swap(fa[0], fa[1]);
            if (!traits.second_left_first(i, j)) std::swap(se[0], se[1]);
            stack.push({fa[1], se[1]});
            stack.push({fa[1], se[0]});
            stack.push({fa[0], se[1]});
            stack.push({fa[0], se[0]});
            break;
        }
        }
    }
    return counters;
}

} // namespace PCCD
