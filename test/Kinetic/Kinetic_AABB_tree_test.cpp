// Kinetic AABB tree (doc/manual/kinetic.md, "Building and advancing" and "Changing the animation at
// run time"): at 1,000 random times per scene every node's box equals the brute-force box of its
// primitives' vertices (exact comparison of the extreme vertices' coordinates, ties allowed); the
// same after flightplan changes and after insertions and removals; the number of events over an
// animation with linear flightplans stays within the stated bound; ties and simultaneous events are
// deterministic; the event queue agrees with an ordered set.
// Also covers Kinetic/Kinetic_statistics.h: the test cases below exercise what it declares.
#include <PCCD/Kinetic/Event_queue.h>
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Kinetic_statistics.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Kinetic/Polynomial_flightplan.h>
#include <PCCD/Kinetic/Refit_AABB_tree.h>
#include <PCCD/Random.h>

#include <PCCD/testing/scenes/Cloth_scene.h>
#include <PCCD/testing/scenes/Deforming_cloud_scene.h>
#include <PCCD/testing/scenes/Random_motion_scene.h>

#include <catch2/catch.hpp>

#include "kinetic_test_helpers.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>
#include "data_helpers.h"

namespace {

/// Checks every node of `tree` at its current time against brute force: the box of all vertices of
/// the primitives below it, computed from the flightplans. Returns the number of nodes checked.
template <class Tree>
std::size_t check_against_brute_force(const Tree& tree)
{
    using Node = typename Tree::Node_index;
    if (tree.root() == Tree::no_node) return 0;
    const double t = tree.now();
    const std::vector<Node> order = pccd_test::nodes_in_preorder(tree);
    std::vector<Eigen::AlignedBox3d> truth(tree.node_count() + 64);
    std::size_t mismatches = 0;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const Node n = *it;
        Eigen::AlignedBox3d box;
        if (tree.is_leaf(n)) {
            const auto& p = tree.primitive(tree.leaf_primitive(n));
            for (std::size_t k = 0; k < std::remove_cvref_t<decltype(p)>::vertex_count; ++k)
                box.extend(tree.flightplan(p.vertex(k)).position(t));
        } else {
            box = truth[tree.left(n)].merged(truth[tree.right(n)]);
        }
        if (n >= truth.size()) truth.resize(n + 1);
        truth[n] = box;
        for (int b = 0; b < 6; ++b) {
            const auto v = tree.extreme_vertex(n, b);
            const double value = tree.flightplan(v).coordinate(b % 3, t);
            const double expected = b < 3 ? box.min()[b % 3] : box.max()[b % 3];
            if (value != expected) ++mismatches;
            // The extreme is one of the node's candidates: a vertex of a leaf's primitive; for an
            // inner node, the extreme of an inner child or any vertex of a leaf child (leaves
            // store no extremes, ties among a primitive's vertices are resolved at the parent).
            const auto leaf_has = [&](Node leaf) {
                const auto& p = tree.primitive(tree.leaf_primitive(leaf));
                bool found = false;
                for (std::size_t k = 0; k < std::remove_cvref_t<decltype(p)>::vertex_count; ++k)
                    found = found || p.vertex(k) == v;
                return found;
            };
            if (tree.is_leaf(n)) {
                CHECK(leaf_has(n));
            } else {
                const auto child_has = [&](Node c) { return tree.is_leaf(c) ? leaf_has(c) : v == tree.extreme_vertex(c, b); };
                CHECK((child_has(tree.left(n)) || child_has(tree.right(n))));
            }
        }
        if (mismatches != 0) {
            INFO("node " << n << " at t = " << t);
            REQUIRE(mismatches == 0);
        }
    }
    return order.size();
}

std::vector<double> random_times(PCCD::Random_engine& rng, double begin, double end, std::size_t count)
{
    std::vector<double> times(count);
    for (double& t : times) t = PCCD::uniform_real(rng, begin, end);
    std::sort(times.begin(), times.end());
    return times;
}

