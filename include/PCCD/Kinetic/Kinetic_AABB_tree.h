// PCCD/Kinetic/Kinetic_AABB_tree.h -- the kinetic AABB tree of Weller and Zachmann (ALGORITHMS.md
// section 7): a bounding volume hierarchy over moving primitives that stores only combinatorial
// structure, the vertex attaining each of the six bounds of every node, and keeps it valid by
// processing certificate failures (events) in time order instead of refitting every frame.
//
// One certificate per inner node and bound says "this vertex is the extreme of its candidates" (the
// extreme of an inner child, every vertex of a leaf child's primitive). Leaves store nothing: a
// leaf's box is the box of its primitive's few vertices, read off directly, so crossings between
// the vertices of one primitive are no events unless they change the parent's extreme. A
// certificate's failure time, the first time a candidate's flightplan overtakes the extreme's, goes
// into an indexed event queue. advance_to(t) pops the events before t in order, swaps the extreme, reschedules that
// certificate and propagates up while the parent's extreme changes. Flightplans can be replaced,
// primitives inserted and removed at run time; each repairs only the affected paths.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Event_queue.h>
#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/Kinetic_ray.h>
#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/AABB_tree_checks.h>
#include <PCCD/Kinetic/internal/AABB_tree_queries.h>
#include <PCCD/Kinetic/internal/Primitive_slots.h>
#include <PCCD/Kinetic/internal/Query_memo_pool.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

namespace PCCD {

/// Counters of a kinetic tree since construction (or the last reset_statistics()).
struct Kinetic_statistics {
    std::uint64_t events = 0;                   ///< certificate failures popped from the queue
    std::uint64_t bv_updates = 0;               ///< changes of one bound's extreme vertex at one node
    /// Distinct nodes whose extremes changed, counted once per node and call of advance_to (or
    /// other change at run time) however many of its bounds changed how often: the kinetic
    /// counterpart of a refit's "node boxes recomputed per frame", so it depends on the query rate.
    std::uint64_t node_updates = 0;
    std::uint64_t certificate_computations = 0; ///< next_crossing evaluations (the real work)
    std::uint64_t flightplan_changes = 0;
    std::uint64_t insertions = 0;
    std::uint64_t removals = 0;
};

/// A kinetic AABB tree over primitives of type `P` whose vertices move along flightplans of type `F`.
///
/// \tparam F a model of Flightplan (one per vertex).
/// \tparam P a model of KineticPrimitive (Kinetic_triangle by default, Kinetic_point for clouds).
/// \tparam Queue the event queue, an Event_queue<Arity>.
///
/// Bounds are numbered 0..5: min x, min y, min z, max x, max y, max z (bound b is on axis b % 3).
/// The tree has a current time now(); node boxes and queries refer to it. Ties between vertices are
/// allowed: an extreme is any vertex attaining the bound. Simultaneous events are processed in
/// order of (node, bound), so the structure after advance_to(t) is a deterministic function of the
/// inputs. Only inner nodes store extremes and hold certificates; a leaf's box is the box of its
/// primitive's vertices (a primitive has at most a few), so the order of one primitive's vertices
/// is never maintained.
///
/// Queries memoize vertex positions and node boxes at now() (each vertex's flightplan is evaluated
/// at most once per query, however many node boxes it bounds, and each node box is assembled at
/// most once, however many node pairs it enters), so they give the same answers as box() and
/// vertex_position() (provided the flightplan's position(t)[axis] equals coordinate(axis, t), as in
/// all models shipped, bit for bit). The memo tables are reused by later queries: the tree keeps
/// one set per query that ran at the same time as others (the size of the tree each).
///
/// Thread safety: const members (access and queries) may run concurrently; advance_to,
/// set_flightplan, insert and remove need exclusive access.
template <Flightplan F, KineticPrimitive P = Kinetic_triangle, class Queue = Event_queue<>>
class Kinetic_AABB_tree {
public:
    using Flightplan_type = F;
    using Primitive = P;
    using Event_queue_type = Queue;
    using Index = std::uint32_t;
    using Node_index = std::uint32_t;
    using Box = Eigen::AlignedBox3d;
    using Statistics = Kinetic_statistics;
    static constexpr Node_index no_node = internal::no_node;
    static constexpr int bound_count = 6;
    /// The time of a certificate that never fails.
    static constexpr double never = std::numeric_limits<double>::infinity();

