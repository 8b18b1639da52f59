// The frame's positions from the caller and the reuse of certificate failure times
// (doc/manual/kinetic.md, "Where positions come from" and "Cost of an event"): with
// advance_to(t, positions) every node box, the overlap with the table and the ray hits equal brute
// force over the given positions and the answers of the flightplan mode, for the kinetic tree and
// the refit; bad position arrays are rejected; the mode ends where the positions stop describing
// the vertices. Every scheduled certificate time, cache or not, equals a fresh next_crossing of the
// node's extreme against its candidates (the independent truth of the reuse argument).
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Refit_AABB_tree.h>
#include <PCCD/Kinetic/boxes_overlap.h>
#include <PCCD/Kinetic/internal/Crossing_cache.h>
#include <PCCD/Random.h>

#include <PCCD/testing/scenes/Cloth_scene.h>
#include <PCCD/testing/scenes/run_kinetic_scene.h>

#include "kinetic_test_helpers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

namespace {

using Plan = PCCD::Piecewise_linear_flightplan;
using Kinetic = PCCD::Kinetic_AABB_tree<Plan>;
using Refit = PCCD::Refit_AABB_tree<Plan>;
using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

std::vector<Eigen::Vector3d> positions_at(const std::vector<Plan>& plans, double t)
{
    std::vector<Eigen::Vector3d> out;
    for (const Plan& p : plans) out.push_back(p.position(t));
    return out;
}

/// Every node box of `tree` equals the box of the given positions of the vertices below it.
template <class Tree>
void check_boxes(const Tree& tree, const std::vector<Eigen::Vector3d>& positions)
{
    const auto order = pccd_test::nodes_in_preorder(tree);
    std::vector<Eigen::AlignedBox3d> truth(tree.node_count() + 64);
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const auto n = *it;
        Eigen::AlignedBox3d box;
        if (tree.is_leaf(n)) {
            const auto& p = tree.primitive(tree.leaf_primitive(n));
            for (std::size_t k = 0; k < 3; ++k) box.extend(positions[p.vertex(k)]);
        } else {
            box = truth[tree.left(n)].merged(truth[tree.right(n)]);
        }
        if (n >= truth.size()) truth.resize(n + 1);
        truth[n] = box;
        const Eigen::AlignedBox3d got = tree.box(n);
        REQUIRE(got.min() == box.min());
        REQUIRE(got.max() == box.max());
    }
}

/// Pairs (cloth triangle, table triangle) whose boxes over `cloth` and `table` positions overlap.
Pairs brute_force_pairs(const PCCD::testing::Kinetic_scene<PCCD::Kinetic_triangle>& scene,
                        const std::vector<Eigen::Vector3d>& cloth, double t)
{
    const auto box_of = [](const PCCD::Kinetic_triangle& tri, auto&& position) {
        Eigen::AlignedBox3d box;
        for (std::size_t k = 0; k < 3; ++k) box.extend(position(tri.vertex(k)));
        return box;
    };
    Pairs out;
    for (std::uint32_t i = 0; i < scene.primitives.size(); ++i) {
        const auto a = box_of(scene.primitives[i], [&](std::uint32_t v) { return cloth[v]; });
        for (std::uint32_t j = 0; j < scene.obstacle_triangles.size(); ++j) {
            const auto b = box_of(scene.obstacle_triangles[j],
                                  [&](std::uint32_t v) { return scene.obstacle_flightplans[v].position(t); });
            if (PCCD::boxes_overlap(a, b, 0.0)) out.emplace_back(i, j);
        }
    }
    return out;
}

Pairs sorted(Pairs p)
{
    std::sort(p.begin(), p.end());
    return p;
}

} // namespace

