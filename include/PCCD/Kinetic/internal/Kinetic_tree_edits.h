// PCCD/Kinetic/internal/Kinetic_tree_edits.h -- the changes of a kinetic AABB tree at run time
// (doc/manual/kinetic.md, "Changing the animation at run time"): replacing a vertex's flightplan,
// inserting a primitive (a new leaf paired with the leaf reached by least surface-area growth) and
// removing one (its sibling takes the parent's place), each repairing only the affected paths at
// now; with the node and incidence bookkeeping they need.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/Kinetic_certificates.h>
#include <PCCD/Kinetic/internal/Kinetic_node_access.h>
#include <PCCD/Kinetic/internal/Kinetic_tree_state.h>

namespace PCCD::internal {

/// Records primitive i in the incidence lists of its vertices (once per vertex).
template <class F, class P, class Queue>
void add_incidence(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t i)
{
    for (std::size_t k = 0; k < P::vertex_count; ++k) {
        std::vector<std::uint32_t>& list = s.incident[s.primitives[i].vertex(k)];
        if (std::find(list.begin(), list.end(), i) == list.end()) list.push_back(i);
    }
}

/// Removes primitive i from the incidence lists of its vertices.
template <class F, class P, class Queue>
void remove_incidence(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t i)
{
    for (std::size_t k = 0; k < P::vertex_count; ++k) {
        std::vector<std::uint32_t>& list = s.incident[s.primitives[i].vertex(k)];
        list.erase(std::remove(list.begin(), list.end(), i), list.end());
    }
}

/// A fresh node: the most recently freed one, or a new one (growing every per-node table).
template <class F, class P, class Queue>
std::uint32_t allocate_node(Kinetic_tree_state<F, P, Queue>& s)
{
    std::uint32_t n;
    if (!s.free_nodes.empty()) {
        n = s.free_nodes.back();
        s.free_nodes.pop_back();
        s.nodes[n] = AABB_node{};
        s.extreme[n] = s.unset_extremes();
        s.updated_in_round[n] = 0;
    } else {
        n = std::uint32_t(s.nodes.size());
        s.nodes.push_back({});
        s.extreme.push_back(s.unset_extremes());
        s.updated_in_round.push_back(0);
        s.queue.resize(s.nodes.size() * s.bound_count);
        s.overtaker.resize(s.nodes.size() * s.bound_count, no_node);
    }
    return n;
}

/// Frees node n and drops its certificates from the queue.
template <class F, class P, class Queue>
void free_node(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n)
{
    for (int b = 0; b < s.bound_count; ++b) s.queue.erase(s.certificate_id(n, b));
    s.free_nodes.push_back(n);
}

/// Puts `new_child` where `old_child` was under `parent` (at the root when parent is no_node).
template <class F, class P, class Queue>
void replace_child(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t parent, std::uint32_t old_child,
                   std::uint32_t new_child)
{
    if (parent == no_node)
        s.root = new_child;
    else if (s.nodes[parent].left == old_child)
        s.nodes[parent].left = new_child;
    else
        s.nodes[parent].right = new_child;
}

/// Growth of the surface area (halved) of `box` when `added` is merged into it.
inline double surface_area_growth(const Eigen::AlignedBox3d& box, const Eigen::AlignedBox3d& added)
{
    auto area = [](const Eigen::AlignedBox3d& b) {
        const Eigen::Vector3d s = b.sizes();
        return s.x() * s.y() + s.y() * s.z() + s.z() * s.x();
    };
    return area(box.merged(added)) - area(box);
}

/// Recomputes all bounds of `from` and then of its ancestors, stopping above `from` at the first
/// node that keeps all its extremes. `from_is_new`: the first extremes of a new node are not
/// counted as BV updates.
template <class F, class P, class Queue>
void repair_path(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t from, bool from_is_new)
{
    bool first = true;
    for (std::uint32_t n = from; n != no_node; n = s.nodes[n].parent) {
        bool any = false;
        for (int b = 0; b < s.bound_count; ++b) {
            if (update_bound(s, n, b)) {
                any = true;
                if (!first || !from_is_new) count_update(s, n);
            }
        }
        if (!any && !first) break;
        first = false;
    }
}

/// After the flightplan of vertex v was replaced: recomputes at now the bounds above the leaves of
/// v's primitives in which v is involved (as extreme or candidate) or whose candidates changed,
/// going up while anything changes or v is an extreme (one update round).
template <class F, class P, class Queue>
void repair_after_flightplan_change(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t v)
{
    constexpr int bound_count = Kinetic_tree_state<F, P, Queue>::bound_count;
    next_update_round(s);
    for (const std::uint32_t i : s.incident[v]) {
        std::array<bool, bound_count> changed{};
        for (std::uint32_t n = s.nodes[s.leaf_of[i]].parent; n != no_node; n = s.nodes[n].parent) {
            bool go_on = false;
            for (int b = 0; b < bound_count; ++b) {
                const bool involved = is_candidate(s, v, s.nodes[n].left, b) || is_candidate(s, v, s.nodes[n].right, b);
                changed[std::size_t(b)] = (involved || changed[std::size_t(b)]) && update_bound(s, n, b);
                if (changed[std::size_t(b)]) count_update(s, n);
                go_on = go_on || changed[std::size_t(b)] || s.extreme[n][std::size_t(b)] == v;
            }
            if (!go_on) break;
        }
    }
}

/// Stores `primitive` (vertices checked by the caller) and gives it a leaf at now, paired with the
/// leaf reached by descending towards the child whose box grows least in surface area; repairs the
/// path above (one update round). Returns the primitive's index (a freed index is reused).
template <class F, class P, class Queue>
std::uint32_t insert_primitive(Kinetic_tree_state<F, P, Queue>& s, const P& primitive, const char* owner)
{
    const std::uint32_t i = s.primitives.insert(primitive, owner);
    if (i >= s.leaf_of.size()) s.leaf_of.resize(s.primitives.capacity(), no_node);
    add_incidence(s, i);
    ++s.stats.insertions;
    next_update_round(s);
    const std::uint32_t leaf = allocate_node(s);
    s.nodes[leaf].primitive = i;
    s.leaf_of[i] = leaf;
    if (s.root == no_node) {
        s.root = leaf;
        return i;
    }
    const Eigen::AlignedBox3d box_new = node_box(s, leaf);
    std::uint32_t sibling = s.root;
    while (!s.nodes[sibling].is_leaf()) {
        const std::uint32_t l = s.nodes[sibling].left, r = s.nodes[sibling].right;
        sibling = surface_area_growth(node_box(s, l), box_new) <= surface_area_growth(node_box(s, r), box_new) ? l : r;
    }
    const std::uint32_t inner = allocate_node(s);
    const std::uint32_t grand = s.nodes[sibling].parent;
    s.nodes[inner].parent = grand;
    s.nodes[inner].left = sibling;
    s.nodes[inner].right = leaf;
    replace_child(s, grand, sibling, inner);
    s.nodes[sibling].parent = inner;
    s.nodes[leaf].parent = inner;
    repair_path(s, inner, true);
    return i;
}

/// Removes live primitive i (checked by the caller): its leaf goes, its sibling takes the parent's
/// place, and the path above is repaired at now (one update round).
template <class F, class P, class Queue>
void remove_primitive(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t i)
{
    ++s.stats.removals;
    next_update_round(s);
    remove_incidence(s, i);
    s.primitives.remove(i);
    const std::uint32_t leaf = s.leaf_of[i];
    s.leaf_of[i] = no_node;
    const std::uint32_t inner = s.nodes[leaf].parent;
    free_node(s, leaf);
    if (inner == no_node) {
        s.root = no_node;
        return;
    }
    const std::uint32_t sibling = s.nodes[inner].left == leaf ? s.nodes[inner].right : s.nodes[inner].left;
    const std::uint32_t grand = s.nodes[inner].parent;
    s.nodes[sibling].parent = grand;
    replace_child(s, grand, inner, sibling);
    free_node(s, inner);
    if (grand != no_node) repair_path(s, grand, false);
}

} // namespace PCCD::internal
