// Tests of Collision_world (doc/manual/world.md): on random scenes of 10 to 200 shared sphere and
// torus clouds (fixed seeds), after random moves, insertions and erasures, the intersecting pairs
// equal those of brute-force do_intersect over all pairs with the documented pair seed; the answers
// do not depend on the thread count, the cache or the world boxes' depth; filters, excluded pairs,
// the one-object queries, within_distance, box and ray queries agree with brute force; bad input gets
// Invalid_input.
#include <PCCD/World/Collision_world.h>
#include <PCCD/World/World_handle.h>
#include <PCCD/World/World_options.h>
#include <PCCD/World/World_results.h>
#include <PCCD/World/world_box.h>

#include <catch2/catch.hpp>

#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/ray_intersection.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using Object = PCCD::Point_cloud_object<>;
using World = PCCD::Collision_world<Object>;
using PCCD::World_handle;

/// Four shared objects: a sphere and a torus cloud at two scales (a few hundred points each).
const std::vector<std::shared_ptr<const Object>>& shapes()
{
    static const std::vector<std::shared_ptr<const Object>> objects = [] {
        std::vector<std::shared_ptr<const Object>> out;
        const auto sphere = pccd_test::sample_shape(pccd_test::unit_sphere(), 500, 0.0, 31);
        const auto torus = pccd_test::sample_shape(pccd_test::test_torus(), 700, 0.0, 32);
        for (const double scale : {0.5, 1.0}) {
            out.push_back(std::make_shared<const Object>(pccd_test::columns(scale * sphere.points)));
            out.push_back(std::make_shared<const Object>(pccd_test::columns(scale * torus.points)));
        }
        return out;
    }();
    return objects;
}

Rigid_transform_3<double> random_pose(PCCD::Random_engine& engine, double side)
{
    const Eigen::Vector3d t(PCCD::uniform_real(engine, 0, side), PCCD::uniform_real(engine, 0, side),
                            PCCD::uniform_real(engine, 0, side));
    return Rigid_transform_3<double>(PCCD::testing::uniform_random_rotation(engine), t);
}

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

bool same(const PCCD::World_pair& x, const PCCD::World_pair& y)
{
    return x.a == y.a && x.b == y.b && x.status == y.status && same_bits(x.point.x(), y.point.x()) &&
           same_bits(x.point.y(), y.point.y()) && same_bits(x.point.z(), y.point.z());
}

/// Every allowed pair answered by do_intersect with the documented seed, in key order.
std::vector<PCCD::World_pair> brute_force(const World& world)
{
    std::vector<PCCD::World_pair> out;
    const std::vector<World_handle> handles = world.handles();
    for (std::size_t i = 0; i < handles.size(); ++i)
        for (std::size_t j = i + 1; j < handles.size(); ++j) {
            const World_handle a = handles[i], b = handles[j];
            if (!PCCD::may_collide(world.filter(a), world.filter(b)) || world.excluded(a, b)) continue;
            PCCD::Intersection_options options = world.options().intersection;
            options.seed = PCCD::pair_seed(options.seed, PCCD::world_pair_key(a.index, b.index));
            const PCCD::Intersection_result r = PCCD::do_intersect(world.object(a), world.pose(a), world.object(b),
                                                                   world.pose(b), options);
            if (r.status == PCCD::Intersection_status::separate) continue;
            PCCD::World_pair p{a, b, r.status, Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN())};
            if (!r.points.empty()) p.point = r.points.front().position;
            out.push_back(p);
        }
    return out;
}

void require_same(const std::vector<PCCD::World_pair>& x, const std::vector<PCCD::World_pair>& y)
{
    REQUIRE(x.size() == y.size());
    for (std::size_t i = 0; i < x.size(); ++i) REQUIRE(same(x[i], y[i]));
}

/// A side of the scene cube giving about two touching neighbours per object.
double scene_side(std::size_t n) { return std::cbrt(2.5 * double(n)); }

} // namespace

