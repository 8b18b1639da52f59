// Queries on kinetic and refit trees (doc/manual/kinetic.md, "Queries" and "Baselines with the same
// interface"): box overlap of two trees, self-overlap without adjacent primitives, first ray hit on
// triangles and box range queries at random times equal brute force over all primitives, for the
// kinetic tree and both baselines; the traversal hook visits the same leaf pairs; point clouds with
// a proximity margin; the ray casts of run_kinetic_scene give the same hits with every method, and
// its query box the primitives of brute force.
// Also covers Kinetic/Kinetic_ray.h: the test cases below exercise what it declares.
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Kinetic_ray.h>
#include <PCCD/Kinetic/Refit_AABB_tree.h>
#include <PCCD/Kinetic/boxes_overlap.h>
#include <PCCD/Kinetic/intersect_ray_triangle.h>
#include <PCCD/Random.h>

#include <PCCD/testing/scenes/Cloth_scene.h>
#include <PCCD/testing/scenes/Deforming_cloud_scene.h>
#include <PCCD/testing/scenes/Random_motion_scene.h>
#include <PCCD/testing/scenes/run_kinetic_scene.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace {

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

template <class P>
std::vector<Eigen::AlignedBox3d> primitive_boxes(const std::vector<PCCD::Piecewise_linear_flightplan>& plans,
                                                 const std::vector<P>& primitives, double t)
{
    std::vector<Eigen::AlignedBox3d> boxes;
    for (const P& p : primitives) {
        Eigen::AlignedBox3d box;
        for (std::size_t k = 0; k < P::vertex_count; ++k) box.extend(plans[p.vertex(k)].position(t));
        boxes.push_back(box);
    }
    return boxes;
}

bool overlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double margin)
{
    return (a.min().array() - margin <= b.max().array()).all() && (b.min().array() <= a.max().array() + margin).all();
}

Pairs sorted(Pairs p)
{
    std::sort(p.begin(), p.end());
    return p;
}

