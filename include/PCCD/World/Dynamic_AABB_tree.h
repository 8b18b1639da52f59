// PCCD/World/Dynamic_AABB_tree.h -- Dynamic_AABB_tree, the broad phase of a collision world: a
// binary tree of axis-aligned boxes over a changing set of proxies (one box and one id each) that
// is updated incrementally. A proxy's box is stored enlarged ("fat"), so that small moves leave the
// tree alone; a move out of the fat box removes the leaf and inserts it again where it adds the
// least surface area, with AVL-style rotations keeping the tree balanced; when the summed surface
// area of the inner nodes has grown past a ratio of the value after the last build, the tree is
// rebuilt top down. Queries: every pair of proxies whose boxes overlap, the proxies a box overlaps,
// the proxies a ray crosses. Implements doc/algorithms.md, "Collision worlds".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/internal/keep_going.h>

namespace PCCD {

/// How a Dynamic_AABB_tree enlarges its boxes and when it rebuilds itself.
struct Dynamic_AABB_tree_options {
    /// A proxy's box is stored grown on every side by fat_margin times the length of its diagonal
    /// (>= 0). Moves that stay inside the grown box cost nothing; larger margins mean fewer
    /// re-insertions and more candidate pairs. Default 0.05.
    double fat_margin = 0.05;
    /// The tree is rebuilt top down when the summed surface area of its inner nodes exceeds
    /// rebuild_ratio times the value right after the last build (> 1; +infinity: never). Default 2.
    double rebuild_ratio = 2.0;
};

/// A dynamic bounding-box tree (the structure of Bullet's btDbvt and Box2D's b2DynamicTree,
/// written for PCCD): proxies with an axis-aligned box and a 32-bit id, inserted, moved and erased
/// one at a time.
///
/// Invariants: every inner node has two children and its box holds theirs; a leaf's box holds the
/// box last given for its proxy. Each insertion and removal rotates taller children up along its
/// path (a node's children then differ in height by at most one where it rotated), and a tree that
/// grew or shrank by a quarter, or whose inner area doubled, is rebuilt, which keeps the height
/// near log2(n) (tested).
///
/// Not thread safe for writes; const queries may run concurrently.
class Dynamic_AABB_tree {
public:
    using Box = Eigen::AlignedBox3d;
    /// A proxy: the index of its leaf node; stable while the proxy lives.
    using Proxy = std::uint32_t;
    static constexpr Proxy no_proxy = std::numeric_limits<std::uint32_t>::max();

    /// Counters of the structure (for benchmarks and tests).
    struct Statistics {
        std::size_t proxies = 0;
        std::size_t height = 0;
        /// Re-insertions because a box left its fat box, and top-down rebuilds, since construction.
        std::size_t reinsertions = 0;
        std::size_t rebuilds = 0;
        /// The summed surface area of the inner nodes, now and right after the last build.
        double inner_area = 0.0;
        double built_area = 0.0;
    };

    explicit Dynamic_AABB_tree(const Dynamic_AABB_tree_options& options = {}) : m_options(options)
    {
        if (!(std::isfinite(options.fat_margin) && options.fat_margin >= 0.0))
            throw Invalid_input(internal::concat("Dynamic_AABB_tree: fat_margin ", options.fat_margin, " must be finite and >= 0"));
        if (!std::isgreater(options.rebuild_ratio, 1.0)) // NaN fails too (without a floating-point exception)
            throw Invalid_input(internal::concat("Dynamic_AABB_tree: rebuild_ratio ", options.rebuild_ratio,
                                       " must be > 1 (+infinity: never rebuild)"));
    }

    const Dynamic_AABB_tree_options& options() const { return m_options; }
    std::size_t size() const { return m_proxies; }
    bool empty() const { return m_proxies == 0; }

    /// Inserts a proxy with `box` (finite, not empty) and `id`; returns the proxy.
    /// \throws Invalid_input if the box is empty or not finite.
    /// Complexity: O(log n) for a balanced tree.
    Proxy insert(const Box& box, std::uint32_t id)
    {
        check_box(box, "Dynamic_AABB_tree::insert");
        const Node_index leaf = allocate();
        m_nodes[leaf].box = fatten(box);
        m_nodes[leaf].id = id;
        m_nodes[leaf].height = 0;
        insert_leaf(leaf);
        ++m_proxies;
        maybe_rebuild();
        return leaf;
    }