TEST_CASE("Collision_world: intersecting pairs equal brute-force do_intersect after moves, insertions and erasures",
          "[world]")
{
    for (const std::size_t n : {10u, 60u, 200u}) {
        PCCD::Random_engine engine(100 + n);
        const double side = scene_side(n);
        PCCD::World_options options;
        options.threads = 2;
        World world(options);
        World_handle last{};
        for (std::size_t i = 0; i < n; ++i)
            last = world.insert(shapes()[PCCD::uniform_index(engine, shapes().size())], random_pose(engine, side));
        std::size_t total_pairs = 0;
        for (int step = 0; step < 4; ++step) {
            const auto pairs = world.intersecting_pairs();
            require_same(pairs, brute_force(world));
            total_pairs += pairs.size();
            for (const auto& p : pairs) CHECK(p.a.index < p.b.index);
            // Move 10-30 %, erase a few, insert a few.
            std::vector<World_handle> handles = world.handles();
            for (const World_handle h : handles)
                if (PCCD::uniform_01(engine) < 0.1 + 0.05 * step) world.set_pose(h, random_pose(engine, side));
            for (int k = 0; k < int(n / 10) + 1; ++k) {
                handles = world.handles();
                world.erase(handles[PCCD::uniform_index(engine, handles.size())]);
            }
            for (int k = 0; k < int(n / 10) + 1; ++k)
                last = world.insert(shapes()[PCCD::uniform_index(engine, shapes().size())], random_pose(engine, side));
            world.broad_phase().check_invariants();
        }
        CHECK(world.contains(last));
        // The scenes do collide: on average about one pair per object per step.
        CHECK(double(total_pairs) >= 0.3 * 4.0 * double(n));
        INFO("n = " << n << ", pairs over 4 steps: " << total_pairs);
    }
}

TEST_CASE("Collision_world: steps that change few instances keep the other candidates and stay exact", "[world]")
{
    // Steps of 200 instances changing a few each (moves, a filter, an exclusion, an erasure and
    // a re-insertion into the freed slot): below a quarter changed, the world looks up only the
    // changed instances' boxes. Its pairs must equal brute force's, and its candidates those of a
    // world built afresh with the same instances in the same slots.
    PCCD::Random_engine engine(2024);
    const std::size_t n = 200;
    const double side = scene_side(n);
    World world;
    std::vector<World_handle> handles;
    for (std::size_t i = 0; i < n; ++i)
        handles.push_back(world.insert(shapes()[PCCD::uniform_index(engine, shapes().size())], random_pose(engine, side)));
    world.intersecting_pairs();
    std::size_t lighter_steps = 0;
    for (int step = 0; step < 6; ++step) {
        for (int k = 0; k < 8; ++k) {
            const World_handle h = handles[PCCD::uniform_index(engine, handles.size())];
            world.set_pose(h, random_pose(engine, side));
        }
        if (step == 1) world.set_filter(handles[3], {2u, 2u});
        if (step == 2) world.exclude_pair(handles[10], handles[11]);
        if (step == 3) {
            const std::size_t k = PCCD::uniform_index(engine, handles.size());
            const auto object = world.shared_object(handles[k]);
            const auto pose = world.pose(handles[k]);
            world.erase(handles[k]);
            handles[k] = world.insert(object, random_pose(engine, side)); // the freed slot
            CHECK(handles[k].index < n);
            world.set_pose(handles[k], pose);
        }
        if (step == 4) world.include_pair(handles[10], handles[11]);
        const auto pairs = world.intersecting_pairs();
        require_same(pairs, brute_force(world));
        const PCCD::World_counters incremental = world.counters();

        PCCD::World_options fresh_options;
        fresh_options.cache_results = false;
        World fresh(fresh_options);
        for (const World_handle h : world.handles()) {
            const World_handle g = fresh.insert(world.shared_object(h), world.pose(h), world.filter(h));
            REQUIRE(g.index == h.index);
        }
        for (const World_handle h : world.handles())
            for (const World_handle g : world.handles())
                if (h.index < g.index && world.excluded(h, g))
                    fresh.exclude_pair(World_handle{h.index, 0}, World_handle{g.index, 0});
        const auto fresh_pairs = fresh.intersecting_pairs(); // handles of generation 0: compare indices
        REQUIRE(fresh_pairs.size() == pairs.size());
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            CHECK(fresh_pairs[i].a.index == pairs[i].a.index);
            CHECK(fresh_pairs[i].b.index == pairs[i].b.index);
            CHECK(fresh_pairs[i].status == pairs[i].status);
        }
        CHECK(incremental.cached_pairs + incremental.narrow_phase_queries == fresh.counters().narrow_phase_queries);
        if (incremental.broad_phase_pairs < fresh.counters().broad_phase_pairs) ++lighter_steps;
    }
    // The lookups of the changed instances hand on fewer pairs than a walk of the whole tree.
    CHECK(lighter_steps == 6);
}

