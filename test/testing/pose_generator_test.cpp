// The benchmark poses (PCCD/testing/pose_generator.h): the layout of the configurations,
// determinism, and the uniformity (Haar measure) of the random rotations by chi-square tests with
// fixed seeds.
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sampling_test_helpers.h"

using Eigen::Vector3d;
using namespace sampling_test;

TEST_CASE("poses: layout of the benchmark configurations", "[sampling][poses]")
{
    const auto poses = PCCD::testing::generate_benchmark_poses({.rotations_per_distance = 20, .seed = 7});
    REQUIRE(poses.size() == 13 * 20);
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const auto& p = poses[i];
        CHECK(p.distance == 0.25 * double(i / 20));
        CHECK(p.rotation_index == i % 20);
        CHECK(p.pose_a.translation() == Vector3d::Zero());
        CHECK(p.pose_b.translation() == Vector3d(p.distance, 0, 0));
        for (const auto* pose : {&p.pose_a, &p.pose_b}) {
            const Eigen::Matrix3d& r = pose->rotation();
            CHECK((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-14);
            CHECK(std::abs(r.determinant() - 1.0) < 1e-14);
        }
        CHECK((p.pose_a.rotation() - p.pose_b.rotation()).norm() > 1e-6); // independent rotations
    }
    const auto default_poses = PCCD::testing::generate_benchmark_poses();
    CHECK(default_poses.size() == 13 * 100);
    CHECK(PCCD::testing::default_benchmark_distances().back() == 3.0);
}

TEST_CASE("poses: deterministic for a seed, independent of the distances asked for", "[sampling][poses]")
{
    const auto full = PCCD::testing::generate_benchmark_poses({.rotations_per_distance = 10, .seed = 42});
    const auto again = PCCD::testing::generate_benchmark_poses({.rotations_per_distance = 10, .seed = 42});
    const auto subset = PCCD::testing::generate_benchmark_poses({.distances = {1.5}, .rotations_per_distance = 3, .seed = 42});
    const auto other_seed = PCCD::testing::generate_benchmark_poses({.rotations_per_distance = 10, .seed = 43});
    REQUIRE(full.size() == again.size());
    for (std::size_t i = 0; i < full.size(); ++i) {
        CHECK(full[i].pose_a.matrix() == again[i].pose_a.matrix());
        CHECK(full[i].pose_b.matrix() == again[i].pose_b.matrix());
        CHECK(full[i].pose_a.matrix() != other_seed[i].pose_a.matrix());
    }
    // distance 1.5 is index 6 of the default list.
    for (std::size_t r = 0; r < 3; ++r) {
        CHECK(subset[r].pose_a.matrix() == full[60 + r].pose_a.matrix());
        CHECK(subset[r].pose_b.matrix() == full[60 + r].pose_b.matrix());
        const auto single = PCCD::testing::benchmark_pose(42, 1.5, r);
        CHECK(single.pose_b.matrix() == full[60 + r].pose_b.matrix());
    }
    // Different distances and indices get different rotations.
    CHECK(full[0].pose_a.matrix() != full[1].pose_a.matrix());
    CHECK(full[0].pose_a.matrix() != full[10].pose_a.matrix());
    CHECK(PCCD::testing::benchmark_pose(42, -0.0, 0).pose_a.matrix() == full[0].pose_a.matrix());
}

TEST_CASE("poses: random rotations are uniform (Haar)", "[sampling][poses][statistics]")
{
    PCCD::Random_engine rng(151);
    const int m = 20000;
    Eigen::Matrix3d mean = Eigen::Matrix3d::Zero(), mean_square = Eigen::Matrix3d::Zero();
    const int bins = 18;
    std::vector<double> angles(bins, 0.0), expected(bins);
    for (int i = 0; i < m; ++i) {
        const Eigen::Matrix3d r = PCCD::testing::uniform_random_rotation(rng);
        mean += r / m;
        mean_square += r.cwiseAbs2() / m;
        const double angle = std::acos(std::clamp((r.trace() - 1.0) / 2.0, -1.0, 1.0));
        angles[std::min(bins - 1, int(angle / pi * bins))] += 1;
    }
    // Each entry of a Haar rotation is a coordinate of a uniform unit vector: mean 0, variance 1/3
    // (standard error of the mean sqrt(1/(3m)) = 0.0041); its square has mean 1/3 and standard
    // deviation 0.298 (standard error 0.0021). Tolerance 5 standard errors.
    CAPTURE(mean, mean_square);
    CHECK(mean.cwiseAbs().maxCoeff() < 5 * std::sqrt(1.0 / (3.0 * m)));
    CHECK((mean_square.array() - 1.0 / 3.0).abs().maxCoeff() < 5 * 0.298 / std::sqrt(double(m)));
    // The rotation angle has density (1 - cos a) / pi on [0, pi], CDF (a - sin a) / pi.
    for (int b = 0; b < bins; ++b) {
        const double a0 = pi * b / bins, a1 = pi * (b + 1) / bins;
        expected[b] = m * ((a1 - std::sin(a1)) - (a0 - std::sin(a0))) / pi;
    }
    CHECK(chi_square(angles, expected) < chi_square_critical(bins - 1));
}

TEST_CASE("poses: invalid options are rejected", "[sampling][poses][errors]")
{
    CHECK_THROWS_WITH(PCCD::testing::generate_benchmark_poses({.distances = {}}), Catch::Contains("distance list is empty"));
    CHECK_THROWS_WITH(PCCD::testing::generate_benchmark_poses({.rotations_per_distance = 0}),
                      Catch::Contains("rotations_per_distance"));
    CHECK_THROWS_WITH(PCCD::testing::generate_benchmark_poses({.distances = {0.0, std::numeric_limits<double>::infinity()}}),
                      Catch::Contains("distance 1 is inf"));
    CHECK_THROWS_AS(PCCD::testing::benchmark_pose(1, std::numeric_limits<double>::quiet_NaN(), 0), PCCD::Invalid_input);
}

