// Point_cloud and Kd_tree against brute force on random, duplicated, planar and collinear inputs,
// in float and double.
// Also covers Kd_tree.h: the test cases below exercise what it declares.
#include <PCCD/Kd_tree.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Random.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

template <class FT>
using Coords = Eigen::Matrix<FT, 3, Eigen::Dynamic>;

// The generators of the four input families, all seeded.
template <class FT>
Coords<FT> make_cloud(const std::string& kind, int n, PCCD::Random_engine& rng)
{
    Coords<FT> c(3, n);
    for (int i = 0; i < n; ++i) {
        const double u = PCCD::uniform_01(rng), v = PCCD::uniform_01(rng), w = PCCD::uniform_01(rng);
        if (kind == "random")
            c.col(i) << FT(u), FT(v), FT(w);
        else if (kind == "planar")
            c.col(i) << FT(u), FT(v), FT(0.25);
        else if (kind == "collinear")
            c.col(i) << FT(u), FT(2 * u), FT(-u);
        else if (kind == "grid") // many exact distance ties
            c.col(i) << FT(i % 7), FT((i / 7) % 7), FT(i / 49);
        else { // "duplicated": a few distinct points, each repeated many times
            const int base = int(PCCD::uniform_index(rng, 12));
            c.col(i) << FT(base % 3), FT(base / 3), FT(0.5);
        }
    }
    return c;
}

template <class FT>
std::vector<PCCD::Neighbor<FT>> brute_force_all(const Coords<FT>& c, const Eigen::Matrix<FT, 3, 1>& q)
{
    std::vector<PCCD::Neighbor<FT>> all;
    for (Eigen::Index i = 0; i < c.cols(); ++i) {
        // Same summation order as the tree's metric (x, then y, then z).
        FT d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (c(k, i) - q[k]) * (c(k, i) - q[k]);
        all.push_back({std::uint32_t(i), d2});
    }
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
        return a.squared_distance < b.squared_distance || (a.squared_distance == b.squared_distance && a.index < b.index);
    });
    return all;
}

template <class FT>
void check_against_brute_force(const std::string& kind)
{
    PCCD::Random_engine rng(1234);
    const int n = 1500;
    const Coords<FT> coords = make_cloud<FT>(kind, n, rng);
    const PCCD::Point_cloud<PCCD::Eigen_kernel<FT>> cloud(coords);
    REQUIRE(cloud.size() == std::size_t(n));
    CHECK(cloud.bbox().min() == coords.rowwise().minCoeff());
    CHECK(cloud.bbox().max() == coords.rowwise().maxCoeff());

    std::vector<PCCD::Neighbor<FT>> got;
    for (int t = 0; t < 200; ++t) {
        // Queries both at cloud points (exact duplicates of data) and at random positions.
        Eigen::Matrix<FT, 3, 1> q = (t % 2 == 0) ? Eigen::Matrix<FT, 3, 1>(coords.col(Eigen::Index(PCCD::uniform_index(rng, n))))
                                                 : make_cloud<FT>("random", 1, rng).col(0);
        const auto all = brute_force_all(coords, q);
        for (std::size_t k : {std::size_t(1), std::size_t(2), std::size_t(8), std::size_t(33)}) {
            cloud.k_nearest(q, k, got);
            REQUIRE(got.size() == k);
            for (std::size_t i = 0; i < k; ++i) REQUIRE(got[i] == all[i]); // order and tie-break too
        }
        const FT radius = FT(0.05 + 0.3 * PCCD::uniform_01(rng));
        cloud.within_radius(q, radius, got);
        std::vector<PCCD::Neighbor<FT>> expected;
        for (const auto& nb : all)
            if (nb.squared_distance <= radius * radius) expected.push_back(nb);
        REQUIRE(got == expected);
        REQUIRE(cloud.nearest(q) == all.front());
    }
}

} // namespace

TEMPLATE_TEST_CASE("kd-tree queries equal brute force", "[point_cloud]", float, double)
{
    for (const char* kind : {"random", "planar", "collinear", "grid", "duplicated"}) {
        INFO("input family: " << kind);
        check_against_brute_force<TestType>(kind);
    }
}

TEMPLATE_TEST_CASE("a kd-tree's memory is its coordinates, its permutation and its nodes", "[point_cloud]", float, double)
{
    // Lower bound: the copy of the coordinates (3 N FT), one 32-bit index per point, and at least
    // N / leaf_size leaves of at least two pointers each (a node holds its children or its range).
    // Upper bound: at most 2 N nodes of at most 64 bytes, and the pool's unused tail (one block).
    PCCD::Random_engine rng(21);
    for (const int n : {1000, 20000}) {
        for (const std::size_t leaf : {std::size_t(1), std::size_t(10), std::size_t(64)}) {
            INFO("N = " << n << ", leaf size " << leaf);
            const PCCD::Kd_tree<TestType> tree(make_cloud<TestType>("random", n, rng), leaf);
            const std::size_t N = std::size_t(n);
            const std::size_t fixed = 3 * N * sizeof(TestType) + 4 * N;
            CHECK(tree.memory_bytes() >= fixed + 2 * sizeof(void*) * (N / leaf));
            CHECK(tree.memory_bytes() <= fixed + 2 * N * 64 + 64 * 1024);
        }
    }
}

