// PCCD/Kinetic/boxes_overlap.h -- the box test of the kinetic trees' overlap queries
// (doc/manual/kinetic.md, "Queries": overlapping_pairs, self_overlapping_pairs, range_query),
// exposed for the node test of a custom traversal (`traverse`'s `descend`) and for brute-force
// checks.
#pragma once

#include <Eigen/Geometry>

namespace PCCD {

/// Closed boxes `a` and `b`, `a` grown by `margin` on every side, overlap.
inline bool boxes_overlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double margin)
{
    for (int i = 0; i < 3; ++i)
        if (a.min()[i] - margin > b.max()[i] || b.min()[i] > a.max()[i] + margin) return false;
    return true;
}

} // namespace PCCD
