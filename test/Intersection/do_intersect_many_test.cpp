// Batch queries (PCCD/Intersection/do_intersect_many.h): do_intersect_many() and
// intersection_points_many() over pairs of a sampled sphere and torus (both orders, some pairs
// the same object twice) answer in input order, and each result equals, bit for bit, the
// sequential do_intersect() / intersection_points() call with the documented per-pair seed, for
// 1, 2 and 4 threads and both leaf intersectors. Bad input (null object, bad options or policy)
// raises Invalid_input naming the problem, never a partial answer.
#include <PCCD/Intersection/Randomized_sampling.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include "build_helpers.h"
#include "intersection_test_helpers.h"
#include "surface_test_helpers.h"

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace {

using PCCD::Point_cloud_object;
using PCCD::Posed_pair;
using PCCD::Rigid_transform_3;
using Pair = Posed_pair<Point_cloud_object<>>;

struct Objects {
    Point_cloud_object<> sphere;
    Point_cloud_object<> torus;
};

const Objects& objects()
{
    static const Objects o = [] {
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 1500, 0.0, 201);
        const auto t = pccd_test::sample_shape(pccd_test::test_torus(), 2000, 0.0, 202);
        return Objects{Point_cloud_object<>(pccd_test::columns(s.points)),
                       Point_cloud_object<>(pccd_test::columns(t.points))};
    }();
    return o;
}

/// `count` pairs at random orientations: every fourth (k = 1, 5, ...) at a distance of 2.6 ... 3.2
/// between the centres, beyond the reach of the sphere (radius 1) and the torus (outer radius 1.4),
/// so separate; the others at 0 ... 2.2, most of them colliding. Every third pair has the torus
/// first, every fifth the sphere against itself.
std::vector<Pair> make_pairs(std::size_t count)
{
    const Objects& o = objects();
    PCCD::Random_engine engine(77);
    std::vector<Pair> pairs;
    for (std::size_t k = 0; k < count; ++k) {
        const Eigen::Vector3d direction(PCCD::standard_normal(engine), PCCD::standard_normal(engine),
                                        PCCD::standard_normal(engine));
        const double distance = k % 4 == 1 ? PCCD::uniform_real(engine, 2.6, 3.2) : PCCD::uniform_real(engine, 0.0, 2.2);
        const Rigid_transform_3<double> first(PCCD::testing::uniform_random_rotation(engine), Eigen::Vector3d::Zero());
        const Rigid_transform_3<double> second(PCCD::testing::uniform_random_rotation(engine), distance * direction.normalized());
        const Point_cloud_object<>* a = k % 3 == 1 ? &o.torus : &o.sphere;
        const Point_cloud_object<>* b = k % 5 == 4 ? &o.sphere : (a == &o.torus ? &o.sphere : &o.torus);
        pairs.push_back({a, first, b, second});
    }
    return pairs;
}

constexpr std::size_t pair_count = pccd_test::by_build<std::size_t>(60, 16);

/// Sample counts capped below the defaults so that the Debug sanitizer build stays fast; the
/// property under test does not depend on them.
const PCCD::Interpolation_search isearch{.min_samples = 100, .max_samples = 150};
const PCCD::Randomized_sampling rst{.max_samples = 1000};

/// The truth: the sequential calls, one after the other, with the documented seeds.
template <class Policy>
std::vector<PCCD::Intersection_result> sequential(const std::vector<Pair>& pairs, const PCCD::Intersection_options& options,
                                                  const Policy& policy, bool first_hit)
{
    std::vector<PCCD::Intersection_result> results;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        PCCD::Intersection_options o = options;
        o.seed = PCCD::pair_seed(options.seed, i);
        const Pair& p = pairs[i];
        results.push_back(first_hit ? PCCD::do_intersect(*p.a, p.pose_a, *p.b, p.pose_b, o, policy)
                                    : PCCD::intersection_points(*p.a, p.pose_a, *p.b, p.pose_b, o, policy));
    }
    return results;
}

template <class Policy>
void check_batches(const Policy& policy, bool first_hit)
{
    const std::vector<Pair> pairs = make_pairs(pair_count);
    const PCCD::Intersection_options options{.seed = 4242};
    const std::vector<PCCD::Intersection_result> truth = sequential(pairs, options, policy, first_hit);

    // The mix the test claims: both answers occur.
    std::size_t hits = 0;
    for (const auto& r : truth) hits += r.intersects ? 1 : 0;
    INFO("pairs " << pairs.size() << ", intersecting " << hits);
    REQUIRE(hits > 0);
    REQUIRE(hits < pairs.size());

    for (const unsigned threads : {1u, 2u, 4u}) {
        INFO("threads " << threads << (first_hit ? ", do_intersect_many" : ", intersection_points_many"));
        const std::vector<PCCD::Intersection_result> batch =
            first_hit ? PCCD::do_intersect_many(pairs, {.threads = threads}, options, policy)
                      : PCCD::intersection_points_many(pairs, {.threads = threads}, options, policy);
        REQUIRE(batch.size() == truth.size());
        for (std::size_t i = 0; i < batch.size(); ++i) {
            INFO("pair " << i);
            CHECK(pccd_test::result_difference(batch[i], truth[i]) == "");
        }
    }
}

} // namespace

