// Tests of PCCD/Hierarchy/traversal.h, the one walk of every hierarchy query, and of its concepts (PCCD/concepts/TreeWalk.h), against brute force on
// explicit trees: a walk whose traits enter every node visits each node once and every leaf in the
// order left_first() asks for; a pruned subtree is never entered; go_further() stops the walk and
// reports what was pending; the pair walk reports every leaf pair exactly once for each split
// rule, in the near-first order; a degenerate tree deeper than the stack's fixed part (a chain of
// 300 levels) is walked completely. The queries built on it (within_reach, nearest_point, the
// reach and overlapping-leaf traversals, the kinetic queries) have tests of their own against
// brute force.
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/concepts/TreeWalk.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace {

/// An explicit binary tree: node n has children children[n] (none for a leaf).
struct Test_tree {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> children; // {0, 0}: a leaf
    bool is_leaf(std::uint32_t n) const { return children[n].first == 0 && children[n].second == 0; }
    std::uint32_t left(std::uint32_t n) const { return children[n].first; }
    std::uint32_t right(std::uint32_t n) const { return children[n].second; }
    std::vector<std::uint32_t> leaves() const
    {
        std::vector<std::uint32_t> out;
        for (std::uint32_t n = 0; n < children.size(); ++n)
            if (is_leaf(n)) out.push_back(n);
        return out;
    }
};

/// A complete tree of `levels` levels in breadth-first numbering (root 0, children 2n+1, 2n+2).
Test_tree complete_tree(int levels)
{
    Test_tree t;
    const std::uint32_t count = (1u << levels) - 1;
    t.children.resize(count, {0, 0});
    for (std::uint32_t n = 0; 2 * n + 2 < count; ++n) t.children[n] = {2 * n + 1, 2 * n + 2};
    return t;
}

/// A chain: every inner node has a leaf as its left child and the rest of the chain as its right.
Test_tree chain_tree(int depth)
{
    Test_tree t;
    t.children.push_back({0, 0});
    std::uint32_t inner = 0;
    for (int d = 0; d < depth; ++d) {
        const auto leaf = std::uint32_t(t.children.size());
        t.children.push_back({0, 0});
        const auto next = std::uint32_t(t.children.size());
        t.children.push_back({0, 0});
        t.children[inner] = {leaf, next};
        inner = next;
    }
    return t;
}

struct Record_all {
    const Test_tree& tree;
    bool left_first_order = true;
    std::uint32_t skip = 0xffffffffu; // a node whose subtree is pruned
    std::size_t stop_after = 0;       // stop after this many leaves (0: never)
    std::vector<std::uint32_t> entered{}, leaves{};
    bool go_further() const { return stop_after == 0 || leaves.size() < stop_after; }
    bool enter(std::uint32_t n)
    {
        entered.push_back(n);
        return n != skip;
    }
    void leaf(std::uint32_t n) { leaves.push_back(n); }
    bool left_first(std::uint32_t) const { return left_first_order; }
};

/// The leaves below n, left to right.
void leaves_below(const Test_tree& t, std::uint32_t n, std::vector<std::uint32_t>& out)
{
    if (t.is_leaf(n)) {
        out.push_back(n);
        return;
    }
    leaves_below(t, t.left(n), out);
    leaves_below(t, t.right(n), out);
}

} // namespace

TEST_CASE("The walk enters every node once and meets the leaves in the order asked", "[hierarchy][traversal]")
{
    const Test_tree tree = complete_tree(6);
    std::vector<std::uint32_t> left_to_right;
    leaves_below(tree, 0, left_to_right);

    Record_all left{tree};
    const PCCD::Walk_counters counters = PCCD::traverse(tree, std::uint32_t(0), left);
    CHECK(counters.tested == tree.children.size());
    CHECK(counters.pending == 0);
    CHECK(std::set<std::uint32_t>(left.entered.begin(), left.entered.end()).size() == tree.children.size());
    CHECK(left.leaves == left_to_right);

    Record_all right{tree, false};
    PCCD::traverse(tree, std::uint32_t(0), right);
    CHECK(std::vector<std::uint32_t>(right.leaves.rbegin(), right.leaves.rend()) == left_to_right);
}