    /// \name Construction
    /// @{

    /// Builds the tree at time `t0` over `primitives`, whose vertex indices refer to `flightplans`.
    /// The topology is a median split of the primitives' centroids at t0 (height ceil(log2 n)),
    /// then every certificate is computed.
    /// \throws Invalid_input if t0 is not finite, a primitive refers to a vertex >= flightplans.size()
    ///         (the message names both), or there are 2^31 primitives or more.
    /// Complexity: O(n log n) plus one next_crossing per candidate of every node and bound.
    Kinetic_AABB_tree(std::vector<F> flightplans, std::vector<P> primitives, double t0 = 0.0)
        : m_flightplans(std::move(flightplans)), m_primitives(std::move(primitives), tree_name), m_now(t0)
    {
        internal::check_start_time(tree_name, t0);
        if (m_flightplans.size() >= std::size_t(no_node))
            throw Invalid_input("Kinetic_AABB_tree: too many vertices (2^32 - 1 or more)");
        m_incident.resize(m_flightplans.size());
        for (Index i = 0; i < Index(m_primitives.capacity()); ++i) {
            internal::check_primitive(tree_name, m_primitives[i], i, m_flightplans.size());
            add_incidence(i);
        }
        m_leaf_of.assign(m_primitives.capacity(), no_node);
        std::vector<Eigen::Vector3d> centroids;
        m_root = internal::build_over_live_primitives(
            m_primitives, [&](Index v) { return m_flightplans[v].position(t0); }, centroids, m_nodes);
        m_extreme.assign(m_nodes.size(), unset_extremes());
        for (Node_index n = 0; n < Node_index(m_nodes.size()); ++n)
            if (m_nodes[n].is_leaf()) m_leaf_of[m_nodes[n].primitive] = n;
        m_queue.resize(m_nodes.size() * bound_count);
        m_overtaker.assign(m_nodes.size() * bound_count, no_node);
        m_updated_in_round.assign(m_nodes.size(), 0);
        initialize_at(t0);
    }
    /// @}

    /// \name Time
    /// @{

    /// The time the tree is valid for.
    double now() const { return m_now; }

    /// Moves the tree to time t. For t >= now() it processes, in order of (time, node, bound), every
    /// event with time < t: the extreme of the failed certificate is swapped, the certificate
    /// rescheduled, and the change propagated upward while parents' extremes change. For t < now()
    /// the certificates are recomputed from scratch at t (as at construction).
    /// \throws Invalid_input if t is not finite.
    /// Complexity: O(log n) per event plus one next_crossing per affected candidate; independent of
    /// how often it is called (the number of events depends on the motion only).
    void advance_to(double t)
    {
        internal::check_advance_time(tree_name, t);
        if (t < m_now) {
            initialize_at(t);
            return;
        }
        next_update_round();
        while (!m_queue.empty() && m_queue.top_time() < t) {
            m_now = m_queue.top_time();
            const typename Queue::Id id = m_queue.top_id();
            ++m_stats.events;
            const Node_index n = id / bound_count;
            const int b = int(id % bound_count);
            if (update_bound(n, b, m_overtaker[id])) {
                count_update(n);
                propagate(n, b);
            }
        }
        m_now = t;
    }

    /// The time of the next pending event (+infinity if none).
    double next_event_time() const { return m_queue.empty() ? never : m_queue.top_time(); }
    /// Number of certificates currently scheduled (the others never fail).
    std::size_t scheduled_certificates() const { return m_queue.size(); }
    /// @}

