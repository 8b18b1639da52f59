// PCCD/Kinetic/Kinetic_AABB_tree.h -- the kinetic AABB tree of Weller and Zachmann
// (doc/manual/kinetic.md, "Building and advancing", "Changing the animation at run time" and
// "Queries"): a bounding volume hierarchy over moving primitives that stores only combinatorial
// structure, the vertex attaining each of the six bounds of every node, and keeps it valid by
// processing certificate failures (events) in time order instead of refitting every frame.
//
// One certificate per inner node and bound says "this vertex is the extreme of its candidates" (the
// extreme of an inner child, every vertex of a leaf child's primitive). Leaves store nothing: a
// leaf's box is the box of its primitive's few vertices, read off directly, so crossings between
// the vertices of one primitive are no events unless they change the parent's extreme. A
// certificate's failure time, the first time a candidate's flightplan overtakes the extreme's, goes
// into an indexed event queue. advance_to(t) pops the events before t in order, swaps the extreme,
// reschedules that certificate and propagates up while the parent's extreme changes. Flightplans
// can be replaced, primitives inserted and removed at run time; each repairs only the affected
// paths. This header holds the interface; the machinery is in internal/: the tree's data
// (Kinetic_tree_state.h), one certificate (Kinetic_certificates.h), the event loop
// (Kinetic_event_loop.h), the changes at run time (Kinetic_tree_edits.h), node boxes
// (Kinetic_node_access.h), the view through which queries read the tree (Kinetic_query_view.h)
// and the cache of certificate failure times (Crossing_cache.h). Node boxes are read off the
// extreme vertices' positions, evaluated from the flightplans or, after advance_to(t, positions),
// taken from the caller's array for the frame.
#pragma once

#include <cstddef>
#include <cstdint>
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
#include <PCCD/Kinetic/Kinetic_statistics.h>
#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/AABB_tree_checks.h>
#include <PCCD/Kinetic/internal/AABB_tree_queries.h>
#include <PCCD/Kinetic/internal/Kinetic_event_loop.h>
#include <PCCD/Kinetic/internal/Kinetic_node_access.h>
#include <PCCD/Kinetic/internal/Kinetic_query_view.h>
#include <PCCD/Kinetic/internal/Kinetic_tree_edits.h>
#include <PCCD/Kinetic/internal/Kinetic_tree_state.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

namespace PCCD {

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
    using State = internal::Kinetic_tree_state<F, P, Queue>;

public:
    using Flightplan_type = F;
    using Primitive = P;
    using Event_queue_type = Queue;
    using Index = std::uint32_t;
    using Node_index = std::uint32_t;
    using Box = Eigen::AlignedBox3d;
    using Statistics = Kinetic_statistics;
    static constexpr Node_index no_node = internal::no_node;
    static constexpr int bound_count = State::bound_count; // 6
    /// The time of a certificate that never fails (+infinity).
    static constexpr double never = State::never;

    /// \name Construction
    /// @{

    /// Builds the tree at time `t0` over `primitives`, whose vertex indices refer to `flightplans`.
    /// The topology is a median split of the primitives' centroids at t0 (height ceil(log2 n)),
    /// then every certificate is computed.
    /// \throws Invalid_input if t0 is not finite, a primitive refers to a vertex >= flightplans.size()
    ///         (the message names both), or there are 2^31 primitives or more.
    /// Complexity: O(n log n) plus one next_crossing per candidate of every node and bound.
    Kinetic_AABB_tree(std::vector<F> flightplans, std::vector<P> primitives, double t0 = 0.0)
        : m_state(std::move(flightplans), std::move(primitives), tree_name, t0)
    {
        State& s = m_state;
        internal::check_start_time(tree_name, t0);
        if (s.flightplans.size() >= std::size_t(no_node))
            throw Invalid_input("Kinetic_AABB_tree: too many vertices (2^32 - 1 or more)");
        s.incident.resize(s.flightplans.size());
        for (Index i = 0; i < Index(s.primitives.capacity()); ++i) {
            internal::check_primitive(tree_name, s.primitives[i], i, s.flightplans.size());
            internal::add_incidence(s, i);
        }
        s.leaf_of.assign(s.primitives.capacity(), no_node);
        std::vector<Eigen::Vector3d> centroids;
        s.root = internal::build_over_live_primitives(
            s.primitives, [&](Index v) { return s.flightplans[v].position(t0); }, centroids, s.nodes);
        s.extreme.assign(s.nodes.size(), s.unset_extremes());
        for (Node_index n = 0; n < Node_index(s.nodes.size()); ++n)
            if (s.nodes[n].is_leaf()) s.leaf_of[s.nodes[n].primitive] = n;
        s.queue.resize(s.nodes.size() * bound_count);
        s.overtaker.assign(s.nodes.size() * bound_count, no_node);
        s.crossings.reset(s.nodes.size() * bound_count);
        s.updated_in_round.assign(s.nodes.size(), 0);
        internal::initialize_at(s, t0);
    }
    /// @}

    /// \name Time
    /// @{

