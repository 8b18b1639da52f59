// PCCD/Kinetic/Refit_AABB_tree.h -- the baselines of the kinetic AABB tree (doc/manual/kinetic.md,
// "Baselines with the same interface"): an AABB tree over the same moving primitives that, at every
// advance_to(t), evaluates all vertex positions and either refits every node's box bottom-up over a
// fixed topology or rebuilds the whole tree. Same node access and queries as Kinetic_AABB_tree, so
// the three update strategies are interchangeable in benchmarks and applications.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/Kinetic_ray.h>
#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/AABB_tree_checks.h>
#include <PCCD/Kinetic/internal/AABB_tree_queries.h>
#include <PCCD/Kinetic/internal/Primitive_slots.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

namespace PCCD {

/// How a Refit_AABB_tree follows the motion at every advance_to.
enum class Refit_update {
    bottom_up, ///< keep the topology, recompute every box from its children (leaves from vertices)
    rebuild    ///< rebuild the topology from scratch (median split at the new positions), then the boxes
};

/// Options of Refit_AABB_tree.
struct Refit_options {
    /// Update strategy; default Refit_update::bottom_up.
    Refit_update update = Refit_update::bottom_up;
};

/// Counters of a Refit_AABB_tree.
struct Refit_statistics {
    std::uint64_t frames = 0;     ///< calls of advance_to
    std::uint64_t bv_updates = 0; ///< node boxes recomputed (every node at every frame)
    std::uint64_t rebuilds = 0;   ///< topology rebuilds (every frame with Refit_update::rebuild)
};

/// An AABB tree over moving primitives that stores boxes and updates all of them at every frame.
///
/// \tparam F a model of Flightplan; \tparam P a model of KineticPrimitive.
///
/// Thread safety: const members may run concurrently; the others need exclusive access.
template <Flightplan F, KineticPrimitive P = Kinetic_triangle>
class Refit_AABB_tree {
public:
    using Flightplan_type = F;
    using Primitive = P;
    using Index = std::uint32_t;
    using Node_index = std::uint32_t;
    using Box = Eigen::AlignedBox3d;
    using Statistics = Refit_statistics;
    static constexpr Node_index no_node = internal::no_node;

    /// Builds the tree at time `t0` (median split, like Kinetic_AABB_tree).
    /// \throws Invalid_input if t0 is not finite, a primitive refers to a vertex out of range, or
    ///         there are 2^31 primitives or more.
    /// Complexity: O(n log n).
    Refit_AABB_tree(std::vector<F> flightplans, std::vector<P> primitives, double t0 = 0.0, Refit_options options = {})
        : m_flightplans(std::move(flightplans)), m_primitives(std::move(primitives), tree_name),
          m_options(options), m_now(t0)
    {
        internal::check_start_time(tree_name, t0);
        for (Index i = 0; i < Index(m_primitives.capacity()); ++i)
            internal::check_primitive(tree_name, m_primitives[i], i, m_flightplans.size());
        evaluate_positions();
        rebuild_topology();
        refit();
        m_stats = Statistics();
    }

    /// \name Time
    /// @{
    double now() const { return m_now; }
    /// Moves the tree to time t (any finite t): evaluates every vertex position, then refits every
    /// box bottom-up or rebuilds the tree. \throws Invalid_input if t is not finite.
    /// Complexity: O(V) flightplan evaluations + O(n) box merges (bottom_up) or O(n log n) (rebuild).
    void advance_to(double t)
    {
        internal::check_advance_time(tree_name, t);
        m_now = t;
        ++m_stats.frames;
        evaluate_positions();
        if (m_options.update == Refit_update::rebuild) rebuild_topology();
        refit();
    }
    /// Moves the tree to time t taking the vertex positions from `positions` (copied; one per
    /// vertex, e.g. the simulation's state at t) instead of evaluating the flightplans, then refits
    /// or rebuilds as advance_to(t). The same input as Kinetic_AABB_tree::advance_to(t, positions),
    /// for a like-for-like comparison. The boxes are those of the given positions; vertex_position()
    /// returns them. Give the flightplans' positions at t to compare with the kinetic tree.
    /// \throws Invalid_input if t is not finite or positions.size() != vertex_count().
    void advance_to(double t, std::span<const Eigen::Vector3d> positions)
    {
        internal::check_advance_time(tree_name, t);
        if (positions.size() != m_flightplans.size())
            throw Invalid_input(internal::concat(tree_name, "::advance_to: ", positions.size(),
                                                 " positions given for ", m_flightplans.size(), " vertices"));
        m_now = t;
        ++m_stats.frames;
        m_positions.assign(positions.begin(), positions.end());
        if (m_options.update == Refit_update::rebuild) rebuild_topology();
        refit();
    }
    /// @}

