// Tests of Dynamic_AABB_tree (doc/algorithms.md "Collision worlds"): after random insertions,
// moves and erasures (fixed seeds) the tree keeps its invariants and a logarithmic height, and its
// three queries report exactly what a brute-force scan of the stored boxes reports.
#include <PCCD/World/Dynamic_AABB_tree.h>

#include <catch2/catch.hpp>

#include <PCCD/Error.h>
#include <PCCD/Random.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace {

using Box = Eigen::AlignedBox3d;
using PCCD::Dynamic_AABB_tree;

Box random_box(PCCD::Random_engine& engine, double world, double size)
{
    const Eigen::Vector3d c(PCCD::uniform_real(engine, 0, world), PCCD::uniform_real(engine, 0, world),
                            PCCD::uniform_real(engine, 0, world));
    const Eigen::Vector3d h(PCCD::uniform_real(engine, 0.1, 1.0) * size, PCCD::uniform_real(engine, 0.1, 1.0) * size,
                            PCCD::uniform_real(engine, 0.1, 1.0) * size);
    return Box(c - h, c + h);
}

/// Squared distance from the segment origin + t d, t in [0, t_max], to the box: a convex function of
/// t, minimized by golden-section search (independent of the tree's slab test).
double segment_box_distance2(const Box& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_max)
{
    double lo = 0.0, hi = t_max;
    const auto g = [&](double t) { return box.squaredExteriorDistance(Eigen::Vector3d(o + t * d)); };
    for (int k = 0; k < 200; ++k) {
        const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
        if (g(m1) <= g(m2)) hi = m2; else lo = m1;
    }
    return std::min({g(lo), g(0.0), g(t_max)});
}

struct Model {
    std::map<std::uint32_t, Dynamic_AABB_tree::Proxy> proxies; // id -> proxy
};

void check_queries(const Dynamic_AABB_tree& tree, const Model& model, PCCD::Random_engine& engine, double world)
{
    tree.check_invariants();
    REQUIRE(tree.size() == model.proxies.size());
    // All overlapping pairs, against all pairs of stored boxes.
    std::set<std::pair<std::uint32_t, std::uint32_t>> found, expected;
    std::size_t calls = 0;
    tree.for_each_overlapping_pair([&](std::uint32_t a, std::uint32_t b) {
        ++calls;
        found.insert({std::min(a, b), std::max(a, b)});
    });
    CHECK(calls == found.size()); // each pair once
    for (auto i = model.proxies.begin(); i != model.proxies.end(); ++i)
        for (auto j = std::next(i); j != model.proxies.end(); ++j)
            if (tree.fat_box(i->second).intersects(tree.fat_box(j->second))) expected.insert({i->first, j->first});
    CHECK(found == expected);
    // Box queries.
    for (int q = 0; q < 20; ++q) {
        const Box query = random_box(engine, world, 3.0);
        std::set<std::uint32_t> hit, truth;
        tree.for_each_overlapping(query, [&](std::uint32_t id) { hit.insert(id); });
        for (const auto& [id, proxy] : model.proxies)
            if (tree.fat_box(proxy).intersects(query)) truth.insert(id);
        CHECK(hit == truth);
    }
    // Ray queries: boxes the segment clearly crosses must be reported, boxes it clearly misses not.
    for (int q = 0; q < 20; ++q) {
        const Eigen::Vector3d o(PCCD::uniform_real(engine, 0, world), PCCD::uniform_real(engine, 0, world), -1.0);
        Eigen::Vector3d d(PCCD::standard_normal(engine), PCCD::standard_normal(engine), 1.0 + std::abs(PCCD::standard_normal(engine)));
        if (q % 5 == 0) d = Eigen::Vector3d(0, 0, 1); // axis-parallel: zero components
        const double t_max = PCCD::uniform_real(engine, 0.3, 1.0) * world;
        std::map<std::uint32_t, double> hit;
        tree.for_each_crossed(o, d, t_max, [&](std::uint32_t id, double t) { hit[id] = t; });
        for (const auto& [id, proxy] : model.proxies) {
            const double d2 = segment_box_distance2(tree.fat_box(proxy), o, d, t_max);
            if (d2 == 0.0 && segment_box_distance2(Box(tree.fat_box(proxy).min().array() + 1e-6,
                                                          tree.fat_box(proxy).max().array() - 1e-6),
                                                      o, d, t_max) == 0.0) {
                REQUIRE(hit.contains(id));
                // The reported entry point is on the segment and inside the (slightly grown) box.
                const Box grown(tree.fat_box(proxy).min().array() - 1e-9, tree.fat_box(proxy).max().array() + 1e-9);
                CHECK(grown.contains(Eigen::Vector3d(o + hit[id] * d)));
                CHECK(hit[id] >= 0.0);
                CHECK(hit[id] <= t_max);
            }
            if (d2 > 1e-12) CHECK_FALSE(hit.contains(id));
        }
    }
}

} // namespace

