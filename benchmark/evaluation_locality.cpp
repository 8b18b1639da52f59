// benchmark/evaluation_locality.cpp -- the cost of one evaluation of f against the cloud's size and
// the order its points are stored in (doc/benchmarks.md "Point cloud hierarchy", "Scale"): the
// bunny of libcgal-demo sampled by area with N points, preprocessed with the points stored as given
// (random order) and in spatial order (Point_cloud_object_options::spatial_order, the default);
// f (the object's geodesic surface) evaluated at 20,000 points near the surface (a second area
// sample moved along its normals by up to one sampling radius), taken in random order and in Morton
// order (consecutive queries close together, as in a query's walk). Printed: µs per evaluation,
// the best of 5 passes, one thread.
//
// Usage: evaluation_locality [--sizes 10000,100000,1000000]
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>
#include <PCCD/internal/spatial_order.h>

#include <PCCD/testing/timing.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// µs per evaluation of f at `xs`, the best of 5 passes; `checksum` keeps the loop alive.
template <class Object>
double microseconds_per_evaluation(const Object& object, const std::vector<Eigen::Vector3d>& xs, double& checksum)
{
    double best = 1e300;
    for (int pass = 0; pass < 5; ++pass) {
        double sum = 0.0;
        const auto start = PCCD::testing::Clock::now();
        for (const Eigen::Vector3d& x : xs) {
            const PCCD::Surface_evaluation e = object.surface().evaluate(x);
            sum += e.defined() ? e.value : 0.0;
        }
        best = std::min(best, 1e3 * PCCD::testing::ms_since(start) / double(xs.size()));
        checksum += sum;
    }
    return best;
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::size_t> sizes{10000, 100000, 1000000};
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::string(argv[i]) != "--sizes") {
            std::fprintf(stderr, "usage: evaluation_locality [--sizes 10000,100000,1000000]\n");
            return 2;
        }
        sizes.clear();
        std::stringstream in(argv[i + 1]);
        for (std::string item; std::getline(in, item, ',');) sizes.push_back(std::size_t(std::atoll(item.c_str())));
    }
    const auto path = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);
    std::printf("%-10s %-14s %14s %14s\n", "points", "stored", "random us", "Morton us");
    double checksum = 0.0;
    for (const std::size_t n : sizes) {
        PCCD::Random_engine engine(1);
        const PCCD::Triangle_mesh_sample cloud = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, engine);
        for (const bool spatial : {false, true}) {
            const PCCD::Point_cloud_object<> object(cloud.points, PCCD::Point_cloud_object_options{.spatial_order = spatial});
            PCCD::Random_engine queries_engine(7);
            const PCCD::Triangle_mesh_sample near =
                PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, 20000, queries_engine);
            std::vector<Eigen::Vector3d> xs;
            for (Eigen::Index i = 0; i < near.points.cols(); ++i)
                xs.push_back(near.points.col(i) +
                             PCCD::uniform_real(queries_engine, -1.0, 1.0) * object.sampling_radius() * near.normals.col(i));
            const double random_us = microseconds_per_evaluation(object, xs, checksum);
            Eigen::Matrix3Xd m(3, Eigen::Index(xs.size()));
            for (std::size_t i = 0; i < xs.size(); ++i) m.col(Eigen::Index(i)) = xs[i];
            std::vector<Eigen::Vector3d> walked;
            for (const std::uint32_t k : PCCD::internal::spatial_order(m)) walked.push_back(xs[k]);
            const double morton_us = microseconds_per_evaluation(object, walked, checksum);
            std::printf("%-10zu %-14s %14.3f %14.3f\n", n, spatial ? "spatial order" : "as given", random_us, morton_us);
        }
    }
    std::printf("(checksum %g)\n", checksum);
}
