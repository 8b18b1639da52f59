// Tests of PCCD/Intersection/internal/Covering_grid.h against brute force: "is a point added so far
// within the radius of x?" for random points in boxes of several sizes and offsets (negative
// coordinates, points on cell boundaries), and radii from tiny to large.
#include <PCCD/Intersection/internal/Covering_grid.h>
#include <PCCD/Random.h>

#include <catch2/catch.hpp>

#include <vector>

TEST_CASE("Covering_grid answers as brute force does", "[intersection]")
{
    PCCD::Random_engine engine(41);
    for (const double radius : {1e-6, 0.01, 0.05, 0.3}) {
        for (const double offset : {0.0, -7.5, 1e3}) {
            PCCD::internal::Covering_grid grid(radius);
            std::vector<Eigen::Vector3d> added;
            const double extent = 40.0 * radius;
            const auto draw = [&] {
                Eigen::Vector3d x;
                for (int d = 0; d < 3; ++d) x(d) = offset + PCCD::uniform_real(engine, -extent, extent);
                // Some points exactly on a cell boundary (multiples of the cell width 2 radius).
                if (PCCD::uniform_index(engine, 8) == 0) x(0) = 2.0 * radius * double(std::int64_t(x(0) / (2.0 * radius)));
                return x;
            };
            std::size_t hits = 0;
            for (int k = 0; k < 3000; ++k) {
                const Eigen::Vector3d x = draw();
                bool brute = false;
                for (const Eigen::Vector3d& p : added) brute = brute || (p - x).squaredNorm() <= radius * radius;
                REQUIRE(grid.covers(x) == brute);
                hits += brute;
                if (!brute) {
                    grid.add(x);
                    added.push_back(x);
                }
            }
            INFO("radius " << radius << ", offset " << offset);
            CHECK(hits > 0); // the test exercised both answers
            CHECK(added.size() > 10);
        }
    }
}
