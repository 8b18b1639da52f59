// Watching a query (doc/manual/hierarchy.md, "Watching a query"): an Intersection_visitor that
// counts the node pairs and leaf pairs of the walk, the brackets of the interpolation search and
// the evaluations of f per object, and keeps the evaluation where |f| was smallest; two sphere
// clouds at a near miss and crossing. The visitor changes nothing in the answer.
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/Sphere_shape.h>

#include <cmath>
#include <cstdio>

struct Counting_visitor final : PCCD::Intersection_visitor {
    std::size_t node_pairs = 0, leaf_pairs = 0, brackets = 0, evaluations[2] = {0, 0};
    double smallest = INFINITY;
    Eigen::Vector3d where = Eigen::Vector3d::Zero();

    void node_pair(std::uint32_t, std::uint32_t) override { ++node_pairs; }
    void leaf_pair(std::uint32_t, std::uint32_t) override { ++leaf_pairs; }
    void bracket(const Eigen::Vector3d&, const Eigen::Vector3d&) override { ++brackets; }
    void evaluation(PCCD::Query_object object, const Eigen::Vector3d& x, const PCCD::Surface_evaluation& f) override
    {
        ++evaluations[int(object)];
        if (f.defined() && std::abs(f.value) < smallest) {
            smallest = std::abs(f.value);
            where = x;
        }
    }
};

int main()
{
    const PCCD::testing::Sphere_shape sphere(Eigen::Vector3d::Zero(), 1.0);
    PCCD::Random_engine engine(5);
    const PCCD::Point_cloud_object<> a(sphere.sample(5000, engine).points);
    const PCCD::Point_cloud_object<> b(sphere.sample(5000, engine).points);
    const PCCD::Rigid_transform_3<double> identity;
    for (const double d : {2.0 + a.sampling_radius(), 1.5}) { // a near miss, then crossing spheres
        const PCCD::Rigid_transform_3<double> pose_b(Eigen::Matrix3d::Identity(), Eigen::Vector3d(d, 0, 0));
        Counting_visitor visitor;
        const auto result = PCCD::do_intersect(a, identity, b, pose_b, {.visitor = &visitor});
        std::printf("d = %.3f: %s; %zu node pairs, %zu leaf pairs, %zu brackets, f_A %zu and f_B %zu times",
                    d, PCCD::to_string(result.status), visitor.node_pairs, visitor.leaf_pairs, visitor.brackets,
                    visitor.evaluations[0], visitor.evaluations[1]);
        if (std::isfinite(visitor.smallest))
            std::printf("; smallest |f| %.2e at (%.3f, %.3f, %.3f)", visitor.smallest, visitor.where.x(),
                        visitor.where.y(), visitor.where.z());
        std::printf("\n");
        // The visitor saw what the counters count.
        if (visitor.node_pairs != result.counters.node_pairs ||
            visitor.evaluations[0] + visitor.evaluations[1] != result.counters.f_evaluations)
            return 1;
    }
    return 0;
}
