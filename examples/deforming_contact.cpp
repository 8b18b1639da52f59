// A ball of points breathes and bobs onto a rigid floor patch: a Deforming_point_cloud_object is
// built once at rest, follows the moved points frame by frame, and answers do_intersect against the
// floor without a rebuild; a stretch beyond the near-isometry bound is refused
// (doc/manual/kinetic.md, "Deforming point clouds").
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Plane_patch_shape.h>
#include <PCCD/testing/Sphere_shape.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

int main()
{
    PCCD::Random_engine engine(7);
    // The deforming cloud at rest: 3000 points on a unit sphere.
    const Eigen::Matrix3Xd rest = PCCD::testing::Sphere_shape(Eigen::Vector3d::Zero(), 1.0).sample(3000, engine).points;
    PCCD::Deforming_point_cloud_object<> ball(rest); // the whole preprocessing, once

    // The rigid floor: a 4 x 4 patch at z = -1.1.
    const PCCD::testing::Plane_patch_shape patch({-2.0, -2.0, -1.1}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0});
    const Eigen::Matrix3Xd floor_points = patch.sample(4000, engine).points;
    std::vector<Eigen::Vector3d> floor_items(floor_points.colwise().begin(), floor_points.colwise().end());
    const PCCD::Point_cloud_object<> floor(floor_items);

    // Each frame: the ball breathes (scale 1 +- 5 %), squashes a little and bobs by 0.15.
    for (int frame = 0; frame <= 20; ++frame) {
        const double t = frame / 10.0, phase = 2.0 * std::numbers::pi * t / 2.0;
        const double s = 1.0 + 0.05 * std::sin(2.0 * phase), squash = 1.0 - 0.04 * std::sin(phase);
        Eigen::Matrix3Xd moved = rest;
        moved.row(0) *= s / std::sqrt(squash);
        moved.row(1) *= s / std::sqrt(squash);
        moved.row(2) *= s * squash;
        moved.row(2).array() -= 0.15 * std::sin(phase);
        const PCCD::Deformation_report& report = ball.set_positions(moved); // O(N k): no rebuild
        const bool contact = PCCD::do_intersect(ball, floor).intersects;
        if (frame % 2 == 0)
            std::cout << "t = " << t << ": " << (contact ? "contact" : "apart") << ", edge stretch in ["
                      << report.min_stretch << ", " << report.max_stretch << "], update " << report.milliseconds
                      << " ms\n";
    }

    // Twice the size is far from an isometry: the frame is refused and the object keeps the last one.
    try {
        ball.set_positions(Eigen::Matrix3Xd(2.0 * rest));
    } catch (const PCCD::Deformation_error& e) {
        std::cout << "refused: " << e.what() << '\n';
    }
}
