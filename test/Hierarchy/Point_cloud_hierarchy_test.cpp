// Tests of PCCD/Hierarchy/Point_cloud_hierarchy.h with reaches, against brute force over the points:
// every point in exactly one leaf, every box contains its children and points, a node's reach is
// the largest of its points', every slab holds its node's points and is thin on a plane, the
// ordered points are the points in order(); bad reaches throw; a refit drops the slabs. The box and
// sphere volumes: every sphere holds its node's points (built and refitted), a box tree has no
// slabs. A hierarchy rebuilt from its layout is the build, bit for bit, and a layout that is not a
// median-split tree of the points is refused; the build does not depend on the thread count.
// Also covers Hierarchy/Point_cloud_hierarchy_options.h: the test cases below exercise what it declares.
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy_options.h>

#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

#include "hierarchy_compare.h"
#include "hierarchy_test_helpers.h"

using Catch::Matchers::Contains;
using Index = PCCD::Point_cloud_hierarchy::Index;

TEST_CASE("A hierarchy with reaches: leaves partition the points, boxes and reaches bound their subtrees", "[hierarchy]")
{
    for (const std::size_t n : {1u, 7u, 8u, 9u, 100u, 1000u}) {
        for (const std::size_t leaf : {1u, 8u, 16u}) {
            const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(n, n + leaf, 0.3);
            const Eigen::VectorXd reach = pccd_test::hierarchy_reaches(n, 7 * n + leaf, 0.0, 0.2);
            const PCCD::Point_cloud_hierarchy h(p, reach, {.leaf_size = leaf});
            REQUIRE(h.has_reach());
            std::vector<int> seen(n, 0);
            for (Index i = 0; i < h.nodes().size(); ++i) {
                const auto& node = h.node(i);
                double largest = 0.0;
                for (const Index k : h.points_of(i)) {
                    CHECK(node.box.contains(p.col(k)));
                    largest = std::max(largest, reach(k));
                }
                CHECK(node.reach == largest);
                // The slab holds the node's points (computed alike, so exactly) and its normal is a unit vector.
                REQUIRE(node.slab_normal.norm() == Approx(1.0).epsilon(1e-12));
                for (const Index k : h.points_of(i)) {
                    CHECK(node.slab_normal.dot(p.col(k)) >= node.slab_min);
                    CHECK(node.slab_normal.dot(p.col(k)) <= node.slab_max);
                }
                if (node.is_leaf()) {
                    CHECK(node.count <= std::max<std::size_t>(leaf, 1));
                    for (const Index k : h.points_of(i)) ++seen[k];
                } else {
                    for (const Index c : {h.left(i), h.right(i)}) {
                        CHECK(node.box.contains(h.node(c).box));
                        CHECK(h.node(c).reach <= node.reach);
                    }
                }
            }
            for (const int c : seen) CHECK(c == 1);
            for (std::size_t k = 0; k < n; ++k) {
                CHECK(h.ordered_points().col(Eigen::Index(k)).head<3>() == p.col(h.order()[k]));
                CHECK(h.ordered_points()(3, Eigen::Index(k)) == reach(h.order()[k]));
            }
        }
    }
}

TEST_CASE("A hierarchy's slabs are normal to the points' direction of least spread: thin on a plane", "[hierarchy]")
{
    // Points on the plane n . p = 0.2, n a unit normal not along an axis, so every box is thick.
    const Eigen::Vector3d n = Eigen::Vector3d(1.0, -2.0, 2.0).normalized();
    const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
    const Eigen::Matrix3Xd uv = pccd_test::hierarchy_points(2000, 17, 0.0);
    Eigen::Matrix3Xd p(3, uv.cols());
    for (Eigen::Index i = 0; i < p.cols(); ++i) p.col(i) = 0.2 * n + uv(0, i) * u + uv(1, i) * v;
    const PCCD::Point_cloud_hierarchy h(p, {.leaf_size = 8});
    for (Index i = 0; i < h.nodes().size(); ++i) {
        const auto& node = h.node(i);
        if (node.count < 3) continue;
        INFO("node " << i << " of " << node.count << " points");
        CHECK(std::abs(node.slab_normal.dot(n)) == Approx(1.0).margin(1e-6));
        CHECK(node.slab_max - node.slab_min <= 1e-6 * node.box.diagonal().norm());
        CHECK(std::abs(0.5 * (node.slab_max + node.slab_min)) == Approx(0.2).margin(1e-6));
    }
}

