// Tests of PCCD/Intersection/internal/reach_region.h: the region sampler of intersection_points()
// under the walked traversals draws every point of s within the reach of t exactly once, and no
// other point (brute force over all point pairs), whether it enumerates at once (a small region) or
// starts by rejection (a deep overlap).
#include <PCCD/Intersection/internal/reach_region.h>

#include <catch2/catch.hpp>

#include <set>
#include <vector>

#include "../Hierarchy/hierarchy_test_helpers.h"
#include "build_helpers.h"

TEST_CASE("The reach region sampler draws exactly the points within reach, each once", "[hierarchy]")
{
    const Eigen::Matrix3Xd ps = pccd_test::hierarchy_points(3000, 41), pt = pccd_test::hierarchy_points(2000, 42, 0.1);
    const Eigen::VectorXd rs = pccd_test::hierarchy_reaches(3000, 43, 0.02, 0.05);
    const Eigen::VectorXd rt = pccd_test::hierarchy_reaches(2000, 44, 0.02, 0.05);
    const PCCD::Point_cloud_hierarchy s(ps, rs), t(pt, rt);
    const PCCD::Reach_rule rule{.scale = 1.0, .cap = 0.04};
    std::size_t enumerated_at_once = 0, by_rejection = 0;
    // Debug builds: every third pose (the brute-force truth is slow there).
    for (std::uint64_t seed = 0; seed < 12; seed += pccd_test::by_build(1, 3)) {
        // From deep overlap (rejection first) to a small overlap (enumerated at once).
        const PCCD::Rigid_transform_3<double> s_to_t = pccd_test::hierarchy_pose(seed, 0.3 * double(seed));
        std::set<std::uint32_t> truth;
        for (Eigen::Index a = 0; a < ps.cols(); ++a) {
            const Eigen::Vector3d q = s_to_t.transform_point(Eigen::Vector3d(ps.col(a)));
            for (Eigen::Index b = 0; b < pt.cols(); ++b)
                if ((pt.col(b) - q).norm() <= rule(rt(b))) {
                    truth.insert(std::uint32_t(a));
                    break;
                }
        }
        PCCD::Intersection_counters counters;
        PCCD::internal::Reach_region_sampler sampler(s, t, s_to_t, rule, counters);
        (sampler.region_size_known() ? enumerated_at_once : by_rejection) += 1;
        PCCD::Random_engine engine(seed);
        std::vector<std::uint32_t> drawn;
        std::uint32_t p = 0;
        while (sampler.next(engine, p)) drawn.push_back(p);
        INFO("seed " << seed << ": " << truth.size() << " points within reach");
        CHECK(drawn.size() == truth.size());
        CHECK(std::set<std::uint32_t>(drawn.begin(), drawn.end()) == truth);
        CHECK(sampler.region_size_known());
        CHECK(sampler.region_size() == double(truth.size()));
    }
    CHECK(enumerated_at_once > 0);
    CHECK(by_rejection > 0);
}
