// A collision world (doc/manual/world.md): two objects, a torus and a sphere, preprocessed once and
// shared by 60 instances at random poses; intersecting_pairs() answers every pair at once (broad
// phase, parallel narrow phase), then a few instances move and only their pairs are answered again
// (the cache). Filters keep the spheres from being tested against each other, one pair is excluded,
// and the example checks one reported pair against do_intersect() with the documented pair seed.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/World/Collision_world.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>
#include <PCCD/testing/pose_generator.h>

#include <cmath>
#include <cstddef>
#include <iostream>
#include <memory>
#include <vector>

using Object = PCCD::Point_cloud_object<>;
using Pose = PCCD::Rigid_transform_3<double>;
using World = PCCD::Collision_world<Object>;

int main()
{
    PCCD::Random_engine engine(5);
    const auto torus = std::make_shared<const Object>(PCCD::testing::Torus_shape(0.7, 0.3).sample(3000, engine).points);
    const auto sphere = std::make_shared<const Object>(
        PCCD::testing::Sphere_shape(Eigen::Vector3d::Zero(), 0.5).sample(1500, engine).points);

    const auto random_pose = [&] {
        const double side = 8.0; // about one intersecting pair per three instances
        return Pose(PCCD::testing::uniform_random_rotation(engine),
                    Eigen::Vector3d(PCCD::uniform_real(engine, 0, side), PCCD::uniform_real(engine, 0, side),
                                    PCCD::uniform_real(engine, 0, side)));
    };

    // Tori in group 1, spheres in group 2; a sphere's mask leaves out group 2: spheres never test
    // each other, every other pair is tested.
    PCCD::World_options options;
    options.intersection.seed = 7;
    World world(options);
    std::vector<PCCD::World_handle> handles;
    for (int i = 0; i < 60; ++i) {
        const bool is_torus = i % 2 == 0;
        const PCCD::Collision_filter filter = is_torus ? PCCD::Collision_filter{1, ~0u} : PCCD::Collision_filter{2, ~2u};
        handles.push_back(world.insert(is_torus ? torus : sphere, random_pose(), filter));
    }

    std::vector<PCCD::World_pair> pairs = world.intersecting_pairs();
    std::cout << world.size() << " instances of 2 objects: " << pairs.size() << " intersecting pairs, "
              << world.counters().narrow_phase_queries << " narrow-phase queries, " << world.memory_bytes()
              << " bytes\n";

    // Pair (a, b) is do_intersect with the seed pair_seed(seed, world_pair_key(a.index, b.index)).
    if (!pairs.empty()) {
        const PCCD::World_pair& p = pairs.front();
        PCCD::Intersection_options o = options.intersection;
        o.seed = PCCD::pair_seed(o.seed, PCCD::world_pair_key(p.a.index, p.b.index));
        const PCCD::Intersection_result r = PCCD::do_intersect(world.object(p.a), world.pose(p.a), world.object(p.b),
                                                               world.pose(p.b), o);
        std::cout << "pair (" << p.a.index << ", " << p.b.index << ") at " << p.point.transpose()
                  << "; do_intersect alone: " << (r.points.front().position == p.point ? "the same point" : "another point")
                  << '\n';
        // Two parts bolted together: never test them.
        world.exclude_pair(p.a, p.b);
    }

    // Five instances move: the cache answers every pair that did not.
    for (int k = 0; k < 5; ++k) world.set_pose(handles[std::size_t(10 * k)], random_pose());
    pairs = world.intersecting_pairs();
    std::cout << "after 5 moves: " << pairs.size() << " pairs, " << world.counters().narrow_phase_queries
              << " narrow-phase queries, " << world.counters().cached_pairs << " answers from the cache\n";

    // Which instances does one more sphere, outside the world, touch?
    const std::vector<PCCD::World_hit> hits = world.intersecting(*sphere, Pose(Eigen::Matrix3d::Identity(),
                                                                             Eigen::Vector3d(2.5, 2.5, 2.5)));
    std::cout << "a sphere at (2.5, 2.5, 2.5) touches " << hits.size() << (hits.size() == 1 ? " instance\n" : " instances\n");
}