template <class P>
void check_scene_at_random_times(const PCCD::testing::Kinetic_scene<P>& scene, std::uint64_t seed)
{
    PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan, P> tree(scene.flightplans, scene.primitives,
                                                                       scene.start_time);
    CHECK(tree.height() <= int(std::ceil(std::log2(double(scene.primitives.size())))));
    check_against_brute_force(tree);
    PCCD::Random_engine rng(seed);
    // Slightly beyond the animation on both sides: flightplans are at rest there.
    const auto times = random_times(rng, scene.start_time - 0.1, scene.end_time + 0.1, 1000);
    for (const double t : times) {
        tree.advance_to(t);
        REQUIRE(tree.now() == t);
        check_against_brute_force(tree);
    }
    CHECK(tree.statistics().events > 0);
    // Going back in time re-initializes.
    tree.advance_to(scene.start_time + 0.25 * (scene.end_time - scene.start_time));
    check_against_brute_force(tree);
    tree.advance_to(scene.end_time);
    check_against_brute_force(tree);
}

} // namespace

TEST_CASE("kinetic tree equals brute force at 1000 random times: cloth", "[kinetic][tree]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 300, .duration = 1.5});
    REQUIRE(std::abs(double(scene.primitives.size()) - 300.0) <= 15.0);
    check_scene_at_random_times(scene, 1);
}

TEST_CASE("cloth scene: level or tilted start", "[kinetic][tree]")
{
    // Level: one height for all particles (exact ties). Tilted by 5 degrees: the height is linear in
    // the horizontal position, with slope tan(5 degrees), centred on drop_height.
    const auto level = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 0.1, .tilt_degrees = 0.0});
    for (const auto& f : level.flightplans) CHECK(f.position(0.0).z() == 0.3);
    const auto tilted = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 0.1});
    double low = 1e9, high = -1e9, mean = 0.0;
    for (const auto& f : tilted.flightplans) {
        const Eigen::Vector3d p = f.position(0.0);
        const double expected = 0.3 + std::tan(5.0 * std::numbers::pi / 180.0) * (std::cos(std::numbers::pi / 6) * p.x() + std::sin(std::numbers::pi / 6) * p.y());
        CHECK(p.z() == Approx(expected).margin(1e-12));
        low = std::min(low, p.z());
        high = std::max(high, p.z());
        mean += p.z() / double(tilted.flightplans.size());
    }
    CHECK(high - low > 0.1);
    CHECK(mean == Approx(0.3).margin(1e-9));
    CHECK_THROWS_AS(PCCD::testing::make_cloth_scene({.triangles = 200, .tilt_degrees = 90.0}), PCCD::Invalid_input);
}

TEST_CASE("kinetic tree equals brute force at 1000 random times: lightly damped cloth", "[kinetic][tree]")
{
    // The former default cloth: dropped level (exact height ties) with air drag 2/s, it keeps
    // swinging, and many more near-ties swap.
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 300, .duration = 1.5, .tilt_degrees = 0.0, .air_damping = 2.0});
    check_scene_at_random_times(scene, 11);
}

TEST_CASE("kinetic tree equals brute force at 1000 random times: deforming cloud", "[kinetic][tree]")
{
    check_scene_at_random_times(PCCD::testing::make_deforming_cloud_scene({.points = 600, .duration = 1.0}), 2);
}

TEST_CASE("kinetic tree equals brute force at 1000 random times: deforming bunny", "[kinetic][tree][data]")
{
    const std::string data = PCCD_DATA_DIR;
    if (data.empty()) PCCD_SKIP_TEST("bunny00.off of libcgal-demo not found (PCCD_DATA_DIR is empty)");
    check_scene_at_random_times(
        PCCD::testing::make_deforming_cloud_scene({.off_file = data + "/bunny00.off", .points = 600, .duration = 1.0}), 3);
}

TEST_CASE("kinetic tree equals brute force at 1000 random times: random linear motion", "[kinetic][tree]")
{
    check_scene_at_random_times(PCCD::testing::make_random_motion_scene({.points = 700, .duration = 1.0}), 4);
}

