// PCCD/Hierarchy/Reach_rule.h -- how a query scales the reaches stored in a point cloud hierarchy
// (Reach_rule) and what a reach traversal visited (Reach_counters) (doc/algorithms.md "Point cloud
// hierarchy", doc/manual/hierarchy.md "Reaches"). Shared by the point queries (point_queries.h)
// and the traversal of two objects (reach_traversal.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>

namespace PCCD {

/// How a query scales the reaches stored in a hierarchy: a point's reach is min(scale * stored, cap).
/// Monotone in the stored reach, so a node's largest reach maps to the largest of its points.
struct Reach_rule {
    /// Factor on the stored reach, > 0 (1: the surface's domain; the contact core of a verified
    /// contact, Intersection_options::contact_core, for where a contact can lie).
    double scale = 1.0;
    /// Upper bound on any reach (e.g. the kernel's support radius: f needs a point that close), > 0.
    double cap = std::numeric_limits<double>::infinity();

    double operator()(double stored) const { return std::min(scale * stored, cap); }
};

/// What a reach traversal visited.
struct Reach_counters {
    /// Node pairs tested.
    std::size_t node_pairs = 0;
    /// Leaf pairs whose points were compared.
    std::size_t leaf_pairs = 0;
    /// Node pairs still waiting when the visitor stopped the traversal (their subtrees were not
    /// visited); 0 when the traversal ran to its end.
    std::size_t pending = 0;
};

} // namespace PCCD
