// Kd-tree choice for Point_cloud: nanoflann (PCCD::Kd_tree) against
// CGAL's Kd_tree + Orthogonal_k_neighbor_search, on the same points and queries.
// Measures build time and the time of Q k-nearest-neighbour queries, each the median of R runs.
//
// Usage: kd_tree_benchmark [N=100000] [Q=1000000] [k=8] [R=5] [--csv FILE]
// Points: N uniform on the unit sphere (a surface, like a scan) and N uniform in the unit cube.
#include <PCCD/Kd_tree.h>
#include <PCCD/Random.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

using Coordinates = Eigen::Matrix<double, 3, Eigen::Dynamic>;
using PCCD::testing::Clock;
using PCCD::testing::seconds_since;
using PCCD::testing::upper_median;

Coordinates make_points(const std::string& kind, int n, PCCD::Random_engine& rng)
{
    Coordinates c(3, n);
    for (int i = 0; i < n; ++i) {
        if (kind == "sphere") {
            Eigen::Vector3d g(PCCD::standard_normal(rng), PCCD::standard_normal(rng), PCCD::standard_normal(rng));
            c.col(i) = g.normalized();
        } else {
            c.col(i) << PCCD::uniform_01(rng), PCCD::uniform_01(rng), PCCD::uniform_01(rng);
        }
    }
    return c;
}

struct Timing {
    double build_s, query_s, checksum;
};

Timing run_nanoflann(const Coordinates& pts, const Coordinates& queries, int k)
{
    auto start = Clock::now();
    const PCCD::Kd_tree<double> tree(pts);
    const double build = seconds_since(start);
    std::vector<PCCD::Neighbor<double>> out;
    double checksum = 0;
    start = Clock::now();
    for (Eigen::Index q = 0; q < queries.cols(); ++q) {
        tree.k_nearest(queries.col(q), std::size_t(k), out);
        checksum += out.back().squared_distance;
    }
    return {build, seconds_since(start), checksum};
}

using Cgal_kernel = CGAL::Simple_cartesian<double>;
using Cgal_point = Cgal_kernel::Point_3;
using Point_map = CGAL::Pointer_property_map<Cgal_point>::type;
using Traits = CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Cgal_kernel>>;
using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
using Cgal_tree = Search::Tree;
using Distance = Search::Distance;

Timing run_cgal(const Coordinates& pts, const Coordinates& queries, int k)
{
    std::vector<Cgal_point> points;
    points.reserve(std::size_t(pts.cols()));
    for (Eigen::Index i = 0; i < pts.cols(); ++i) points.emplace_back(pts(0, i), pts(1, i), pts(2, i));
    const Point_map point_map = CGAL::make_property_map(points);
    std::vector<std::size_t> indices(points.size());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;

    auto start = Clock::now();
    Cgal_tree tree(indices.begin(), indices.end(), Cgal_tree::Splitter(), Traits(point_map));
    tree.build();
    const double build = seconds_since(start);
    const Distance distance(point_map);
    double checksum = 0;
    start = Clock::now();
    for (Eigen::Index q = 0; q < queries.cols(); ++q) {
        const Search search(tree, Cgal_point(queries(0, q), queries(1, q), queries(2, q)), unsigned(k), 0, true,
                            distance);
        double farthest = 0;
        for (const auto& [index, d2] : search) farthest = std::max(farthest, d2);
        checksum += farthest;
    }
    return {build, seconds_since(start), checksum};
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    std::string csv_path;
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == "--csv") {
            csv_path = args[i + 1];
            args.erase(args.begin() + long(i), args.begin() + long(i) + 2);
            break;
        }
    const int n = args.size() > 0 ? std::atoi(args[0].c_str()) : 100000;
    const int q = args.size() > 1 ? std::atoi(args[1].c_str()) : 1000000;
    const int k = args.size() > 2 ? std::atoi(args[2].c_str()) : 8;
    const int repeats = args.size() > 3 ? std::atoi(args[3].c_str()) : 5;
    if (n < k || q < 1 || k < 1 || repeats < 1) {
        std::fprintf(stderr, "usage: kd_tree_benchmark [N>=k] [Q>=1] [k>=1] [R>=1] [--csv FILE]\n");
        return 1;
    }

    std::string csv = "points,backend,n,queries,k,build_ms_median,query_ms_median,us_per_query\n";
    std::printf("%-7s %-10s %9s %9s %3s %14s %14s %12s\n", "points", "backend", "N", "queries", "k", "build ms", "queries ms",
                "us/query");
    for (const std::string kind : {"sphere", "cube"}) {
        PCCD::Random_engine rng(2024);
        const Coordinates pts = make_points(kind, n, rng);
        Coordinates queries(3, q);
        for (int i = 0; i < q; ++i)
            queries.col(i) = pts.col(Eigen::Index(PCCD::uniform_index(rng, std::uint64_t(n)))) +
                             0.01 * Eigen::Vector3d(PCCD::standard_normal(rng), PCCD::standard_normal(rng),
                                                    PCCD::standard_normal(rng));
        std::vector<double> build[2], query[2];
        double checksum[2] = {0, 0};
        for (int r = 0; r < repeats; ++r) {
            const Timing a = run_nanoflann(pts, queries, k);
            const Timing b = run_cgal(pts, queries, k);
            build[0].push_back(a.build_s);
            query[0].push_back(a.query_s);
            build[1].push_back(b.build_s);
            query[1].push_back(b.query_s);
            checksum[0] = a.checksum;
            checksum[1] = b.checksum;
        }
        if (std::abs(checksum[0] - checksum[1]) > 1e-9 * std::abs(checksum[0])) {
            std::fprintf(stderr, "backends disagree: %.17g vs %.17g\n", checksum[0], checksum[1]);
            return 2;
        }
        const char* names[2] = {"nanoflann", "cgal"};
        for (int b = 0; b < 2; ++b) {
            const double bm = 1e3 * upper_median(build[b]), qm = 1e3 * upper_median(query[b]);
            std::printf("%-7s %-10s %9d %9d %3d %14.1f %14.1f %12.3f\n", kind.c_str(), names[b], n, q, k, bm, qm,
                        1e3 * qm / q);
            char line[256];
            std::snprintf(line, sizeof line, "%s,%s,%d,%d,%d,%.3f,%.3f,%.4f\n", kind.c_str(), names[b], n, q, k, bm, qm,
                          1e3 * qm / q);
            csv += line;
        }
        std::printf("%-7s ratio cgal/nanoflann: build %.2f, queries %.2f\n", kind.c_str(),
                    upper_median(build[1]) / upper_median(build[0]), upper_median(query[1]) / upper_median(query[0]));
    }
    if (!csv_path.empty()) std::ofstream(csv_path) << csv;
    return 0;
}
