// PCCD/concepts/TreeWalk.h -- concepts of the one walk over bounding-volume trees
// (PCCD/Hierarchy/traversal.h; doc/manual/hierarchy.md "Traversals: one walk, queries as traits"):
// the trees it descends (WalkableTree) and the traits a query gives it, for one tree
// (TreeWalkTraits) or two at once (TreePairWalkTraits, with the Pair_split a pair's traits choose).
// Archetypes: test/Hierarchy/traversal_test.cpp walks explicit trees with minimal traits.
#pragma once

#include <concepts>
#include <cstdint>

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

} // namespace PCCD
