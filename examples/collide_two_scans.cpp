// Two scans of one object and whether they collide in given poses (doc/manual/intersection.md).
// Each scan is preprocessed once into a Point_cloud_object; do_intersect() then answers for any pair
// of rigid poses (here built from an Eigen rotation and translation) without rebuilding anything, and
// reports the work it did. The scans are two independent samples of the Stanford bunny of Debian's
// libcgal-demo (PCCD_DATA_DIR), normalized into [-1, 1]^3, or of a procedural torus without it.
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/testing/Torus_shape.h>
#include <PCCD/sample_triangle_mesh.h>

#include <Eigen/Geometry>

#include <cstdlib>
#include <filesystem>
#include <iostream>

using Object = PCCD::Point_cloud_object<>; // Eigen_kernel<double>
using Pose = PCCD::Rigid_transform_3<double>;
using Rotation = Eigen::AngleAxisd;
using Vector = Eigen::Vector3d;

// A "scan": n points drawn by area from the bunny mesh, or from a torus when the mesh is absent.
Eigen::Matrix3Xd scan(std::size_t n, std::uint64_t seed)
{
    const char* env = std::getenv("PCCD_DATA_DIR");
    const std::filesystem::path bunny = std::filesystem::path(env && *env ? env : PCCD_DATA_DIR) / "bunny00.off";
    PCCD::Random_engine engine(seed);
    if (!std::filesystem::exists(bunny)) return PCCD::testing::Torus_shape(0.7, 0.3).sample(n, engine).points;
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(bunny.string());
    const PCCD::Similarity_3 to_unit_cube = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (Vector& v : mesh.vertices) v = to_unit_cube.transform_point(v);
    return PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, engine).points;
}

int main()
{
    const Object a(scan(10000, 1)); // graph, CPSP map, normals, hierarchy: once per object
    const Object b(scan(10000, 2));
    std::cout << "scans of " << a.size() << " and " << b.size() << " points, r(P) = " << a.sampling_radius() << '\n';

    // A turned about z; B turned about a diagonal axis and moved along x by d.
    const Pose pose_a(Rotation(0.3, Vector::UnitZ()).toRotationMatrix(), Vector::Zero());
    for (const double d : {0.5, 1.0, 1.5, 2.5}) {
        const Pose pose_b(Rotation(1.2, Vector(1, 1, 0).normalized()).toRotationMatrix(), Vector(d, 0, 0));
        const PCCD::Intersection_result isearch = PCCD::do_intersect(a, pose_a, b, pose_b, {.seed = 7});
        const PCCD::Intersection_result rst =
            PCCD::do_intersect(a, pose_a, b, pose_b, {.seed = 7}, PCCD::Randomized_sampling{});
        std::cout << "d = " << d << ": interpolation search says " << PCCD::to_string(isearch.status) << " ("
                  << isearch.counters.f_evaluations << " f evaluations, " << isearch.counters.brackets_found
                  << " brackets), RST says " << PCCD::to_string(rst.status) << " (" << rst.counters.f_evaluations
                  << " f evaluations, " << rst.counters.samples << " samples)\n";
        if (isearch) std::cout << "  first point " << isearch.points.front().position.transpose() << '\n';
    }
    return 0;
}