TEST_CASE("kinetic tree with cubic flightplans equals brute force", "[kinetic][tree]")
{
    PCCD::Random_engine rng(8);
    std::vector<PCCD::Polynomial_flightplan> plans;
    std::vector<PCCD::Kinetic_triangle> triangles;
    const std::vector<double> keys{0.0, 0.25, 0.5, 0.75, 1.0};
    auto r = [&](double s) {
        return Eigen::Vector3d(PCCD::uniform_real(rng, -s, s), PCCD::uniform_real(rng, -s, s),
                               PCCD::uniform_real(rng, -s, s));
    };
    for (int i = 0; i < 300; ++i) {
        if (i % 2 == 0) {
            PCCD::Polynomial_flightplan::Coefficients c{r(1), r(1), r(1), r(1)};
            plans.emplace_back(c, 0.5);
        } else {
            std::vector<Eigen::Vector3d> p, v;
            for (std::size_t k = 0; k < keys.size(); ++k) {
                p.push_back(r(1));
                v.push_back(r(2));
            }
            plans.push_back(PCCD::Polynomial_flightplan::hermite(keys, p, v));
        }
    }
    for (std::uint32_t i = 0; i + 2 < 300; i += 3) triangles.push_back({{i, i + 1, i + 2}});
    for (std::uint32_t i = 0; i + 5 < 300; i += 5) triangles.push_back({{i, i + 2, i + 5}}); // shared vertices
    PCCD::Kinetic_AABB_tree<PCCD::Polynomial_flightplan> tree(plans, triangles, -0.2);
    for (const double t : random_times(rng, -0.2, 1.2, 1000)) {
        tree.advance_to(t);
        check_against_brute_force(tree);
    }
    CHECK(tree.statistics().events > 100);
}

TEST_CASE("events over an animation with linear flightplans stay within the bound", "[kinetic][tree]")
{
    // Each pair of linear flightplans crosses at most once per axis, so the extreme of a node with
    // m vertices below it changes at most m - 1 times per bound (the upper envelope of m lines has at
    // most m - 1 breakpoints), and every event changes the extreme of its node:
    //     events <= 6 * sum over nodes (m_node - 1) <= 6 n ceil(log2 n)   (one point per leaf).
    for (const std::size_t n : {100, 1000, 4000}) {
        PCCD::Random_engine rng(n);
        std::vector<PCCD::Linear_flightplan> plans;
        std::vector<PCCD::Kinetic_point> points;
        for (std::size_t i = 0; i < n; ++i) {
            Eigen::Vector3d p, v;
            for (int a = 0; a < 3; ++a) {
                p[a] = PCCD::uniform_real(rng, -1, 1);
                v[a] = PCCD::uniform_real(rng, -1, 1);
            }
            plans.emplace_back(p, v);
            points.push_back({std::uint32_t(i)});
        }
        PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan, PCCD::Kinetic_point> tree(plans, points, -100.0);
        // Sum of (m - 1) over nodes: subtree sizes.
        const std::uint64_t envelope_bound = pccd_test::envelope_bound(tree);
        // From t = -100 to +100 every crossing of the lines happens (|crossing time| <= 2 / |dv|
        // is rarely beyond 100; the bound holds for any interval).
        tree.advance_to(100.0);
        check_against_brute_force(tree);
        const auto events = tree.statistics().events;
        const double nlogn = 6.0 * double(n) * std::ceil(std::log2(double(n)));
        INFO("n = " << n << ", events = " << events << ", envelope bound = " << envelope_bound << ", 6 n log n = " << nlogn);
        CHECK(events <= envelope_bound);
        CHECK(double(envelope_bound) <= nlogn);
        CHECK(events > n); // there is real work
        WARN("linear motion, n = " << n << ": " << events << " events, envelope bound " << envelope_bound
                                   << ", 6 n ceil(log2 n) = " << nlogn);
    }
}

