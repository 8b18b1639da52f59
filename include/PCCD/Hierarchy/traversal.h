// PCCD/Hierarchy/traversal.h -- the one depth-first walk over a bounding-volume tree, or over two
// trees at once, that every hierarchy query of PCCD runs (doc/algorithms.md "Point cloud
// hierarchy"; doc/manual/hierarchy.md "Traversals"). A query is a traits class: it tests nodes (or
// node pairs), acts at leaves (or leaf pairs), chooses which children come first and may stop the
// walk, the way CGAL's AABB_tree::traversal(query, traits) separates the walk from what it is for.
// The point queries (within_reach, nearest_point; descend_to_near_point on descend(), a descent
// without a stack), the reach traversal of two objects, the overlapping leaves of the flat traversal
// and the kinetic and refit trees' overlap, range and ray queries are traits of these functions.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include <PCCD/concepts/TreeWalk.h>

namespace PCCD {

namespace internal {

/// A LIFO stack that keeps its first N items in place (no allocation for the balanced trees of
/// PCCD: a depth-first walk holds at most a few pending siblings per level) and moves to the heap,
/// doubling, beyond them (a degenerate tree of any depth). pop() is one decrement and one load.
template <class T, std::size_t N>
class Walk_stack {
public:
    Walk_stack() = default;
    Walk_stack(const Walk_stack&) = delete;
    Walk_stack& operator=(const Walk_stack&) = delete;

    bool empty() const { return m_top == 0; }
    /// The number of items held.
    std::size_t size() const { return m_top; }
    void push(const T& item)
    {
        if (m_top == m_capacity) [[unlikely]]
            grow();
        m_data[m_top++] = item;
    }
    T pop() { return m_data[--m_top]; }

private:
    /// Out of line and cold, so that push() stays small enough to be inlined into the walk.
    [[gnu::noinline, gnu::cold]] void grow()
    {
        const bool in_place = m_data == m_items;
        m_heap.resize(2 * m_capacity);
        if (in_place) std::copy(m_items, m_items + m_top, m_heap.begin());
        m_data = m_heap.data();
        m_capacity = m_heap.size();
    }

    std::size_t m_top = 0;
    std::size_t m_capacity = N;
    T m_items[N];
    T* m_data = m_items;
    std::vector<T> m_heap;
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

/// Descends `tree` from node `root` to one leaf without backtracking (a walk that stops at its first
/// leaf and keeps no sibling): at each inner node i into the child traits.next(i) returns (one of
/// tree.left(i), tree.right(i)), then traits.leaf() of the leaf reached, which it returns.
/// Complexity: O(height), no stack.
template <class Tree, class Index, class Traits>
    requires WalkableTree<Tree, Index> && requires(Traits& traits, Index i) {
        { traits.next(i) } -> std::convertible_to<Index>;
        traits.leaf(i);
    }
Index descend(const Tree& tree, Index root, Traits& traits)
{
    Index i = root;
    while (!tree.is_leaf(i)) i = traits.next(i);
    traits.leaf(i);
    return i;
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
            Index sooner = first.left(i), later = first.right(i); // not near/far: macros on some platforms
            if (!traits.first_left_first(i, j)) std::swap(sooner, later);
            stack.push({later, j});
            stack.push({sooner, j});
            break;
        }
        case Pair_split::second: {
            Index sooner = second.left(j), later = second.right(j);
            if (!traits.second_left_first(i, j)) std::swap(sooner, later);
            stack.push({i, later});
            stack.push({i, sooner});
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