TEST_CASE("k larger than the cloud returns every point", "[point_cloud]")
{
    Coords<double> c(3, 3);
    c << 0, 1, 2, 0, 0, 0, 0, 0, 0;
    const PCCD::Point_cloud<> cloud(c);
    const auto got = cloud.k_nearest(Eigen::Vector3d(2.2, 0, 0), 10);
    REQUIRE(got.size() == 3);
    CHECK(got[0].index == 2);
    CHECK(got[2].index == 0);
    CHECK(cloud.within_radius(Eigen::Vector3d(0, 0, 0), 1.0).size() == 2); // the boundary point counts
    CHECK(cloud.k_nearest(Eigen::Vector3d(0, 0, 0), 0).empty());
}

TEST_CASE("mean spacing", "[point_cloud]")
{
    SECTION("regular grid: every nearest neighbour at the grid step")
    {
        std::vector<Eigen::Vector3d> pts;
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j) pts.emplace_back(0.1 * i, 0.1 * j, 0.0);
        CHECK(PCCD::Point_cloud<>(pts).mean_spacing() == Approx(0.1).epsilon(1e-12));
    }
    SECTION("duplicates count at distance zero")
    {
        const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
        CHECK(PCCD::Point_cloud<>(pts).mean_spacing() == 0.0);
    }
    SECTION("uniform random points in the unit square: 0.5 / sqrt(density) up to the border effect")
    {
        PCCD::Random_engine rng(99);
        std::vector<Eigen::Vector3d> pts;
        const int n = 20000;
        for (int i = 0; i < n; ++i) pts.emplace_back(PCCD::uniform_01(rng), PCCD::uniform_01(rng), 0.0);
        // Border correction for the unit square (Donnelly 1978): E[d] ~ 0.5/sqrt(n) + 0.0514/n + 0.041/n^1.5
        const double expected = 0.5 / std::sqrt(n) + 0.0514 / n + 0.041 / std::pow(n, 1.5);
        CHECK(PCCD::Point_cloud<>(pts).mean_spacing() == Approx(expected).epsilon(0.02));
    }
    SECTION("a single point has no spacing")
    {
        const std::vector<Eigen::Vector3d> pts = {{1, 2, 3}};
        CHECK_THROWS_AS(PCCD::Point_cloud<>(pts).mean_spacing(), PCCD::Invalid_input);
    }
}

TEST_CASE("invalid clouds are rejected with a message naming the problem", "[point_cloud]")
{
    const std::vector<Eigen::Vector3d> empty;
    CHECK_THROWS_WITH(PCCD::Point_cloud<>(empty), Catch::Contains("empty"));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<Eigen::Vector3d> with_nan = {{0, 0, 0}, {1, nan, 0}};
    CHECK_THROWS_AS(PCCD::Point_cloud<>(with_nan), PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::Point_cloud<>(with_nan), Catch::Contains("point 1"));
    const std::vector<Eigen::Vector3d> with_inf = {{0, 0, 0}, {1, 0, 0}, {0, 0, -inf}};
    CHECK_THROWS_WITH(PCCD::Point_cloud<>(with_inf), Catch::Contains("point 2"));
    const PCCD::Point_cloud<> one(std::vector<Eigen::Vector3d>{{1, 2, 3}});
    CHECK(one.nearest(Eigen::Vector3d(0, 0, 0)).index == 0);
    CHECK_THROWS_AS(one.within_radius(Eigen::Vector3d(0, 0, 0), -1.0), PCCD::Precondition_failure);
}

TEST_CASE("copies share the data and stay valid after the original is gone", "[point_cloud]")
{
    PCCD::Point_cloud<> copy(std::vector<Eigen::Vector3d>{{0, 0, 0}});
    {
        std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {5, 0, 0}, {9, 0, 0}};
        PCCD::Point_cloud<> original(pts);
        copy = original;
    }
    CHECK(copy.size() == 3);
    CHECK(copy.nearest(Eigen::Vector3d(6, 0, 0)).index == 1);
}

TEST_CASE("a range of points with a kernel object needs no point map", "[point_cloud]")
{
    const std::vector<Eigen::Vector3d> points{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
    const PCCD::Eigen_kernel<double> kernel;
    const PCCD::Point_cloud<> with_kernel(points, kernel);
    const PCCD::Point_cloud<> with_map(points, PCCD::Identity_point_map<Eigen::Vector3d>(), kernel);
    CHECK(with_kernel.coordinates() == with_map.coordinates());
    CHECK(with_kernel.size() == 4);
    CHECK(with_kernel.k_nearest(Eigen::Vector3d(0, 1.9, 0), 1).front().index == 2);
}
