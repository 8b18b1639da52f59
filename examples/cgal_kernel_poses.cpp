// PCCD with a CGAL kernel (doc/manual/intersection.md, "CGAL kernels and poses"): the points are
// CGAL::Exact_predicates_inexact_constructions_kernel points drawn by CGAL's own generator, the
// object is a Point_cloud_object<Epick> built from them with no point map, and the poses are
// CGAL::Aff_transformation_3 objects, which Rigid_transform_3 reads (and checks for rigidity).
// Two unit spheres touch exactly when their centres are less than 2 apart: the example checks the
// answers against that.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/point_generators_3.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;
using Aff_transformation_3 = CGAL::Aff_transformation_3<Kernel>;
using Object = PCCD::Point_cloud_object<Kernel>;
using Pose = PCCD::Rigid_transform_3<double>;

int main()
{
    // 4000 points on the unit sphere from CGAL's generator, twice.
    CGAL::Random random(7);
    CGAL::Random_points_on_sphere_3<Point_3> on_sphere(1.0, random);
    std::vector<Point_3> a_points, b_points;
    std::copy_n(on_sphere, 4000, std::back_inserter(a_points));
    std::copy_n(on_sphere, 4000, std::back_inserter(b_points));
    const Object a(a_points, {.threads = 2});
    const Object b(b_points, {.threads = 2});

    // B turned by 0.4 about z (a rotation that CGAL stores as a 3 x 4 matrix), then moved along x.
    const double c = std::cos(0.4), s = std::sin(0.4);
    const Aff_transformation_3 turn(c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0);
    bool right = true;
    for (const double d : {1.0, 1.9, 2.1, 3.0}) {
        const Aff_transformation_3 pose_b = Aff_transformation_3(CGAL::TRANSLATION, Vector_3(d, 0, 0)) * turn;
        const PCCD::Intersection_result result = PCCD::do_intersect(a, Pose(), b, Pose(pose_b), {.seed = 3});
        const bool truth = d < 2.0;
        right = right && result.intersects == truth;
        std::cout << "centres " << d << " apart: " << PCCD::to_string(result.status) << " (exact: "
                  << (truth ? "intersecting" : "separate") << "), " << result.counters.f_evaluations
                  << " f evaluations\n";
    }
    // A scaling is no rigid motion: refused with a message.
    try {
        (void)Pose(Aff_transformation_3(CGAL::SCALING, 2.0));
        right = false;
    } catch (const PCCD::Invalid_input& e) {
        std::cout << "a scaling pose is refused: " << e.what() << '\n';
    }
    return right ? 0 : 1;
}