template <class TreeA, class TreeB, class TreeC>
void check_cloth_queries(TreeA& kinetic, TreeB& refit, TreeC& rebuild, const PCCD::testing::Kinetic_scene<PCCD::Kinetic_triangle>& scene,
                         std::uint64_t seed)
{
    PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan> table(scene.obstacle_flightplans,
                                                                     scene.obstacle_triangles);
    PCCD::Random_engine rng(seed);
    std::vector<double> times(60);
    for (double& t : times) t = PCCD::uniform_real(rng, scene.start_time, scene.end_time);
    std::sort(times.begin(), times.end());
    std::size_t total_pairs = 0, total_self = 0, hits = 0;
    for (const double t : times) {
        kinetic.advance_to(t);
        refit.advance_to(t);
        rebuild.advance_to(t);
        table.advance_to(t);
        const auto boxes = primitive_boxes(scene.flightplans, scene.primitives, t);
        const auto table_boxes = primitive_boxes(scene.obstacle_flightplans, scene.obstacle_triangles, t);

        // Overlap with the table.
        Pairs expected;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
            for (std::uint32_t j = 0; j < table_boxes.size(); ++j)
                if (overlap(boxes[i], table_boxes[j], 0.01)) expected.emplace_back(i, j);
        Pairs got;
        kinetic.overlapping_pairs(table, got, 0.01);
        CHECK(sorted(got) == expected);
        refit.overlapping_pairs(table, got, 0.01);
        CHECK(sorted(got) == expected);
        rebuild.overlapping_pairs(table, got, 0.01);
        CHECK(sorted(got) == expected);
        total_pairs += expected.size();

        // Self-overlap without adjacent triangles.
        Pairs expected_self;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
            for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
                const auto& a = scene.primitives[i].indices;
                const auto& b = scene.primitives[j].indices;
                const bool adjacent = std::any_of(a.begin(), a.end(), [&](std::uint32_t v) {
                    return std::find(b.begin(), b.end(), v) != b.end();
                });
                if (!adjacent && overlap(boxes[i], boxes[j], 0.0)) expected_self.emplace_back(i, j);
            }
        kinetic.self_overlapping_pairs(got);
        CHECK(sorted(got) == expected_self);
        refit.self_overlapping_pairs(got);
        CHECK(sorted(got) == expected_self);
        rebuild.self_overlapping_pairs(got);
        CHECK(sorted(got) == expected_self);
        total_self += expected_self.size();

        // Rays from above and from the side towards the cloth; afterwards the same rays as one batch.
        std::vector<PCCD::Kinetic_ray> batch;
        std::vector<std::optional<PCCD::Kinetic_ray_hit>> truths;
        for (int r = 0; r < 20; ++r) {
            PCCD::Kinetic_ray ray;
            ray.origin = Eigen::Vector3d(PCCD::uniform_real(rng, -1.2, 1.2), PCCD::uniform_real(rng, -1.2, 1.2), 1.0);
            ray.direction = Eigen::Vector3d(PCCD::uniform_real(rng, -0.5, 0.5), PCCD::uniform_real(rng, -0.5, 0.5), -1.0);
            if (r % 4 == 3) ray.direction = Eigen::Vector3d(0, 0, -1); // axis-parallel: zero components
            std::optional<PCCD::Kinetic_ray_hit> truth;
            for (std::uint32_t i = 0; i < scene.primitives.size(); ++i) {
                const auto& tri = scene.primitives[i];
                auto hit = PCCD::intersect_ray_triangle(ray, scene.flightplans[tri.vertex(0)].position(t),
                                                        scene.flightplans[tri.vertex(1)].position(t),
                                                        scene.flightplans[tri.vertex(2)].position(t));
                if (hit && (!truth || hit->s < truth->s)) {
                    hit->primitive = i;
                    truth = hit;
                }
            }
            for (const auto& got_hit : {kinetic.first_hit(ray), refit.first_hit(ray), rebuild.first_hit(ray)}) {
                REQUIRE(got_hit.has_value() == truth.has_value());
                if (truth) {
                    CHECK(got_hit->primitive == truth->primitive);
                    CHECK(got_hit->s == truth->s);
                }
            }
            hits += truth.has_value();
            batch.push_back(ray);
            truths.push_back(truth);
        }
        std::vector<std::optional<PCCD::Kinetic_ray_hit>> batch_hits;
        for (int method = 0; method < 3; ++method) {
            if (method == 0) kinetic.first_hits(batch, batch_hits);
            if (method == 1) refit.first_hits(batch, batch_hits);
            if (method == 2) rebuild.first_hits(batch, batch_hits);
            REQUIRE(batch_hits.size() == batch.size());
            for (std::size_t r = 0; r < batch.size(); ++r) {
                REQUIRE(batch_hits[r].has_value() == truths[r].has_value());
                if (truths[r]) {
                    CHECK(batch_hits[r]->primitive == truths[r]->primitive);
                    CHECK(batch_hits[r]->s == truths[r]->s);
                }
            }
        }

        // Range queries.
        for (int r = 0; r < 5; ++r) {
            const Eigen::Vector3d c(PCCD::uniform_real(rng, -1, 1), PCCD::uniform_real(rng, -1, 1),
                                    PCCD::uniform_real(rng, -0.6, 0.3));
            const Eigen::AlignedBox3d query(c, c + Eigen::Vector3d::Constant(0.3));
            std::vector<std::uint32_t> expected_range, got_range;
            for (std::uint32_t i = 0; i < boxes.size(); ++i)
                if (overlap(boxes[i], query, 0.0)) expected_range.push_back(i);
            kinetic.range_query(query, got_range);
            std::sort(got_range.begin(), got_range.end());
            CHECK(got_range == expected_range);
            refit.range_query(query, got_range);
            std::sort(got_range.begin(), got_range.end());
            CHECK(got_range == expected_range);
        }
    }
    CHECK(total_pairs > 100);
    CHECK(total_self > 100);
    CHECK(hits > 100);
}

} // namespace

TEST_CASE("cloth queries equal brute force for the kinetic tree and both baselines", "[kinetic][query]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 400, .duration = 1.5});
    PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan> kinetic(scene.flightplans, scene.primitives);
    PCCD::Refit_AABB_tree<PCCD::Piecewise_linear_flightplan> refit(scene.flightplans, scene.primitives);
    PCCD::Refit_AABB_tree<PCCD::Piecewise_linear_flightplan> rebuild(scene.flightplans, scene.primitives, 0.0,
                                                                     {.update = PCCD::Refit_update::rebuild});
    check_cloth_queries(kinetic, refit, rebuild, scene, 5);
    CHECK(refit.statistics().bv_updates == refit.statistics().frames * refit.node_count());
    CHECK(rebuild.statistics().rebuilds == rebuild.statistics().frames);
}

