// Validating an approximate answer against the exact one (doc/manual/exact.md): two point clouds
// are sampled from one triangle mesh (a torus), posed a sweep of distances apart, and
// do_intersect()'s answer is compared, pose by pose, with CGAL's exact verdict on the meshes
// (exact_separation: whether the surfaces meet, and by how much they are apart or interpenetrate).
// The stated error: a cloud cannot decide a pose whose gap or penetration is below one sampling
// radius r(P) (classify_pose: grazing); every other pose must be answered as the meshes are.
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/sample_triangle_mesh.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

using Mesh = PCCD::Triangle_mesh_data;
using Exact_mesh = PCCD::Exact_mesh;
using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;
using PCCD::Pose_class;

// A torus (radii R, r) as nu x nv quads, each split into two triangles.
Mesh torus_mesh(double R, double r, std::uint32_t nu, std::uint32_t nv)
{
    Mesh mesh;
    for (std::uint32_t i = 0; i < nu; ++i)
        for (std::uint32_t j = 0; j < nv; ++j) {
            const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
            mesh.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                       r * std::sin(v));
        }
    const auto at = [&](std::uint32_t i, std::uint32_t j) { return (i % nu) * nv + j % nv; };
    for (std::uint32_t i = 0; i < nu; ++i)
        for (std::uint32_t j = 0; j < nv; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

int main()
{
    const Mesh mesh = torus_mesh(0.7, 0.3, 64, 32);
    const Exact_mesh exact(mesh); // CGAL Surface_mesh, AABB tree, inside test
    PCCD::Random_engine engine(5);
    const Object a(PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, 8000, engine).points);
    const Object b(PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, 8000, engine).points);
    const double r = std::max(a.sampling_radius(), b.sampling_radius());

    // B stands upright (turned about x) and moves along x: through A's hole, then out of it.
    int wrong = 0, grazing = 0, poses = 0;
    for (double d = 0.0; d <= 2.2; d += 0.05, ++poses) {
        const Pose pose_b(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
                          Eigen::Vector3d(d, 0.0, 0.0));
        const PCCD::Exact_separation truth = PCCD::exact_separation(exact, Pose(), exact, pose_b);
        const Pose_class kind = PCCD::classify_pose(truth, r);
        const bool answer = PCCD::do_intersect(a, Pose(), b, pose_b, {.seed = 9}).intersects;
        const bool agrees = kind == Pose_class::grazing || answer == truth.surfaces_intersect;
        grazing += kind == Pose_class::grazing;
        wrong += !agrees;
        std::printf("d = %.2f: exact %s (%+.4f = %+.2f r), cloud %s%s\n", d,
                    truth.surfaces_intersect ? "intersecting" : "separate  ", truth.signed_measure(),
                    truth.signed_measure() / r, answer ? "intersecting" : "separate",
                    kind == Pose_class::grazing ? "  [grazing: either answer stands]" : agrees ? "" : "  WRONG");
    }
    std::printf("r(P) = %.4f; %d poses, %d grazing (|gap| < r(P)), %d wrong answers outside them\n", r, poses, grazing,
                wrong);
    return wrong == 0 ? 0 : 1;
}
