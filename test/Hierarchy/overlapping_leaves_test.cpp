// Tests of PCCD/Hierarchy/overlapping_leaves.h against brute force over the leaves and points:
// boxes_may_overlap() never separates boxes that share a point, for_each_overlapping_leaf_pair()
// reports every leaf pair holding a point of a within the grown box of b's leaf (each pair once,
// every reported pair passing the box test), stops b's descent at b_stop_size with nodes that cover
// the same leaves, and refuses a bad margin.
#include <PCCD/Hierarchy/overlapping_leaves.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "hierarchy_test_helpers.h"

using Index = PCCD::Point_cloud_hierarchy::Index;

namespace {

/// Whether the point q lies in the box grown by `margin` on every side.
bool in_grown_box(const Eigen::AlignedBox3d& box, double margin, const Eigen::Vector3d& q)
{
    return (q.array() >= box.min().array() - margin).all() && (q.array() <= box.max().array() + margin).all();
}

} // namespace

TEST_CASE("boxes_may_overlap never separates boxes that share a point", "[hierarchy]")
{
    PCCD::Random_engine engine(3);
    int shared = 0;
    for (int k = 0; k < 2000; ++k) {
        const Eigen::Vector3d a_min(PCCD::uniform_real(engine, -1, 0), PCCD::uniform_real(engine, -1, 0), PCCD::uniform_real(engine, -1, 0));
        const Eigen::AlignedBox3d a(a_min, a_min + Eigen::Vector3d::Constant(PCCD::uniform_real(engine, 0.01, 0.6)));
        const Eigen::Vector3d b_min(PCCD::uniform_real(engine, -1, 0), PCCD::uniform_real(engine, -1, 0), PCCD::uniform_real(engine, -1, 0));
        const Eigen::AlignedBox3d b(b_min, b_min + Eigen::Vector3d(0.3, 0.05, 0.4));
        const PCCD::Rigid_transform_3<double> a_to_b = pccd_test::hierarchy_pose(std::uint64_t(k), 0.5);
        const double margin = PCCD::uniform_real(engine, 0.0, 0.1);
        // A point of a (sampled on a grid of its box) inside grown b proves the boxes meet.
        bool meet = false;
        for (int x = 0; x <= 4 && !meet; ++x)
            for (int y = 0; y <= 4 && !meet; ++y)
                for (int z = 0; z <= 4 && !meet; ++z) {
                    const Eigen::Vector3d p = a.min() + (a.max() - a.min()).cwiseProduct(Eigen::Vector3d(x, y, z) / 4.0);
                    meet = in_grown_box(b, margin, a_to_b.transform_point(p));
                }
        if (meet) {
            ++shared;
            CHECK(PCCD::boxes_may_overlap(a, a_to_b, b, margin));
        }
    }
    CHECK(shared > 100);
}

TEST_CASE("for_each_overlapping_leaf_pair reports every leaf pair whose points meet the grown box", "[hierarchy]")
{
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const Eigen::Matrix3Xd pa = pccd_test::hierarchy_points(600, seed, seed % 2 == 0 ? 0.05 : 1.0);
        const Eigen::Matrix3Xd pb = pccd_test::hierarchy_points(400, seed + 50, 0.3);
        const PCCD::Point_cloud_hierarchy a(pa, Eigen::VectorXd(), {.leaf_size = 8});
        const PCCD::Point_cloud_hierarchy b(pb, Eigen::VectorXd(), {.leaf_size = 8});
        const PCCD::Rigid_transform_3<double> a_to_b = pccd_test::hierarchy_pose(seed + 9, 0.3 * double(seed));
        const double margin = 0.02 * double(seed);
        std::map<std::pair<Index, Index>, int> reported;
        const auto counters = PCCD::for_each_overlapping_leaf_pair(a, b, a_to_b, margin, [&](Index i, Index j) {
            ++reported[{i, j}];
        });
        CHECK(counters.leaf_pairs == reported.size());
        for (const auto& [pair, times] : reported) {
            CHECK(times == 1);
            CHECK(a.node(pair.first).is_leaf());
            CHECK(b.node(pair.second).is_leaf());
            CHECK(PCCD::boxes_may_overlap(a.node(pair.first).box, a_to_b, b.node(pair.second).box, margin));
        }
        std::size_t meeting = 0;
        for (Index i = 0; i < a.nodes().size(); ++i) {
            if (!a.node(i).is_leaf()) continue;
            for (Index j = 0; j < b.nodes().size(); ++j) {
                if (!b.node(j).is_leaf()) continue;
                bool meet = false;
                for (const Index k : a.points_of(i))
                    meet = meet || in_grown_box(b.node(j).box, margin, a_to_b.transform_point(Eigen::Vector3d(pa.col(k))));
                if (!meet) continue;
                ++meeting;
                CHECK(reported.count({i, j}) == 1);
            }
        }
        INFO("seed " << seed << ": " << meeting << " leaf pairs meet, " << reported.size() << " reported");
        if (seed <= 3) CHECK(meeting > 0);

        // With b's descent stopped at a box size, the reported nodes of b cover the same leaves.
        const double stop = 0.4;
        std::set<std::pair<Index, Index>> covered;
        PCCD::for_each_overlapping_leaf_pair(
            a, b, a_to_b, margin,
            [&](Index i, Index j) {
                const auto& nb = b.node(j);
                CHECK((nb.is_leaf() || nb.box.sizes().maxCoeff() <= stop));
                for (Index l = j; l < b.nodes().size() && b.node(l).first < nb.first + nb.count; ++l)
                    if (b.node(l).is_leaf() && b.node(l).first >= nb.first) covered.emplace(i, l);
            },
            stop);
        for (const auto& [pair, times] : reported) CHECK(covered.count(pair) == 1);
    }
}

TEST_CASE("for_each_overlapping_leaf_pair refuses a bad margin and visits nothing for an empty hierarchy", "[hierarchy]")
{
    const Eigen::Matrix3Xd p = pccd_test::hierarchy_points(50, 4, 0.3);
    const PCCD::Point_cloud_hierarchy h(p);
    const auto none = [](Index, Index) {};
    const PCCD::Rigid_transform_3<double> identity;
    CHECK_THROWS_AS(PCCD::for_each_overlapping_leaf_pair(h, h, identity, -1.0, none), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::for_each_overlapping_leaf_pair(h, h, identity, std::nan(""), none), PCCD::Invalid_input);
    const auto counters = PCCD::for_each_overlapping_leaf_pair(PCCD::Point_cloud_hierarchy(), h, identity, 0.1, none);
    CHECK(counters.node_pairs == 0);
    CHECK(counters.leaf_pairs == 0);
}
