// PCCD/Kinetic/Kinetic_statistics.h -- the counters of a Kinetic_AABB_tree (doc/manual/kinetic.md,
// "When to use which": events, BV updates, node updates and certificate computations, the figures
// by which the kinetic tree is compared with a refit), read with Kinetic_AABB_tree::statistics().
#pragma once

#include <cstdint>

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
    /// Failure times taken from the cache of earlier evaluations instead of computing them again
    /// (same pair, bound and still-valid time window; exact, see internal/Crossing_cache.h).
    std::uint64_t certificate_reuses = 0;
    std::uint64_t flightplan_changes = 0;
    std::uint64_t insertions = 0;
    std::uint64_t removals = 0;
};

} // namespace PCCD