TEST_CASE("A hierarchy without reaches has reach 0 everywhere", "[hierarchy]")
{
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(200, 3);
    const PCCD::Point_cloud_hierarchy h(p);
    CHECK_FALSE(h.has_reach());
    for (const auto& node : h.nodes()) CHECK(node.reach == 0.0);
    CHECK(h.ordered_points().row(3).isZero(0.0));
}

TEST_CASE("A hierarchy rejects bad reaches", "[hierarchy]")
{
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(10, 1);
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p, Eigen::VectorXd::Ones(9)), Contains("9 reaches for 10 points"));
    Eigen::VectorXd reach = Eigen::VectorXd::Ones(10);
    reach(4) = -1.0;
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p, reach), Contains("reach of point 4"));
    reach(4) = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p, reach), Contains("reach of point 4"));
    reach(4) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p, reach), Contains("reach of point 4"));
}

TEST_CASE("A refitted hierarchy keeps the tree and has tight boxes and reaches over the new positions", "[hierarchy]")
{
    for (const std::size_t n : {1u, 9u, 1000u}) {
        const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(n, n + 3, 0.3);
        const Eigen::VectorXd reach = pccd_test::hierarchy_reaches(n, 5 * n, 0.0, 0.2);
        const PCCD::Point_cloud_hierarchy h(p, reach, {.leaf_size = 8});
        // New positions: a shear and a shuffle of the points' offsets (far from the old order).
        Eigen::Matrix3Xd q = p;
        for (Eigen::Index i = 0; i < q.cols(); ++i) q.col(i) += Eigen::Vector3d(0.7 * p(2, i), 0.0, p(0, i) * p(1, i));
        q += pccd_test::hierarchy_points(n, 3 * n + 11, 0.3);
        const Eigen::VectorXd new_reach = pccd_test::hierarchy_reaches(n, 9 * n, 0.1, 0.4);
        const PCCD::Point_cloud_hierarchy r(h, q, new_reach);
        REQUIRE(r.nodes().size() == h.nodes().size());
        REQUIRE(r.order() == h.order());
        CHECK(r.has_reach());
        CHECK(r.leaf_size() == h.leaf_size());
        for (Index i = 0; i < r.nodes().size(); ++i) {
            const auto& node = r.node(i);
            CHECK(node.first == h.node(i).first);
            CHECK(node.count == h.node(i).count);
            CHECK(node.right == h.node(i).right);
            // Brute force: the tight box and the largest reach of the node's points.
            Eigen::AlignedBox3d box;
            double largest = 0.0;
            for (const Index k : r.points_of(i)) {
                box.extend(q.col(k));
                largest = std::max(largest, new_reach(k));
            }
            CHECK(node.box.min() == box.min());
            CHECK(node.box.max() == box.max());
            CHECK(node.reach == largest);
            // The old slabs do not bound the new positions: a refitted node has none.
            CHECK(node.slab_normal.isZero(0.0));
            CHECK(node.slab_min == -std::numeric_limits<double>::infinity());
            CHECK(node.slab_max == std::numeric_limits<double>::infinity());
        }
        for (std::size_t k = 0; k < n; ++k) {
            CHECK(r.ordered_points().col(Eigen::Index(k)).head<3>() == q.col(r.order()[k]));
            CHECK(r.ordered_points()(3, Eigen::Index(k)) == new_reach(r.order()[k]));
        }
        // Without reaches.
        const PCCD::Point_cloud_hierarchy bare(h, q, Eigen::VectorXd());
        CHECK_FALSE(bare.has_reach());
        CHECK(bare.root().reach == 0.0);
    }
}

TEST_CASE("A refit with the wrong number of points, a non-finite point or a bad reach throws", "[hierarchy]")
{
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(50, 3, 0.3);
    const PCCD::Point_cloud_hierarchy h(p);
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(h, Eigen::Matrix3Xd(p.leftCols(49)), Eigen::VectorXd()),
                      Contains("refit with 49 points"));
    Eigen::Matrix3Xd bad = p;
    bad(1, 17) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(h, bad, Eigen::VectorXd()), Contains("point 17 is not finite"));
    Eigen::VectorXd reach = Eigen::VectorXd::Constant(50, 0.1);
    reach(3) = -1.0;
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(h, p, reach), Contains("reach of point 3"));
    CHECK_THROWS_AS(PCCD::Point_cloud_hierarchy(h, p, Eigen::VectorXd::Constant(7, 0.1)), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::Point_cloud_hierarchy(PCCD::Point_cloud_hierarchy(), p, Eigen::VectorXd()), PCCD::Invalid_input);
}

