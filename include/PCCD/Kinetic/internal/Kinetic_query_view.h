// PCCD/Kinetic/internal/Kinetic_query_view.h -- the kinetic AABB tree as one query reads it
// (doc/manual/kinetic.md, "Queries" and "Where positions come from"): the tree's nodes and
// primitives, with node boxes read off the extreme vertices' positions at now and memoized for the
// rest of the query in Query_memo tables (Query_memo_pool.h). The positions are the caller's when
// it gave the frame's positions (advance_to(t, positions)); otherwise each is evaluated from its
// flightplan at most once per query and memoized too. (Without the box memo, the cloth's overlap
// query assembled each cloth box once per table node it meets: a third slower.) It offers the
// interface the shared queries of AABB_tree_queries.h read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Kinetic/internal/Kinetic_tree_state.h>
#include <PCCD/Kinetic/internal/Query_memo_pool.h>

namespace PCCD::internal {

/// The tree as one query reads it: the same nodes and primitives, with vertex positions and
/// node boxes at now computed on first use and memoized for the rest of the query. The memo
/// tables come from the tree's pool and go back to it when the query ends (one set per query
/// running at the same time), so concurrent queries share nothing mutable and a query neither
/// allocates nor clears tables of the size of the tree (stamps invalidate them).
template <class F, class P, class Queue>
class Kinetic_query_view {
public:
    using Index = std::uint32_t;
    using Node_index = std::uint32_t;
    using Box = Eigen::AlignedBox3d;
    using State = Kinetic_tree_state<F, P, Queue>;

    explicit Kinetic_query_view(const State& tree)
        : m_tree(tree), m_given(tree.frame_positions), m_memo(tree.memo_pool.acquire())
    {
        m_memo->start(tree.flightplans.size(), tree.nodes.size());
        m_stamp = m_memo->stamp;
    }
    Kinetic_query_view(const Kinetic_query_view&) = delete;
    Kinetic_query_view& operator=(const Kinetic_query_view&) = delete;
    ~Kinetic_query_view() { m_tree.memo_pool.release(std::move(m_memo)); }

    Node_index root() const { return m_tree.root; }
    bool is_leaf(Node_index n) const { return m_tree.nodes[n].is_leaf(); }
    Node_index left(Node_index n) const { return m_tree.nodes[n].left; }
    Node_index right(Node_index n) const { return m_tree.nodes[n].right; }
    Index leaf_primitive(Node_index n) const { return m_tree.nodes[n].primitive; }
    const P& primitive(Index i) const { return m_tree.primitives[i]; }
    const Eigen::Vector3d& vertex_position(Index v) const
    {
        if (m_given) return m_given[v];
        Query_memo::Position& entry = m_memo->positions[v];
        if (entry.stamp != m_stamp) {
            entry.value = m_tree.flightplans[v].position(m_tree.now);
            entry.stamp = m_stamp;
        }
        return entry.value;
    }
    /// Equal to the tree's box(n).
    const Box& box(Node_index n) const
    {
        Query_memo::Box& entry = m_memo->boxes[n];
        if (entry.stamp != m_stamp) {
            assemble(n, entry.value);
            entry.stamp = m_stamp;
        }
        return entry.value;
    }

private:
    void assemble(Node_index n, Box& result) const
    {
        const AABB_node& node = m_tree.nodes[n];
        if (node.is_leaf()) {
            const P& p = m_tree.primitives[node.primitive];
            result.setEmpty();
            for (std::size_t k = 0; k < P::vertex_count; ++k) result.extend(vertex_position(p.vertex(k)));
            return;
        }
        const typename State::Extremes& e = m_tree.extreme[n];
        for (int axis = 0; axis < 3; ++axis) {
            result.min()[axis] = vertex_position(e[std::size_t(axis)])[axis];
            result.max()[axis] = vertex_position(e[std::size_t(axis + 3)])[axis];
        }
    }

    const State& m_tree;
    const Eigen::Vector3d* m_given;
    std::unique_ptr<Query_memo> m_memo;
    std::uint32_t m_stamp = 0;
};

} // namespace PCCD::internal
