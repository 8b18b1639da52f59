// First-hit queries that walk the two objects' hierarchies, and time-critical queries with a budget
// (doc/manual/hierarchy.md): two sphere clouds at a near miss, touching, and far apart, answered by
// the default walk (Traversal::likelihood), by the published flat traversal, and with a time budget
// of a few microseconds, which may leave the answer undecided but never wrongly "separate".
#include <PCCD/Hierarchy/Sphere_covering.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/Sphere_shape.h>

#include <cstdio>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;

int main()
{
    const PCCD::testing::Sphere_shape sphere(Eigen::Vector3d::Zero(), 1.0);
    PCCD::Random_engine engine(5);
    const Object a(sphere.sample(5000, engine).points);
    const Object b(sphere.sample(5000, engine).points);
    const PCCD::Point_cloud_hierarchy& h = a.hierarchy();
    const PCCD::Sphere_covering covering(h);
    std::printf("hierarchy: %zu nodes, depth %zu, largest reach %.4f; root covered by %zu spheres of radius %.3f\n",
                h.nodes().size(), h.height(), h.root().reach, covering.centres(0).size(), covering.radius(0));

    const Pose identity;
    const double r = a.sampling_radius();
    // Centres 1.5 apart (the spheres cross), 2 + r apart (a near miss), 3 apart (far).
    for (const double d : {1.5, 2.0 + r, 3.0}) {
        const Pose pose_b(Eigen::Matrix3d::Identity(), Eigen::Vector3d(d, 0, 0));
        const auto walked = PCCD::do_intersect(a, identity, b, pose_b);
        const auto flat = PCCD::do_intersect(a, identity, b, pose_b, {.traversal = PCCD::Traversal::flat});
        const auto timed = PCCD::do_intersect(a, identity, b, pose_b, {.max_time_us = 3.0});
        std::printf("d = %.3f: walk %s (%zu f evaluations), flat %s (%zu), 3 us budget %s\n", d,
                    PCCD::to_string(walked.status), walked.counters.f_evaluations, PCCD::to_string(flat.status),
                    flat.counters.f_evaluations, PCCD::to_string(timed.status));
        // A time budget may leave the answer undecided, never contradict the unlimited answer.
        if (timed.status != PCCD::Intersection_status::undecided && timed.intersects != walked.intersects) return 1;
    }
    return 0;
}
