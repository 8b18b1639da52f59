// A scan with noise and stray points (doc/manual/surface.md, "Scans"): what preprocessing finds out
// about it (noise estimate, outliers left out, the surface's domain) and what a query does with it
// (candidates that are no common zero of both surfaces are rejected, not reported). The cloud is a
// procedural torus with Gaussian noise of half a mean spacing and 1 % points scattered in its
// bounding box, so the example needs no data files.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/Torus_shape.h>

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;
using Vector = Eigen::Vector3d;

int main()
{
    // 8000 points on a torus (spacing about 0.5 sqrt(area / n)), noise 0.5 spacings, 80 stray points.
    const PCCD::testing::Torus_shape torus(0.7, 0.3);
    const double spacing = 0.5 * std::sqrt(torus.area() / 8000.0);
    PCCD::Random_engine engine(3);
    Eigen::Matrix3Xd points = torus.sample(8000, engine, {.noise_sigma = 0.5 * spacing}).points;
    points.conservativeResize(3, 8080);
    for (Eigen::Index k = 8000; k < 8080; ++k)
        points.col(k) = Vector(PCCD::uniform_real(engine, -1.0, 1.0), PCCD::uniform_real(engine, -1.0, 1.0),
                               PCCD::uniform_real(engine, -0.3, 0.3));

    const Object scan(points); // outliers removed, noise estimated, domain set: all by default
    std::cout << scan.scan().input_points << " points given, " << scan.scan().outliers.size()
              << " left out as isolated outliers\n"
              << "noise estimate " << scan.noise_estimate() / spacing << " spacings (true: 0.5)\n";

    // Far from the data f is undefined, and says why.
    const PCCD::Surface_evaluation far = scan.surface().evaluate(Vector(0.7, 0.0, 0.3 + 6.0 * spacing));
    std::cout << "6 spacings above the tube: " << PCCD::to_string(far.status) << '\n';

    // Two copies: apart by a few spacings, then overlapping.
    for (const double gap : {4.0 * spacing, -0.2}) {
        const Pose pose_b(Eigen::Matrix3d::Identity(), Vector(0.0, 0.0, 0.6 + gap));
        const PCCD::Intersection_result result = PCCD::do_intersect(scan, Pose(), scan, pose_b, {.seed = 1});
        std::cout << "gap " << gap << ": " << PCCD::to_string(result.status) << ", "
                  << result.counters.candidates_rejected << " candidates rejected";
        if (result.intersects)
            std::cout << ", contact at " << result.points[0].position.transpose() << " with |f_A|, |f_B| = "
                      << std::abs(result.points[0].f_a) << ", " << std::abs(result.points[0].f_b);
        std::cout << '\n';
    }
    return 0;
}
