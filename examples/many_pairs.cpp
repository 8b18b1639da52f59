// Many object pairs in one call (doc/manual/intersection.md, "Many pairs at once"): a torus and a
// sphere, preprocessed once, posed in 200 pairs; do_intersect_many() answers them on every core (TBB)
// in input order, and pair i's answer is that of do_intersect() with the seed pair_seed(seed, i),
// whatever the number of threads -- the example checks one pair to show it.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cstddef>
#include <iostream>
#include <vector>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;
using Pair = PCCD::Posed_pair<Object>;
using Result = PCCD::Intersection_result;
using Clock = std::chrono::steady_clock;

int main()
{
    PCCD::Random_engine engine(3);
    const Object torus(PCCD::testing::Torus_shape(0.7, 0.3).sample(4000, engine).points);
    const Object sphere(PCCD::testing::Sphere_shape(Eigen::Vector3d::Zero(), 0.5).sample(2000, engine).points);

    // The sphere slides along x past the torus, turned a little more at each step.
    std::vector<Pair> pairs;
    for (std::size_t k = 0; k < 200; ++k) {
        const double x = -2.0 + 4.0 * double(k) / 199.0;
        const Pose pose(Eigen::AngleAxisd(0.05 * double(k), Eigen::Vector3d::UnitY()).toRotationMatrix(),
                        Eigen::Vector3d(x, 0.0, 0.2));
        pairs.push_back({&torus, Pose(), &sphere, pose});
    }

    // All available threads (Batch_options{.threads = n} sets a count).
    const PCCD::Intersection_options options{.seed = 11};
    const auto start = Clock::now();
    const std::vector<Result> results = PCCD::do_intersect_many(pairs, {}, options);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();

    std::size_t hits = 0;
    for (const Result& r : results) hits += r.intersects ? 1 : 0;
    std::cout << pairs.size() << " pairs in " << ms << " ms: " << hits << " intersecting\n";

    // Pair 57 again, alone: the same answer and work, from the documented seed.
    const std::size_t i = 57;
    const Result alone = PCCD::do_intersect(*pairs[i].a, pairs[i].pose_a, *pairs[i].b, pairs[i].pose_b,
                                            {.seed = PCCD::pair_seed(options.seed, i)});
    const bool same = alone.intersects == results[i].intersects && alone.counters == results[i].counters;
    std::cout << "pair " << i << ": " << PCCD::to_string(results[i].status) << ", "
              << results[i].counters.f_evaluations << " f evaluations; alone: " << PCCD::to_string(alone.status)
              << ", " << alone.counters.f_evaluations << " f evaluations (" << (same ? "same" : "DIFFERENT") << ")\n";
    return same ? 0 : 1;
}