TEST_CASE("flightplan changes reschedule the affected certificates", "[kinetic][tree]")
{
    SECTION("continuous and discontinuous changes in the cloth")
    {
        const auto scene = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 1.0});
        PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan> tree(scene.flightplans, scene.primitives, 0.0);
        PCCD::Random_engine rng(12);
        const auto times = random_times(rng, 0.0, 1.2, 1000);
        for (std::size_t k = 0; k < times.size(); ++k) {
            tree.advance_to(times[k]);
            if (k % 10 == 0) {
                const auto v = std::uint32_t(PCCD::uniform_index(rng, tree.vertex_count()));
                const Eigen::Vector3d here = tree.vertex_position(v);
                Eigen::Vector3d there(PCCD::uniform_real(rng, -1, 1), PCCD::uniform_real(rng, -1, 1),
                                      PCCD::uniform_real(rng, -1, 1));
                const bool jump = k % 20 == 0;
                const Eigen::Vector3d start = jump ? Eigen::Vector3d(there.reverse()) : here;
                tree.set_flightplan(v, PCCD::Piecewise_linear_flightplan(
                                           std::vector<double>{times[k], times[k] + 0.2}, {start, there}));
                CHECK(tree.vertex_position(v) == start);
            }
            check_against_brute_force(tree);
        }
        CHECK(tree.statistics().flightplan_changes == 100);
    }
    SECTION("linear flightplans of a cloud")
    {
        const auto scene = PCCD::testing::make_random_motion_scene({.points = 300});
        std::vector<PCCD::Linear_flightplan> plans;
        for (const auto& f : scene.flightplans)
            plans.emplace_back(f.key_positions()[0], f.key_positions()[1] - f.key_positions()[0]);
        PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan, PCCD::Kinetic_point> tree(plans, scene.primitives);
        PCCD::Random_engine rng(13);
        for (const double t : random_times(rng, 0.0, 2.0, 1000)) {
            tree.advance_to(t);
            const auto v = std::uint32_t(PCCD::uniform_index(rng, tree.vertex_count()));
            const Eigen::Vector3d velocity(PCCD::uniform_real(rng, -1, 1), PCCD::uniform_real(rng, -1, 1),
                                           PCCD::uniform_real(rng, -1, 1));
            tree.set_flightplan(v, PCCD::Linear_flightplan(tree.vertex_position(v), velocity, t));
            check_against_brute_force(tree);
        }
    }
    SECTION("out of range vertex")
    {
        const auto scene = PCCD::testing::make_random_motion_scene({.points = 10});
        PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan, PCCD::Kinetic_point> tree(scene.flightplans,
                                                                                             scene.primitives);
        CHECK_THROWS_AS(tree.set_flightplan(10, scene.flightplans[0]), PCCD::Invalid_input);
    }
}