TEST_CASE("given positions: boxes, overlap and rays equal brute force and the flightplan mode", "[kinetic][query]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 400, .duration = 1.5});
    Kinetic given(scene.flightplans, scene.primitives), evaluated(scene.flightplans, scene.primitives);
    Refit refit_given(scene.flightplans, scene.primitives), refit(scene.flightplans, scene.primitives);
    Kinetic table(scene.obstacle_flightplans, scene.obstacle_triangles);
    Eigen::AlignedBox3d bounds;
    for (const Plan& p : scene.flightplans) bounds.extend(p.position(0.0));
    const auto rays = PCCD::testing::detail::kinetic_run_rays(bounds, 16);
    PCCD::Random_engine rng(41);
    std::size_t total_pairs = 0, total_hits = 0;
    for (int k = 0; k < 40; ++k) {
        // Mostly forward, sometimes back in time (which re-initializes the certificates).
        const double t = k % 10 == 9 ? PCCD::uniform_real(rng, 0.0, 1.5) : 1.5 * (k + PCCD::uniform_01(rng)) / 40.0;
        const auto positions = positions_at(scene.flightplans, t);
        given.advance_to(t, positions);
        evaluated.advance_to(t);
        refit_given.advance_to(t, positions);
        refit.advance_to(t);
        table.advance_to(t);
        REQUIRE(given.has_frame_positions());
        REQUIRE_FALSE(evaluated.has_frame_positions());
        check_boxes(given, positions);
        check_boxes(refit_given, positions);
        for (std::uint32_t v = 0; v < positions.size(); v += 37) CHECK(given.vertex_position(v) == positions[v]);

        const Pairs expected = brute_force_pairs(scene, positions, t);
        Pairs got;
        given.overlapping_pairs(table, got);
        CHECK(sorted(got) == expected);
        refit_given.overlapping_pairs(table, got);
        CHECK(sorted(got) == expected);
        total_pairs += expected.size();

        std::vector<std::optional<PCCD::Kinetic_ray_hit>> a, b, c;
        given.first_hits(rays, a);
        evaluated.first_hits(rays, b);
        refit_given.first_hits(rays, c);
        REQUIRE(a.size() == rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) {
            REQUIRE(a[r].has_value() == b[r].has_value());
            REQUIRE(a[r].has_value() == c[r].has_value());
            if (!a[r]) continue;
            ++total_hits;
            CHECK(a[r]->primitive == b[r]->primitive);
            CHECK(a[r]->s == b[r]->s);
            CHECK(a[r]->primitive == c[r]->primitive);
        }
    }
    CHECK(total_pairs > 100);
    CHECK(total_hits > 50);
    // Same events and extremes whichever way the positions come.
    CHECK(given.statistics().events == evaluated.statistics().events);
}

TEST_CASE("given positions: bad arrays are rejected, the mode ends with the positions' validity", "[kinetic][query]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 0.5});
    Kinetic tree(scene.flightplans, scene.primitives);
    Refit refit(scene.flightplans, scene.primitives);
    auto positions = positions_at(scene.flightplans, 0.25);
    const std::vector<Eigen::Vector3d> short_array(positions.begin(), positions.end() - 1);
    CHECK_THROWS_AS(tree.advance_to(0.25, short_array), PCCD::Invalid_input);
    CHECK_THROWS_WITH(refit.advance_to(0.25, short_array),
                      Catch::Contains(std::to_string(short_array.size()) + " positions given for"));
    CHECK_THROWS_AS(tree.advance_to(NAN, positions), PCCD::Invalid_input);
    CHECK_FALSE(tree.has_frame_positions());

    CHECK(tree.positions_match(0.25, positions));
    positions[7].z() = std::nextafter(positions[7].z(), 1.0);
    CHECK_FALSE(tree.positions_match(0.25, positions));
    CHECK_FALSE(tree.positions_match(0.25, short_array));
    positions[7] = scene.flightplans[7].position(0.25);

    tree.advance_to(0.25, positions);
    CHECK(tree.has_frame_positions());
    tree.advance_to(0.3); // a plain advance evaluates flightplans again
    CHECK_FALSE(tree.has_frame_positions());
    const auto at_035 = positions_at(scene.flightplans, 0.35); // must outlive its use by the tree
    tree.advance_to(0.35, at_035);
    CHECK(tree.has_frame_positions());
    // Replacing a flightplan (here with a jump) or adding a vertex ends the given positions: the
    // array no longer describes the vertices.
    const auto times = scene.flightplans[3].key_times();
    std::vector<Eigen::Vector3d> moved = scene.flightplans[3].key_positions();
    for (auto& p : moved) p.z() += 0.5;
    tree.set_flightplan(3, Plan(times, moved));
    CHECK_FALSE(tree.has_frame_positions());
    CHECK(tree.vertex_position(3) == Plan(times, moved).position(0.35));
    std::vector<Eigen::Vector3d> now;
    for (std::uint32_t v = 0; v < tree.vertex_count(); ++v) now.push_back(tree.flightplan(v).position(0.35));
    check_boxes(tree, now);
    CHECK_FALSE(tree.positions_match(0.4, positions_at(scene.flightplans, 0.4))); // vertex 3 moved
    std::vector<Eigen::Vector3d> at_04;
    for (std::uint32_t v = 0; v < tree.vertex_count(); ++v) at_04.push_back(tree.flightplan(v).position(0.4));
    CHECK(tree.positions_match(0.4, at_04));
    tree.advance_to(0.4, at_04);
    check_boxes(tree, at_04);
#ifndef NDEBUG
    // Debug builds check the precondition: these positions miss vertex 3's new flightplan.
    CHECK_THROWS_AS(tree.advance_to(0.45, positions_at(scene.flightplans, 0.45)), PCCD::Precondition_failure);
    CHECK_FALSE(tree.has_frame_positions());
    tree.advance_to(0.4, at_04);
#endif
    tree.add_vertex(Plan());
    CHECK_FALSE(tree.has_frame_positions());
}

