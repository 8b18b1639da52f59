// PCCD/Kinetic/internal/Kinetic_certificates.h -- one certificate of the kinetic AABB tree
// (doc/manual/kinetic.md, "Building and advancing"): the candidates of a node's bound (the extreme
// of an inner child, every vertex of a leaf child's primitive), the choice of the extreme among
// them, the failure time of "this vertex stays the extreme" and its place in the event queue; and
// the counters of the changes (bv_updates, node_updates per update round).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/internal/Kinetic_tree_state.h>

namespace PCCD::internal {

/// Failure time after now of "x stays the extreme of bound b against y".
template <class F, class P, class Queue>
double certificate_failure(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t x, std::uint32_t y, int b)
{
    if (x == y) return s.never;
    double result;
    if (s.crossings.find(x, y, b, s.now, result)) {
        ++s.stats.certificate_reuses;
        return result;
    }
    ++s.stats.certificate_computations;
    const int axis = b % 3;
    result = b >= 3 ? s.flightplans[x].next_crossing(s.flightplans[y], axis, s.now)
                    : s.flightplans[y].next_crossing(s.flightplans[x], axis, s.now);
    s.crossings.store(x, y, b, s.now, result);
    return result;
}

/// Whether vertex v is a candidate for bound b of a node whose child is `child`: v is the
/// child's extreme (inner child) or one of its primitive's vertices (leaf child).
template <class F, class P, class Queue>
bool is_candidate(const Kinetic_tree_state<F, P, Queue>& s, std::uint32_t v, std::uint32_t child, int b)
{
    if (!s.nodes[child].is_leaf()) return s.extreme[child][std::size_t(b)] == v;
    const P& p = s.primitives[s.nodes[child].primitive];
    for (std::size_t k = 0; k < P::vertex_count; ++k)
        if (std::uint32_t(p.vertex(k)) == v) return true;
    return false;
}

/// Chooses the extreme of inner node n for bound b among its candidates (each child's extreme,
/// or all vertices of a leaf child's primitive) as the one that holds just after now (keeping
/// the current extreme when it still holds, so ties never cause swaps), and schedules its
/// certificate. At an event, `overtaker` is the candidate whose crossing made the certificate
/// fail; trying it first as the new extreme saves the certificate computations against the
/// extreme it overtook. Returns whether the extreme changed.
template <class F, class P, class Queue>
bool update_bound(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n, int b, std::uint32_t overtaker = no_node)
{
    using Index = std::uint32_t;
    constexpr std::size_t capacity = 2 * P::vertex_count;
    std::array<Index, capacity> candidates;
    std::size_t count = 0;
    const AABB_node& node = s.nodes[n];
    PCCD_debug_precondition(!node.is_leaf());
    for (const std::uint32_t child : {node.left, node.right}) {
        const auto add = [&](Index v) {
            for (std::size_t k = 0; k < count; ++k)
                if (candidates[k] == v) return;
            candidates[count++] = v;
        };
        if (!s.nodes[child].is_leaf()) {
            add(s.extreme[child][std::size_t(b)]);
        } else {
            const P& p = s.primitives[s.nodes[child].primitive];
            for (std::size_t k = 0; k < P::vertex_count; ++k) add(p.vertex(k));
        }
    }
    const Index current = s.extreme[n][std::size_t(b)];
    Index champion = candidates[0];
    for (std::size_t k = 0; k < count; ++k)
        if (candidates[k] == current) champion = current;
    for (std::size_t k = 0; k < count; ++k)
        if (candidates[k] == overtaker) champion = overtaker;

    std::array<double, capacity> fails;
    std::array<bool, capacity> known{};
    for (std::size_t k = 0; k < count; ++k) {
        if (candidates[k] == champion) continue;
        const double f = certificate_failure(s, champion, candidates[k], b);
        if (f > s.now) {
            fails[k] = f;
            known[k] = true;
        } else {
            champion = candidates[k];
            known.fill(false);
        }
    }
    double certificate = s.never;
    Index witness = no_node;
    for (std::size_t k = 0; k < count; ++k) {
        if (candidates[k] == champion) continue;
        const double f = known[k] ? fails[k] : certificate_failure(s, champion, candidates[k], b);
        if (f < certificate) {
            certificate = f;
            witness = candidates[k];
        }
    }
    s.overtaker[s.certificate_id(n, b)] = witness;
    // Two candidates cannot both fail immediately (Piecewise_cubic.h explains why); with three,
    // rounding could make "holds just after now" intransitive. Deferring by one ulp keeps time
    // strictly increasing, so event processing always terminates.
    if (certificate <= s.now) certificate = std::nextafter(s.now, s.never);
    s.queue.set(s.certificate_id(n, b), certificate);
    const bool changed = champion != current;
    s.extreme[n][std::size_t(b)] = champion;
    return changed;
}

/// Counts a change of one bound's extreme at node n (and n itself once per update round).
template <class F, class P, class Queue>
void count_update(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n)
{
    ++s.stats.bv_updates;
    if (s.updated_in_round[n] != s.round) {
        s.updated_in_round[n] = s.round;
        ++s.stats.node_updates;
    }
}

/// Starts an update round (one advance_to call or run-time change), for node_updates.
template <class F, class P, class Queue>
void next_update_round(Kinetic_tree_state<F, P, Queue>& s)
{
    if (++s.round == 0) { // after 2^32 rounds: restart the stamps
        std::fill(s.updated_in_round.begin(), s.updated_in_round.end(), 0);
        s.round = 1;
    }
}

} // namespace PCCD::internal
