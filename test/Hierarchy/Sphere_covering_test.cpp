// Tests of PCCD/Hierarchy/Sphere_covering.h against brute force over each node's points: the balls
// of radius(i) around the centres cover every point of node i, the radius is the largest
// point-to-nearest-centre distance, the centres are distinct points of the node, and small nodes
// keep all their points.
#include <PCCD/Hierarchy/Sphere_covering.h>

#include <catch2/catch.hpp>

#include <set>

#include "hierarchy_test_helpers.h"

using Catch::Matchers::Contains;
using Index = PCCD::Point_cloud_hierarchy::Index;

TEST_CASE("Sphere coverings cover every point of their node within their radius", "[hierarchy]")
{
    for (const std::size_t subsample : {1u, 4u, 8u}) {
        for (const double flat : {1.0, 0.01}) {
            const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(1500, 9 + subsample, flat);
            const PCCD::Point_cloud_hierarchy h(p, {.leaf_size = 8});
            const PCCD::Sphere_covering covering(h, subsample);
            REQUIRE(covering.size() == h.nodes().size());
            const Eigen::Matrix4Xd& q = h.ordered_points();
            for (Index i = 0; i < h.nodes().size(); ++i) {
                const auto& node = h.node(i);
                const auto centres = covering.centres(i);
                REQUIRE(!centres.empty());
                CHECK(centres.size() <= subsample);
                CHECK(std::set<Index>(centres.begin(), centres.end()).size() == centres.size());
                double largest = 0.0;
                for (Index k = node.first; k < node.first + node.count; ++k) {
                    double nearest = std::numeric_limits<double>::infinity();
                    for (const Index c : centres) nearest = std::min(nearest, (q.col(k).head<3>() - q.col(c).head<3>()).norm());
                    largest = std::max(largest, nearest);
                }
                for (const Index c : centres) CHECK((c >= node.first && c < node.first + node.count));
                CHECK(covering.radius(i) == Approx(largest).margin(1e-12));
                if (node.count <= subsample) CHECK(covering.radius(i) == 0.0);
                // Farthest-point sampling: with K centres the radius is at most the box's diagonal.
                CHECK(covering.radius(i) <= node.box.diagonal().norm() + 1e-12);
            }
        }
    }
}

TEST_CASE("More centres never cover worse at the root", "[hierarchy]")
{
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(4000, 77, 0.2);
    const PCCD::Point_cloud_hierarchy h(p);
    double previous = std::numeric_limits<double>::infinity();
    for (const std::size_t k : {1u, 2u, 4u, 8u, 16u, 32u}) {
        const double r = PCCD::Sphere_covering(h, k).radius(0);
        CHECK(r <= previous);
        previous = r;
    }
}

TEST_CASE("Sphere covering rejects a bad subsample size", "[hierarchy]")
{
    const PCCD::Point_cloud_hierarchy h(pccd_test::hierarchy_points(20, 1));
    CHECK_THROWS_WITH(PCCD::Sphere_covering(h, 0), Contains("subsample"));
    CHECK_THROWS_WITH(PCCD::Sphere_covering(h, 256), Contains("subsample"));
}