TEST_CASE("Collision_world: the cache and the thread count do not change the answers", "[world]")
{
    PCCD::Random_engine engine(7);
    const std::size_t n = 80;
    const double side = scene_side(n);
    PCCD::World_options one, two, uncached;
    one.threads = 1;
    two.threads = 2;
    uncached.cache_results = false;
    uncached.box_depth = 0; // looser boxes: more candidates, the same answers
    World w1(one), w2(two), w3(uncached);
    std::vector<World_handle> handles;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& object = shapes()[i % shapes().size()];
        const auto pose = random_pose(engine, side);
        handles.push_back(w1.insert(object, pose));
        w2.insert(object, pose);
        w3.insert(object, pose);
    }
    const auto first = w1.intersecting_pairs();
    CHECK(w1.counters().cached_pairs == 0);
    const std::size_t candidates = w1.counters().narrow_phase_queries;
    require_same(first, w2.intersecting_pairs());
    require_same(first, w3.intersecting_pairs());
    // Nothing moved: every answer comes from the cache.
    require_same(first, w1.intersecting_pairs());
    CHECK(w1.counters().narrow_phase_queries == 0);
    CHECK(w1.counters().cached_pairs == candidates);
    // One instance moves: only its pairs are answered again.
    const auto moved_pose = random_pose(engine, side);
    for (World* w : {&w1, &w2, &w3}) w->set_pose(handles[5], moved_pose);
    const auto second = w1.intersecting_pairs();
    CHECK(w1.counters().narrow_phase_queries <= w1.counters().cached_pairs + w1.counters().narrow_phase_queries);
    std::size_t involving = 0;
    w1.broad_phase().for_each_overlapping(w1.box(handles[5]), [&](std::uint32_t) { ++involving; });
    CHECK(w1.counters().narrow_phase_queries <= involving);
    require_same(second, w2.intersecting_pairs());
    require_same(second, w3.intersecting_pairs());
    require_same(second, brute_force(w1));
    CHECK(w3.counters().cached_pairs == 0);
}

TEST_CASE("Collision_world: filters, excluded pairs and early stop", "[world]")
{
    PCCD::Random_engine engine(11);
    const std::size_t n = 60;
    const double side = scene_side(n);
    World world;
    std::vector<World_handle> handles;
    for (std::size_t i = 0; i < n; ++i) {
        // Three groups; group 4 ignores group 2.
        const std::uint32_t group = 1u << (i % 3);
        const std::uint32_t mask = group == 4u ? ~2u : ~0u;
        handles.push_back(world.insert(shapes()[i % shapes().size()], random_pose(engine, side), {group, mask}));
    }
    const auto all = world.intersecting_pairs();
    REQUIRE(all.size() >= 6);
    for (const auto& p : all) CHECK(PCCD::may_collide(world.filter(p.a), world.filter(p.b)));
    // Exclude two of the reported pairs: they disappear, the rest stays.
    world.exclude_pair(all[0].a, all[0].b);
    world.exclude_pair(all[2].b, all[2].a);
    CHECK(world.excluded(all[0].b, all[0].a));
    CHECK_FALSE(world.tested(all[0].a, all[0].b));
    auto fewer = world.intersecting_pairs();
    require_same(fewer, brute_force(world));
    CHECK(fewer.size() == all.size() - 2);
    world.include_pair(all[0].a, all[0].b);
    CHECK(world.intersecting_pairs().size() == all.size() - 1);
    // A filter change takes effect at once (the cached answer is still right for the pair).
    world.set_filter(all[1].a, {8u, 8u});
    require_same(world.intersecting_pairs(), brute_force(world));
    // Early stop: the first three pairs, in order.
    const auto full = world.intersecting_pairs();
    std::vector<PCCD::World_pair> seen;
    world.for_each_intersecting_pair([&](const PCCD::World_pair& p) {
        seen.push_back(p);
        return seen.size() < 3;
    });
    REQUIRE(seen.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) CHECK(same(seen[i], full[i]));
    // Erasing an instance drops its exclusions.
    world.erase(all[2].a);
    const World_handle again = world.insert(shapes()[0], world.pose(all[2].b));
    CHECK(again.index == all[2].a.index);
    CHECK(again.generation != all[2].a.generation);
    CHECK_FALSE(world.excluded(again, all[2].b));
}