    /// The time the tree is valid for.
    double now() const { return m_state.now; }

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
        m_state.frame_positions = nullptr;
        if (t < m_state.now)
            internal::initialize_at(m_state, t);
        else
            internal::process_events_before(m_state, t);
    }

    /// Moves the tree to time t as advance_to(t), then takes the vertex positions at t from
    /// `positions` (one per vertex, e.g. the state of the simulation that recorded the flightplans)
    /// instead of evaluating flightplans: box(), vertex_position() and every query read them until
    /// the next advance_to, set_flightplan or add_vertex. The array is not copied; it must stay
    /// alive and unchanged until then.
    /// \pre positions[v] == flightplan(v).position(t) for every v, bit for bit (the extremes are
    ///      those of the flightplans; a box read off other positions need not contain them).
    ///      Checked in debug builds; positions_match(t, positions) checks it on demand.
    /// \throws Invalid_input if t is not finite or positions.size() != vertex_count().
    /// Complexity: that of advance_to(t); no flightplan evaluation at query time.
    void advance_to(double t, std::span<const Eigen::Vector3d> positions)
    {
        if (positions.size() != m_state.flightplans.size())
            throw Invalid_input(internal::concat(tree_name, "::advance_to: ", positions.size(),
                                                 " positions given for ", m_state.flightplans.size(), " vertices"));
        advance_to(t);
        PCCD_debug_precondition(positions_match(t, positions));
        m_state.frame_positions = positions.data();
    }

    /// Whether `positions` holds every vertex's flightplan position at t, bit for bit (the
    /// precondition of advance_to(t, positions)). O(vertex_count()) flightplan evaluations.
    bool positions_match(double t, std::span<const Eigen::Vector3d> positions) const
    {
        if (positions.size() != m_state.flightplans.size()) return false;
        for (std::size_t v = 0; v < positions.size(); ++v)
            if (m_state.flightplans[v].position(t) != positions[v]) return false;
        return true;
    }

    /// Whether the tree currently reads the caller's positions (advance_to with positions).
    bool has_frame_positions() const { return m_state.frame_positions != nullptr; }

    /// The time of the next pending event (+infinity if none).
    double next_event_time() const { return m_state.queue.empty() ? never : m_state.queue.top_time(); }
    /// Number of certificates currently scheduled (the others never fail).
    std::size_t scheduled_certificates() const { return m_state.queue.size(); }
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
        internal::check_vertex(tree_name, v, m_state.flightplans.size());
        m_state.flightplans[v] = std::move(flightplan);
        m_state.crossings.clear();            // cached failure times of v's pairs no longer hold
        m_state.frame_positions = nullptr;    // the caller's positions no longer describe v
        ++m_state.stats.flightplan_changes;
        internal::repair_after_flightplan_change(m_state, v);
    }

    /// Adds a vertex (used by primitives inserted later); returns its index.
    Index add_vertex(F flightplan)
    {
        if (m_state.flightplans.size() + 1 >= std::size_t(no_node))
            throw Invalid_input("Kinetic_AABB_tree::add_vertex: too many vertices");
        m_state.flightplans.push_back(std::move(flightplan));
        m_state.incident.emplace_back();
        m_state.frame_positions = nullptr; // the caller's array has no entry for the new vertex
        return Index(m_state.flightplans.size() - 1);
    }

    /// Inserts a primitive at now(): a new leaf is paired with the leaf reached by descending
    /// towards the child whose box grows least in surface area. Returns the primitive's index
    /// (a freed index is reused).
    /// \throws Invalid_input if the primitive refers to a vertex >= vertex_count().
    /// Complexity: O(h) box evaluations and certificate computations, h the height. Many insertions
    /// can unbalance the tree; rebuild it when the height matters.
    Index insert(const P& primitive)
    {
        const State& s = m_state;
        internal::check_primitive(tree_name, primitive, Index(s.primitives.capacity()), s.flightplans.size());
        return internal::insert_primitive(m_state, primitive, tree_name);
    }

    /// Removes primitive `i`: its leaf goes, its sibling takes the parent's place, and the path
    /// above is repaired at now(). \throws Invalid_input if `i` is not a live primitive.
    /// Complexity: O(h) certificate computations.
    void remove(Index i)
    {
        internal::check_live_primitive(tree_name, i, contains(i));
        internal::remove_primitive(m_state, i);
    }
    /// @}

    /// \name Access
    /// @{
    std::size_t vertex_count() const { return m_state.flightplans.size(); }
    /// Number of live primitives.
    std::size_t primitive_count() const { return m_state.primitives.live_count(); }
    /// One past the largest primitive index ever used (live or freed).
    std::size_t primitive_capacity() const { return m_state.primitives.capacity(); }
    bool contains(Index i) const { return m_state.primitives.contains(i); }
    const P& primitive(Index i) const { return m_state.primitives[i]; }
    const F& flightplan(Index v) const { return m_state.flightplans[v]; }
    /// Position of vertex v at now().
    Eigen::Vector3d vertex_position(Index v) const { return internal::vertex_position(m_state, v); }
    const Statistics& statistics() const { return m_state.stats; }
    void reset_statistics() { m_state.stats = Statistics(); }
    /// @}

    /// \name Nodes (for custom traversals, e.g. a point cloud hierarchy over a deforming cloud)
    /// @{
    Node_index root() const { return m_state.root; }
    bool is_leaf(Node_index n) const { return m_state.nodes[n].is_leaf(); }
    Node_index left(Node_index n) const { return m_state.nodes[n].left; }
    Node_index right(Node_index n) const { return m_state.nodes[n].right; }
    Node_index parent(Node_index n) const { return m_state.nodes[n].parent; }
    /// The primitive of leaf n.
    Index leaf_primitive(Node_index n) const { return m_state.nodes[n].primitive; }
    /// The leaf holding live primitive i.
    Node_index leaf_of(Index i) const { return m_state.leaf_of[i]; }
    /// The vertex attaining bound b (0..5) of node n: the stored extreme of an inner node; for a
    /// leaf, the first vertex of its primitive attaining the bound at now() (leaves store nothing).
    Index extreme_vertex(Node_index n, int b) const { return internal::extreme_vertex(m_state, n, b); }
    /// The scheduled failure time of the certificate of node n and bound b (+infinity: never, and
    /// for every leaf).
    double certificate_time(Node_index n, int b) const { return m_state.queue.time(State::certificate_id(n, b)); }
    /// The box of node n at now(): an inner node's is read off its six extreme vertices, a leaf's is
    /// the box of its primitive's vertices. O(1) flightplan evaluations.
    Box box(Node_index n) const { return internal::node_box(m_state, n); }
    /// Nodes in use. Every live node is reachable from root().
    std::size_t node_count() const { return m_state.nodes.size() - m_state.free_nodes.size(); }
    /// Height of the tree (0 for one leaf, -1 when empty). O(n).
    int height() const { return internal::height(m_state.nodes, m_state.root); }
    /// @}

    /// \name Queries at now() (const, allocation only for the output and a traversal stack)
    /// @{

    /// Pairs (i, j) of primitive i of this tree and j of `other` whose boxes, grown by `margin`,
    /// overlap. \tparam Tree another Kinetic_AABB_tree or a Refit_AABB_tree.
    /// \throws Invalid_input if the trees are at different times or margin < 0.
    template <class Tree>
    void overlapping_pairs(const Tree& other, std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        internal::check_query(m_state.now, other.now(), margin);
        internal::overlapping_pairs(Query_view(m_state), query_view_of(other), margin, out);
    }
    /// Pairs i < j of non-adjacent primitives (sharing no vertex) whose boxes, grown by `margin`,
    /// overlap. \throws Invalid_input if margin < 0.
    void self_overlapping_pairs(std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        internal::check_query(m_state.now, m_state.now, margin);
        internal::self_overlapping_pairs(Query_view(m_state), margin, out);
    }
    /// Primitives whose boxes overlap the closed box `query`.
    void range_query(const Box& query, std::vector<Index>& out) const
    {
        internal::range_query(Query_view(m_state), query, out);
    }
    /// The first triangle hit by `ray` (smallest parameter, then smallest index).
    std::optional<Kinetic_ray_hit> first_hit(const Kinetic_ray& ray) const
        requires(P::vertex_count == 3)
    {
        return internal::first_hit(Query_view(m_state), ray);
    }
    /// The first hits of several rays at now(), written into `out` (cleared first; one entry per
    /// ray, in order). Equal to first_hit() per ray, but the rays share one query's memo, so a
    /// node box near the root is assembled once for all of them instead of once per ray.
    void first_hits(std::span<const Kinetic_ray> rays, std::vector<std::optional<Kinetic_ray_hit>>& out) const
        requires(P::vertex_count == 3)
    {
        internal::first_hits(Query_view(m_state), rays, out);
    }
    /// Simultaneous traversal with `other`: `descend(node_a, node_b, box_a, box_b) -> bool` opens a
    /// node pair, `on_leaf_pair(node_a, node_b)` receives the leaf pairs it lets through. This is
    /// the hook through which a point cloud hierarchy drives its traversal over deforming clouds.
    template <class Tree, class Descend, class OnLeafPair>
    void traverse(const Tree& other, Descend&& descend, OnLeafPair&& on_leaf_pair) const
    {
        internal::check_query(m_state.now, other.now(), 0.0);
        internal::traverse_pairs(Query_view(m_state), m_state.root, query_view_of(other), other.root(), descend,
                                 on_leaf_pair);
    }
    /// @}

private:
    template <Flightplan, KineticPrimitive, class>
    friend class Kinetic_AABB_tree;

    using Query_view = internal::Kinetic_query_view<F, P, Queue>;

    /// The tree's name in the messages of its exceptions.
    static constexpr const char* tree_name = "Kinetic_AABB_tree";

    /// `other` as a query reads it: a Query_view for a kinetic tree, the tree itself otherwise.
    template <class Tree>
    static decltype(auto) query_view_of(const Tree& other)
    {
        if constexpr (requires { typename Tree::Event_queue_type; })
            return typename Tree::Query_view(other.m_state);
        else
            return (other);
    }

    State m_state;
};

} // namespace PCCD
