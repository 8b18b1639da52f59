// When do two moving clouds first touch? A rigid ball shot along a line past a fixed one, then a
// deforming ball that sways and twists along flightplans onto a rigid floor patch: time_of_contact()
// answers for the whole motion, not at sampled frames (doc/manual/continuous.md).
#include <PCCD/Kinetic/Deforming_motion.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Plane_patch_shape.h>
#include <PCCD/testing/Sphere_shape.h>

#include <iostream>
#include <memory>
#include <span>
#include <vector>

namespace {

void report(const char* what, const PCCD::Contact_time_result& r)
{
    std::cout << what << ": ";
    if (r.status == PCCD::Contact_time_status::contact)
        std::cout << "first contact at t = " << r.t << " (none before " << r.t_low << "), at " << r.point.transpose() << '\n';
    else
        std::cout << (r.status == PCCD::Contact_time_status::no_contact ? "no contact" : "undecided") << '\n';
}

} // namespace

int main()
{
    PCCD::Random_engine engine(11);
    const Eigen::Matrix3Xd unit = PCCD::testing::Sphere_shape(Eigen::Vector3d::Zero(), 1.0).sample(2000, engine).points;
    std::vector<Eigen::Vector3d> items(unit.colwise().begin(), unit.colwise().end());
    const PCCD::Point_cloud_object<> ball(items);

    // Rigid: A rests at the origin, B flies from x = 4 to x = -4; the balls touch at t = 0.25.
    const PCCD::Rigid_transform_3<double> rest;
    const PCCD::Linear_motion still(rest, rest);
    const PCCD::Linear_motion shot(PCCD::Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(4, 0, 0)),
                                   PCCD::Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-4, 0, 0)));
    report("rigid ball through ball", PCCD::time_of_contact(ball, still, ball, shot));

    // Deforming: key frames at t = 0, 1, 2 s; the ball twists about z and sways down onto a floor at
    // z = -1.6 and up again. Deforming_motion looks at the frame of each time the query needs.
    const PCCD::testing::Plane_patch_shape patch({-2.0, -2.0, -1.6}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0});
    const Eigen::Matrix3Xd floor_points = patch.sample(4000, engine).points;
    std::vector<Eigen::Vector3d> floor_items(floor_points.colwise().begin(), floor_points.colwise().end());
    const PCCD::Point_cloud_object<> floor(floor_items);
    PCCD::Deforming_point_cloud_object<> soft(unit);
    const auto times = std::make_shared<const std::vector<double>>(std::vector<double>{0.0, 1.0, 2.0});
    const double heights[] = {0.0, -0.9, 0.0};
    std::vector<PCCD::Piecewise_linear_flightplan> plans;
    for (Eigen::Index i = 0; i < unit.cols(); ++i) {
        std::vector<Eigen::Vector3d> keys;
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d twisted = Eigen::AngleAxisd(0.2 * unit(2, i) * k, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d(unit.col(i));
            keys.push_back(twisted + Eigen::Vector3d(0, 0, heights[k]));
        }
        plans.emplace_back(times, keys);
    }
    const std::span<const PCCD::Piecewise_linear_flightplan> span(plans);
    const PCCD::Deforming_motion<PCCD::Eigen_kernel<double>, PCCD::Piecewise_linear_flightplan> sway(soft, span, 0.0, 2.0);
    const PCCD::Contact_time_result r = PCCD::time_of_contact(soft, sway, floor, still);
    report("deforming ball onto the floor", r);
    if (r.status == PCCD::Contact_time_status::contact)
        std::cout << "  that is " << sway.time(r.t) << " s into the flightplans (the floor is touched when the ball's bottom, "
                  << "-1 - 0.9 t, reaches -1.6: t = 0.67 s)\n";
}
