// How far apart two scans are, how deep they interpenetrate, where they touch, and whether they keep
// a clearance (doc/manual/proximity.md). Two torus scans (PCCD::testing's analytic torus, sampled
// by area with a little noise) are preprocessed once; distance(), contacts() and within_distance()
// then answer for any pair of rigid poses. The torus's analytic distance is printed beside the
// answers so that the figures can be judged.
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/contacts.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Torus_shape.h>

#include <cmath>
#include <iostream>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;

int main()
{
    // Two scans of a torus of radii 0.7 and 0.3, 8,000 points each, noise 0.002.
    const PCCD::testing::Torus_shape torus(0.7, 0.3);
    PCCD::Random_engine engine(3);
    const auto scan = [&] {
        Eigen::Matrix3Xd points = torus.sample(8000, engine).points;
        for (Eigen::Index i = 0; i < points.cols(); ++i)
            for (int d = 0; d < 3; ++d) points(d, i) += 0.002 * PCCD::standard_normal(engine);
        return points;
    };
    const Object a(scan()), b(scan());
    const Pose identity;

    // Side by side along x: the outer equators are 2 (0.7 + 0.3) apart at the centres' distance
    // 2.0 + gap, so the surfaces are `gap` apart.
    const double gap = 0.05;
    const Pose apart(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0 + gap, 0.0, 0.0));
    const PCCD::Distance_result d = PCCD::distance(a, identity, b, apart);
    std::cout << "separate: " << PCCD::to_string(d.status) << ", distance " << d.distance << " (analytic " << gap
              << "), honest interval [" << d.lower_bound << ", " << d.upper_bound << "]\n"
              << "  witnesses " << d.point_a.transpose() << "  and  " << d.point_b.transpose() << "\n"
              << "  work: " << d.counters.node_pairs << " node pairs, "
              << d.counters.f_evaluations + d.counters.intersection.f_evaluations << " evaluations of f\n";

    // Clearance: do they come within 0.1? within 0.02?
    std::cout << "within 0.1: " << bool(PCCD::within_distance(a, identity, b, apart, 0.1))
              << ", within 0.02: " << bool(PCCD::within_distance(a, identity, b, apart, 0.02)) << "\n";

    // Pushed 0.08 into each other: the local penetration depth and the direction to push B out.
    const Pose overlapping(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.0 - 0.08, 0.0, 0.0));
    const PCCD::Distance_result p = PCCD::distance(a, identity, b, overlapping, {.penetration = true});
    std::cout << "overlapping: " << PCCD::to_string(p.status) << ", depth " << p.depth << " (analytic 0.08), contact normal "
              << p.contact_normal.transpose() << "\n";

    // The contact regions a physics engine would consume.
    const PCCD::Contact_result c = PCCD::contacts(a, identity, b, overlapping);
    for (const PCCD::Contact& k : c.contacts)
        std::cout << "  contact at " << k.position.transpose() << ", depth " << k.depth << ", normal " << k.normal.transpose()
                  << "\n";
    const bool ok = d.status == PCCD::Intersection_status::separate && std::abs(d.distance - gap) < 0.01 &&
                    p.intersecting() && std::abs(p.depth - 0.08) < 0.02 && c.contacts.size() == 1;
    return ok ? 0 : 1;
}