TEST_CASE("A pruned subtree is not entered and go_further stops the walk", "[hierarchy][traversal]")
{
    const Test_tree tree = complete_tree(5);
    Record_all pruned{tree};
    pruned.skip = 1; // the root's left subtree
    PCCD::traverse(tree, std::uint32_t(0), pruned);
    std::vector<std::uint32_t> expected;
    leaves_below(tree, 2, expected);
    CHECK(pruned.leaves == expected);
    for (std::uint32_t n : pruned.entered) CHECK((n <= 2 || (n - 1) / 2 != 1)); // no child of node 1

    Record_all stopped{tree};
    stopped.stop_after = 3;
    const PCCD::Walk_counters counters = PCCD::traverse(tree, std::uint32_t(0), stopped);
    CHECK(stopped.leaves.size() == 3);
    CHECK(counters.pending > 0);
    CHECK(counters.tested < tree.children.size());
}

TEST_CASE("A chain deeper than the fixed stack is walked completely", "[hierarchy][traversal]")
{
    const Test_tree tree = chain_tree(300);
    Record_all all{tree};
    // Right child first: the pending left leaves pile up, 300 of them, past the 64 held in place.
    all.left_first_order = false;
    PCCD::traverse(tree, std::uint32_t(0), all);
    CHECK(all.leaves.size() == tree.leaves().size());
    CHECK(std::set<std::uint32_t>(all.leaves.begin(), all.leaves.end()).size() == all.leaves.size());
}

namespace {

struct Record_pairs {
    const Test_tree& a;
    const Test_tree& b;
    PCCD::Pair_split inner_rule; // what to do with two inner nodes
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs{};
    bool go_further() const { return true; }
    bool enter(std::uint32_t, std::uint32_t) const { return true; }
    PCCD::Pair_split split(std::uint32_t i, std::uint32_t j) const
    {
        if (a.is_leaf(i) && b.is_leaf(j)) return PCCD::Pair_split::leaves;
        if (a.is_leaf(i)) return PCCD::Pair_split::second;
        if (b.is_leaf(j)) return PCCD::Pair_split::first;
        return inner_rule;
    }
    void leaf_pair(std::uint32_t i, std::uint32_t j) { pairs.emplace_back(i, j); }
    bool first_left_first(std::uint32_t, std::uint32_t) const { return true; }
    bool second_left_first(std::uint32_t, std::uint32_t) const { return false; }
};

} // namespace

TEST_CASE("The pair walk reports every leaf pair once, for each split rule", "[hierarchy][traversal]")
{
    const Test_tree a = complete_tree(4);
    const Test_tree b = chain_tree(5);
    std::set<std::pair<std::uint32_t, std::uint32_t>> all;
    for (std::uint32_t i : a.leaves())
        for (std::uint32_t j : b.leaves()) all.emplace(i, j);
    for (const PCCD::Pair_split rule : {PCCD::Pair_split::first, PCCD::Pair_split::second, PCCD::Pair_split::both}) {
        Record_pairs walk{a, b, rule};
        PCCD::traverse(a, std::uint32_t(0), b, std::uint32_t(0), walk);
        CHECK(walk.pairs.size() == all.size());
        CHECK(std::set<std::pair<std::uint32_t, std::uint32_t>>(walk.pairs.begin(), walk.pairs.end()) == all);
        // second_left_first() is false: b's right subtree comes first, so the first pair holds the
        // first leaf of b met by always going right, and a's leftmost leaf.
        std::uint32_t leftmost_a = 0, rightmost_b = 0;
        while (!a.is_leaf(leftmost_a)) leftmost_a = a.left(leftmost_a);
        while (!b.is_leaf(rightmost_b)) rightmost_b = b.right(rightmost_b);
        CHECK(walk.pairs.front() == std::make_pair(leftmost_a, rightmost_b));
    }
}

TEST_CASE("The pair walk of a tree with itself pairs its two subtrees", "[hierarchy][traversal]")
{
    const Test_tree t = complete_tree(4);
    Record_pairs walk{t, t, PCCD::Pair_split::both};
    PCCD::traverse(t, t.left(0), t, t.right(0), walk);
    std::vector<std::uint32_t> left, right;
    leaves_below(t, t.left(0), left);
    leaves_below(t, t.right(0), right);
    CHECK(walk.pairs.size() == left.size() * right.size());
}
