// Radius queries from the kd-tree against a cell grid (Kd_tree::lay_cell_grid) on the same points
// and queries: the scanned bunny normalized into [-1, 1]^3 and sampled by area with N points (seed
// 1), stored in the spatial order the objects use; the radius three sampling radii (the default
// support radius of the surface, whose evaluations ask these queries); queries in clusters of five
// around random cloud points (Gaussian offsets of half the radius per axis), as the evaluations of
// one query come. Each configuration answers every query; the answers of the grids are checked
// equal to the tree's (points, distances and order). Times: thread CPU time per query, the median
// of R passes over the queries.
//
// Usage: radius_grid_benchmark [--points N,N,...] [--queries Q] [--passes R] [--cells S,S,...]
//   --cells: the grids' sides in support radii (default 1,2; the lean object lays 2)
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Kd_tree.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/internal/spatial_order.h>
#include <PCCD/sample_triangle_mesh.h>
#include <PCCD/sampling_radius.h>

#include <PCCD/testing/statistics.h>

#include <ctime>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

double thread_cpu_us()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e6 + double(t.tv_nsec) * 1e-3;
}

std::vector<double> split_numbers(const std::string& s)
{
    std::vector<double> out;
    std::size_t start = 0;
    while (start <= s.size()) {
        const std::size_t end = s.find(',', start);
        out.push_back(std::stod(s.substr(start, end - start)));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return out;
}

} // namespace

int main(int argc, char** argv)
try {
    std::vector<double> sizes{30000, 1000000, 10000000}, cells{1.0, 2.0};
    std::size_t queries = 500000;
    int passes = 3;
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--points") sizes = split_numbers(value);
        else if (key == "--queries") queries = std::stoul(value);
        else if (key == "--passes") passes = std::stoi(value);
        else if (key == "--cells") cells = split_numbers(value);
        else throw std::invalid_argument("unknown option " + key);
    }
    if (queries < 5 || passes < 1) throw std::invalid_argument("--queries must be >= 5 and --passes >= 1");
    PCCD::Triangle_mesh_data mesh =
        PCCD::IO::read_triangle_mesh((std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off").string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);
    std::printf("points      radius   neighbours  structure        us/query  / tree  bytes/point (grid: added)\n");
    for (const double size : sizes) {
        PCCD::Random_engine engine(1);
        const auto sample = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, std::size_t(size), engine);
        const Eigen::Matrix3Xd points =
            PCCD::internal::gather_columns(Eigen::Matrix3Xd(sample.points), PCCD::internal::spatial_order(sample.points));
        const PCCD::Point_cloud<> cloud(points);
        const double radius = 3.0 * PCCD::sampling_radius(cloud);
        // Clusters of five queries around random cloud points.
        PCCD::Random_engine query_engine(7);
        std::vector<Eigen::Vector3d> at;
        at.reserve(queries);
        while (at.size() + 5 <= queries) {
            const Eigen::Vector3d p = points.col(Eigen::Index(PCCD::uniform_index(query_engine, points.cols())));
            for (int k = 0; k < 5; ++k) {
                const Eigen::Vector3d offset(PCCD::standard_normal(query_engine), PCCD::standard_normal(query_engine),
                                             PCCD::standard_normal(query_engine));
                at.push_back(p + 0.5 * radius * offset);
            }
        }
        const PCCD::Kd_tree<double>& tree = cloud.kd_tree();
        std::vector<std::vector<PCCD::Neighbor<double>>> expected(at.size() < 20000 ? at.size() : 20000);
        double neighbours = 0.0;
        for (std::size_t q = 0; q < expected.size(); ++q) {
            tree.within_radius(at[q], radius, expected[q]);
            neighbours += double(expected[q].size());
        }
        neighbours /= double(expected.size());
        const auto time_of = [&](const PCCD::Kd_tree<double>& t) {
            std::vector<double> times;
            std::vector<PCCD::Neighbor<double>> out;
            std::size_t found = 0;
            for (int pass = 0; pass < passes; ++pass) {
                const double start = thread_cpu_us();
                for (const auto& x : at) {
                    t.within_radius(x, radius, out);
                    found += out.size();
                }
                times.push_back((thread_cpu_us() - start) / double(at.size()));
            }
            if (found == 0) std::printf("(no neighbours found)\n");
            return PCCD::testing::median(times);
        };
        const double tree_us = time_of(tree);
        const double bare = double(tree.memory_bytes()) / size;
        std::printf("%-10.0f  %.5f  %9.1f   %-15s  %8.3f  %6.2f  %10.1f\n", size, radius, neighbours, "kd-tree", tree_us, 1.0,
                    bare);
        for (const double side : cells) {
            PCCD::Kd_tree<double> gridded(points);
            if (!gridded.lay_cell_grid(side * radius)) throw std::runtime_error("the grid does not fit");
            std::vector<PCCD::Neighbor<double>> out;
            for (std::size_t q = 0; q < expected.size(); ++q) {
                gridded.within_radius(at[q], radius, out);
                if (out != expected[q]) throw std::runtime_error("the grid's answer differs from the tree's");
            }
            const double us = time_of(gridded);
            char name[32];
            std::snprintf(name, sizeof name, "grid, %.0f radius", side);
            std::printf("%-10.0f  %.5f  %9.1f   %-15s  %8.3f  %6.2f  %10.1f\n", size, radius, neighbours, name, us,
                        us / tree_us, double(gridded.memory_bytes()) / size - bare);
        }
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "radius_grid_benchmark: %s\n", e.what());
    return 1;
}