    /// \name Changes at run time (all at the current time now())
    /// @{

    /// Replaces the flightplan of vertex `v`. The new trajectory may disagree with the old one at
    /// now() (a jump): the extremes on the paths above the primitives of `v` are recomputed at now()
    /// and exactly the certificates that have `v` as extreme or as candidate, or whose candidates
    /// changed, are rescheduled.
    /// \throws Invalid_input if v >= vertex_count().
    /// Complexity: O(d log n) certificate computations, d the number of primitives using v.
    void set_flightplan(Index v, F flightplan)
    {
        internal::check_vertex(tree_name, v, m_flightplans.size());
        m_flightplans[v] = std::move(flightplan);
        ++m_stats.flightplan_changes;
        next_update_round();
        for (const Index i : m_incident[v]) {
            std::array<bool, bound_count> changed{};
            for (Node_index n = m_nodes[m_leaf_of[i]].parent; n != no_node; n = m_nodes[n].parent) {
                bool go_on = false;
                for (int b = 0; b < bound_count; ++b) {
                    const bool involved = is_candidate(v, m_nodes[n].left, b) || is_candidate(v, m_nodes[n].right, b);
                    changed[std::size_t(b)] = (involved || changed[std::size_t(b)]) && update_bound(n, b);
                    if (changed[std::size_t(b)]) count_update(n);
                    go_on = go_on || changed[std::size_t(b)] || m_extreme[n][std::size_t(b)] == v;
                }
                if (!go_on) break;
            }
        }
    }

    /// Adds a vertex (used by primitives inserted later); returns its index.
    Index add_vertex(F flightplan)
    {
        if (m_flightplans.size() + 1 >= std::size_t(no_node))
            throw Invalid_input("Kinetic_AABB_tree::add_vertex: too many vertices");
        m_flightplans.push_back(std::move(flightplan));
        m_incident.emplace_back();
        return Index(m_flightplans.size() - 1);
    }

    /// Inserts a primitive at now(): a new leaf is paired with the leaf reached by descending
    /// towards the child whose box grows least in surface area. Returns the primitive's index
    /// (a freed index is reused).
    /// \throws Invalid_input if the primitive refers to a vertex >= vertex_count().
    /// Complexity: O(h) box evaluations and certificate computations, h the height. Many insertions
    /// can unbalance the tree; rebuild it when the height matters.
    Index insert(const P& primitive)
    {
        internal::check_primitive(tree_name, primitive, Index(m_primitives.capacity()), m_flightplans.size());
        const Index i = m_primitives.insert(primitive, tree_name);
        if (i >= m_leaf_of.size()) m_leaf_of.resize(m_primitives.capacity(), no_node);
        add_incidence(i);
        ++m_stats.insertions;
        next_update_round();
        const Node_index leaf = allocate_node();
        m_nodes[leaf].primitive = i;
        m_leaf_of[i] = leaf;
        if (m_root == no_node) {
            m_root = leaf;
            return i;
        }
        const Box box_new = box(leaf);
        Node_index sibling = m_root;
        while (!m_nodes[sibling].is_leaf()) {
            const Node_index l = m_nodes[sibling].left, r = m_nodes[sibling].right;
            sibling = growth(box(l), box_new) <= growth(box(r), box_new) ? l : r;
        }
        const Node_index inner = allocate_node();
        const Node_index grand = m_nodes[sibling].parent;
        m_nodes[inner].parent = grand;
        m_nodes[inner].left = sibling;
        m_nodes[inner].right = leaf;
        replace_child(grand, sibling, inner);
        m_nodes[sibling].parent = inner;
        m_nodes[leaf].parent = inner;
        repair_path(inner, true);
        return i;
    }