    /// Gives `proxy` its new `box`. Returns true when the box left the stored fat box and the leaf
    /// was moved (false: the tree is unchanged).
    /// \throws Invalid_input if the proxy is not alive or the box is empty or not finite.
    bool update(Proxy proxy, const Box& box)
    {
        check_proxy(proxy, "Dynamic_AABB_tree::update");
        check_box(box, "Dynamic_AABB_tree::update");
        if (m_nodes[proxy].box.contains(box)) return false;
        remove_leaf(proxy);
        m_nodes[proxy].box = fatten(box);
        insert_leaf(proxy);
        ++m_reinsertions;
        maybe_rebuild();
        return true;
    }

    /// Removes `proxy`. \throws Invalid_input if it is not alive.
    void erase(Proxy proxy)
    {
        check_proxy(proxy, "Dynamic_AABB_tree::erase");
        remove_leaf(proxy);
        release(proxy);
        --m_proxies;
    }

    /// The stored (fat) box of a live proxy, and its id.
    const Box& fat_box(Proxy proxy) const { return m_nodes.at(proxy).box; }
    std::uint32_t id(Proxy proxy) const { return m_nodes.at(proxy).id; }
    bool alive(Proxy proxy) const { return proxy < m_nodes.size() && m_nodes[proxy].height >= 0 && m_nodes[proxy].is_leaf(); }

    /// Calls `f(id_a, id_b)` once for every unordered pair of proxies whose fat boxes overlap
    /// (touching counts); the order of the two ids and of the pairs is that of the tree. `f` may
    /// return void, or bool: false stops the walk.
    /// Complexity: O(n + k) node pairs for n proxies of bounded overlap and k pairs, O(n^2) worst.
    template <class F>
    void for_each_overlapping_pair(F&& f) const
    {
        if (m_root == null) return;
        std::vector<std::pair<Node_index, Node_index>> stack;
        stack.emplace_back(m_root, m_root);
        while (!stack.empty()) {
            const auto [a, b] = stack.back();
            stack.pop_back();
            const Node& na = m_nodes[a];
            if (a == b) {
                if (na.is_leaf()) continue;
                stack.emplace_back(na.left, na.right);
                stack.emplace_back(na.right, na.right);
                stack.emplace_back(na.left, na.left);
                continue;
            }
            const Node& nb = m_nodes[b];
            if (!na.box.intersects(nb.box)) continue;
            if (na.is_leaf() && nb.is_leaf()) {
                if (!internal::keep_going(f, na.id, nb.id)) return;
                continue;
            }
            // Descend the larger inner node (a leaf is never split).
            if (nb.is_leaf() || (!na.is_leaf() && na.box.volume() >= nb.box.volume())) {
                stack.emplace_back(na.right, b);
                stack.emplace_back(na.left, b);
            } else {
                stack.emplace_back(a, nb.right);
                stack.emplace_back(a, nb.left);
            }
        }
    }

    /// Calls `f(id)` for every proxy whose fat box overlaps `box`; `f` may return bool (false stops).
    template <class F>
    void for_each_overlapping(const Box& box, F&& f) const
    {
        if (m_root == null || box.isEmpty()) return;
        std::vector<Node_index> stack{m_root};
        while (!stack.empty()) {
            const Node& n = m_nodes[stack.back()];
            stack.pop_back();
            if (!n.box.intersects(box)) continue;
            if (n.is_leaf()) {
                if (!internal::keep_going(f, n.id)) return;
                continue;
            }
            stack.push_back(n.right);
            stack.push_back(n.left);
        }
    }

    /// Calls `f(id, t_enter)` for every proxy whose fat box the segment origin + t direction,
    /// t in [0, t_max], crosses, with the t at which it enters the box (0 if the origin is inside).
    /// `f` may return bool (false stops). The direction need not be normalized (t is in its units).
    template <class F>
    void for_each_crossed(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_max, F&& f) const
    {
        if (m_root == null) return;
        if (!origin.allFinite() || !direction.allFinite() || std::isnan(t_max))
            throw Invalid_input(internal::concat("Dynamic_AABB_tree::for_each_crossed: origin [", origin.transpose(),
                                                 "], direction [", direction.transpose(), "] and t_max ", t_max,
                                                 " must be finite (t_max may be +infinity)"));
        std::vector<Node_index> stack{m_root};
        while (!stack.empty()) {
            const Node& n = m_nodes[stack.back()];
            stack.pop_back();
            double t_enter = 0.0;
            if (!crosses(n.box, origin, direction, t_max, t_enter)) continue;
            if (n.is_leaf()) {
                if (!internal::keep_going(f, n.id, t_enter)) return;
                continue;
            }
            stack.push_back(n.right);
            stack.push_back(n.left);
        }
    }

