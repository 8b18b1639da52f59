// PCCD/Kinetic/internal/Kinetic_node_access.h -- what a node of the kinetic AABB tree is at the
// tree's current time (doc/manual/kinetic.md, "Queries": the node accessors box and
// extreme_vertex): an inner node's box read off its six extreme vertices, a leaf's the box of its
// primitive's vertices, and the vertex attaining one bound of a leaf (leaves store no extremes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <Eigen/Geometry>

#include <PCCD/Kinetic/internal/Kinetic_tree_state.h>

namespace PCCD::internal {

/// Coordinate `axis` of vertex v at now: from the caller's positions when the tree has them, else
/// from v's flightplan.
template <class F, class P, class Queue>
double vertex_coordinate(const Kinetic_tree_state<F, P, Queue>& s, std::uint32_t v, int axis)
{
    return s.frame_positions ? s.frame_positions[v][axis] : s.flightplans[v].coordinate(axis, s.now);
}

/// Position of vertex v at now (see vertex_coordinate).
template <class F, class P, class Queue>
Eigen::Vector3d vertex_position(const Kinetic_tree_state<F, P, Queue>& s, std::uint32_t v)
{
    return s.frame_positions ? s.frame_positions[v] : s.flightplans[v].position(s.now);
}

/// The vertex attaining bound b (0..5) of node n: the stored extreme of an inner node; for a leaf,
/// the first vertex of its primitive attaining the bound at now.
template <class F, class P, class Queue>
std::uint32_t extreme_vertex(const Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n, int b)
{
    using Index = std::uint32_t;
    if (!s.nodes[n].is_leaf()) return s.extreme[n][std::size_t(b)];
    const P& p = s.primitives[s.nodes[n].primitive];
    const int axis = b % 3;
    Index best = p.vertex(0);
    double best_value = vertex_coordinate(s, best, axis);
    for (std::size_t k = 1; k < P::vertex_count; ++k) {
        const double value = vertex_coordinate(s, p.vertex(k), axis);
        if (b < 3 ? value < best_value : value > best_value) {
            best = p.vertex(k);
            best_value = value;
        }
    }
    return best;
}

/// The box of node n at now: an inner node's is read off its six extreme vertices, a leaf's is the
/// box of its primitive's vertices. O(1) flightplan evaluations (none with the caller's positions).
template <class F, class P, class Queue>
Eigen::AlignedBox3d node_box(const Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n)
{
    Eigen::AlignedBox3d result;
    if (s.nodes[n].is_leaf()) {
        const P& p = s.primitives[s.nodes[n].primitive];
        result.setEmpty();
        for (std::size_t k = 0; k < P::vertex_count; ++k) result.extend(vertex_position(s, p.vertex(k)));
        return result;
    }
    const auto& e = s.extreme[n];
    for (int axis = 0; axis < 3; ++axis) {
        result.min()[axis] = vertex_coordinate(s, e[std::size_t(axis)], axis);
        result.max()[axis] = vertex_coordinate(s, e[std::size_t(axis + 3)], axis);
    }
    return result;
}

} // namespace PCCD::internal