    /// Removes primitive `i`: its leaf goes, its sibling takes the parent's place, and the path
    /// above is repaired at now(). \throws Invalid_input if `i` is not a live primitive.
    /// Complexity: O(h) certificate computations.
    void remove(Index i)
    {
        internal::check_live_primitive(tree_name, i, contains(i));
        ++m_stats.removals;
        next_update_round();
        remove_incidence(i);
        m_primitives.remove(i);
        const Node_index leaf = m_leaf_of[i];
        m_leaf_of[i] = no_node;
        const Node_index inner = m_nodes[leaf].parent;
        free_node(leaf);
        if (inner == no_node) {
            m_root = no_node;
            return;
        }
        const Node_index sibling = m_nodes[inner].left == leaf ? m_nodes[inner].right : m_nodes[inner].left;
        const Node_index grand = m_nodes[inner].parent;
        m_nodes[sibling].parent = grand;
        replace_child(grand, inner, sibling);
        free_node(inner);
        if (grand != no_node) repair_path(grand, false);
    }
    /// @}

    /// \name Access
    /// @{
    std::size_t vertex_count() const { return m_flightplans.size(); }
    /// Number of live primitives.
    std::size_t primitive_count() const { return m_primitives.live_count(); }
    /// One past the largest primitive index ever used (live or freed).
    std::size_t primitive_capacity() const { return m_primitives.capacity(); }
    bool contains(Index i) const { return m_primitives.contains(i); }
    const P& primitive(Index i) const { return m_primitives[i]; }
    const F& flightplan(Index v) const { return m_flightplans[v]; }
    /// Position of vertex v at now().
    Eigen::Vector3d vertex_position(Index v) const { return m_flightplans[v].position(m_now); }
    const Statistics& statistics() const { return m_stats; }
    void reset_statistics() { m_stats = Statistics(); }
    /// @}

    /// \name Nodes (for custom traversals, e.g. a point cloud hierarchy over a deforming cloud)
    /// @{
    Node_index root() const { return m_root; }
    bool is_leaf(Node_index n) const { return m_nodes[n].is_leaf(); }
    Node_index left(Node_index n) const { return m_nodes[n].left; }
    Node_index right(Node_index n) const { return m_nodes[n].right; }
    Node_index parent(Node_index n) const { return m_nodes[n].parent; }
    /// The primitive of leaf n.
    Index leaf_primitive(Node_index n) const { return m_nodes[n].primitive; }
    /// The leaf holding live primitive i.
    Node_index leaf_of(Index i) const { return m_leaf_of[i]; }
    /// The vertex attaining bound b (0..5) of node n: the stored extreme of an inner node; for a
    /// leaf, the first vertex of its primitive attaining the bound at now() (leaves store nothing).
    Index extreme_vertex(Node_index n, int b) const
    {
        if (!m_nodes[n].is_leaf()) return m_extreme[n][std::size_t(b)];
        const P& p = m_primitives[m_nodes[n].primitive];
        const int axis = b % 3;
        Index best = p.vertex(0);
        double best_value = m_flightplans[best].coordinate(axis, m_now);
        for (std::size_t k = 1; k < P::vertex_count; ++k) {
            const double value = m_flightplans[p.vertex(k)].coordinate(axis, m_now);
            if (b < 3 ? value < best_value : value > best_value) {
                best = p.vertex(k);
                best_value = value;
            }
        }
        return best;
    }
    /// The scheduled failure time of the certificate of node n and bound b (+infinity: never, and
    /// for every leaf).
    double certificate_time(Node_index n, int b) const { return m_queue.time(certificate_id(n, b)); }
    /// The box of node n at now(): an inner node's is read off its six extreme vertices, a leaf's is
    /// the box of its primitive's vertices. O(1) flightplan evaluations.
    Box box(Node_index n) const
    {
        Box result;
        if (m_nodes[n].is_leaf()) {
            const P& p = m_primitives[m_nodes[n].primitive];
            result.setEmpty();
            for (std::size_t k = 0; k < P::vertex_count; ++k) result.extend(m_flightplans[p.vertex(k)].position(m_now));
            return result;
        }
        const std::array<Index, bound_count>& e = m_extreme[n];
        for (int axis = 0; axis < 3; ++axis) {
            result.min()[axis] = m_flightplans[e[std::size_t(axis)]].coordinate(axis, m_now);
            result.max()[axis] = m_flightplans[e[std::size_t(axis + 3)]].coordinate(axis, m_now);
        }
        return result;
    }
    /// Nodes in use. Every live node is reachable from root().
    std::size_t node_count() const { return m_nodes.size() - m_free_nodes.size(); }
    /// Height of the tree (0 for one leaf, -1 when empty). O(n).
    int height() const { return internal::height(m_nodes, m_root); }
    /// @}