TEST_CASE("every scheduled certificate equals a fresh next_crossing, with failure times reused", "[kinetic][tree]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 400, .duration = 2.0});
    Kinetic tree(scene.flightplans, scene.primitives);
    PCCD::Random_engine rng(7);
    for (int k = 0; k < 60; ++k) {
        const double t = 2.0 * (k + PCCD::uniform_01(rng)) / 60.0;
        tree.advance_to(t);
        for (const auto n : pccd_test::nodes_in_preorder(tree)) {
            if (tree.is_leaf(n)) continue;
            for (int b = 0; b < 6; ++b) {
                const auto champion = tree.extreme_vertex(n, b);
                std::vector<std::uint32_t> candidates;
                for (const auto c : {tree.left(n), tree.right(n)}) {
                    if (!tree.is_leaf(c)) {
                        candidates.push_back(tree.extreme_vertex(c, b));
                        continue;
                    }
                    const auto& p = tree.primitive(tree.leaf_primitive(c));
                    for (std::size_t i = 0; i < 3; ++i) candidates.push_back(p.vertex(i));
                }
                double expected = INFINITY;
                for (const auto c : candidates) {
                    if (c == champion) continue;
                    const Plan& x = tree.flightplan(champion);
                    const Plan& y = tree.flightplan(c);
                    expected = std::min(expected, b >= 3 ? x.next_crossing(y, b % 3, t) : y.next_crossing(x, b % 3, t));
                }
                if (expected <= t) expected = std::nextafter(t, INFINITY); // deferred by one ulp
                INFO("node " << n << " bound " << b << " at t = " << t);
                REQUIRE(tree.certificate_time(n, b) == expected);
            }
        }
    }
    CHECK(tree.statistics().certificate_reuses > tree.statistics().certificate_computations / 10);
}

TEST_CASE("crossing cache: an answer is reused exactly inside its window, never outside", "[kinetic][tree]")
{
    PCCD::internal::Crossing_cache cache;
    double r = 0.0;
    CHECK_FALSE(cache.find(1, 2, 0, 0.0, r)); // unsized: never finds
    cache.reset(100);
    cache.store(1, 2, 3, 0.5, 1.25);
    CHECK(cache.find(1, 2, 3, 0.5, r));
    CHECK(r == 1.25);
    CHECK(cache.find(1, 2, 3, 1.0, r));
    CHECK_FALSE(cache.find(1, 2, 3, 1.25, r)); // at the failure time the answer is another one
    CHECK_FALSE(cache.find(1, 2, 3, 0.25, r)); // before the time it was computed at
    CHECK_FALSE(cache.find(2, 1, 3, 0.75, r)); // the ordered pair matters
    CHECK_FALSE(cache.find(1, 2, 0, 0.75, r)); // and the bound
    cache.store(4, 5, 1, 0.5, 0.5);            // immediate failures are not kept
    CHECK_FALSE(cache.find(4, 5, 1, 0.5, r));
    cache.store(4, 5, 1, 0.0, INFINITY);
    CHECK(cache.find(4, 5, 1, 1e9, r));
    CHECK(r == INFINITY);
    cache.clear(); // a flightplan changed
    CHECK_FALSE(cache.find(1, 2, 3, 1.0, r));
    CHECK_FALSE(cache.find(4, 5, 1, 1.0, r));
}
