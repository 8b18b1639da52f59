// Points on the intersection curves of two point cloud surfaces, at a density the caller chooses
// (doc/algorithms.md, "Interpolation search"): a sphere and a torus whose tube straddles it meet in
// two circles. intersection_points() searches the whole overlap, keeps points at least
// point_spacing apart and projects each candidate onto both surfaces (verified contacts); the
// result is written to a PLY file (argument 1, default intersection_curve.ply) and compared with
// the exact curves.
#include <PCCD/IO/write_points.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;
using Sphere = PCCD::testing::Sphere_shape;
using Torus = PCCD::testing::Torus_shape;

int main(int argc, char** argv)
{
    const std::string out = argc > 1 ? argv[1] : "intersection_curve.ply";
    const Sphere sphere(Eigen::Vector3d::Zero(), 1.0);
    const Torus torus(1.0, 0.35); // its tube is centred on the sphere's equator
    PCCD::Random_engine engine(3);
    const Object a(sphere.sample(8000, engine).points);
    const Object b(torus.sample(8000, engine).points);

    // Both objects in place (identity poses); one point every 0.05 along the curves, each a verified
    // contact: projected onto f_A = f_B = 0 inside both surfaces' domains.
    const PCCD::Intersection_result result =
        PCCD::intersection_points(a, Pose(), b, Pose(), {.seed = 11, .point_spacing = 0.05});

    PCCD::Point_data data;
    double worst = 0.0;
    for (const PCCD::Intersection_point& p : result.points) {
        data.points.push_back(p.position);
        worst = std::max({worst, std::abs(sphere.signed_distance(p.position)), std::abs(torus.signed_distance(p.position))});
    }
    // The exact curves: two circles of radius 1 - r^2/2 at z = +-sqrt(1 - (1 - r^2/2)^2).
    const double rho = 1.0 - 0.35 * 0.35 / 2.0;
    std::cout << result.points.size() << " points for curves of length " << 4.0 * std::numbers::pi * rho << ", "
              << result.counters.f_evaluations << " f evaluations; farthest point from the exact surfaces: " << worst
              << '\n';
    if (data.points.empty()) return 1;
    PCCD::IO::write_points(out, data);
    std::cout << "wrote " << out << '\n';
    return 0;
}
