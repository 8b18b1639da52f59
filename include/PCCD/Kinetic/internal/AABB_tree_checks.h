// PCCD/Kinetic/internal/AABB_tree_checks.h -- the argument checks shared by Kinetic_AABB_tree and
// Refit_AABB_tree (doc/manual/kinetic.md, "Building and advancing", "Changing the animation at run
// time" and "Queries"): each throws PCCD::Invalid_input with a message that names the tree, the
// member function and the offending value, the same message for both trees.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <PCCD/Error.h>

namespace PCCD::internal {

/// The start time of a tree named `tree` is finite.
inline void check_start_time(const char* tree, double t0)
{
    if (!std::isfinite(t0)) throw Invalid_input(concat(tree, ": start time ", t0, " is not finite"));
}

/// The time passed to `tree`::advance_to is finite.
inline void check_advance_time(const char* tree, double t)
{
    if (!std::isfinite(t)) throw Invalid_input(concat(tree, "::advance_to: time ", t, " is not finite"));
}

/// Primitive `p`, to be stored at index `i`, refers only to vertices below `vertex_count`.
template <class P>
void check_primitive(const char* tree, const P& p, std::uint32_t i, std::size_t vertex_count)
{
    for (std::size_t k = 0; k < P::vertex_count; ++k)
        if (std::uint32_t(p.vertex(k)) >= vertex_count)
            throw Invalid_input(concat(tree, ": primitive ", i, " refers to vertex ", std::uint32_t(p.vertex(k)),
                                       " but there are ", vertex_count, " vertices"));
}

/// The vertex `v` passed to `tree`::set_flightplan is below `vertex_count`.
inline void check_vertex(const char* tree, std::uint32_t v, std::size_t vertex_count)
{
    if (v >= vertex_count)
        throw Invalid_input(
            concat(tree, "::set_flightplan: vertex ", v, " out of range (", vertex_count, " vertices)"));
}

/// The primitive `i` passed to `tree`::remove is live (`live` = the tree's contains(i)).
inline void check_live_primitive(const char* tree, std::uint32_t i, bool live)
{
    if (!live) throw Invalid_input(concat(tree, "::remove: primitive ", i, " is not in the tree"));
}

/// A query between a tree at time `now` and one at `other_now` (the same tree for a self-query)
/// with box margin `margin`: both trees at the same time, margin >= 0 (NaN rejected).
inline void check_query(double now, double other_now, double margin)
{
    if (other_now != now)
        throw Invalid_input(concat("kinetic query: the trees are at different times (", now, " and ", other_now,
                                   "); advance both first"));
    if (!std::isgreaterequal(margin, 0.0))
        throw Invalid_input(concat("kinetic query: margin ", margin, " is negative"));
}

} // namespace PCCD::internal
