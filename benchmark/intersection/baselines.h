// benchmark/intersection/baselines.h -- the two baselines of Fig. 10 and 11 as methods of the pose
// runner: FCL on the mesh the cloud was sampled from and the nearest-neighbour threshold test on
// the cloud (benchmark/collision_baselines.h). They are what doc/manual/intersection.md's queries
// are compared with in doc/benchmarks.md.
#pragma once

#include "../collision_baselines.h"
#include "runner.h"

namespace pccd_bench::intersection {

/// "fcl" then "threshold"; both keep references to their baseline, which must outlive them.
inline std::vector<Method> baseline_methods(const PCCD::benchmark::Fcl_mesh_baseline& fcl,
                                            const PCCD::benchmark::Threshold_baseline& threshold)
{
    return {Method{"fcl", false,
                   [&fcl](const PCCD::testing::Benchmark_pose& p, std::uint64_t) { return Answer{fcl.collide(p.pose_a, p.pose_b), 0}; }},
            Method{"threshold", false, [&threshold](const PCCD::testing::Benchmark_pose& p, std::uint64_t) {
                       return Answer{threshold.collide(p.pose_a, p.pose_b), 0};
                   }}};
}

} // namespace pccd_bench::intersection
