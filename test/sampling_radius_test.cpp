// Tests of PCCD/sampling_radius.h: the Monte-Carlo r(P) and r(P') against a dense Monte-Carlo ground
// truth on a uniform sphere sample (where the true surface is known), the subsample rule, the
// surfel count, determinism and option checks.
// Also covers sampling_radius_options.h: the test cases below exercise what it declares.
#include "graph_test_helpers.h"

#include <PCCD/Error.h>
#include <PCCD/sampling_radius.h>
#include <PCCD/sampling_radius_options.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace pccd_test;

namespace {

/// The `quantile` of the distance from `n` area-uniform points of the unit sphere to the nearest
/// point of `centres`.
double sphere_truth(const PCCD::Kd_tree<double>& centres, double quantile, std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine rng(seed);
    std::vector<double> d(n);
    for (double& x : d) x = std::sqrt(centres.nearest(random_unit_vector(rng)).squared_distance);
    std::sort(d.begin(), d.end());
    return d[std::min(n - 1, std::size_t(std::ceil(quantile * double(n))) - 1)];
}

} // namespace

TEST_CASE("r(P) of a uniform sphere sample matches a dense Monte-Carlo ground truth", "[graph][sampling_radius]")
{
    for (std::size_t n : {2000u, 20000u}) {
        const Cloud cloud(sphere_sample(n, 31 + n));
        for (double q : {0.5, 0.9, 0.99}) {
            const double estimate = PCCD::sampling_radius(cloud, {.quantile = q});
            const double truth = sphere_truth(cloud.kd_tree(), q, 200000, 32);
            INFO("n = " << n << ", quantile " << q << ": estimate " << estimate << ", truth " << truth);
            CHECK(std::abs(estimate / truth - 1.0) < 0.2);
        }
    }
}

TEST_CASE("r(P') of a subset and the subsample rule", "[graph][sampling_radius]")
{
    const std::size_t n = 8000, n_sub = 1000;
    const Coordinates points = sphere_sample(n, 33);
    const Cloud cloud(points);
    // The sample is in random order, so its first points are a random subset.
    std::vector<std::uint32_t> subset(n_sub);
    for (std::uint32_t i = 0; i < n_sub; ++i) subset[i] = i;
    const double r_full = PCCD::sampling_radius(cloud);
    const double r_sub = PCCD::sampling_radius(cloud, std::span<const std::uint32_t>(subset));
    const PCCD::Kd_tree<double> sub_tree(points.leftCols(Eigen::Index(n_sub)));
    const double truth = sphere_truth(sub_tree, 0.99, 200000, 34);
    INFO("r(P) " << r_full << ", r(P') " << r_sub << ", truth " << truth);
    CHECK(std::abs(r_sub / truth - 1.0) < 0.2);
    const double rule = PCCD::subsample_sampling_radius(r_full, n, n_sub);
    CHECK(std::abs(rule / truth - 1.0) < 0.2);
    CHECK(rule == Approx(std::sqrt(8.0) * r_full));
}

TEST_CASE("surfel count estimate", "[graph][sampling_radius]")
{
    CHECK(PCCD::estimated_surface_area(100, 0.5) == Approx(25.0 * std::numbers::pi));
    // a = |A| r(A)^2 / r^2.
    CHECK(PCCD::estimated_surfel_count(100, 0.5, 1.0) == Approx(25.0));
    CHECK(PCCD::estimated_surfel_count(100, 0.5, 0.5) == Approx(100.0));
    CHECK_THROWS_AS(PCCD::estimated_surfel_count(100, 0.5, 0.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::subsample_sampling_radius(1.0, 10, 0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::subsample_sampling_radius(1.0, 10, 11), PCCD::Invalid_input);
}

TEST_CASE("r(P) is deterministic and checks its options", "[graph][sampling_radius]")
{
    const Cloud cloud(clustered_with_duplicates(3000, 35));
    const double one = PCCD::sampling_radius(cloud, {.threads = 1});
    CHECK(PCCD::sampling_radius(cloud, {.threads = 2}) == one);
    CHECK(PCCD::sampling_radius(cloud, {.seed = 2}) != one);
    CHECK(PCCD::sampling_radius(cloud, {.quantile = 1.0}) >= one);
    CHECK_THROWS_AS(PCCD::sampling_radius(cloud, {.samples = 0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sampling_radius(cloud, {.quantile = 0.0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sampling_radius(cloud, {.quantile = 1.5}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sampling_radius(cloud, {.neighbors = 1}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sampling_radius(cloud, {.disk_factor = -1}), PCCD::Invalid_input);
    const std::vector<std::uint32_t> bad = {0, 5000};
    CHECK_THROWS_AS(PCCD::sampling_radius(cloud, std::span<const std::uint32_t>(bad)), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sampling_radius(Cloud(Coordinates::Zero(3, 1))), PCCD::Invalid_input);
}