    /// Rebuilds the tree top down (median splits of the box centres along the longest axis); the
    /// proxies keep their handles and fat boxes. Complexity: O(n log n).
    void rebuild()
    {
        std::vector<Node_index> leaves;
        leaves.reserve(m_proxies);
        for (Node_index i = 0; i < m_nodes.size(); ++i)
            if (m_nodes[i].height >= 0 && m_nodes[i].is_leaf()) leaves.push_back(i);
        // Free every inner node, then build new ones over the leaves.
        for (Node_index i = 0; i < m_nodes.size(); ++i)
            if (m_nodes[i].height >= 0 && !m_nodes[i].is_leaf()) release(i);
        m_root = leaves.empty() ? null : build(leaves.begin(), leaves.end());
        if (m_root != null) m_nodes[m_root].parent = null;
        m_built_area = inner_area();
        m_built_proxies = m_proxies;
        ++m_rebuilds;
    }

    Statistics statistics() const
    {
        Statistics s;
        s.proxies = m_proxies;
        s.height = m_root == null ? 0 : std::size_t(m_nodes[m_root].height) + 1;
        s.reinsertions = m_reinsertions;
        s.rebuilds = m_rebuilds;
        s.inner_area = inner_area();
        s.built_area = m_built_area;
        return s;
    }

    /// Bytes held by the tree (node storage, allocated capacity).
    std::size_t memory_bytes() const { return m_nodes.capacity() * sizeof(Node); }

    /// Checks the invariants (parents, heights, boxes holding their children's); for tests.
    /// \throws Invalid_input naming the first node that breaks one.
    void check_invariants() const
    {
        std::size_t leaves = 0;
        if (m_root != null) {
            if (m_nodes[m_root].parent != null) throw Invalid_input("Dynamic_AABB_tree: the root has a parent");
            check_subtree(m_root, leaves);
        }
        if (leaves != m_proxies)
            throw Invalid_input(internal::concat("Dynamic_AABB_tree: ", leaves, " leaves for ", m_proxies, " proxies"));
    }

private:
    using Node_index = std::uint32_t;
    static constexpr Node_index null = std::numeric_limits<std::uint32_t>::max();

    struct Node {
        Box box;
        Node_index parent = null; // the next free node while the node is free
        Node_index left = null;   // null for a leaf
        Node_index right = null;
        std::int32_t height = -1; // -1: free; 0: leaf
        std::uint32_t id = 0;

        bool is_leaf() const { return left == null; }
    };

    static double area(const Box& b)
    {
        const Eigen::Vector3d d = b.sizes();
        return 2.0 * (d.x() * d.y() + d.y() * d.z() + d.z() * d.x());
    }

    static void check_box(const Box& box, const char* function)
    {
        if (!box.min().allFinite() || !box.max().allFinite() || box.isEmpty())
            throw Invalid_input(internal::concat(function, ": the box [", box.min().transpose(), "] - [", box.max().transpose(),
                                       "] is empty or not finite"));
    }

    void check_proxy(Proxy proxy, const char* function) const
    {
        if (!alive(proxy)) throw Invalid_input(internal::concat(function, ": proxy ", proxy, " is not in the tree"));
    }

    /// Whether the segment origin + t direction, t in [0, t_max], meets `box`; its entry t then.
    /// Axes along which the direction is 0 are tested as slabs (no division by zero).
    static bool crosses(const Box& box, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_max,
                        double& t_enter)
    {
        double t0 = 0.0, t1 = t_max;
        for (int k = 0; k < 3; ++k) {
            if (direction[k] == 0.0) {
                if (origin[k] < box.min()[k] || origin[k] > box.max()[k]) return false;
                continue;
            }
            double a = (box.min()[k] - origin[k]) / direction[k];
            double b = (box.max()[k] - origin[k]) / direction[k];
            if (a > b) std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
            if (t0 > t1) return false;
        }
        t_enter = t0;
        return true;
    }

