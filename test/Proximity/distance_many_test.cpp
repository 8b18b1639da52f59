// Tests of distance_many() (doc/manual/proximity.md "Many pairs"): each result is bit for bit the
// sequential distance() with the pair's seed, for one thread and for two; bad batches are refused
// before any work.
#include <PCCD/Proximity/distance_many.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>

#include "proximity_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using namespace pccd_test;

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

bool same(const PCCD::Distance_result& x, const PCCD::Distance_result& y)
{
    bool ok = x.status == y.status && same_bits(x.distance, y.distance) && same_bits(x.lower_bound, y.lower_bound) &&
              same_bits(x.upper_bound, y.upper_bound) && same_bits(x.depth, y.depth) && x.counters == y.counters;
    for (int d = 0; d < 3; ++d)
        ok = ok && same_bits(x.point_a(d), y.point_a(d)) && same_bits(x.point_b(d), y.point_b(d)) &&
             same_bits(x.contact_normal(d), y.contact_normal(d));
    return ok;
}

} // namespace

TEST_CASE("distance_many: the sequential answers, whatever the thread count", "[proximity]")
{
    const Sphere_pair& s = spheres();
    PCCD::Random_engine engine(12);
    std::vector<PCCD::Posed_pair<PCCD::Point_cloud_object<>>> pairs;
    for (int k = 0; k < 16; ++k) {
        const double d = 2.0 + s.spacing * (-10.0 + 25.0 * PCCD::uniform_01(engine)); // both intersecting and separate
        pairs.push_back({&s.a, Rigid_transform_3<double>(), &s.b, centred_at(d * random_direction(engine), 500 + k)});
    }
    const PCCD::Distance_options options{.penetration = true};
    const auto one = PCCD::distance_many(pairs, {.threads = 1}, options);
    const auto two = PCCD::distance_many(pairs, {.threads = 2}, options);
    REQUIRE(one.size() == pairs.size());
    std::size_t separate = 0, intersecting = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        PCCD::Distance_options single = options;
        single.intersection.seed = PCCD::pair_seed(options.intersection.seed, i);
        const PCCD::Distance_result r = PCCD::distance(*pairs[i].a, pairs[i].pose_a, *pairs[i].b, pairs[i].pose_b, single);
        CHECK(same(one[i], r));
        CHECK(same(two[i], r));
        separate += r.status == PCCD::Intersection_status::separate;
        intersecting += r.status == PCCD::Intersection_status::intersecting;
    }
    CHECK(separate > 0);
    CHECK(intersecting > 0);
}

TEST_CASE("distance_many: bad batches are refused before any work", "[proximity]")
{
    const Sphere_pair& s = spheres();
    std::vector<PCCD::Posed_pair<PCCD::Point_cloud_object<>>> pairs{{&s.a, {}, nullptr, {}}};
    using Catch::Matchers::Contains;
    CHECK_THROWS_WITH(PCCD::distance_many(pairs), Contains("pair 0 has no object b"));
    pairs[0].b = &s.b;
    CHECK_THROWS_WITH(PCCD::distance_many(pairs, {.threads = 0}), Contains("threads"));
    CHECK_THROWS_WITH(PCCD::distance_many(pairs, {}, {.relative_tolerance = -1.0}), Contains("relative_tolerance"));
}