    /// \name Queries at now() (const, allocation only for the output and a traversal stack)
    /// @{

    /// Pairs (i, j) of primitive i of this tree and j of `other` whose boxes, grown by `margin`,
    /// overlap. \tparam Tree another Kinetic_AABB_tree or a Refit_AABB_tree.
    /// \throws Invalid_input if the trees are at different times or margin < 0.
    template <class Tree>
    void overlapping_pairs(const Tree& other, std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        internal::check_query(m_now, other.now(), margin);
        internal::overlapping_pairs(Query_view(*this), query_view_of(other), margin, out);
    }
    /// Pairs i < j of non-adjacent primitives (sharing no vertex) whose boxes, grown by `margin`,
    /// overlap. \throws Invalid_input if margin < 0.
    void self_overlapping_pairs(std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        internal::check_query(m_now, m_now, margin);
        internal::self_overlapping_pairs(Query_view(*this), margin, out);
    }
    /// Primitives whose boxes overlap the closed box `query`.
    void range_query(const Box& query, std::vector<Index>& out) const
    {
        internal::range_query(Query_view(*this), query, out);
    }
    /// The first triangle hit by `ray` (smallest parameter, then smallest index).
    std::optional<Kinetic_ray_hit> first_hit(const Kinetic_ray& ray) const
        requires(P::vertex_count == 3)
    {
        return internal::first_hit(Query_view(*this), ray);
    }
    /// The first hits of several rays at now(), written into `out` (cleared first; one entry per
    /// ray, in order). Equal to first_hit() per ray, but the rays share one query's memo, so a
    /// node box near the root is assembled once for all of them instead of once per ray.
    void first_hits(std::span<const Kinetic_ray> rays, std::vector<std::optional<Kinetic_ray_hit>>& out) const
        requires(P::vertex_count == 3)
    {
        internal::first_hits(Query_view(*this), rays, out);
    }
    /// Simultaneous traversal with `other`: `descend(node_a, node_b, box_a, box_b) -> bool` opens a
    /// node pair, `on_leaf_pair(node_a, node_b)` receives the leaf pairs it lets through. This is
    /// the hook through which a point cloud hierarchy drives its traversal over deforming clouds.
    template <class Tree, class Descend, class OnLeafPair>
    void traverse(const Tree& other, Descend&& descend, OnLeafPair&& on_leaf_pair) const
    {
        internal::check_query(m_now, other.now(), 0.0);
        internal::traverse_pairs(Query_view(*this), m_root, query_view_of(other), other.root(), descend, on_leaf_pair);
    }
    /// @}

private:
    template <Flightplan, KineticPrimitive, class>
    friend class Kinetic_AABB_tree;

    /// The tree's name in the messages of its exceptions.
    static constexpr const char* tree_name = "Kinetic_AABB_tree";