    Box fatten(const Box& box) const
    {
        const double grow = m_options.fat_margin * box.diagonal().norm();
        return Box(box.min().array() - grow, box.max().array() + grow);
    }

    Node_index allocate()
    {
        if (m_free == null) {
            if (m_nodes.size() >= std::size_t(null) - 1)
                throw Invalid_input("Dynamic_AABB_tree: more than 2^32 - 2 nodes");
            m_nodes.emplace_back();
            m_nodes.back().height = 0;
            return Node_index(m_nodes.size() - 1);
        }
        const Node_index i = m_free;
        m_free = m_nodes[i].parent;
        m_nodes[i] = Node{};
        m_nodes[i].height = 0;
        return i;
    }

    void release(Node_index i)
    {
        m_nodes[i] = Node{};
        m_nodes[i].height = -1;
        m_nodes[i].parent = m_free;
        m_free = i;
    }

    void refit(Node_index i)
    {
        Node& n = m_nodes[i];
        n.box = m_nodes[n.left].box.merged(m_nodes[n.right].box);
        n.height = 1 + std::max(m_nodes[n.left].height, m_nodes[n.right].height);
    }

    void replace_child(Node_index parent, Node_index old_child, Node_index new_child)
    {
        if (parent == null) {
            m_root = new_child;
            return;
        }
        Node& p = m_nodes[parent];
        (p.left == old_child ? p.left : p.right) = new_child;
    }

    void insert_leaf(Node_index leaf)
    {
        if (m_root == null) {
            m_root = leaf;
            m_nodes[leaf].parent = null;
            return;
        }
        const Box& box = m_nodes[leaf].box;
        // Descend to the sibling that adds the least surface area (the cost of a new parent there
        // plus the growth of every ancestor on the way).
        Node_index index = m_root;
        while (!m_nodes[index].is_leaf()) {
            const Node& n = m_nodes[index];
            const double merged_area = area(n.box.merged(box));
            const double here = 2.0 * merged_area;
            const double inherited = 2.0 * (merged_area - area(n.box));
            const auto descend_cost = [&](Node_index child) {
                const Node& c = m_nodes[child];
                const double grown = area(c.box.merged(box));
                return (c.is_leaf() ? grown : grown - area(c.box)) + inherited;
            };
            const double cost_left = descend_cost(n.left);
            const double cost_right = descend_cost(n.right);
            if (here < cost_left && here < cost_right) break;
            index = cost_left <= cost_right ? n.left : n.right;
        }
        const Node_index sibling = index;
        const Node_index old_parent = m_nodes[sibling].parent;
        const Node_index parent = allocate();
        m_nodes[parent].parent = old_parent;
        m_nodes[parent].left = sibling;
        m_nodes[parent].right = leaf;
        m_nodes[sibling].parent = parent;
        m_nodes[leaf].parent = parent;
        replace_child(old_parent, sibling, parent);
        refit(parent);
        fix_upwards(old_parent);
    }

    void remove_leaf(Node_index leaf)
    {
        if (leaf == m_root) {
            m_root = null;
            return;
        }
        const Node_index parent = m_nodes[leaf].parent;
        const Node_index grand_parent = m_nodes[parent].parent;
        const Node_index sibling = m_nodes[parent].left == leaf ? m_nodes[parent].right : m_nodes[parent].left;
        replace_child(grand_parent, parent, sibling);
        m_nodes[sibling].parent = grand_parent;
        release(parent);
        m_nodes[leaf].parent = null;
        fix_upwards(grand_parent);
    }

    /// Balances and refits every node from `i` up to the root.
    void fix_upwards(Node_index i)
    {
        while (i != null) {
            i = balance(i);
            refit(i);
            i = m_nodes[i].parent;
        }
    }

    /// If the children of inner node `a` differ in height by more than one, rotates the taller
    /// child up; returns the node now at a's place.
    Node_index balance(Node_index a)
    {
        Node& na = m_nodes[a];
        if (na.is_leaf() || na.height < 2) return a;
        const std::int32_t difference = m_nodes[na.right].height - m_nodes[na.left].height;
        if (difference > 1) return rotate_up(a, na.right, false);
        if (difference < -1) return rotate_up(a, na.left, true);
        return a;
    }

