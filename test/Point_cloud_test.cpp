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
#include <numeric>
#include <optional>
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

// Queries of `cloud` (k nearest, radius, nearest) against brute force over `coords`, `queries`
// times, at points of the cloud and at random positions.
template <class FT>
void check_queries(const PCCD::Point_cloud<PCCD::Eigen_kernel<FT>>& cloud, const Coords<FT>& coords,
                   PCCD::Random_engine& rng, int queries = 200)
{
    const Eigen::Index n = coords.cols();
    REQUIRE(cloud.size() == std::size_t(n));
    REQUIRE(cloud.coordinates() == coords);
    CHECK(cloud.bbox().min() == coords.rowwise().minCoeff());
    CHECK(cloud.bbox().max() == coords.rowwise().maxCoeff());
    std::vector<PCCD::Neighbor<FT>> got;
    for (int t = 0; t < queries; ++t) {
        // Queries both at cloud points (exact duplicates of data) and at random positions.
        Eigen::Matrix<FT, 3, 1> q = (t % 2 == 0) ? Eigen::Matrix<FT, 3, 1>(coords.col(Eigen::Index(PCCD::uniform_index(rng, n))))
                                                 : make_cloud<FT>("random", 1, rng).col(0);
        const auto all = brute_force_all(coords, q);
        for (std::size_t k : {std::size_t(1), std::size_t(2), std::size_t(8), std::size_t(33)}) {
            cloud.k_nearest(q, k, got);
            k = std::min(k, std::size_t(n));
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

template <class FT>
void check_against_brute_force(const std::string& kind)
{
    PCCD::Random_engine rng(1234);
    const Coords<FT> coords = make_cloud<FT>(kind, 1500, rng);
    check_queries<FT>(PCCD::Point_cloud<PCCD::Eigen_kernel<FT>>(coords), coords, rng);
}

// The columns of `c` but those in `removed` (sorted).
template <class FT>
Coords<FT> without_columns(const Coords<FT>& c, const std::vector<std::uint32_t>& removed)
{
    Coords<FT> kept(3, c.cols() - Eigen::Index(removed.size()));
    Eigen::Index next = 0;
    for (Eigen::Index i = 0; i < c.cols(); ++i)
        if (!std::binary_search(removed.begin(), removed.end(), std::uint32_t(i))) kept.col(next++) = c.col(i);
    return kept;
}

} // namespace

TEMPLATE_TEST_CASE("a cloud without some of its points answers as brute force on the points left", "[point_cloud]",
                   float, double)
{
    // The kd-tree kept with the removed points dropped from its leaves (the cloud alone holds its
    // points) and the tree built afresh (a copy is alive) must both answer exactly.
    using Cloud = PCCD::Point_cloud<PCCD::Eigen_kernel<TestType>>;
    PCCD::Random_engine rng(4321);
    for (const char* kind : {"random", "planar", "grid", "duplicated"}) {
        const Coords<TestType> coords = make_cloud<TestType>(kind, 1200, rng);
        std::vector<std::uint32_t> scattered, block, all_but_two;
        for (std::uint32_t i = 0; i < 1200; ++i) {
            if (PCCD::uniform_01(rng) < 0.1) scattered.push_back(i);
            if (i >= 300 && i < 700) block.push_back(i);
            if (i != 17 && i != 1100) all_but_two.push_back(i);
        }
        for (const auto* removed : {&scattered, &block, &all_but_two}) {
            for (const bool shared : {false, true}) {
                INFO("input family " << kind << ", " << removed->size() << " removed, copy alive: " << shared);
                Cloud cloud(coords);
                const std::optional<Cloud> copy = shared ? std::optional<Cloud>(cloud) : std::nullopt;
                const Cloud left(std::move(cloud), *removed);
                check_queries<TestType>(left, without_columns(coords, *removed), rng, 60);
                if (copy) check_queries<TestType>(*copy, coords, rng, 10); // the copy is untouched
            }
        }
    }
    // The tree alone, with leaves of one point (whole leaves emptied) and of 64.
    for (const std::size_t leaf : {std::size_t(1), std::size_t(64)}) {
        const Coords<TestType> coords = make_cloud<TestType>("random", 800, rng);
        const std::vector<std::uint32_t> removed{0, 5, 6, 7, 400, 799};
        const PCCD::Kd_tree<TestType> tree = PCCD::Kd_tree<TestType>(coords, leaf).without(removed);
        const Coords<TestType> kept = without_columns(coords, removed);
        REQUIRE(tree.coordinates() == kept);
        for (int t = 0; t < 50; ++t) {
            const Eigen::Matrix<TestType, 3, 1> q = make_cloud<TestType>("random", 1, rng).col(0);
            const auto all = brute_force_all(kept, q);
            const auto got = tree.k_nearest(q, 12);
            CHECK(std::equal(got.begin(), got.end(), all.begin()));
        }
    }
    // Bad removals: unsorted, repeated, out of range, every point.
    const Coords<TestType> coords = make_cloud<TestType>("random", 50, rng);
    const auto remove = [&](std::vector<std::uint32_t> removed) { return Cloud(Cloud(coords), removed); };
    CHECK_THROWS_WITH(remove({3, 1}), Catch::Contains("must be sorted indices below 50, each once"));
    CHECK_THROWS_AS(remove({1, 1}), PCCD::Invalid_input);
    CHECK_THROWS_AS(remove({1, 50}), PCCD::Invalid_input);
    std::vector<std::uint32_t> every(50);
    std::iota(every.begin(), every.end(), 0u);
    CHECK_THROWS_WITH(remove(every), Catch::Contains("leaves none"));
    CHECK(remove({}).size() == 50);
    CHECK_THROWS_AS(PCCD::Kd_tree<TestType>(coords).without({7, 2}), PCCD::Invalid_input);
}

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

TEMPLATE_TEST_CASE("a cell grid answers radius queries as brute force", "[point_cloud]", float, double)
{
    // Kd_tree::lay_cell_grid: radius queries whose ball meets at most 27 cells come from the grid,
    // the others from the tree; both must give brute force's points, distances and order. The
    // "grid" family has integer coordinates, so with cells of side 1 (and 0.5) every point lies on
    // cell faces and many distances tie with the radius exactly.
    using Cloud = PCCD::Point_cloud<PCCD::Eigen_kernel<TestType>>;
    using Vector = Eigen::Matrix<TestType, 3, 1>;
    PCCD::Random_engine rng(77);
    for (const char* kind : {"random", "planar", "collinear", "grid", "duplicated"}) {
        const Coords<TestType> coords = make_cloud<TestType>(kind, 1500, rng);
        for (const double cell : {0.05, 0.3, 0.5, 1.0}) {
            INFO("input family " << kind << ", cells of side " << cell);
            PCCD::Kd_tree<TestType> tree(coords);
            REQUIRE(tree.lay_cell_grid(cell));
            REQUIRE(tree.cell_grid_side() == cell);
            std::vector<PCCD::Neighbor<TestType>> got;
            for (int t = 0; t < 150; ++t) {
                // At cloud points, at random positions, and outside the points' box.
                Vector q = t % 3 == 0 ? Vector(coords.col(Eigen::Index(PCCD::uniform_index(rng, 1500))))
                                      : Vector(make_cloud<TestType>("random", 1, rng).col(0));
                if (t % 3 == 2) q *= TestType(3);
                const auto all = brute_force_all(coords, q);
                // Radii from 0 through cell / 2 (at most 8 cells) to 2 cells (the tree answers), and
                // the exact distance of some point (a tie with the bound).
                const TestType radius = t % 5 == 4 ? std::sqrt(all[std::size_t(t) % 40].squared_distance)
                                                   : TestType(cell * 2.0 * PCCD::uniform_01(rng));
                tree.within_radius(q, radius, got);
                std::vector<PCCD::Neighbor<TestType>> expected;
                for (const auto& nb : all)
                    if (nb.squared_distance <= radius * radius) expected.push_back(nb);
                REQUIRE(got == expected);
            }
        }
    }
    // The grid itself declines a ball meeting more than 27 cells, and answers one that misses the
    // points' box with nothing.
    const Coords<TestType> coords = make_cloud<TestType>("random", 500, rng);
    const PCCD::internal::Cell_grid<TestType> grid(coords, 0.1);
    std::vector<PCCD::Neighbor<TestType>> got;
    CHECK_FALSE(grid.within_radius(coords, Vector(0.5, 0.5, 0.5), TestType(0.2), got));
    CHECK(got.empty());
    CHECK(grid.within_radius(coords, Vector(coords.col(0)), TestType(0.09), got));
    CHECK_FALSE(got.empty()); // the point itself
    got.clear();
    CHECK(grid.within_radius(coords, Vector(5, 5, 5), TestType(0.09), got));
    CHECK(got.empty());
    // Far queries, beyond the integers the cells are counted in, and an infinite radius.
    const TestType far = PCCD::Point_cloud<PCCD::Eigen_kernel<TestType>>::max_coordinate_magnitude();
    CHECK(grid.within_radius(coords, Vector(far, -far, far), TestType(0.09), got));
    CHECK(got.empty());
    CHECK_FALSE(grid.within_radius(coords, Vector(far, 0, 0), std::numeric_limits<TestType>::infinity(), got));
    CHECK(got.empty());
    CHECK(grid.memory_bytes() >= 500 * sizeof(std::uint32_t));

    // Grids that cannot be laid: no grid, the tree answers.
    PCCD::Kd_tree<TestType> tree(coords);
    for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::denorm_min() /* subnormal: no finite inverse */,
                             1e-7 /* 10^7 cells along an axis: more than 2^21 */}) {
        CHECK_FALSE(tree.lay_cell_grid(bad));
        CHECK_FALSE(tree.cell_grid_side());
    }
    const std::size_t bare = tree.memory_bytes();
    REQUIRE(tree.lay_cell_grid(0.1));
    CHECK(tree.memory_bytes() >= bare + 500 * sizeof(std::uint32_t));
    // Removing points drops the grid (its indices are the old ones); the tree still answers.
    const PCCD::Kd_tree<TestType> fewer = std::move(tree).without({0, 1, 2});
    CHECK_FALSE(fewer.cell_grid_side());

    // Point_cloud::with_cell_grid, alone and with a copy alive (the copy keeps no grid).
    for (const bool shared : {false, true}) {
        Cloud cloud(coords);
        std::vector<Cloud> copies; // one when a copy is alive
        if (shared) copies.push_back(cloud);
        const Cloud gridded = std::move(cloud).with_cell_grid(0.1);
        CHECK(gridded.kd_tree().cell_grid_side() == 0.1);
        check_queries<TestType>(gridded, coords, rng, 60);
        for (const Cloud& copy : copies) CHECK_FALSE(copy.kd_tree().cell_grid_side());
        Cloud plain(coords);
        CHECK_FALSE(std::move(plain).with_cell_grid(0.0).kd_tree().cell_grid_side()); // none laid, still a cloud
    }
}
