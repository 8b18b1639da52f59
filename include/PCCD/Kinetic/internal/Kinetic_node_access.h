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
    double best_value = s.flightplans[best].coordinate(axis, s.now);
    for (std::size_t k = 1; k < P::vertex_count; ++k) {
        const double value = s.flightplans[p.vertex(k)].coordinate(axis, s.now);
        if (b < 3 ? value < best_value : value > best_value) {
            best = p.vertex(k);
            best_value = value;
        }
    }
    return best;
}

/// The box of node n at now: an inner node's is read off its six extreme vertices, a leaf's is the
/// box of its primitive's vertices. O(1) flightplan evaluations.
template <class F, class P, class Queue>
Eigen::AlignedBox3d node_box(const Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n)
{
    Eigen::AlignedBox3d result;
    if (s.nodes[n].is_leaf()) {
        const P& p = s.primitives[s.nodes[n].primitive];
        result.setEmpty();
        for (std::size_t k = 0; k < P::vertex_count; ++k) result.extend(s.flightplans[p.vertex(k)].position(s.now));
        return result;
    }
    const auto& e = s.extreme[n];
    for (int axis = 0; axis < 3; ++axis) {
        result.min()[axis] = s.flightplans[e[std::size_t(axis)]].coordinate(axis, s.now);
        result.max()[axis] = s.flightplans[e[std::size_t(axis + 3)]].coordinate(axis, s.now);
    }
    return result;
}

} // namespace PCCD::internal
