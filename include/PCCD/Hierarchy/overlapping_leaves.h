// PCCD/Hierarchy/overlapping_leaves.h -- simultaneous traversal of two point cloud hierarchies under
// a relative rigid motion (doc/manual/hierarchy.md; the flat traversal): the pairs of leaves whose boxes, the second one
// grown by a margin, may overlap. Depth-first, always descending the larger node; a pair is pruned
// by the separating-axis test on the six face normals of the two boxes (conservative: a pair the
// test keeps may still be disjoint, a pair it prunes never overlaps).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// Whether the box `a` (in the frame of a's hierarchy, mapped by `a_to_b` into b's frame) and the
/// axis-aligned box `b` grown by `margin` on every side may overlap: false only when one of the six
/// face normals separates them. O(1). Pure function: safe to call concurrently.
inline bool boxes_may_overlap(const Eigen::AlignedBox3d& a, const Rigid_transform_3<double>& a_to_b,
                              const Eigen::AlignedBox3d& b, double margin)
{
    const Eigen::Matrix3d& r = a_to_b.rotation();
    const Eigen::Vector3d ha = 0.5 * (a.max() - a.min());
    const Eigen::Vector3d hb = 0.5 * (b.max() - b.min()) + Eigen::Vector3d::Constant(margin);
    const Eigen::Vector3d t = a_to_b.transform_point(0.5 * (a.min() + a.max())) - 0.5 * (b.min() + b.max());
    const Eigen::Matrix3d abs_r = r.cwiseAbs();
    // b's axes.
    for (int i = 0; i < 3; ++i)
        if (std::abs(t(i)) > hb(i) + abs_r.row(i).dot(ha)) return false;
    // a's axes.
    for (int j = 0; j < 3; ++j)
        if (std::abs(t.dot(r.col(j))) > ha(j) + abs_r.col(j).dot(hb)) return false;
    return true;
}

/// What a traversal visited.
struct Traversal_counters {
    /// Node pairs tested.
    std::size_t node_pairs = 0;
    /// Leaf pairs reported.
    std::size_t leaf_pairs = 0;
};

/// Calls `visit(leaf_a, node_b)` (node indices) for every pair of a leaf of `a` and a node of `b`
/// whose boxes may overlap once a's box is mapped by `a_to_b` (local frame of a to local frame of b)
/// and b's box is grown by `margin` (>= 0). `node_b` is a leaf of b, or an inner node whose largest
/// side is at most `b_stop_size` (b's descent stops there: below the margin's scale, smaller boxes
/// hardly prune more but multiply the pairs; 0, the default, descends to b's leaves). Pairs come in
/// depth-first order; the order is deterministic.
/// Complexity: O(number of node pairs visited); each node pair is visited at most once, so at most
/// |nodes a| |nodes b| (also for degenerate boxes: flat, collinear or coincident points;
/// test_bounded_work); O(height) extra space.
/// Thread safety: reads the two hierarchies only; any number of traversals may run concurrently
/// (`visit` is called on the calling thread).
template <class Visitor>
Traversal_counters for_each_overlapping_leaf_pair(const Point_cloud_hierarchy& a, const Point_cloud_hierarchy& b,
                                                  const Rigid_transform_3<double>& a_to_b, double margin,
                                                  Visitor&& visit, double b_stop_size = 0.0)
{
    Traversal_counters counters;
    if (a.empty() || b.empty()) return counters;
    if (!(std::isfinite(margin) && margin >= 0.0)) // isfinite first: no ordered comparison with NaN (FP traps)
        throw Invalid_input(internal::concat("overlapping leaves: margin ", margin, " must be finite and >= 0"));
    using Index = Point_cloud_hierarchy::Index;
    std::vector<std::pair<Index, Index>> stack;
    stack.emplace_back(0, 0);
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        ++counters.node_pairs;
        const auto& na = a.node(i);
        const auto& nb = b.node(j);
        if (!boxes_may_overlap(na.box, a_to_b, nb.box, margin)) continue;
        const bool b_done = nb.is_leaf() || nb.box.sizes().maxCoeff() <= b_stop_size;
        if (na.is_leaf() && b_done) {
            ++counters.leaf_pairs;
            visit(i, j);
            continue;
        }
        // Descend the node with more points (a's on ties), the larger box in practice.
        const bool descend_a = !na.is_leaf() && (b_done || na.count >= nb.count);
        if (descend_a) {
            stack.emplace_back(a.right(i), j);
            stack.emplace_back(a.left(i), j);
        } else {
            stack.emplace_back(i, b.right(j));
            stack.emplace_back(i, b.left(j));
        }
    }
    return counters;
}

} // namespace PCCD
