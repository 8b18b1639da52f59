// A user's first program, written against PCCD/PCCD.h alone (no other PCCD header, no CGAL): two
// sampled spheres made into objects straight from their coordinate matrices
// (make_point_cloud_object), posed 1.5 apart and 2.5 apart, asked whether they touch and where.
// Exits with 0 only when every answer is right: the spheres of radius 1 meet in the circle
// x = 0.75, y^2 + z^2 = 1 - 0.75^2 at distance 1.5 and are separate at distance 2.5.
#include <PCCD/PCCD.h>

#ifdef CGAL_VERSION_NR
#error "PCCD/PCCD.h pulled in a CGAL header; the core must not need CGAL"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

int main()
{
    // 3000 points uniform on the unit sphere (Archimedes: z uniform in [-1, 1], azimuth uniform);
    // the outward normal of each is the point itself.
    PCCD::Random_engine engine(7);
    Eigen::Matrix3Xd points(3, 3000);
    for (Eigen::Index i = 0; i < points.cols(); ++i) {
        const double z = PCCD::uniform_real(engine, -1.0, 1.0);
        const double phi = 2.0 * std::numbers::pi * PCCD::uniform_01(engine);
        const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
        points.col(i) = Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), z);
    }
    const Eigen::Matrix3Xd& normals = points;

    const auto a = PCCD::make_point_cloud_object(points);           // normals estimated
    const auto b = PCCD::make_point_cloud_object(points, normals);  // normals as hints

    const PCCD::Rigid_transform_3<double> pose_a;
    const PCCD::Rigid_transform_3<double> near(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.5, 0.0, 0.0));
    const PCCD::Rigid_transform_3<double> far(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.5, 0.0, 0.0));

    const PCCD::Intersection_result touching = PCCD::do_intersect(a, pose_a, b, near);
    const PCCD::Intersection_result apart = PCCD::do_intersect(a, pose_a, b, far);
    const PCCD::Intersection_result curve = PCCD::intersection_points(a, pose_a, b, near);

    double worst = 0.0;
    for (const PCCD::Intersection_point& p : curve.points)
        worst = std::max({worst, std::abs(p.position.x() - 0.75),
                          std::abs(p.position.tail<2>().norm() - std::sqrt(1.0 - 0.75 * 0.75))});
    std::printf("PCCD %s: %zu points each; at 1.5: %s; at 2.5: %s; %zu curve points, farthest %.4f off the circle\n",
                PCCD_VERSION_STRING, a.size(), PCCD::to_string(touching.status), PCCD::to_string(apart.status),
                curve.points.size(), worst);
    const bool right = touching.intersects && !apart.intersects && curve.points.size() >= 20 && worst < 0.02;
    if (!right) std::printf("wrong answer\n");

    // Bad input is rejected with a clear message.
    try {
        (void)PCCD::make_point_cloud_object(points, Eigen::Matrix3Xd(3, 2));
        std::printf("mismatched normals were accepted\n");
        return 1;
    } catch (const PCCD::Invalid_input& e) {
        std::printf("rejected as expected: %s\n", e.what());
    }
    return right ? 0 : 1;
}
