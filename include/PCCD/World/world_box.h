// PCCD/World/world_box.h -- world_box(), the axis-aligned world box a collision world files a
// posed object under: it holds every point where the object's implicit surface can be defined, so
// two objects whose boxes are disjoint cannot touch (doc/algorithms.md, "Collision worlds").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/CollisionObject.h>

namespace PCCD {

/// The world-frame axis-aligned box holding the domain of `object`'s surface at `pose`: the union,
/// over the hierarchy nodes `depth` levels below the root (or the leaves above them), of the
/// world box of each node's local box grown by its reach (by the surface's support radius when the
/// hierarchy has no reaches). depth 0 is the root's rotated box; deeper levels fit rotated
/// objects tighter (up to 2^depth nodes, each O(1)). Default 3.
/// Guarantee: every world point x with f defined (x within reach of a point) lies in the box.
template <CollisionObject Object>
Eigen::AlignedBox3d world_box(const Object& object, const Rigid_transform_3<double>& pose, int depth = 3)
{
    const Point_cloud_hierarchy& h = object.hierarchy();
    const Eigen::Matrix3d r_abs = pose.rotation().cwiseAbs();
    const double support = double(object.surface().support_radius());
    Eigen::AlignedBox3d box;
    // Depth-first over the nodes down to `depth` (the left child of node i is i + 1); the stack
    // holds at most one pending right child per level.
    std::array<std::pair<std::uint32_t, int>, 66> fixed;
    std::vector<std::pair<std::uint32_t, int>> spill; // levels beyond 64 (depth > 64 and a deep hierarchy)
    std::size_t top = 0;
    const auto push = [&](std::uint32_t i, int level) {
        if (top < fixed.size()) fixed[top] = {i, level};
        else spill.emplace_back(i, level);
        ++top;
    };
    const auto pop = [&] {
        --top;
        if (top < fixed.size()) return fixed[top];
        const auto item = spill.back();
        spill.pop_back();
        return item;
    };
    push(0u, 0);
    while (top > 0) {
        const auto [i, level] = pop();
        const auto& node = h.node(i);
        if (level < depth && !node.is_leaf()) {
            push(std::uint32_t(node.right), level + 1);
            push(i + 1, level + 1);
            continue;
        }
        const double grow = h.has_reach() ? double(node.reach) : support;
        const Eigen::Vector3d half = 0.5 * node.box.sizes() + Eigen::Vector3d::Constant(grow);
        const Eigen::Vector3d centre = pose.transform_point(node.box.center());
        const Eigen::Vector3d extent = r_abs * half;
        box.extend(centre - extent);
        box.extend(centre + extent);
    }
    return box;
}

} // namespace PCCD
