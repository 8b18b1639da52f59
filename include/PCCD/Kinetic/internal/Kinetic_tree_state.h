// PCCD/Kinetic/internal/Kinetic_tree_state.h -- the data of a Kinetic_AABB_tree
// (doc/manual/kinetic.md, "Building and advancing"): flightplans, primitive slots, nodes, the
// extreme vertex of every inner node and bound, the event queue of their certificates, the query
// memo pool and the counters. The machinery that keeps it valid works on this struct:
// Kinetic_certificates.h (one certificate), Kinetic_event_loop.h (events in time order),
// Kinetic_tree_edits.h (changes at run time), Kinetic_node_access.h (boxes at now) and
// Kinetic_query_view.h (queries).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Kinetic/Kinetic_statistics.h>
#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/Crossing_cache.h>
#include <PCCD/Kinetic/internal/Primitive_slots.h>
#include <PCCD/Kinetic/internal/Query_memo_pool.h>

namespace PCCD::internal {

/// The data of a kinetic tree over primitives `P` whose vertices move along flightplans `F`, with
/// the event queue `Queue`. Bounds are numbered 0..5: min x, min y, min z, max x, max y, max z
/// (bound b is on axis b % 3); certificate (n, b) has id n * bound_count + b in the queue.
template <class F, class P, class Queue>
struct Kinetic_tree_state {
    using Index = std::uint32_t;
    using Node_index = std::uint32_t;
    static constexpr int bound_count = 6;
    using Extremes = std::array<Index, bound_count>;
    /// The time of a certificate that never fails.
    static constexpr double never = std::numeric_limits<double>::infinity();

    /// `owner` names the tree in the messages of Primitive_slots.
    Kinetic_tree_state(std::vector<F> flightplans_, std::vector<P> primitives_, const char* owner, double t0)
        : flightplans(std::move(flightplans_)), primitives(std::move(primitives_), owner), now(t0)
    {
    }

    static Extremes unset_extremes()
    {
        Extremes e;
        e.fill(no_node);
        return e;
    }
    static typename Queue::Id certificate_id(Node_index n, int b) { return n * bound_count + Index(b); }

    std::vector<F> flightplans;
    Primitive_slots<P> primitives;
    /// Per primitive slot, its leaf (no_node for a free slot).
    std::vector<Node_index> leaf_of;
    /// Per vertex, the primitives using it.
    std::vector<std::vector<Index>> incident;
    std::vector<AABB_node> nodes;
    /// Per node, the vertex attaining each bound (inner nodes only; leaves store nothing).
    std::vector<Extremes> extreme;
    std::vector<Node_index> free_nodes;
    Node_index root = no_node;
    Queue queue;
    /// Per certificate, the candidate that attains its failure time (the next extreme at the event).
    std::vector<Index> overtaker;
    Query_memo_pool memo_pool;
    /// The caller's vertex positions at now (advance_to with positions), or null: then positions
    /// are evaluated from the flightplans (doc/manual/kinetic.md, "Where positions come from").
    const Eigen::Vector3d* frame_positions = nullptr;
    /// Failure times already computed, reused while they are still valid (Crossing_cache.h).
    Crossing_cache crossings;
    /// Per node, the last update round (advance_to call or run-time change) that changed it.
    std::vector<std::uint32_t> updated_in_round;
    std::uint32_t round = 1;
    double now;
    Kinetic_statistics stats;
};

} // namespace PCCD::internal