TEST_CASE("point clouds: proximity pairs with a margin and the traversal hook", "[kinetic][query]")
{
    const auto cloud = PCCD::testing::make_deforming_cloud_scene({.points = 500, .duration = 1.0});
    const auto other = PCCD::testing::make_random_motion_scene({.points = 400, .duration = 1.0, .seed = 3});
    using Tree = PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan, PCCD::Kinetic_point>;
    Tree a(cloud.flightplans, cloud.primitives);
    Tree b(other.flightplans, other.primitives);
    PCCD::Refit_AABB_tree<PCCD::Piecewise_linear_flightplan, PCCD::Kinetic_point> b_refit(other.flightplans,
                                                                                          other.primitives);
    PCCD::Random_engine rng(17);
    const double margin = 0.05;
    std::size_t total = 0;
    for (int k = 1; k <= 40; ++k) {
        const double t = k / 40.0;
        a.advance_to(t);
        b.advance_to(t);
        b_refit.advance_to(t);
        Pairs expected;
        for (std::uint32_t i = 0; i < cloud.primitives.size(); ++i)
            for (std::uint32_t j = 0; j < other.primitives.size(); ++j) {
                const Eigen::Vector3d p = cloud.flightplans[i].position(t), q = other.flightplans[j].position(t);
                if (((p - q).cwiseAbs().array() <= margin).all()) expected.emplace_back(i, j);
            }
        Pairs got;
        a.overlapping_pairs(b, got, margin);
        CHECK(sorted(got) == expected);
        a.overlapping_pairs(b_refit, got, margin);
        CHECK(sorted(got) == expected);
        // The hook: a custom descend test and leaf callback see the same pairs.
        Pairs via_hook;
        a.traverse(
            b,
            [&](std::uint32_t, std::uint32_t, const Eigen::AlignedBox3d& ba, const Eigen::AlignedBox3d& bb) {
                return PCCD::boxes_overlap(ba, bb, margin);
            },
            [&](std::uint32_t na, std::uint32_t nb) { via_hook.emplace_back(a.leaf_primitive(na), b.leaf_primitive(nb)); });
        CHECK(sorted(via_hook) == expected);
        total += expected.size();
    }
    CHECK(total > 50);
    b.advance_to(2.0);
    Pairs out;
    CHECK_THROWS_AS(a.overlapping_pairs(b, out), PCCD::Invalid_input);
    CHECK_THROWS_AS(a.self_overlapping_pairs(out, -1.0), PCCD::Invalid_input);
}

TEST_CASE("memoized queries give exactly the answers of the uncached traversal", "[kinetic][query]")
{
    // The tree's queries read positions through a per-query memo; the internal traversals run on
    // the tree itself evaluate box() and vertex_position() afresh at every visit. Same pairs, in the
    // same order, same ray hit bit for bit.
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 400, .duration = 1.5, .tilt_degrees = 0.0, .air_damping = 2.0});
    using Tree = PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan>;
    Tree cloth(scene.flightplans, scene.primitives);
    Tree table(scene.obstacle_flightplans, scene.obstacle_triangles);
    PCCD::Refit_AABB_tree<PCCD::Piecewise_linear_flightplan> table_refit(scene.obstacle_flightplans,
                                                                         scene.obstacle_triangles);
    PCCD::Random_engine rng(23);
    std::size_t pairs = 0, hits = 0;
    for (int k = 0; k < 40; ++k) {
        const double t = PCCD::uniform_real(rng, 0.0, 1.5);
        cloth.advance_to(t);
        table.advance_to(t);
        table_refit.advance_to(t);
        Pairs memo, plain;
        cloth.overlapping_pairs(table, memo, 0.01);
        PCCD::internal::overlapping_pairs(cloth, table, 0.01, plain);
        CHECK(memo == plain);
        pairs += memo.size();
        cloth.overlapping_pairs(table_refit, memo, 0.01);
        CHECK(memo == plain);
        cloth.self_overlapping_pairs(memo);
        PCCD::internal::self_overlapping_pairs(cloth, 0.0, plain);
        CHECK(memo == plain);
        const Eigen::AlignedBox3d range(Eigen::Vector3d(-0.5, -0.5, -0.3), Eigen::Vector3d(0.3, 0.4, 0.2));
        std::vector<std::uint32_t> memo_hits, plain_hits;
        cloth.range_query(range, memo_hits);
        PCCD::internal::range_query(cloth, range, plain_hits);
        CHECK(memo_hits == plain_hits);
        const PCCD::Kinetic_ray down{Eigen::Vector3d(PCCD::uniform_real(rng, -0.8, 0.8), PCCD::uniform_real(rng, -0.8, 0.8), 1.0),
                                     -Eigen::Vector3d::UnitZ()};
        const auto memo_hit = cloth.first_hit(down);
        const auto plain_hit = PCCD::internal::first_hit(cloth, down);
        REQUIRE(memo_hit.has_value() == plain_hit.has_value());
        if (memo_hit) {
            ++hits;
            CHECK(memo_hit->primitive == plain_hit->primitive);
            CHECK(memo_hit->s == plain_hit->s);
            CHECK(memo_hit->u == plain_hit->u);
            CHECK(memo_hit->v == plain_hit->v);
        }
        // Memoized positions equal the flightplans' coordinates at now(), bit for bit.
        for (std::uint32_t v = 0; v < cloth.vertex_count(); v += 7)
            for (int axis = 0; axis < 3; ++axis)
                CHECK(cloth.vertex_position(v)[axis] == cloth.flightplan(v).coordinate(axis, t));
    }
    CHECK(pairs > 100);
    CHECK(hits > 10);
}