TEST_CASE("Collision_world: one-object queries agree with brute force", "[world]")
{
    PCCD::Random_engine engine(21);
    const std::size_t n = 50;
    const double side = scene_side(n);
    World world;
    for (std::size_t i = 0; i < n; ++i) world.insert(shapes()[i % shapes().size()], random_pose(engine, side));
    const auto pairs = world.intersecting_pairs();
    // intersecting(h) = the pairs containing h.
    for (const World_handle h : world.handles()) {
        std::vector<World_handle> expected;
        for (const auto& p : pairs) {
            if (p.a == h) expected.push_back(p.b);
            if (p.b == h) expected.push_back(p.a);
        }
        std::sort(expected.begin(), expected.end());
        std::vector<World_handle> got;
        for (const auto& hit : world.intersecting(h)) got.push_back(hit.handle);
        CHECK(got == expected);
    }
    // A query object not in the world: do_intersect with seed pair_seed(seed, index) against each.
    const Object& query = *shapes()[3];
    for (int q = 0; q < 5; ++q) {
        const auto pose = random_pose(engine, side);
        std::vector<World_handle> expected;
        for (const World_handle h : world.handles()) {
            PCCD::Intersection_options o = world.options().intersection;
            o.seed = PCCD::pair_seed(o.seed, h.index);
            if (PCCD::do_intersect(query, pose, world.object(h), world.pose(h), o).status != PCCD::Intersection_status::separate)
                expected.push_back(h);
        }
        std::vector<World_handle> got;
        for (const auto& hit : world.intersecting(query, pose)) got.push_back(hit.handle);
        CHECK(got == expected);
        // within_distance: brute force over all instances.
        const double margin = 0.2;
        std::vector<World_handle> near_expected;
        for (const World_handle h : world.handles())
            if (PCCD::within_distance(query, pose, world.object(h), world.pose(h), margin).within) near_expected.push_back(h);
        std::vector<World_handle> near;
        for (const auto& w : world.within_distance(query, pose, margin)) near.push_back(w.handle);
        CHECK(near == near_expected);
        // Everything that intersects is within any margin.
        for (const World_handle h : got) CHECK(std::find(near.begin(), near.end(), h) != near.end());
    }
    // The callback forms stop early and agree with the lists.
    for (const World_handle h : world.handles()) {
        const auto all = world.intersecting(h);
        if (all.size() < 2) continue;
        std::vector<World_handle> first;
        world.for_each_intersecting(h, [&](const PCCD::World_hit& hit) {
            first.push_back(hit.handle);
            return false;
        });
        REQUIRE(first.size() == 1);
        CHECK(first[0] == all[0].handle);
        break;
    }
    {
        const Eigen::AlignedBox3d everything(Eigen::Vector3d::Constant(-10.0), Eigen::Vector3d::Constant(side + 10.0));
        CHECK(world.overlapping(everything) == world.handles());
        int calls = 0;
        world.for_each_overlapping(everything, [&](World_handle) { return ++calls < 4; });
        CHECK(calls == 4);
        calls = 0;
        world.for_each_within_distance(world.handles()[1], 50.0, [&](const PCCD::World_proximity& w) {
            CHECK(w.clearance.within);
            return ++calls < 2;
        });
        CHECK(calls == 2);
    }
    // within_distance of an instance.
    const World_handle h0 = world.handles().front();
    std::vector<World_handle> near_expected;
    for (const World_handle h : world.handles())
        if (h != h0 && PCCD::within_distance(world.object(h0), world.pose(h0), world.object(h), world.pose(h), 0.5).within)
            near_expected.push_back(h);
    std::vector<World_handle> near;
    for (const auto& w : world.within_distance(h0, 0.5)) near.push_back(w.handle);
    CHECK(near == near_expected);
    // Box queries: instances with a cloud point in the box.
    for (int q = 0; q < 10; ++q) {
        const Eigen::Vector3d c(PCCD::uniform_real(engine, 0, side), PCCD::uniform_real(engine, 0, side),
                                PCCD::uniform_real(engine, 0, side));
        const Eigen::AlignedBox3d box(c - Eigen::Vector3d::Constant(0.7), c + Eigen::Vector3d::Constant(0.7));
        std::vector<World_handle> expected;
        for (const World_handle h : world.handles()) {
            const Object& o = world.object(h);
            for (std::uint32_t i = 0; i < o.size(); ++i)
                if (box.contains(world.pose(h).transform_point(o.cloud().position(i).cast<double>()))) {
                    expected.push_back(h);
                    break;
                }
        }
        CHECK(world.overlapping(box) == expected);
    }
}

