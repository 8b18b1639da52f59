// PCCD/Kinetic/Kinetic_AABB_tree.h -- the kinetic AABB tree of Weller and Zachmann (ALGORITHMS.md
// section 7): a bounding volume hierarchy over moving primitives that stores only combinatorial
// structure, the vertex attaining each of the six bounds of every node, and keeps it valid by
// processing certificate failures (events) in time order instead of refitting every frame.
//
// One certificate per node and bound says "this vertex is the extreme of its candidates" (the
// children's extremes for an inner node, the primitive's vertices for a leaf). Its failure time,
// the first time a candidate's flightplan overtakes the extreme's, goes into an indexed event
// queue. advance_to(t) pops the events before t in order, swaps the extreme, reschedules that
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
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Event_queue.h>
#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/AABB_tree_queries.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

namespace PCCD {

/// Counters of a kinetic tree since construction (or the last reset_statistics()).
struct Kinetic_statistics {
    std::uint64_t events = 0;                   ///< certificate failures popped from the queue
    std::uint64_t bv_updates = 0;               ///< changes of one bound's extreme vertex at one node
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
/// inputs.
///
/// Queries memoize vertex positions and node boxes at now() in tables owned by the query call (each
/// vertex's flightplan is evaluated at most once per query, however many node boxes it bounds, and
/// each node box is assembled at most once, however many node pairs it enters), so they give the
/// same answers as box() and vertex_position() without any mutable state in the tree (provided the
/// flightplan's position(t)[axis] equals coordinate(axis, t), as in all models shipped, bit for bit).
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
        : m_flightplans(std::move(flightplans)), m_primitives(std::move(primitives)), m_now(t0)
    {
        if (!std::isfinite(t0)) throw Invalid_input(internal::concat("Kinetic_AABB_tree: start time ", t0, " is not finite"));
        if (m_primitives.size() >= (std::size_t(1) << 31))
            throw Invalid_input("Kinetic_AABB_tree: too many primitives (2^31 or more)");
        if (m_flightplans.size() >= std::size_t(no_node))
            throw Invalid_input("Kinetic_AABB_tree: too many vertices (2^32 - 1 or more)");
        m_incident.resize(m_flightplans.size());
        for (Index i = 0; i < Index(m_primitives.size()); ++i) {
            check_primitive(m_primitives[i], i);
            add_incidence(i);
        }
        m_alive.assign(m_primitives.size(), 1);
        m_leaf_of.assign(m_primitives.size(), no_node);
        std::vector<Index> ids(m_primitives.size());
        std::vector<Eigen::Vector3d> centroids(m_primitives.size());
        for (Index i = 0; i < Index(ids.size()); ++i) {
            ids[i] = i;
            centroids[i] = centroid(m_primitives[i], t0);
        }
        m_root = internal::build_median_split(std::move(ids), centroids, m_nodes);
        m_extreme.assign(m_nodes.size(), unset_extremes());
        for (Node_index n = 0; n < Node_index(m_nodes.size()); ++n)
            if (m_nodes[n].is_leaf()) m_leaf_of[m_nodes[n].primitive] = n;
        m_queue.resize(m_nodes.size() * bound_count);
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
        if (!std::isfinite(t)) throw Invalid_input(internal::concat("Kinetic_AABB_tree::advance_to: time ", t, " is not finite"));
        if (t < m_now) {
            initialize_at(t);
            return;
        }
        while (!m_queue.empty() && m_queue.top_time() < t) {
            m_now = m_queue.top_time();
            const typename Queue::Id id = m_queue.top_id();
            ++m_stats.events;
            const Node_index n = id / bound_count;
            const int b = int(id % bound_count);
            if (update_bound(n, b)) {
                ++m_stats.bv_updates;
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
        if (v >= m_flightplans.size())
            throw Invalid_input(internal::concat("Kinetic_AABB_tree::set_flightplan: vertex ", v, " out of range (",
                                                 m_flightplans.size(), " vertices)"));
        m_flightplans[v] = std::move(flightplan);
        ++m_stats.flightplan_changes;
        for (const Index i : m_incident[v]) {
            std::array<bool, bound_count> changed{};
            for (Node_index n = m_leaf_of[i]; n != no_node; n = m_nodes[n].parent) {
                bool go_on = false;
                for (int b = 0; b < bound_count; ++b) {
                    const bool involved = m_nodes[n].is_leaf() || m_extreme[m_nodes[n].left][std::size_t(b)] == v ||
                                          m_extreme[m_nodes[n].right][std::size_t(b)] == v;
                    changed[std::size_t(b)] = (involved || changed[std::size_t(b)]) && update_bound(n, b);
                    if (changed[std::size_t(b)]) ++m_stats.bv_updates;
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
        check_primitive(primitive, Index(m_primitives.size()));
        Index i;
        if (!m_free_primitives.empty()) {
            i = m_free_primitives.back();
            m_free_primitives.pop_back();
            m_primitives[i] = primitive;
            m_alive[i] = 1;
        } else {
            if (m_primitives.size() + 1 >= (std::size_t(1) << 31))
                throw Invalid_input("Kinetic_AABB_tree::insert: too many primitives");
            i = Index(m_primitives.size());
            m_primitives.push_back(primitive);
            m_alive.push_back(1);
            m_leaf_of.push_back(no_node);
        }
        add_incidence(i);
        ++m_stats.insertions;
        const Node_index leaf = allocate_node();
        m_nodes[leaf].primitive = i;
        m_leaf_of[i] = leaf;
        for (int b = 0; b < bound_count; ++b) update_bound(leaf, b);
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
        if (!contains(i))
            throw Invalid_input(internal::concat("Kinetic_AABB_tree::remove: primitive ", i, " is not in the tree"));
        ++m_stats.removals;
        remove_incidence(i);
        m_alive[i] = 0;
        m_free_primitives.push_back(i);
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
    std::size_t primitive_count() const { return m_primitives.size() - m_free_primitives.size(); }
    /// One past the largest primitive index ever used (live or freed).
    std::size_t primitive_capacity() const { return m_primitives.size(); }
    bool contains(Index i) const { return i < m_primitives.size() && m_alive[i]; }
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
    /// The vertex attaining bound b (0..5) of node n.
    Index extreme_vertex(Node_index n, int b) const { return m_extreme[n][std::size_t(b)]; }
    /// The scheduled failure time of the certificate of node n and bound b (+infinity: never).
    double certificate_time(Node_index n, int b) const { return m_queue.time(certificate_id(n, b)); }
    /// The box of node n at now(), read off its six extreme vertices. O(1) flightplan evaluations.
    Box box(Node_index n) const
    {
        const std::array<Index, bound_count>& e = m_extreme[n];
        Box result;
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
        check_query(other.now(), margin);
        internal::overlapping_pairs(Query_view(*this), query_view_of(other), margin, out);
    }
    /// Pairs i < j of non-adjacent primitives (sharing no vertex) whose boxes, grown by `margin`,
    /// overlap. \throws Invalid_input if margin < 0.
    void self_overlapping_pairs(std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        check_query(m_now, margin);
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
    /// Simultaneous traversal with `other`: `descend(node_a, node_b, box_a, box_b) -> bool` opens a
    /// node pair, `on_leaf_pair(node_a, node_b)` receives the leaf pairs it lets through. This is
    /// the hook through which a point cloud hierarchy drives its traversal over deforming clouds.
    template <class Tree, class Descend, class OnLeafPair>
    void traverse(const Tree& other, Descend&& descend, OnLeafPair&& on_leaf_pair) const
    {
        check_query(other.now(), 0.0);
        internal::traverse_pairs(Query_view(*this), m_root, query_view_of(other), other.root(), descend, on_leaf_pair);
    }
    /// @}

private:
    template <Flightplan, KineticPrimitive, class>
    friend class Kinetic_AABB_tree;

    /// The tree as one query reads it: the same nodes and primitives, with vertex positions and
    /// node boxes at now() computed on first use and memoized for the rest of the query. Lives on
    /// the querying thread's stack, so concurrent queries share nothing mutable. Construction
    /// zeroes one flag byte per vertex and per node (positions and boxes are written before they
    /// are read).
    class Query_view {
    public:
        explicit Query_view(const Kinetic_AABB_tree& tree)
            : m_tree(tree), m_evaluated(tree.m_flightplans.size(), 0),
              m_positions(std::make_unique_for_overwrite<Eigen::Vector3d[]>(tree.m_flightplans.size())),
              m_boxed(tree.m_nodes.size(), 0), m_boxes(std::make_unique_for_overwrite<Box[]>(tree.m_nodes.size()))
        {
        }
        Node_index root() const { return m_tree.m_root; }
        bool is_leaf(Node_index n) const { return m_tree.m_nodes[n].is_leaf(); }
        Node_index left(Node_index n) const { return m_tree.m_nodes[n].left; }
        Node_index right(Node_index n) const { return m_tree.m_nodes[n].right; }
        Index leaf_primitive(Node_index n) const { return m_tree.m_nodes[n].primitive; }
        const P& primitive(Index i) const { return m_tree.m_primitives[i]; }
        const Eigen::Vector3d& vertex_position(Index v) const
        {
            if (!m_evaluated[v]) {
                m_positions[v] = m_tree.m_flightplans[v].position(m_tree.m_now);
                m_evaluated[v] = 1;
            }
            return m_positions[v];
        }
        /// Equal to the tree's box(n).
        const Box& box(Node_index n) const
        {
            Box& result = m_boxes[n];
            if (!m_boxed[n]) {
                const std::array<Index, bound_count>& e = m_tree.m_extreme[n];
                for (int axis = 0; axis < 3; ++axis) {
                    result.min()[axis] = vertex_position(e[std::size_t(axis)])[axis];
                    result.max()[axis] = vertex_position(e[std::size_t(axis + 3)])[axis];
                }
                m_boxed[n] = 1;
            }
            return result;
        }

    private:
        const Kinetic_AABB_tree& m_tree;
        mutable std::vector<char> m_evaluated;
        std::unique_ptr<Eigen::Vector3d[]> m_positions;
        mutable std::vector<char> m_boxed;
        std::unique_ptr<Box[]> m_boxes;
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

    void check_primitive(const P& p, Index i) const
    {
        for (std::size_t k = 0; k < P::vertex_count; ++k)
            if (std::uint32_t(p.vertex(k)) >= m_flightplans.size())
                throw Invalid_input(internal::concat("Kinetic_AABB_tree: primitive ", i, " refers to vertex ",
                                                     std::uint32_t(p.vertex(k)), " but there are ",
                                                     m_flightplans.size(), " vertices"));
    }

    void check_query(double other_now, double margin) const
    {
        if (other_now != m_now)
            throw Invalid_input(internal::concat("kinetic query: the trees are at different times (", m_now, " and ",
                                                 other_now, "); advance both first"));
        if (!std::isgreaterequal(margin, 0.0))
            throw Invalid_input(internal::concat("kinetic query: margin ", margin, " is negative"));
    }

    Eigen::Vector3d centroid(const P& p, double t) const
    {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < P::vertex_count; ++k) c += m_flightplans[p.vertex(k)].position(t);
        return c / double(P::vertex_count);
    }

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
        } else {
            n = Node_index(m_nodes.size());
            m_nodes.push_back({});
            m_extreme.push_back(unset_extremes());
            m_queue.resize(m_nodes.size() * bound_count);
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
                    if (!first || !from_is_new) ++m_stats.bv_updates;
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

    /// Chooses the extreme of node n for bound b among its candidates as the one that holds just
    /// after now() (keeping the current extreme when it still holds, so ties never cause swaps),
    /// and schedules its certificate. Returns whether the extreme changed.
    bool update_bound(Node_index n, int b)
    {
        constexpr std::size_t capacity = P::vertex_count > 2 ? P::vertex_count : 2;
        std::array<Index, capacity> candidates;
        std::size_t count;
        const internal::AABB_node& node = m_nodes[n];
        if (node.is_leaf()) {
            const P& p = m_primitives[node.primitive];
            for (std::size_t k = 0; k < P::vertex_count; ++k) candidates[k] = p.vertex(k);
            count = P::vertex_count;
        } else {
            candidates[0] = m_extreme[node.left][std::size_t(b)];
            candidates[1] = m_extreme[node.right][std::size_t(b)];
            count = 2;
        }
        const Index current = m_extreme[n][std::size_t(b)];
        Index champion = candidates[0];
        for (std::size_t k = 0; k < count; ++k)
            if (candidates[k] == current) champion = current;

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
        for (std::size_t k = 0; k < count; ++k) {
            if (candidates[k] == champion) continue;
            certificate = std::min(certificate, known[k] ? fails[k] : failure(champion, candidates[k], b));
        }
        // Two candidates cannot both fail immediately (Piecewise_cubic.h explains why); with three,
        // rounding could make "holds just after now" intransitive. Deferring by one ulp keeps time
        // strictly increasing, so event processing always terminates.
        if (certificate <= m_now) certificate = std::nextafter(m_now, never);
        m_queue.set(certificate_id(n, b), certificate);
        const bool changed = champion != current;
        m_extreme[n][std::size_t(b)] = champion;
        return changed;
    }

    void propagate(Node_index n, int b)
    {
        for (Node_index p = m_nodes[n].parent; p != no_node; p = m_nodes[p].parent) {
            if (!update_bound(p, b)) break;
            ++m_stats.bv_updates;
        }
    }

    std::vector<F> m_flightplans;
    std::vector<P> m_primitives;
    std::vector<char> m_alive;
    std::vector<Index> m_free_primitives;
    std::vector<Node_index> m_leaf_of;
    std::vector<std::vector<Index>> m_incident;
    std::vector<internal::AABB_node> m_nodes;
    std::vector<std::array<Index, bound_count>> m_extreme;
    std::vector<Node_index> m_free_nodes;
    Node_index m_root = no_node;
    Queue m_queue;
    double m_now;
    Statistics m_stats;
};

} // namespace PCCD