TEST_CASE("concurrent queries on one tree give the answers of sequential ones", "[kinetic][query]")
{
    // Queries take memo tables from the tree's pool and give them back; two threads querying the
    // same trees at once get separate tables, and later queries reuse them.
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 400, .duration = 1.5});
    using Tree = PCCD::Kinetic_AABB_tree<PCCD::Piecewise_linear_flightplan>;
    Tree cloth(scene.flightplans, scene.primitives);
    Tree table(scene.obstacle_flightplans, scene.obstacle_triangles);
    for (const double t : {0.4, 0.9, 1.4}) {
        cloth.advance_to(t);
        table.advance_to(t);
        Pairs self, overlap;
        cloth.self_overlapping_pairs(self);
        cloth.overlapping_pairs(table, overlap, 0.01);
        std::vector<Pairs> results(4);
        {
            std::thread first([&] {
                for (int k = 0; k < 5; ++k) cloth.self_overlapping_pairs(results[0]);
                cloth.overlapping_pairs(table, results[2], 0.01);
            });
            std::thread second([&] {
                for (int k = 0; k < 5; ++k) cloth.self_overlapping_pairs(results[1]);
                cloth.overlapping_pairs(table, results[3], 0.01);
            });
            first.join();
            second.join();
        }
        CHECK(results[0] == self);
        CHECK(results[1] == self);
        CHECK(results[2] == overlap);
        CHECK(results[3] == overlap);
    }
}

TEST_CASE("run_kinetic_scene: ray casts hit the same triangles with every method", "[kinetic][query]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 0.5});
    const PCCD::testing::Kinetic_run_options options{.overlap_query = false, .rays_per_frame = 16};
    const auto kinetic = PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::kinetic, options);
    const auto bottom_up = PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::bottom_up, options);
    const auto rebuild = PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::rebuild, options);
    REQUIRE(kinetic.frames > 0);
    CHECK(kinetic.queries == kinetic.frames * 16);
    CHECK(bottom_up.queries == kinetic.queries);
    CHECK(rebuild.queries == kinetic.queries);
    CHECK(bottom_up.reported == kinetic.reported);
    CHECK(rebuild.reported == kinetic.reported);
    CHECK(kinetic.reported > 0);              // the rays hit the cloth sometimes...
    CHECK(kinetic.reported < kinetic.queries); // ... and miss it sometimes
    // The rays are fixed for a run: playing again gives the same hits.
    CHECK(PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::kinetic, options).reported == kinetic.reported);
}

TEST_CASE("run_kinetic_scene: a query box replaces the overlap, with the primitives of brute force", "[kinetic][query]")
{
    const auto scene = PCCD::testing::make_cloth_scene({.triangles = 200, .duration = 1.0});
    // A box over the table's edge at +x (the cloth drapes over it once it has fallen).
    Eigen::AlignedBox3d table;
    for (const auto& plan : scene.obstacle_flightplans) table.extend(plan.position(scene.start_time));
    const Eigen::Vector3d edge(table.max().x(), table.center().y(), table.max().z());
    const Eigen::AlignedBox3d box(edge - Eigen::Vector3d(0.2, 0.2, 0.3), edge + Eigen::Vector3d(0.2, 0.2, 0.1));
    const PCCD::testing::Kinetic_run_options options{.query_hz = 20, .query_box = box};
    std::uint64_t expected = 0;
    for (int k = 1; k <= 20; ++k) {
        const double t = scene.start_time + k / 20.0;
        for (const auto& b : primitive_boxes(scene.flightplans, scene.primitives, t))
            if (overlap(b, box, 0.0)) ++expected;
    }
    REQUIRE(expected > 0);
    for (const auto method : {PCCD::testing::Kinetic_method::kinetic, PCCD::testing::Kinetic_method::bottom_up,
                              PCCD::testing::Kinetic_method::rebuild}) {
        const auto r = PCCD::testing::run_kinetic_scene(scene, method, options);
        CHECK(r.frames == 20);
        CHECK(r.queries == 20);
        CHECK(r.reported == expected);
    }
    // Without the box the same run answers the table overlap: other counts.
    CHECK(PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::kinetic, {.query_hz = 20}).reported != expected);
}

TEST_CASE("run_kinetic_scene: ray casts on a point scene are rejected", "[kinetic][query]")
{
    const auto scene = PCCD::testing::make_random_motion_scene({.points = 20, .duration = 0.2});
    CHECK_THROWS_AS(PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::kinetic, {.rays_per_frame = 4}),
                    PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::bottom_up,
                                            {.overlap_query = false, .rays_per_frame = 1}),
                    PCCD::Invalid_input);
    CHECK_NOTHROW(PCCD::testing::run_kinetic_scene(scene, PCCD::testing::Kinetic_method::kinetic, {.rays_per_frame = 0}));
}
