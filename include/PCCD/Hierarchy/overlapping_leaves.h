// PCCD/Hierarchy/overlapping_leaves.h -- simultaneous traversal of two point cloud hierarchies under
// a relative rigid motion (doc/manual/hierarchy.md; the flat traversal): the pairs of leaves whose boxes, the second one
// grown by a margin, may overlap. Depth-first, always descending the larger node; a pair is pruned
// by the separating-axis test on the six face normals of the two boxes (conservative: a pair the
// test keeps may still be disjoint, a pair it prunes never overlaps).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/node_pair_tests.h>
#include <PCCD/Hierarchy/traversal.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD {

/// What a traversal visited.
struct Traversal_counters {
    /// Node pairs tested.
    std::size_t node_pairs = 0;
    /// Leaf pairs reported.
    std::size_t leaf_pairs = 0;
};

namespace internal {

/// for_each_overlapping_leaf_pair() as traits of the pair walk of traversal.h.
template <class Visitor>
struct Overlapping_leaves_traits {
    const Point_cloud_hierarchy& a;
    const Point_cloud_hierarchy& b;
    const Rigid_transform_3<double>& a_to_b;
    double margin;
    double b_stop_size;
    Visitor& visit;
    /// |R| of the motion, once per walk rather than once per node pair.
    Eigen::Matrix3d abs_r = a_to_b.rotation().cwiseAbs();
    std::size_t leaf_pairs = 0;

    using Index = Point_cloud_hierarchy::Index;
    bool go_further() const { return true; }
    /// boxes_may_overlap() with |R| computed once.
    bool enter(Index i, Index j) const
    {
        const Eigen::AlignedBox3d& box_a = a.node(i).box;
        return grown_boxes_may_overlap(box_a, a_to_b.rotation(), abs_r, a_to_b.transform_point(box_a.center()), 0.0,
                                       b.node(j).box, margin);
    }
    Pair_split split(Index i, Index j) const
    {
        const auto& na = a.node(i);
        const auto& nb = b.node(j);
        const bool b_done = nb.is_leaf() || nb.box.sizes().maxCoeff() <= b_stop_size;
        if (na.is_leaf() && b_done) return Pair_split::leaves;
        // Descend the node with more points (a's on ties), the larger box in practice.
        return !na.is_leaf() && (b_done || na.count >= nb.count) ? Pair_split::first : Pair_split::second;
    }
    void leaf_pair(Index i, Index j)
    {
        ++leaf_pairs;
        visit(i, j);
    }
    bool first_left_first(Index, Index) const { return true; }
    bool second_left_first(Index, Index) const { return true; }
};

} // namespace internal

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
    internal::Overlapping_leaves_traits<std::remove_reference_t<Visitor>> traits{a, b, a_to_b, margin, b_stop_size, visit};
    counters.node_pairs = traverse(a, Point_cloud_hierarchy::Index(0), b, Point_cloud_hierarchy::Index(0), traits).tested;
    counters.leaf_pairs = traits.leaf_pairs;
    return counters;
}

} // namespace PCCD