TEST_CASE("pair_seed: documented formula, distinct seeds for neighbouring indices", "[intersection][batch]")
{
    // SplitMix64's first output for state 0 (seed + 1 * golden gamma with seed = 0), a published value.
    CHECK(PCCD::pair_seed(0, 0) == 0xe220a8397b1dcdafULL);
    std::set<std::uint64_t> seeds;
    for (std::uint64_t i = 0; i < 1000; ++i) seeds.insert(PCCD::pair_seed(0x5eed, i));
    CHECK(seeds.size() == 1000);
    CHECK(PCCD::pair_seed(1, 0) != PCCD::pair_seed(0, 0));
}

TEST_CASE("do_intersect_many equals the sequential do_intersect calls for 1, 2 and 4 threads", "[intersection][batch]")
{
    SECTION("interpolation search") { check_batches(isearch, true); }
    SECTION("randomized sampling") { check_batches(rst, true); }
}

TEST_CASE("intersection_points_many equals the sequential intersection_points calls for 1, 2 and 4 threads",
          "[intersection][batch]")
{
    SECTION("interpolation search") { check_batches(isearch, false); }
    SECTION("randomized sampling") { check_batches(rst, false); }
}

TEST_CASE("Batch results depend on the pair index, not on the neighbours", "[intersection][batch]")
{
    // Pair i of a batch answers as pair 0 of a one-pair batch seeded so that its seed matches.
    const std::vector<Pair> pairs = make_pairs(6);
    const PCCD::Intersection_options options{.seed = 99};
    const auto all = PCCD::intersection_points_many(pairs, {.threads = 2}, options, isearch);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const PCCD::Intersection_options o{.seed = PCCD::pair_seed(99, i)};
        const auto& p = pairs[i];
        CHECK(pccd_test::result_difference(all[i], PCCD::intersection_points(*p.a, p.pose_a, *p.b, p.pose_b, o, isearch)) ==
              "");
    }
}

TEST_CASE("Chunks with first_index together equal the whole batch", "[intersection][batch]")
{
    const std::vector<Pair> pairs = make_pairs(9);
    const PCCD::Intersection_options options{.seed = 5};
    const auto whole = PCCD::do_intersect_many(pairs, {.threads = 2}, options, rst);
    for (const std::size_t first : {std::size_t(0), std::size_t(4), std::size_t(7)}) {
        const std::vector<Pair> chunk(pairs.begin() + std::ptrdiff_t(first), pairs.end());
        const auto part = PCCD::do_intersect_many(chunk, {.threads = 1, .first_index = first}, options, rst);
        for (std::size_t i = 0; i < chunk.size(); ++i) {
            INFO("chunk from " << first << ", pair " << i);
            CHECK(pccd_test::result_difference(part[i], whole[first + i]) == "");
        }
    }
}

TEST_CASE("Batch queries reject bad input with Invalid_input", "[intersection][batch][robustness]")
{
    using Catch::Matchers::Contains;
    std::vector<Pair> pairs = make_pairs(4);

    SECTION("an empty batch answers nothing")
    {
        CHECK(PCCD::do_intersect_many(std::vector<Pair>{}).empty());
        CHECK(PCCD::intersection_points_many(std::vector<Pair>{}, {.threads = 2}).empty());
    }
    SECTION("a null object names the pair")
    {
        pairs[2].b = nullptr;
        CHECK_THROWS_WITH(PCCD::do_intersect_many(pairs), Contains("pair 2 has no object b"));
        pairs[2].b = pairs[2].a;
        pairs[3].a = nullptr;
        CHECK_THROWS_AS(PCCD::intersection_points_many(pairs, {.threads = 4}), PCCD::Invalid_input);
        CHECK_THROWS_WITH(PCCD::intersection_points_many(pairs), Contains("pair 3 has no object a"));
    }
    SECTION("invalid options and policies are named, before any query")
    {
        CHECK_THROWS_WITH(PCCD::do_intersect_many(pairs, {}, {.epsilon = -1.0}),
                          Contains("do_intersect_many: epsilon -1"));
        CHECK_THROWS_WITH(PCCD::intersection_points_many(pairs, {}, {.max_f_evaluations = 0}),
                          Contains("max_f_evaluations = 0"));
        CHECK_THROWS_WITH(PCCD::do_intersect_many(pairs, {}, {}, PCCD::Interpolation_search{.min_samples = 0}),
                          Contains("min_samples must be >= 1"));
        CHECK_THROWS_AS(PCCD::do_intersect_many(pairs, {.threads = 2}, {.contact_core = 2.0}), PCCD::Invalid_input);
    }
    SECTION("a visitor is refused: the batch runs its queries on several threads")
    {
        PCCD::Intersection_visitor visitor;
        CHECK_THROWS_WITH(PCCD::do_intersect_many(pairs, {}, {.visitor = &visitor}), Contains("options.visitor is set"));
        CHECK_THROWS_WITH(PCCD::intersection_points_many(pairs, {}, {.visitor = &visitor}), Contains("options.visitor"));
    }
    SECTION("an absurd thread count is refused, not passed on to TBB")
    {
        CHECK_THROWS_WITH(PCCD::do_intersect_many(pairs, {.threads = 1'000'000}),
                          Contains("threads 1000000 exceeds the limit 4096"));
        CHECK_NOTHROW(PCCD::do_intersect_many(pairs, {.threads = PCCD::Batch_options::max_threads}));
        CHECK_THROWS_WITH(PCCD::do_intersect_many(pairs, {.threads = 0}), Contains("threads = 0"));
    }
}