    /// The tree as one query reads it: the same nodes and primitives, with vertex positions and
    /// node boxes at now() computed on first use and memoized for the rest of the query. The memo
    /// tables come from the tree's pool and go back to it when the query ends (one set per query
    /// running at the same time), so concurrent queries share nothing mutable and a query neither
    /// allocates nor clears tables of the size of the tree (stamps invalidate them).
    class Query_view {
    public:
        explicit Query_view(const Kinetic_AABB_tree& tree) : m_tree(tree), m_memo(tree.m_memo_pool.acquire())
        {
            m_memo->start(tree.m_flightplans.size(), tree.m_nodes.size());
            m_stamp = m_memo->stamp;
        }
        Query_view(const Query_view&) = delete;
        Query_view& operator=(const Query_view&) = delete;
        ~Query_view() { m_tree.m_memo_pool.release(std::move(m_memo)); }

        Node_index root() const { return m_tree.m_root; }
        bool is_leaf(Node_index n) const { return m_tree.m_nodes[n].is_leaf(); }
        Node_index left(Node_index n) const { return m_tree.m_nodes[n].left; }
        Node_index right(Node_index n) const { return m_tree.m_nodes[n].right; }
        Index leaf_primitive(Node_index n) const { return m_tree.m_nodes[n].primitive; }
        const P& primitive(Index i) const { return m_tree.m_primitives[i]; }
        const Eigen::Vector3d& vertex_position(Index v) const
        {
            internal::Query_memo::Position& entry = m_memo->positions[v];
            if (entry.stamp != m_stamp) {
                entry.value = m_tree.m_flightplans[v].position(m_tree.m_now);
                entry.stamp = m_stamp;
            }
            return entry.value;
        }
        /// Equal to the tree's box(n).
        const Box& box(Node_index n) const
        {
            internal::Query_memo::Box& entry = m_memo->boxes[n];
            if (entry.stamp != m_stamp) {
                assemble(n, entry.value);
                entry.stamp = m_stamp;
            }
            return entry.value;
        }

    private:
        void assemble(Node_index n, Box& result) const
        {
            const internal::AABB_node& node = m_tree.m_nodes[n];
            if (node.is_leaf()) {
                const P& p = m_tree.m_primitives[node.primitive];
                result.setEmpty();
                for (std::size_t k = 0; k < P::vertex_count; ++k) result.extend(vertex_position(p.vertex(k)));
                return;
            }
            const std::array<Index, bound_count>& e = m_tree.m_extreme[n];
            for (int axis = 0; axis < 3; ++axis) {
                result.min()[axis] = vertex_position(e[std::size_t(axis)])[axis];
                result.max()[axis] = vertex_position(e[std::size_t(axis + 3)])[axis];
            }
        }

        const Kinetic_AABB_tree& m_tree;
        std::unique_ptr<internal::Query_memo> m_memo;
        std::uint32_t m_stamp;
    };

    /// `other` as a query reads it: a Query_view for a kinetic tree, the tree itself otherwise.
    template <class Tree>
    static decltype(auto) query_view_of(const Tree& other)
    {
        if constexpr (requires { typename Tree::Event_queue_type; })
            return typename Tree::Query_view(other);
        else
            return (other);
    }

    static std::array<Index, bound_count> unset_extremes()
    {
        std::array<Index, bound_count> e;
        e.fill(no_node);
        return e;
    }
    static typename Queue::Id certificate_id(Node_index n, int b) { return n * bound_count + Index(b); }

    void add_incidence(Index i)
    {
        for (std::size_t k = 0; k < P::vertex_count; ++k) {
            std::vector<Index>& list = m_incident[m_primitives[i].vertex(k)];
            if (std::find(list.begin(), list.end(), i) == list.end()) list.push_back(i);
        }
    }
    void remove_incidence(Index i)
    {
        for (std::size_t k = 0; k < P::vertex_count; ++k) {
            std::vector<Index>& list = m_incident[m_primitives[i].vertex(k)];
            list.erase(std::remove(list.begin(), list.end(), i), list.end());
        }
    }