TEST_CASE("Collision_world: rays against the world agree with ray_intersection on every instance", "[world]")
{
    PCCD::Random_engine engine(31);
    const std::size_t n = 40;
    const double side = scene_side(n);
    World world;
    for (std::size_t i = 0; i < n; ++i)
        world.insert(shapes()[i % shapes().size()], random_pose(engine, side), {i % 2 == 0 ? 1u : 2u, ~0u});
    std::size_t hits = 0;
    for (int q = 0; q < 40; ++q) {
        const Eigen::Vector3d origin(PCCD::uniform_real(engine, -1, side + 1), PCCD::uniform_real(engine, -1, side + 1), -2.0);
        const Eigen::Vector3d target(PCCD::uniform_real(engine, 0, side), PCCD::uniform_real(engine, 0, side), side);
        const Eigen::Vector3d direction = target - origin;
        const double t_max = q % 4 == 0 ? 0.5 * direction.norm() : std::numeric_limits<double>::infinity();
        const PCCD::Collision_filter only_even{1u, 1u};
        for (const bool filtered : {false, true}) {
            // Brute force: every instance's first hit, sorted by t.
            std::vector<std::pair<double, World_handle>> expected;
            for (const World_handle h : world.handles()) {
                if (filtered && !PCCD::may_collide(only_even, world.filter(h))) continue;
                const PCCD::Ray_hit r = PCCD::ray_intersection(world.object(h), world.pose(h), origin, direction, t_max);
                REQUIRE(r.status != PCCD::Ray_status::undecided);
                if (r.hit) expected.emplace_back(r.t, h);
            }
            std::sort(expected.begin(), expected.end());
            std::vector<std::pair<double, World_handle>> found;
            world.for_each_ray_hit(origin, direction, t_max, {}, filtered ? only_even : PCCD::Collision_filter{},
                                   [&](const PCCD::World_ray_hit& h) { found.emplace_back(h.hit.t, h.handle); });
            CHECK(found == expected);
            const auto first = world.ray_cast(origin, direction, t_max, {}, filtered ? only_even : PCCD::Collision_filter{});
            REQUIRE(first.has_value() == !expected.empty());
            if (first) {
                CHECK(first->handle == expected.front().second);
                CHECK(first->hit.t == expected.front().first);
                ++hits;
            }
        }
    }
    CHECK(hits >= 10);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(world.ray_cast(Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d::UnitZ()), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.ray_cast(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.ray_cast(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), -1.0), PCCD::Invalid_input);
}

TEST_CASE("Collision_world: world boxes hold every point's domain ball", "[world]")
{
    PCCD::Random_engine engine(5);
    for (const auto& object : shapes()) {
        REQUIRE(object->hierarchy().has_reach());
        for (int k = 0; k < 5; ++k) {
            const auto pose = random_pose(engine, 3.0);
            for (const int depth : {0, 2, 5}) {
                const Eigen::AlignedBox3d box = PCCD::world_box(*object, pose, depth);
                for (std::uint32_t i = 0; i < object->size(); ++i) {
                    const Eigen::Vector3d p = pose.transform_point(object->cloud().position(i).cast<double>());
                    const double r = object->domain_radii()(i) * (1.0 - 1e-12);
                    REQUIRE(box.contains(Eigen::AlignedBox3d(p.array() - r, p.array() + r)));
                }
            }
            // Deeper levels are no looser.
            CHECK(PCCD::world_box(*object, pose, 0).contains(PCCD::world_box(*object, pose, 4)));
        }
    }
}