    /// \name Changes at run time (at now())
    /// @{
    /// Replaces the flightplan of vertex v and refits all boxes at now().
    /// \throws Invalid_input if v is out of range. Complexity: O(n).
    void set_flightplan(Index v, F flightplan)
    {
        internal::check_vertex(tree_name, v, m_flightplans.size());
        m_flightplans[v] = std::move(flightplan);
        m_positions[v] = m_flightplans[v].position(m_now);
        refit();
    }
    Index add_vertex(F flightplan)
    {
        m_flightplans.push_back(std::move(flightplan));
        m_positions.push_back(m_flightplans.back().position(m_now));
        return Index(m_flightplans.size() - 1);
    }
    /// Inserts a primitive and rebuilds the tree at now(). Complexity: O(n log n).
    Index insert(const P& primitive)
    {
        internal::check_primitive(tree_name, primitive, Index(m_primitives.capacity()), m_flightplans.size());
        const Index i = m_primitives.insert(primitive, tree_name);
        rebuild_topology();
        refit();
        return i;
    }
    /// Removes primitive i and rebuilds the tree at now(). \throws Invalid_input if i is not live.
    void remove(Index i)
    {
        internal::check_live_primitive(tree_name, i, contains(i));
        m_primitives.remove(i);
        rebuild_topology();
        refit();
    }
    /// @}

    /// \name Access and nodes (same interface as Kinetic_AABB_tree)
    /// @{
    std::size_t vertex_count() const { return m_flightplans.size(); }
    std::size_t primitive_count() const { return m_primitives.live_count(); }
    bool contains(Index i) const { return m_primitives.contains(i); }
    const P& primitive(Index i) const { return m_primitives[i]; }
    const F& flightplan(Index v) const { return m_flightplans[v]; }
    /// Position of vertex v at now() (cached at the last update).
    const Eigen::Vector3d& vertex_position(Index v) const { return m_positions[v]; }
    const Statistics& statistics() const { return m_stats; }
    void reset_statistics() { m_stats = Statistics(); }
    Node_index root() const { return m_root; }
    bool is_leaf(Node_index n) const { return m_nodes[n].is_leaf(); }
    Node_index left(Node_index n) const { return m_nodes[n].left; }
    Node_index right(Node_index n) const { return m_nodes[n].right; }
    Node_index parent(Node_index n) const { return m_nodes[n].parent; }
    Index leaf_primitive(Node_index n) const { return m_nodes[n].primitive; }
    /// The stored box of node n at now().
    const Box& box(Node_index n) const { return m_boxes[n]; }
    std::size_t node_count() const { return m_nodes.size(); }
    int height() const { return internal::height(m_nodes, m_root); }
    /// @}

    /// \name Queries at now() (see Kinetic_AABB_tree for the contracts)
    /// @{
    template <class Tree>
    void overlapping_pairs(const Tree& other, std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        internal::check_query(m_now, other.now(), margin);
        internal::overlapping_pairs(*this, other, margin, out);
    }
    void self_overlapping_pairs(std::vector<std::pair<Index, Index>>& out, double margin = 0.0) const
    {
        internal::check_query(m_now, m_now, margin);
        internal::self_overlapping_pairs(*this, margin, out);
    }
    void range_query(const Box& query, std::vector<Index>& out) const { internal::range_query(*this, query, out); }
    std::optional<Kinetic_ray_hit> first_hit(const Kinetic_ray& ray) const
        requires(P::vertex_count == 3)
    {
        return internal::first_hit(*this, ray);
    }
    /// As Kinetic_AABB_tree::first_hits: first_hit() of every ray, in order.
    void first_hits(std::span<const Kinetic_ray> rays, std::vector<std::optional<Kinetic_ray_hit>>& out) const
        requires(P::vertex_count == 3)
    {
        internal::first_hits(*this, rays, out);
    }
    template <class Tree, class Descend, class OnLeafPair>
    void traverse(const Tree& other, Descend&& descend, OnLeafPair&& on_leaf_pair) const
    {
        internal::check_query(m_now, other.now(), 0.0);
        internal::traverse_pairs(*this, m_root, other, other.root(), descend, on_leaf_pair);
    }
    /// @}

private:
    /// The tree's name in the messages of its exceptions.
    static constexpr const char* tree_name = "Refit_AABB_tree";

    void evaluate_positions()
    {
        m_positions.resize(m_flightplans.size());
        for (std::size_t v = 0; v < m_flightplans.size(); ++v) m_positions[v] = m_flightplans[v].position(m_now);
    }

    void rebuild_topology()
    {
        m_nodes.clear();
        m_root = internal::build_over_live_primitives(
            m_primitives, [&](Index v) -> const Eigen::Vector3d& { return m_positions[v]; }, m_centroids, m_nodes);
        internal::postorder(m_nodes, m_root, m_order);
        m_boxes.resize(m_nodes.size());
        ++m_stats.rebuilds;
    }

    void refit()
    {
        for (const Node_index n : m_order) {
            const internal::AABB_node& node = m_nodes[n];
            Box& box = m_boxes[n];
            if (node.is_leaf()) {
                const P& p = m_primitives[node.primitive];
                box.setEmpty();
                for (std::size_t k = 0; k < P::vertex_count; ++k) box.extend(m_positions[p.vertex(k)]);
            } else {
                box = m_boxes[node.left].merged(m_boxes[node.right]);
            }
        }
        m_stats.bv_updates += m_order.size();
    }

    std::vector<F> m_flightplans;
    internal::Primitive_slots<P> m_primitives;
    Refit_options m_options;
    double m_now;
    std::vector<Eigen::Vector3d> m_positions;
    std::vector<Eigen::Vector3d> m_centroids;
    std::vector<internal::AABB_node> m_nodes;
    std::vector<Node_index> m_order;
    std::vector<Box> m_boxes;
    Node_index m_root = no_node;
    Statistics m_stats;
};

} // namespace PCCD