    Node_index allocate_node()
    {
        Node_index n;
        if (!m_free_nodes.empty()) {
            n = m_free_nodes.back();
            m_free_nodes.pop_back();
            m_nodes[n] = internal::AABB_node{};
            m_extreme[n] = unset_extremes();
            m_updated_in_round[n] = 0;
        } else {
            n = Node_index(m_nodes.size());
            m_nodes.push_back({});
            m_extreme.push_back(unset_extremes());
            m_updated_in_round.push_back(0);
            m_queue.resize(m_nodes.size() * bound_count);
            m_overtaker.resize(m_nodes.size() * bound_count, no_node);
        }
        return n;
    }
    void free_node(Node_index n)
    {
        for (int b = 0; b < bound_count; ++b) m_queue.erase(certificate_id(n, b));
        m_free_nodes.push_back(n);
    }
    void replace_child(Node_index parent, Node_index old_child, Node_index new_child)
    {
        if (parent == no_node)
            m_root = new_child;
        else if (m_nodes[parent].left == old_child)
            m_nodes[parent].left = new_child;
        else
            m_nodes[parent].right = new_child;
    }

    static double growth(const Box& box, const Box& added)
    {
        auto area = [](const Box& b) {
            const Eigen::Vector3d s = b.sizes();
            return s.x() * s.y() + s.y() * s.z() + s.z() * s.x();
        };
        return area(box.merged(added)) - area(box);
    }

    /// Recomputes all bounds of `from` and then of its ancestors, stopping above `from` at the first
    /// node that keeps all its extremes. `from_is_new`: the first extremes of a new node are not
    /// counted as BV updates.
    void repair_path(Node_index from, bool from_is_new)
    {
        bool first = true;
        for (Node_index n = from; n != no_node; n = m_nodes[n].parent) {
            bool any = false;
            for (int b = 0; b < bound_count; ++b) {
                if (update_bound(n, b)) {
                    any = true;
                    if (!first || !from_is_new) count_update(n);
                }
            }
            if (!any && !first) break;
            first = false;
        }
    }

    void initialize_at(double t)
    {
        m_now = t;
        m_queue.clear();
        std::vector<Node_index> order;
        internal::postorder(m_nodes, m_root, order);
        for (const Node_index n : order)
            if (!m_nodes[n].is_leaf())
                for (int b = 0; b < bound_count; ++b) update_bound(n, b);
    }

    /// Failure time after now() of "x stays the extreme of bound b against y".
    double failure(Index x, Index y, int b)
    {
        if (x == y) return never;
        ++m_stats.certificate_computations;
        const int axis = b % 3;
        return b >= 3 ? m_flightplans[x].next_crossing(m_flightplans[y], axis, m_now)
                      : m_flightplans[y].next_crossing(m_flightplans[x], axis, m_now);
    }

    /// Whether vertex v is a candidate for bound b of a node whose child is `child`: v is the
    /// child's extreme (inner child) or one of its primitive's vertices (leaf child).
    bool is_candidate(Index v, Node_index child, int b) const
    {
        if (!m_nodes[child].is_leaf()) return m_extreme[child][std::size_t(b)] == v;
        const P& p = m_primitives[m_nodes[child].primitive];
        for (std::size_t k = 0; k < P::vertex_count; ++k)
            if (Index(p.vertex(k)) == v) return true;
        return false;
    }