TEST_CASE("Dynamic_AABB_tree: random insertions, moves and erasures against brute force", "[world][tree]")
{
    for (const double fat : {0.0, 0.05, 0.3}) {
        PCCD::Random_engine engine(1234 + std::uint64_t(fat * 100));
        const double world = 30.0;
        Dynamic_AABB_tree tree(PCCD::Dynamic_AABB_tree_options{fat, 2.0});
        Model model;
        std::uint32_t next_id = 0;
        for (int round = 0; round < 6; ++round) {
            for (int k = 0; k < 60; ++k) {
                const std::uint32_t id = next_id++;
                model.proxies[id] = tree.insert(random_box(engine, world, 1.0), id);
            }
            // Move 30 %: small moves (mostly inside the fat box) and jumps.
            for (auto& [id, proxy] : model.proxies) {
                if (PCCD::uniform_01(engine) > 0.3) continue;
                const Box old = tree.fat_box(proxy);
                const Box moved = PCCD::uniform_01(engine) < 0.5
                                      ? Box(old.center() - 0.3 * old.sizes(), old.center() + 0.3 * old.sizes())
                                      : random_box(engine, world, 1.0);
                tree.update(proxy, moved);
                CHECK(tree.fat_box(proxy).contains(moved));
                CHECK(tree.id(proxy) == id);
            }
            // Erase 20 %.
            for (auto it = model.proxies.begin(); it != model.proxies.end();) {
                if (PCCD::uniform_01(engine) < 0.2) {
                    tree.erase(it->second);
                    it = model.proxies.erase(it);
                } else {
                    ++it;
                }
            }
            check_queries(tree, model, engine, world);
            const auto s = tree.statistics();
            CHECK(s.proxies == model.proxies.size());
            // Height near log2(n): the balancing and the rebuilds keep it within twice the optimum.
            CHECK(double(s.height) <= 2.0 * std::ceil(std::log2(double(std::max<std::size_t>(2, s.proxies)))) + 2.0);
        }
        tree.rebuild();
        check_queries(tree, model, engine, world);
        // Erase everything: the tree is empty and queries report nothing.
        for (const auto& [id, proxy] : model.proxies) tree.erase(proxy);
        CHECK(tree.empty());
        tree.check_invariants();
        bool any = false;
        tree.for_each_overlapping_pair([&](std::uint32_t, std::uint32_t) { any = true; });
        CHECK_FALSE(any);
    }
}

TEST_CASE("Dynamic_AABB_tree: a move inside the fat box leaves the tree alone", "[world][tree]")
{
    Dynamic_AABB_tree tree(PCCD::Dynamic_AABB_tree_options{0.1, 2.0});
    const auto p = tree.insert(Box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 7);
    tree.insert(Box(Eigen::Vector3d::Constant(5.0), Eigen::Vector3d::Constant(6.0)), 8);
    CHECK_FALSE(tree.update(p, Box(Eigen::Vector3d::Constant(0.1), Eigen::Vector3d::Constant(1.1))));
    CHECK(tree.update(p, Box(Eigen::Vector3d::Constant(2.0), Eigen::Vector3d::Constant(3.0))));
    CHECK(tree.statistics().reinsertions == 1);
}

TEST_CASE("Dynamic_AABB_tree: early stop and bad input", "[world][tree]")
{
    Dynamic_AABB_tree tree;
    for (std::uint32_t i = 0; i < 10; ++i) tree.insert(Box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), i);
    int seen = 0;
    tree.for_each_overlapping_pair([&](std::uint32_t, std::uint32_t) { return ++seen < 3; });
    CHECK(seen == 3);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(tree.insert(Box(), 1), PCCD::Invalid_input); // empty
    CHECK_THROWS_AS(tree.insert(Box(Eigen::Vector3d::Zero(), Eigen::Vector3d(nan, 1, 1)), 1), PCCD::Invalid_input);
    CHECK_THROWS_AS(tree.update(999, Box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones())), PCCD::Invalid_input);
    const auto p = tree.insert(Box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), 11);
    tree.erase(p);
    CHECK_THROWS_AS(tree.erase(p), PCCD::Invalid_input); // twice
    CHECK_THROWS_AS(Dynamic_AABB_tree(PCCD::Dynamic_AABB_tree_options{-1.0, 2.0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(Dynamic_AABB_tree(PCCD::Dynamic_AABB_tree_options{0.1, 1.0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(Dynamic_AABB_tree(PCCD::Dynamic_AABB_tree_options{0.1, nan}), PCCD::Invalid_input);
}
