// PCCD/Kinetic/internal/AABB_tree_queries.h -- the queries shared by Kinetic_AABB_tree and
// Refit_AABB_tree (doc/manual/kinetic.md, "Queries"): box overlap of two trees, self-overlap
// without adjacent primitives, box range queries, first hit of a ray on triangles, and a generic
// simultaneous traversal with user callbacks. The public pieces they use, Kinetic_ray,
// intersect_ray_triangle and boxes_overlap, have headers of their own.
//
// A tree is read through: root(), is_leaf(n), left(n), right(n), leaf_primitive(n), box(n) (the
// node's box at the tree's current time), primitive(i) and vertex_position(v).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Kinetic/Kinetic_ray.h>
#include <PCCD/Kinetic/boxes_overlap.h>
#include <PCCD/Kinetic/intersect_ray_triangle.h>
#include <PCCD/Kinetic/internal/AABB_tree_build.h>

namespace PCCD::internal {

template <class Tree>
bool primitives_adjacent(const Tree& tree, std::uint32_t i, std::uint32_t j)
{
    using P = std::remove_cvref_t<decltype(tree.primitive(i))>;
    const P& a = tree.primitive(i);
    const P& b = tree.primitive(j);
    for (std::size_t x = 0; x < P::vertex_count; ++x)
        for (std::size_t y = 0; y < P::vertex_count; ++y)
            if (std::uint32_t(a.vertex(x)) == std::uint32_t(b.vertex(y))) return true;
    return false;
}

/// Simultaneous depth-first traversal of two trees (the pair walk of PCCD/Hierarchy/traversal.h):
/// `descend(na, nb, box_a, box_b)` decides whether a node pair is opened, `on_leaf_pair(na, nb)` is
/// called for leaf pairs that pass `descend`. The node with the larger box (by diagonal) is opened
/// first; leaves are never opened.
template <class TreeA, class TreeB, class Descend, class OnLeafPair>
void traverse_pairs(const TreeA& a, std::uint32_t root_a, const TreeB& b, std::uint32_t root_b, Descend&& descend,
                    OnLeafPair&& on_leaf_pair)
{
    if (root_a == no_node || root_b == no_node) return;
    // A node's box may be computed on demand (a kinetic tree evaluates its flightplans): the last box
    // of each tree is kept, since consecutive pairs of the walk mostly share the node not opened.
    struct Traits {
        const TreeA& a;
        const TreeB& b;
        Descend& descend;
        OnLeafPair& on_leaf_pair;
        std::uint32_t last_a = no_node, last_b = no_node;
        Eigen::AlignedBox3d box_a{}, box_b{};

        bool go_further() const { return true; }
        bool enter(std::uint32_t na, std::uint32_t nb)
        {
            if (na != last_a) {
                last_a = na;
                box_a = a.box(na);
            }
            if (nb != last_b) {
                last_b = nb;
                box_b = b.box(nb);
            }
            return descend(na, nb, box_a, box_b);
        }
        Pair_split split(std::uint32_t na, std::uint32_t nb) const
        {
            const bool leaf_a = a.is_leaf(na), leaf_b = b.is_leaf(nb);
            if (leaf_a && leaf_b) return Pair_split::leaves;
            // box_a and box_b are the pair's, set by enter() just before.
            const bool open_a = !leaf_a && (leaf_b || box_a.diagonal().squaredNorm() >= box_b.diagonal().squaredNorm());
            return open_a ? Pair_split::first : Pair_split::second;
        }
        void leaf_pair(std::uint32_t na, std::uint32_t nb) { on_leaf_pair(na, nb); }
        bool first_left_first(std::uint32_t, std::uint32_t) const { return true; }
        bool second_left_first(std::uint32_t, std::uint32_t) const { return true; }
    } traits{a, b, descend, on_leaf_pair};
    traverse(a, root_a, b, root_b, traits);
}

template <class TreeA, class TreeB>
void overlapping_pairs(const TreeA& a, const TreeB& b, double margin,
                       std::vector<std::pair<std::uint32_t, std::uint32_t>>& out)
{
    out.clear();
    traverse_pairs(
        a, a.root(), b, b.root(),
        [&](std::uint32_t, std::uint32_t, const Eigen::AlignedBox3d& ba, const Eigen::AlignedBox3d& bb) {
            return boxes_overlap(ba, bb, margin);
        },
        [&](std::uint32_t na, std::uint32_t nb) { out.emplace_back(a.leaf_primitive(na), b.leaf_primitive(nb)); });
}

template <class Tree>
void self_overlapping_pairs(const Tree& tree, double margin, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out)
{
    out.clear();
    if (tree.root() == no_node) return;
    auto descend = [&](std::uint32_t, std::uint32_t, const Eigen::AlignedBox3d& ba, const Eigen::AlignedBox3d& bb) {
        return boxes_overlap(ba, bb, margin);
    };
    auto on_leaf_pair = [&](std::uint32_t na, std::uint32_t nb) {
        const std::uint32_t i = tree.leaf_primitive(na), j = tree.leaf_primitive(nb);
        if (!primitives_adjacent(tree, i, j)) out.emplace_back(std::min(i, j), std::max(i, j));
    };
    // Every unordered pair of distinct leaves is met exactly once, under its lowest common ancestor:
    // a walk over every node pairs the two subtrees of each inner node.
    struct Traits {
        const Tree& tree;
        decltype(descend)& test;
        decltype(on_leaf_pair)& report;
        bool go_further() const { return true; }
        bool enter(std::uint32_t n)
        {
            if (!tree.is_leaf(n)) traverse_pairs(tree, tree.left(n), tree, tree.right(n), test, report);
            return true;
        }
        void leaf(std::uint32_t) {}
        bool left_first(std::uint32_t) const { return true; }
    } traits{tree, descend, on_leaf_pair};
    traverse(tree, tree.root(), traits);
}

template <class Tree>
void range_query(const Tree& tree, const Eigen::AlignedBox3d& query, std::vector<std::uint32_t>& out)
{
    out.clear();
    if (tree.root() == no_node) return;
    struct Traits {
        const Tree& tree;
        const Eigen::AlignedBox3d& query;
        std::vector<std::uint32_t>& out;
        bool go_further() const { return true; }
        bool enter(std::uint32_t n) const { return boxes_overlap(tree.box(n), query, 0.0); }
        void leaf(std::uint32_t n) { out.push_back(tree.leaf_primitive(n)); }
        bool left_first(std::uint32_t) const { return true; }
    } traits{tree, query, out};
    traverse(tree, tree.root(), traits);
}

/// Entry parameter of the ray into `box` within [s_min, s_max], or nothing. Conservative: the exit
/// is enlarged by a few ulps (Ize's robust slab test) so a hit on a face is never culled.
inline std::optional<double> ray_box_entry(const Kinetic_ray& ray, const Eigen::AlignedBox3d& box, double s_max)
{
    constexpr double eps = std::numeric_limits<double>::epsilon();
    constexpr double grow = 1.0 + 4.0 * eps;
    double lo = ray.s_min, hi = s_max;
    for (int i = 0; i < 3; ++i) {
        const double d = ray.direction[i], o = ray.origin[i];
        if (d == 0.0) {
            if (o < box.min()[i] || o > box.max()[i]) return std::nullopt;
            continue;
        }
        double t0 = (box.min()[i] - o) / d, t1 = (box.max()[i] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        t0 = t0 > 0.0 ? t0 / grow : t0 * grow;
        t1 = t1 > 0.0 ? t1 * grow : t1 / grow;
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (lo > hi) return std::nullopt;
    }
    if (lo > hi) return std::nullopt;
    return lo;
}

/// The first hit of `ray` on the triangles of `tree` (smallest s, then smallest primitive index):
/// a walk that enters a node when the ray meets its box before the best hit so far, the child the
/// ray enters first first.
template <class Tree>
std::optional<Kinetic_ray_hit> first_hit(const Tree& tree, const Kinetic_ray& ray)
{
    if (tree.root() == no_node) return std::nullopt;
    struct Traits {
        const Tree& tree;
        const Kinetic_ray& ray;
        std::optional<Kinetic_ray_hit> best;
        double limit() const { return best ? best->s : ray.s_max; }
        bool go_further() const { return true; }
        bool enter(std::uint32_t n) const { return ray_box_entry(ray, tree.box(n), limit()).has_value(); }
        void leaf(std::uint32_t n)
        {
            const std::uint32_t i = tree.leaf_primitive(n);
            const auto& t = tree.primitive(i);
            auto hit = intersect_ray_triangle(ray, tree.vertex_position(t.vertex(0)), tree.vertex_position(t.vertex(1)),
                                              tree.vertex_position(t.vertex(2)));
            if (hit && (!best || hit->s < best->s || (hit->s == best->s && i < best->primitive))) {
                hit->primitive = i;
                best = hit;
            }
        }
        bool left_first(std::uint32_t n) const
        {
            const auto sl = ray_box_entry(ray, tree.box(tree.left(n)), limit());
            const auto sr = ray_box_entry(ray, tree.box(tree.right(n)), limit());
            return !(sl && sr && *sl > *sr) && !(!sl && sr);
        }
    } traits{tree, ray, std::nullopt};
    traverse(tree, tree.root(), traits);
    return traits.best;
}

/// first_hit() of each ray in `rays`, in order, into `out` (cleared first), all through the same
/// tree view (for the kinetic tree: one query memo shared by the rays).
template <class Tree, class Rays>
void first_hits(const Tree& tree, const Rays& rays, std::vector<std::optional<Kinetic_ray_hit>>& out)
{
    out.clear();
    out.reserve(rays.size());
    for (const Kinetic_ray& ray : rays) out.push_back(first_hit(tree, ray));
}

} // namespace PCCD::internal