    /// Rotates child `c` of `a` (the taller one) into a's place: a becomes
    /// a child of c, and c's shorter child becomes a's child in c's old place. `c_was_left` says
    /// which side c was on.
    Node_index rotate_up(Node_index a, Node_index c, bool c_was_left)
    {
        Node& nc = m_nodes[c];
        const Node_index f = nc.left;
        const Node_index g = nc.right;
        const Node_index a_parent = m_nodes[a].parent;
        // c takes a's place.
        nc.parent = a_parent;
        replace_child(a_parent, a, c);
        m_nodes[a].parent = c;
        // c keeps its taller child; the shorter one moves to a, where c was.
        const bool keep_f = m_nodes[f].height > m_nodes[g].height;
        const Node_index kept = keep_f ? f : g;
        const Node_index moved = keep_f ? g : f;
        nc.left = a;
        nc.right = kept;
        if (c_was_left)
            m_nodes[a].left = moved;
        else
            m_nodes[a].right = moved;
        m_nodes[moved].parent = a;
        refit(a);
        refit(c);
        return c;
    }

    Node_index build(std::vector<Node_index>::iterator first, std::vector<Node_index>::iterator last)
    {
        const std::ptrdiff_t n = last - first;
        if (n == 1) return *first;
        Box centres;
        for (auto it = first; it != last; ++it) centres.extend(m_nodes[*it].box.center());
        int axis = 0;
        centres.sizes().maxCoeff(&axis);
        const auto middle = first + n / 2;
        std::nth_element(first, middle, last, [&](Node_index x, Node_index y) {
            const double cx = m_nodes[x].box.center()[axis], cy = m_nodes[y].box.center()[axis];
            return cx < cy || (cx == cy && x < y);
        });
        const Node_index left = build(first, middle);
        const Node_index right = build(middle, last);
        const Node_index parent = allocate();
        m_nodes[parent].left = left;
        m_nodes[parent].right = right;
        m_nodes[left].parent = parent;
        m_nodes[right].parent = parent;
        refit(parent);
        return parent;
    }

    double inner_area() const
    {
        double sum = 0.0;
        for (const Node& n : m_nodes)
            if (n.height > 0) sum += area(n.box);
        return sum;
    }

    void maybe_rebuild()
    {
        // The summed area costs O(n): it is compared every max(16, n / 4) edits only.
        if (++m_edits_since_check < std::max<std::size_t>(16, m_proxies / 4)) return;
        m_edits_since_check = 0;
        // A tree that grew or shrank by a quarter since its build is rebuilt (amortized O(log n) per
        // edit); otherwise the area it gained by moves decides.
        const std::size_t grown = m_proxies > m_built_proxies ? m_proxies - m_built_proxies : m_built_proxies - m_proxies;
        if (4 * grown > m_built_proxies || inner_area() > m_options.rebuild_ratio * m_built_area) rebuild();
    }

    void check_subtree(Node_index i, std::size_t& leaves) const
    {
        const Node& n = m_nodes[i];
        if (n.height < 0) throw Invalid_input(internal::concat("Dynamic_AABB_tree: node ", i, " is free but in the tree"));
        if (n.is_leaf()) {
            if (n.height != 0) throw Invalid_input(internal::concat("Dynamic_AABB_tree: leaf ", i, " has height ", n.height));
            ++leaves;
            return;
        }
        const Node& l = m_nodes[n.left];
        const Node& r = m_nodes[n.right];
        if (l.parent != i || r.parent != i)
            throw Invalid_input(internal::concat("Dynamic_AABB_tree: a child of node ", i, " names another parent"));
        if (n.height != 1 + std::max(l.height, r.height))
            throw Invalid_input(internal::concat("Dynamic_AABB_tree: node ", i, " has a wrong height"));
        if (!n.box.contains(l.box) || !n.box.contains(r.box))
            throw Invalid_input(internal::concat("Dynamic_AABB_tree: the box of node ", i, " misses a child's"));
        check_subtree(n.left, leaves);
        check_subtree(n.right, leaves);
    }

    Dynamic_AABB_tree_options m_options;
    std::vector<Node> m_nodes;
    Node_index m_root = null;
    Node_index m_free = null;
    std::size_t m_proxies = 0;
    std::size_t m_reinsertions = 0;
    std::size_t m_rebuilds = 0;
    std::size_t m_edits_since_check = 0;
    double m_built_area = 0.0;
    std::size_t m_built_proxies = 0;
};

} // namespace PCCD