namespace {

using V = PCCD::Bounding_volume;

using pccd_test::require_same_hierarchy;

} // namespace

TEST_CASE("Bounding volumes by name: to_string and back", "[hierarchy]")
{
    for (const V v : {V::box_and_slab, V::box, V::sphere}) CHECK(PCCD::bounding_volume_from_string(PCCD::to_string(v)) == v);
    CHECK(std::string(PCCD::to_string(V::box_and_slab)) == "box_and_slab");
    for (const char* other : {"", "Box", "spheres", "obb", "unknown"}) CHECK_FALSE(PCCD::bounding_volume_from_string(other));
    CHECK(std::string(PCCD::to_string(V(9))) == "unknown");
}

TEST_CASE("Sphere and box volumes: every sphere holds its node's points, a box tree has no slabs", "[hierarchy]")
{
    for (const std::size_t n : {1u, 9u, 1000u}) {
        const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(n, 2 * n + 1, 0.2);
        const Eigen::VectorXd reach = pccd_test::hierarchy_reaches(n, 3 * n, 0.0, 0.1);
        const PCCD::Point_cloud_hierarchy spheres(p, reach, {.volume = V::sphere});
        const PCCD::Point_cloud_hierarchy boxes(p, reach, {.volume = V::box});
        const PCCD::Point_cloud_hierarchy slabs(p, reach);
        CHECK(spheres.volume() == V::sphere);
        CHECK(slabs.volume() == V::box_and_slab);
        REQUIRE(spheres.has_spheres());
        CHECK_FALSE(boxes.has_spheres());
        CHECK_FALSE(slabs.has_spheres());
        // The tree itself does not depend on the volume.
        CHECK(spheres.order() == slabs.order());
        CHECK(boxes.order() == slabs.order());
        REQUIRE(spheres.nodes().size() == slabs.nodes().size());
        // A refit of the sphere tree over moved points: spheres from children, still holding every point.
        Eigen::Matrix3Xd q = p;
        for (Eigen::Index i = 0; i < q.cols(); ++i) q.col(i) += Eigen::Vector3d(0.5 * p(1, i) * p(1, i), 0.0, 0.3 * p(0, i));
        const PCCD::Point_cloud_hierarchy refitted(spheres, q, reach);
        REQUIRE(refitted.has_spheres());
        for (Index i = 0; i < slabs.nodes().size(); ++i) {
            CHECK(spheres.node(i).right == slabs.node(i).right);
            CHECK_FALSE(spheres.node(i).has_slab());
            CHECK_FALSE(boxes.node(i).has_slab());
            CHECK(slabs.node(i).has_slab());
            const auto& sphere = spheres.sphere(i);
            // No larger than the ball about the box centre through the box's corners.
            CHECK(sphere.radius <= 0.5 * slabs.node(i).box.diagonal().norm() * (1 + 1e-12) + 1e-300);
            for (const Index k : spheres.points_of(i)) {
                CHECK((p.col(k) - sphere.centre).norm() <= sphere.radius);
                CHECK((q.col(k) - refitted.sphere(i).centre).norm() <= refitted.sphere(i).radius);
            }
        }
    }
}

TEST_CASE("A hierarchy rebuilt from its layout is the build, bit for bit, for every volume", "[hierarchy]")
{
    for (const V volume : {V::box_and_slab, V::box, V::sphere})
        for (const std::size_t n : {1u, 8u, 9u, 777u}) {
            const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(n, 5 * n + 2, 0.1);
            const Eigen::VectorXd reach = pccd_test::hierarchy_reaches(n, 11 * n, 0.0, 0.1);
            for (const std::size_t leaf : {1u, 8u}) {
                const PCCD::Point_cloud_hierarchy built(p, reach, {.leaf_size = leaf, .volume = volume});
                const PCCD::Point_cloud_hierarchy::Layout layout = built.layout();
                CHECK(layout.leaf_size == leaf);
                CHECK(layout.volume == volume);
                require_same_hierarchy(PCCD::Point_cloud_hierarchy(layout, p, reach), built);
            }
        }
    // Coincident points: one leaf above the leaf size, kept by the layout.
    const Eigen::Matrix3Xd same = Eigen::Matrix3Xd::Constant(3, 20, 0.5);
    const PCCD::Point_cloud_hierarchy one(same, Eigen::VectorXd(), {.leaf_size = 4});
    REQUIRE(one.nodes().size() == 1);
    require_same_hierarchy(PCCD::Point_cloud_hierarchy(one.layout(), same, Eigen::VectorXd()), one);
}