TEST_CASE("Collision_world: memory per instance of a shared object", "[world]")
{
    PCCD::Random_engine engine(3);
    World world;
    // A scene as the benchmark's: about four candidate pairs (overlapping world boxes) per instance.
    const std::size_t n = 1000;
    const double side = 2.0 * scene_side(n);
    for (std::size_t i = 0; i < n; ++i) world.insert(shapes()[i % shapes().size()], random_pose(engine, side));
    world.intersecting_pairs(); // the cache filled
    const double per_instance = double(world.memory_bytes()) / double(world.size());
    INFO("bytes per instance: " << per_instance << "; tree " << world.broad_phase().memory_bytes() << ", candidate pairs "
                                 << world.counters().narrow_phase_queries << ", broad-phase pairs "
                                 << world.counters().broad_phase_pairs);
    CHECK(per_instance <= 1024.0);
    CHECK(world.counters().narrow_phase_queries >= 2 * n); // the cache holds answers
    CHECK(per_instance >= double(sizeof(Rigid_transform_3<double>))); // the count is not empty
}

TEST_CASE("Collision_world: bad input gets Invalid_input", "[world]")
{
    World world;
    const World_handle a = world.insert(shapes()[0], Rigid_transform_3<double>());
    const World_handle b = world.insert(shapes()[1], Rigid_transform_3<double>());
    CHECK_THROWS_AS(world.insert(nullptr, Rigid_transform_3<double>()), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.set_pose(World_handle{}, Rigid_transform_3<double>()), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.set_pose(World_handle{99, 0}, Rigid_transform_3<double>()), PCCD::Invalid_input);
    world.erase(b);
    CHECK_THROWS_AS(world.erase(b), PCCD::Invalid_input); // erasing twice
    CHECK_THROWS_AS(world.set_pose(b, Rigid_transform_3<double>()), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.pose(b), PCCD::Invalid_input);
    CHECK_THROWS_WITH(world.intersecting(b), Catch::Matchers::Contains("stale"));
    const World_handle c = world.insert(shapes()[1], Rigid_transform_3<double>());
    CHECK_THROWS_AS(world.set_pose(b, Rigid_transform_3<double>()), PCCD::Invalid_input); // same slot, new generation
    CHECK_THROWS_AS(world.exclude_pair(a, a), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.within_distance(a, -1.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.within_distance(a, std::numeric_limits<double>::quiet_NaN()), PCCD::Invalid_input);
    CHECK_THROWS_AS(world.overlapping(Eigen::AlignedBox3d()), PCCD::Invalid_input);
    const std::vector<World_handle> hs{a, c};
    const std::vector<Rigid_transform_3<double>> one_pose(1);
    CHECK_THROWS_AS(world.set_poses(hs, one_pose), PCCD::Invalid_input);
    // A NaN pose cannot be built at all.
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    r(0, 0) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(Rigid_transform_3<double>(r, Eigen::Vector3d::Zero()), PCCD::Invalid_input);
    PCCD::World_options bad;
    bad.threads = 0;
    CHECK_THROWS_AS(World(bad), PCCD::Invalid_input);
    PCCD::World_options visitor;
    PCCD::Intersection_visitor watcher;
    visitor.intersection.visitor = &watcher;
    CHECK_THROWS_AS(World(visitor), PCCD::Invalid_input);
    PCCD::World_options tree;
    tree.tree.fat_margin = -1.0;
    CHECK_THROWS_AS(World(tree), PCCD::Invalid_input);
    PCCD::World_options depth;
    depth.box_depth = -1;
    CHECK_THROWS_AS(World(depth), PCCD::Invalid_input);
    depth.box_depth = 33;
    CHECK_THROWS_AS(World(depth), PCCD::Invalid_input);
    CHECK(world.size() == 2);
}