TEST_CASE("insertions and removals at run time", "[kinetic][tree]")
{
    auto scene = PCCD::testing::make_deforming_cloud_scene({.points = 400, .duration = 1.0});
    PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan, PCCD::Kinetic_point> tree(scene.flightplans,
                                                                                         scene.primitives);
    std::set<std::uint32_t> live;
    for (std::uint32_t i = 0; i < scene.primitives.size(); ++i) live.insert(i);
    PCCD::Random_engine rng(21);
    const auto times = random_times(rng, 0.0, 1.0, 1000);
    for (std::size_t k = 0; k < times.size(); ++k) {
        tree.advance_to(times[k]);
        const auto action = PCCD::uniform_index(rng, 3);
        if (action == 0 && !live.empty()) {
            auto it = live.begin();
            std::advance(it, std::ptrdiff_t(PCCD::uniform_index(rng, live.size())));
            tree.remove(*it);
            CHECK_FALSE(tree.contains(*it));
            live.erase(it);
        } else if (action == 1) {
            // A new vertex moving from a random point, or an existing vertex.
            std::uint32_t v;
            if (PCCD::uniform_index(rng, 2) == 0) {
                const Eigen::Vector3d a(PCCD::uniform_real(rng, -1, 1), PCCD::uniform_real(rng, -1, 1), 0.0);
                v = tree.add_vertex(PCCD::Piecewise_linear_flightplan(std::vector<double>{times[k], 1.0},
                                                                      {a, Eigen::Vector3d(a.reverse())}));
            } else {
                v = std::uint32_t(PCCD::uniform_index(rng, tree.vertex_count()));
            }
            const auto i = tree.insert({v});
            CHECK(tree.contains(i));
            live.insert(i);
        }
        REQUIRE(tree.primitive_count() == live.size());
        check_against_brute_force(tree);
        // The leaves hold exactly the live primitives.
        std::set<std::uint32_t> leaves;
        for (const auto i : live) {
            REQUIRE(tree.is_leaf(tree.leaf_of(i)));
            leaves.insert(tree.leaf_primitive(tree.leaf_of(i)));
        }
        CHECK(leaves == live);
    }
    CHECK(tree.statistics().insertions > 200);
    CHECK(tree.statistics().removals > 200);
    // Remove everything, then insert again.
    for (const auto i : live) tree.remove(i);
    CHECK(tree.root() == tree.no_node);
    CHECK(tree.node_count() == 0);
    const auto i = tree.insert({0});
    CHECK(tree.root() == tree.leaf_of(i));
    tree.advance_to(0.5);
    check_against_brute_force(tree);
    CHECK_THROWS_AS(tree.remove(12345), PCCD::Invalid_input);
    CHECK_THROWS_AS(tree.insert({99999}), PCCD::Invalid_input);
}

TEST_CASE("triangle insertions and removals: kinetic and refit trees agree", "[kinetic][tree]")
{
    // Leaves hold no certificates, so a leaf child's vertices are candidates of its parent: inserting
    // and removing triangles moves leaves between parents. Both trees share the slot bookkeeping, so
    // they hand out the same indices; their overlap queries with the table agree.
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 1.0});
    using F = PCCD::Piecewise_linear_flightplan;
    PCCD::Kinetic_AABB_tree<F> tree(scene.flightplans, scene.primitives);
    PCCD::Refit_AABB_tree<F> refit(scene.flightplans, scene.primitives);
    PCCD::Kinetic_AABB_tree<F> table(scene.obstacle_flightplans, scene.obstacle_triangles);
    std::vector<std::uint32_t> live(scene.primitives.size());
    for (std::uint32_t i = 0; i < live.size(); ++i) live[i] = i;
    PCCD::Random_engine rng(31);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> a, b;
    for (const double t : random_times(rng, 0.0, 1.1, 300)) {
        const auto before = tree.statistics();
        tree.advance_to(t);
        // Each node counts at most once per advance_to, and only when one of its bounds changed.
        CHECK(tree.statistics().node_updates - before.node_updates <= tree.node_count());
        CHECK(tree.statistics().node_updates - before.node_updates <=
              tree.statistics().bv_updates - before.bv_updates);
        refit.advance_to(t);
        table.advance_to(t);
        if (PCCD::uniform_index(rng, 2) == 0 && live.size() > 1) {
            const auto k = PCCD::uniform_index(rng, live.size());
            tree.remove(live[k]);
            refit.remove(live[k]);
            live.erase(live.begin() + std::ptrdiff_t(k));
        } else {
            const PCCD::Kinetic_triangle triangle =
                scene.primitives[PCCD::uniform_index(rng, scene.primitives.size())];
            const auto i = tree.insert(triangle);
            CHECK(refit.insert(triangle) == i);
            live.push_back(i);
        }
        REQUIRE(tree.primitive_count() == live.size());
        REQUIRE(refit.primitive_count() == live.size());
        check_against_brute_force(tree);
        tree.overlapping_pairs(table, a, 0.01);
        refit.overlapping_pairs(table, b, 0.01);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        CHECK(a == b);
    }
    CHECK(tree.statistics().insertions > 100);
    CHECK(tree.statistics().removals > 100);
}

