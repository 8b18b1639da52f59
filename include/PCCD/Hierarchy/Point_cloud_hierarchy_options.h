// PCCD/Hierarchy/Point_cloud_hierarchy_options.h -- what a Point_cloud_hierarchy can be told: its
// leaf size, its bounding volume (Bounding_volume) and its build's threads (doc/algorithms.md "Point
// cloud hierarchy", doc/manual/hierarchy.md "Bounding volumes"). Options only: it includes no
// implementation, so the options of a whole object (Point_cloud_object_options.h) stay light.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace PCCD {

/// The bounding volume whose test prunes the node pairs of a hierarchy traversal
/// (doc/manual/hierarchy.md, "Bounding volumes"). Every node keeps its axis-aligned box whatever
/// the volume: the build splits boxes, and the point queries (within_reach(), nearest_point()) and
/// the flat traversal's regions use them; the volume decides what else a node stores and which test
/// a pair of nodes gets.
enum class Bounding_volume : std::uint8_t {
    /// The box and a slab normal to the points' direction of least spread (Node::slab_normal); a
    /// pair is pruned by the boxes' separating axes, then by either slab. Measured fastest
    /// (doc/benchmarks.md "Point cloud hierarchy"). Default.
    box_and_slab = 0,
    /// The axis-aligned box alone (no slab is computed).
    box = 1,
    /// A bounding sphere per node (Point_cloud_hierarchy::sphere(): the centroid of the node's points,
    /// or its box centre when that is nearer them all, and the largest distance of a point from it);
    /// a pair is pruned when the spheres, grown by the margin, are apart. The boxes are not tested
    /// (unless the other hierarchy of the pair is box-based).
    sphere = 2,
};

/// The name of a bounding volume ("box_and_slab", "box", "sphere").
inline const char* to_string(Bounding_volume v)
{
    switch (v) {
    case Bounding_volume::box_and_slab: return "box_and_slab";
    case Bounding_volume::box: return "box";
    case Bounding_volume::sphere: return "sphere";
    }
    return "unknown";
}

/// The bounding volume whose to_string() is `name`; std::nullopt for any other name.
inline std::optional<Bounding_volume> bounding_volume_from_string(std::string_view name)
{
    for (const auto v : {Bounding_volume::box_and_slab, Bounding_volume::box, Bounding_volume::sphere})
        if (name == to_string(v)) return v;
    return std::nullopt;
}

/// Options of Point_cloud_hierarchy.
struct Point_cloud_hierarchy_options {
    /// Largest number of points in a leaf (>= 1). Default 8: leaves about two sampling radii wide, so
    /// that the leaf pairs of two touching objects hug their contact region; measured faster than 16
    /// and 32 for first-hit queries (doc/benchmarks.md "Point cloud hierarchy").
    std::size_t leaf_size = 8;
    /// The bounding volume of the node-pair tests. Default: box and slab.
    Bounding_volume volume = Bounding_volume::box_and_slab;
    /// Worker threads of the build, >= 1 (at most 4096). Unset (default): all available. The tree
    /// does not depend on it.
    std::optional<unsigned> threads = std::nullopt;
};

} // namespace PCCD
