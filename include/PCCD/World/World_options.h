// PCCD/World/World_options.h -- World_options, how a Collision_world answers its queries (narrow
// phase options, threads, broad-phase tree, result cache), and World_counters, what its last query
// did (doc/manual/world.md, "Options and counters").
#pragma once

#include <cstddef>
#include <cstdint>

#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Proximity/Distance_options.h>
#include <PCCD/World/Dynamic_AABB_tree.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// How a Collision_world answers. Checked when the world is built (Invalid_input names the field).
struct World_options {
    /// The narrow phase of intersection queries: the options of do_intersect(). Pair (a, b) is
    /// answered with the seed pair_seed(intersection.seed, pair key), see Collision_world. A visitor
    /// is refused (queries run on several threads).
    Intersection_options intersection;
    /// The narrow phase of within_distance queries: the options of PCCD::within_distance().
    Distance_options distance;
    /// Worker threads of the narrow phase (unset: all available); answers never depend on it.
    internal::Thread_count threads = std::nullopt;
    /// The broad phase: fat margin and rebuild ratio of the Dynamic_AABB_tree.
    Dynamic_AABB_tree_options tree;
    /// Keep the narrow-phase answer of every candidate pair and reuse it while neither instance
    /// moved (set_pose) -- the answer is a function of the two poses, so a reused answer is the
    /// one a new query would give. Costs about 64 bytes per candidate pair. Default true.
    bool cache_results = true;
    /// The hierarchy depth of the instances' world boxes (world_box()'s `depth`, in [0, 32]): deeper
    /// boxes fit rotated objects tighter, so fewer pairs reach the narrow phase, and cost O(2^depth)
    /// per insertion or pose change. Default 6 (64 nodes: on scenes of scanned models 27 % fewer
    /// candidate pairs and cached answers than depth 3, for under 1 us more per pose change; the
    /// narrow phase gains little, as do_intersect rejects the dropped pairs at its first test;
    /// doc/benchmarks.md, "Collision worlds").
    int box_depth = 6;
};

/// What the last intersecting_pairs() / for_each_intersecting_pair() call did.
struct World_counters {
    /// Pairs of fat broad-phase boxes that overlap (the tree's candidates).
    std::size_t broad_phase_pairs = 0;
    /// Of those, pairs dropped by the tight world boxes, the filters or the excluded pairs.
    std::size_t filtered_pairs = 0;
    /// Narrow-phase answers reused from the cache, and narrow-phase queries run.
    std::size_t cached_pairs = 0;
    std::size_t narrow_phase_queries = 0;
    /// Pairs reported (intersecting or undecided).
    std::size_t reported_pairs = 0;
};

} // namespace PCCD