    /// Chooses the extreme of inner node n for bound b among its candidates (each child's extreme,
    /// or all vertices of a leaf child's primitive) as the one that holds just after now() (keeping
    /// the current extreme when it still holds, so ties never cause swaps), and schedules its
    /// certificate. At an event, `overtaker` is the candidate whose crossing made the certificate
    /// fail; trying it first as the new extreme saves the certificate computations against the
    /// extreme it overtook. Returns whether the extreme changed.
    bool update_bound(Node_index n, int b, Index overtaker = no_node)
    {
        constexpr std::size_t capacity = 2 * P::vertex_count;
        std::array<Index, capacity> candidates;
        std::size_t count = 0;
        const internal::AABB_node& node = m_nodes[n];
        PCCD_debug_precondition(!node.is_leaf());
        for (const Node_index child : {node.left, node.right}) {
            const auto add = [&](Index v) {
                for (std::size_t k = 0; k < count; ++k)
                    if (candidates[k] == v) return;
                candidates[count++] = v;
            };
            if (!m_nodes[child].is_leaf()) {
                add(m_extreme[child][std::size_t(b)]);
            } else {
                const P& p = m_primitives[m_nodes[child].primitive];
                for (std::size_t k = 0; k < P::vertex_count; ++k) add(p.vertex(k));
            }
        }
        const Index current = m_extreme[n][std::size_t(b)];
        Index champion = candidates[0];
        for (std::size_t k = 0; k < count; ++k)
            if (candidates[k] == current) champion = current;
        for (std::size_t k = 0; k < count; ++k)
            if (candidates[k] == overtaker) champion = overtaker;

        std::array<double, capacity> fails;
        std::array<bool, capacity> known{};
        for (std::size_t k = 0; k < count; ++k) {
            if (candidates[k] == champion) continue;
            const double f = failure(champion, candidates[k], b);
            if (f > m_now) {
                fails[k] = f;
                known[k] = true;
            } else {
                champion = candidates[k];
                known.fill(false);
            }
        }
        double certificate = never;
        Index witness = no_node;
        for (std::size_t k = 0; k < count; ++k) {
            if (candidates[k] == champion) continue;
            const double f = known[k] ? fails[k] : failure(champion, candidates[k], b);
            if (f < certificate) {
                certificate = f;
                witness = candidates[k];
            }
        }
        m_overtaker[certificate_id(n, b)] = witness;
        // Two candidates cannot both fail immediately (Piecewise_cubic.h explains why); with three,
        // rounding could make "holds just after now" intransitive. Deferring by one ulp keeps time
        // strictly increasing, so event processing always terminates.
        if (certificate <= m_now) certificate = std::nextafter(m_now, never);
        m_queue.set(certificate_id(n, b), certificate);
        const bool changed = champion != current;
        m_extreme[n][std::size_t(b)] = champion;
        return changed;
    }

    /// Counts a change of one bound's extreme at node n (and n itself once per update round).
    void count_update(Node_index n)
    {
        ++m_stats.bv_updates;
        if (m_updated_in_round[n] != m_round) {
            m_updated_in_round[n] = m_round;
            ++m_stats.node_updates;
        }
    }
    void next_update_round()
    {
        if (++m_round == 0) { // after 2^32 rounds: restart the stamps
            std::fill(m_updated_in_round.begin(), m_updated_in_round.end(), 0);
            m_round = 1;
        }
    }

    void propagate(Node_index n, int b)
    {
        for (Node_index p = m_nodes[n].parent; p != no_node; p = m_nodes[p].parent) {
            if (!update_bound(p, b)) break;
            count_update(p);
        }
    }

    std::vector<F> m_flightplans;
    internal::Primitive_slots<P> m_primitives;
    std::vector<Node_index> m_leaf_of;
    std::vector<std::vector<Index>> m_incident;
    std::vector<internal::AABB_node> m_nodes;
    std::vector<std::array<Index, bound_count>> m_extreme;
    std::vector<Node_index> m_free_nodes;
    Node_index m_root = no_node;
    Queue m_queue;
    /// Per certificate, the candidate that attains its failure time (the next extreme at the event).
    std::vector<Index> m_overtaker;
    internal::Query_memo_pool m_memo_pool;
    /// Per node, the last update round (advance_to call or run-time change) that changed it.
    std::vector<std::uint32_t> m_updated_in_round;
    std::uint32_t m_round = 1;
    double m_now;
    Statistics m_stats;
};

} // namespace PCCD
