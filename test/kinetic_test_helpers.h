// Shared helpers of the kinetic tests: the nodes of a tree in preorder, and the bound on the number
// of events of a kinetic tree over points with linear flightplans.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

namespace pccd_test {

/// The nodes of a kinetic tree in depth-first preorder, checking on the way that every child's
/// parent link points back and that every node is reached.
template <class Tree>
std::vector<typename Tree::Node_index> nodes_in_preorder(const Tree& tree)
{
    using Node = typename Tree::Node_index;
    std::vector<Node> order, stack{tree.root()};
    while (!stack.empty()) {
        const Node n = stack.back();
        stack.pop_back();
        order.push_back(n);
        if (!tree.is_leaf(n)) {
            REQUIRE(tree.parent(tree.left(n)) == n);
            REQUIRE(tree.parent(tree.right(n)) == n);
            stack.push_back(tree.left(n));
            stack.push_back(tree.right(n));
        }
    }
    REQUIRE(order.size() == tree.node_count());
    return order;
}

/// 6 times the sum over the nodes of (points below - 1): each pair of linear flightplans crosses at
/// most once per axis, so the upper envelope of a node's m lines changes its extreme at most m - 1
/// times per bound, six bounds per node.
template <class Tree>
std::uint64_t envelope_bound(const Tree& tree)
{
    std::vector<std::size_t> size(tree.node_count(), 0);
    const auto order = nodes_in_preorder(tree);
    std::uint64_t bound = 0;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        size[*it] = tree.is_leaf(*it) ? 1 : size[tree.left(*it)] + size[tree.right(*it)];
        bound += 6 * (size[*it] - 1);
    }
    return bound;
}

} // namespace pccd_test
