// Clearance along a path (doc/manual/proximity.md "Clearance along a path"): a scan of a ball of
// radius 0.5 (the "wagon") moves through a scan of a tunnel -- two parallel walls 1.6 apart, planes
// y = -0.8 and y = 0.8 -- along x, drifting towards one wall. clearance() answers every pose at once
// (in parallel): the clearance against a safety margin, the first pose below it and where, the
// minimum. The walls and the ball are analytic shapes (PCCD::testing), so the true clearance,
// 0.8 - 0.5 - |y|, is printed beside the answers.
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/clearance.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Parallel_sheets_shape.h>
#include <PCCD/testing/Sphere_shape.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <vector>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;

int main()
{
    PCCD::Random_engine engine(11);
    // The tunnel: walls 4 long (x) and 2 high (z), 30,000 points; the ball: 6,000 points.
    const PCCD::testing::Parallel_sheets_shape walls(Eigen::Vector3d(-2.0, 0.8, -1.0), Eigen::Vector3d(4.0, 0.0, 0.0),
                                                     Eigen::Vector3d(0.0, 0.0, 2.0), 1.6);
    const PCCD::testing::Sphere_shape ball(Eigen::Vector3d::Zero(), 0.5);
    const Object tunnel(walls.sample(30000, engine).points);
    const Object wagon(ball.sample(6000, engine).points);

    // The path: 25 poses, x from -1.2 to 1.2, y drifting from 0 to 0.24 (towards the wall y = 0.8),
    // the ball turning as it rolls (a sphere does not care).
    std::vector<Pose> poses;
    std::vector<double> truth;
    for (int k = 0; k <= 24; ++k) {
        const double x = -1.2 + 0.1 * k, y = 0.01 * k;
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.2 * k, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        poses.emplace_back(turn, Eigen::Vector3d(x, y, 0.0));
        truth.push_back(0.8 - 0.5 - std::abs(y));
    }
    const double margin = 0.155; // between the true clearances 0.16 (pose 14) and 0.15 (pose 15)
    const PCCD::Clearance_profile p = PCCD::clearance(wagon, tunnel, poses, margin, {.max_distance = 0.5});

    std::printf("pose  true clearance  status        clearance  [lower_bound, upper_bound]\n");
    for (std::size_t i = 0; i < p.samples.size(); ++i) {
        const PCCD::Clearance_sample& s = p.samples[i];
        std::printf("%4zu  %14.4f  %-12s  %9.4f  [%.4f, %.4f]\n", i, truth[i], PCCD::to_string(s.status), s.clearance,
                    s.lower_bound, s.upper_bound);
    }
    std::size_t expected = 0;
    while (expected < truth.size() && truth[expected] >= margin) ++expected;
    if (p.first_below_margin) {
        const Eigen::Vector3d& a = p.first_point_object;
        const Eigen::Vector3d& b = p.first_point_scene;
        std::printf("first pose below the margin %.3f: %zu (true: %zu), the ball at [%.3f %.3f %.3f], the wall at [%.3f %.3f %.3f]\n",
                    margin, *p.first_below_margin, expected, a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
    } else
        std::printf("no pose below the margin %.3f (true: pose %zu)\n", margin, expected);
    if (p.minimum)
        std::printf("minimum clearance %.4f at pose %zu (true: %.4f at pose %zu)\n", p.minimum_clearance, *p.minimum,
                    truth.back(), truth.size() - 1);
    std::printf("poses: %zu clear, %zu below the margin, %zu beyond the cap 0.5; %zu evaluations of f in all\n",
                p.counters.clear, p.counters.below_margin, p.counters.beyond_cap,
                p.counters.work.f_evaluations + p.counters.work.intersection.f_evaluations);
    // The margin lies 0.005 from the neighbouring true clearances, a quarter spacing here: the first
    // pose found may be off by one (the distance's accuracy is half a mean spacing).
    const bool ok = p.first_below_margin && *p.first_below_margin + 1 >= expected && *p.first_below_margin <= expected + 1 &&
                    p.minimum && std::abs(p.minimum_clearance - truth.back()) < 0.02;
    return ok ? 0 : 1;
}