TEST_CASE("exact ties and simultaneous events are deterministic", "[kinetic][tree]")
{
    // Every point passes through the origin's plane x = 0 at t = 1, and many share velocities: a
    // burst of simultaneous crossings and exact ties.
    std::vector<PCCD::Linear_flightplan> plans;
    std::vector<PCCD::Kinetic_point> points;
    for (int i = 0; i < 256; ++i) {
        const double speed = double(i % 7) - 3.0;
        plans.emplace_back(Eigen::Vector3d(0.0, double(i % 5), double(i % 3)), Eigen::Vector3d(speed, 0.0, 1.0), 1.0);
        points.push_back({std::uint32_t(i)});
    }
    auto run = [&]() {
        PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan, PCCD::Kinetic_point> tree(plans, points, 0.0);
        std::vector<std::uint32_t> trace;
        for (const double t : {0.5, 1.0, std::nextafter(1.0, 2.0), 1.5, 3.0}) {
            tree.advance_to(t);
            check_against_brute_force(tree);
            for (std::uint32_t n = 0; n < tree.node_count(); ++n)
                for (int b = 0; b < 6; ++b) trace.push_back(tree.extreme_vertex(n, b));
        }
        trace.push_back(std::uint32_t(tree.statistics().events));
        return trace;
    };
    const auto first = run();
    CHECK(first.back() > 0);
    CHECK(run() == first);

    SECTION("the cloth's exact height ties give the same result twice")
    {
        const auto scene = PCCD::testing::make_cloth_scene({.triangles = 128, .duration = 1.0, .tilt_degrees = 0.0});
        auto trace = [&]() {
            PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan> tree(scene.flightplans, scene.primitives);
            tree.advance_to(1.0);
            return std::pair(tree.statistics().events, tree.statistics().bv_updates);
        };
        CHECK(trace() == trace());
    }
}

TEST_CASE("invalid trees and times are rejected", "[kinetic][tree]")
{
    std::vector<PCCD::Linear_flightplan> plans(3);
    CHECK_THROWS_WITH((PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan>(plans, {{{0, 1, 3}}})),
                      Catch::Contains("refers to vertex 3"));
    PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan> tree(plans, {{{0, 1, 2}}});
    CHECK_THROWS_AS(tree.advance_to(std::nan("")), PCCD::Invalid_input);
    CHECK_THROWS_AS((PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan>(plans, {}, INFINITY)), PCCD::Invalid_input);
    PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan> empty(plans, {});
    CHECK(empty.root() == empty.no_node);
    empty.advance_to(3.0);
    CHECK(empty.height() == -1);
}

TEST_CASE("event queue agrees with an ordered set", "[kinetic][queue]")
{
    auto exercise = [](auto queue) {
        PCCD::Random_engine rng(99);
        std::set<std::pair<double, std::uint32_t>> reference;
        std::vector<double> time_of(500, INFINITY);
        queue.resize(500);
        for (int step = 0; step < 100000; ++step) {
            const auto id = std::uint32_t(PCCD::uniform_index(rng, 500));
            const auto op = PCCD::uniform_index(rng, 10);
            if (op < 6) {
                // Few distinct times: many exact ties, resolved by id.
                const double t = op == 0 ? INFINITY : double(PCCD::uniform_index(rng, 50));
                if (time_of[id] != INFINITY) reference.erase({time_of[id], id});
                time_of[id] = t;
                if (t != INFINITY) reference.insert({t, id});
                queue.set(id, t);
            } else if (op < 8) {
                if (time_of[id] != INFINITY) reference.erase({time_of[id], id});
                time_of[id] = INFINITY;
                queue.erase(id);
            } else if (!reference.empty()) {
                REQUIRE(queue.top_time() == reference.begin()->first);
                REQUIRE(queue.top_id() == reference.begin()->second);
                time_of[queue.top_id()] = INFINITY;
                reference.erase(reference.begin());
                queue.pop();
            }
            REQUIRE(queue.size() == reference.size());
            REQUIRE(queue.time(id) == time_of[id]);
        }
    };
    exercise(PCCD::Event_queue<2>());
    exercise(PCCD::Event_queue<4>());
    exercise(PCCD::Event_queue<8>());
}