TEST_CASE("A layout that is not a median-split tree of the points is refused", "[hierarchy]")
{
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(100, 9, 0.5);
    const PCCD::Point_cloud_hierarchy h(p, Eigen::VectorXd(), {.leaf_size = 4});
    const PCCD::Point_cloud_hierarchy::Layout good = h.layout();
    REQUIRE(good.rights[0] != 0);
    const auto refused = [&](auto&& edit, const std::string& words) {
        PCCD::Point_cloud_hierarchy::Layout bad = good;
        edit(bad);
        CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(bad, p, Eigen::VectorXd()), Contains(words));
    };
    refused([](auto& l) { l.order[7] = l.order[3]; }, "not a permutation");
    refused([](auto& l) { l.order[7] = 100; }, "not a permutation");
    refused([](auto& l) { l.order.pop_back(); }, "99 indices in the order for 100 points");
    refused([](auto& l) { l.counts[0] = 99; }, "the root holds 99 of 100 points");
    refused([](auto& l) { l.rights.pop_back(); }, "right children");
    refused([](auto& l) { l.counts.clear(), l.rights.clear(); }, "0 node counts");
    refused([](auto& l) { l.rights[0] += 1; }, "is not where its left subtree ends");
    refused([](auto& l) { l.rights[0] = 0xffffffffu; }, "is not where its left subtree ends");
    refused([](auto& l) { l.counts[1] -= 1, l.counts[l.rights[0]] += 1; }, "is not split at its median");
    refused([](auto& l) { l.leaf_size = 1000; }, "is not split at its median");
    refused([](auto& l) { l.volume = PCCD::Bounding_volume(7); }, "unknown bounding volume 7");
    // The root made a leaf of all 100 points (the rest of the nodes dangling; then alone).
    refused([](auto& l) { l.rights[0] = 0; }, "nodes outside the tree");
    refused([](auto& l) { l.rights = {0}, l.counts = {100}; }, "leaf 0 holds 100 points that do not coincide");
    // Points that do not match: another cloud of the same size is fine (a layout is only a shape),
    // another size is not.
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(good, Eigen::Matrix3Xd(p.leftCols(50)), Eigen::VectorXd()),
                      Contains("50 points"));
}

TEST_CASE("The build does not depend on the thread count", "[hierarchy]")
{
    // Enough points for the parallel halves (more than 2^14 per subtree at the top).
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(70000, 21, 0.05);
    const Eigen::VectorXd reach = pccd_test::hierarchy_reaches(70000, 22, 0.0, 0.01);
    for (const V volume : {V::box_and_slab, V::sphere}) {
        const PCCD::Point_cloud_hierarchy one(p, reach, {.volume = volume, .threads = 1u});
        const PCCD::Point_cloud_hierarchy all(p, reach, {.volume = volume});
        require_same_hierarchy(all, one);
    }
    // 500 copies of one point end in a leaf of more than 8 coincident points, which the in-place build
    // does not foresee: it starts again sequentially, with the same tree whatever the thread count.
    Eigen::Matrix3Xd duplicates = p;
    for (Eigen::Index i = 0; i < 500; ++i) duplicates.col(1000 + 7 * i) = p.col(3);
    const PCCD::Point_cloud_hierarchy one(duplicates, reach, {.threads = 1u});
    const PCCD::Point_cloud_hierarchy all(duplicates, reach);
    require_same_hierarchy(all, one);
    std::size_t largest = 0;
    for (const auto& node : all.nodes())
        if (node.is_leaf()) largest = std::max<std::size_t>(largest, node.count);
    CHECK(largest > 8); // a leaf of coincident points, beyond the leaf size
    require_same_hierarchy(PCCD::Point_cloud_hierarchy(all.layout(), duplicates, reach), all);
    CHECK_THROWS_WITH(PCCD::Point_cloud_hierarchy(p, reach, {.threads = 0u}), Contains("threads = 0"));
}
