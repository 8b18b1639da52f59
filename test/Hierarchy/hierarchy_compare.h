// test/Hierarchy/hierarchy_compare.h -- require_same_hierarchy(): two point cloud hierarchies equal
// bit for bit (tree, order, ordered points, boxes, reaches, slabs, spheres), for the tests of the
// hierarchy's layout, thread count and the object file.
#pragma once

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>

#include <catch2/catch.hpp>

#include <cstring>

namespace pccd_test {

inline void require_same_hierarchy(const PCCD::Point_cloud_hierarchy& a, const PCCD::Point_cloud_hierarchy& b)
{
    using Index = PCCD::Point_cloud_hierarchy::Index;
    REQUIRE(a.nodes().size() == b.nodes().size());
    REQUIRE(a.order() == b.order());
    REQUIRE(a.volume() == b.volume());
    REQUIRE(a.leaf_size() == b.leaf_size());
    CHECK(a.has_reach() == b.has_reach());
    CHECK(a.ordered_points() == b.ordered_points());
    REQUIRE(a.has_spheres() == b.has_spheres());
    for (Index i = 0; i < a.nodes().size(); ++i) {
        const auto &x = a.node(i), &y = b.node(i);
        CHECK(x.box.min() == y.box.min());
        CHECK(x.box.max() == y.box.max());
        CHECK(x.first == y.first);
        CHECK(x.count == y.count);
        CHECK(x.right == y.right);
        CHECK(x.reach == y.reach);
        CHECK(x.slab_normal == y.slab_normal);
        // Bitwise: a node without a slab has infinite bounds, equal as values too, but NaN would not be.
        CHECK(std::memcmp(&x.slab_min, &y.slab_min, sizeof(double)) == 0);
        CHECK(std::memcmp(&x.slab_max, &y.slab_max, sizeof(double)) == 0);
        if (a.has_spheres()) {
            CHECK(a.sphere(i).centre == b.sphere(i).centre);
            CHECK(a.sphere(i).radius == b.sphere(i).radius);
        }
    }
}

} // namespace pccd_test
