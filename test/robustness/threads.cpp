// Thread safety and determinism of the intersection queries (doc/reliability.md,
// "Threads"): two shared preprocessed objects (a sampled sphere and torus) answer ~200 queries --
// colliding and separate poses, both leaf intersectors, do_intersect() and intersection_points() --
// sequentially, from 4 threads taking interleaved queries, and from 4 threads taking them in
// reversed order. Every result (answer, status, counters, every point bit for bit) must equal the
// sequential one. Built with -DPCCD_SANITIZE=thread this is also the ThreadSanitizer test.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include "build_helpers.h"
#include "intersection_test_helpers.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;

struct Objects {
    PCCD::Point_cloud_object<> sphere;
    PCCD::Point_cloud_object<> torus;
};

/// Built once and shared by every thread (read only). Single-threaded preprocessing keeps TBB's
/// worker pool out of the ThreadSanitizer run: the queries under test use no TBB.
const Objects& objects()
{
    static const Objects o = [] {
        const PCCD::Point_cloud_object_options options{.threads = 1};
        const auto s = pccd_test::sample_shape(pccd_test::unit_sphere(), 2000, 0.0, 101);
        const auto t = pccd_test::sample_shape(pccd_test::test_torus(), 2500, 0.0, 102);
        return Objects{PCCD::Point_cloud_object<>(pccd_test::columns(s.points), PCCD::Identity_point_map<Eigen::Vector3d>(), options),
                       PCCD::Point_cloud_object<>(pccd_test::columns(t.points), PCCD::Identity_point_map<Eigen::Vector3d>(), options)};
    }();
    return o;
}

enum class Policy { isearch, rst };

struct Query {
    Rigid_transform_3<double> pose_sphere;
    Rigid_transform_3<double> pose_torus;
    Policy policy;
    bool first_hit;
    PCCD::Intersection_options options;
};

/// Sample counts capped below the defaults so that the test stays fast in the Debug sanitizer
/// builds (intersection_points() has no early stop); determinism does not depend on them.
const PCCD::Interpolation_search isearch_policy{.min_samples = 100, .max_samples = 150};
const PCCD::Randomized_sampling rst_policy{.max_samples = 1000};

PCCD::Intersection_result answer(const Query& q)
{
    const Objects& o = objects();
    if (q.policy == Policy::isearch)
        return q.first_hit ? PCCD::do_intersect(o.sphere, q.pose_sphere, o.torus, q.pose_torus, q.options, isearch_policy)
                           : PCCD::intersection_points(o.sphere, q.pose_sphere, o.torus, q.pose_torus, q.options,
                                                       isearch_policy);
    return q.first_hit ? PCCD::do_intersect(o.sphere, q.pose_sphere, o.torus, q.pose_torus, q.options, rst_policy)
                       : PCCD::intersection_points(o.sphere, q.pose_sphere, o.torus, q.pose_torus, q.options, rst_policy);
}

/// ~200 queries: the sphere at random orientations and distances 0 ... 2.8 from the torus's centre
/// (the torus spans radius 0.6 ... 1.4 in its plane), so both colliding and separate poses occur;
/// the torus posed too; every combination of policy and entry point; distinct seeds.
std::vector<Query> make_queries(std::size_t count)
{
    PCCD::Random_engine engine(2024);
    std::vector<Query> queries;
    for (std::size_t k = 0; k < count; ++k) {
        const Eigen::Vector3d direction(PCCD::standard_normal(engine), PCCD::standard_normal(engine),
                                        PCCD::standard_normal(engine));
        const double distance = PCCD::uniform_real(engine, 0.0, 2.8);
        const Eigen::Matrix3d rs = PCCD::testing::uniform_random_rotation(engine);
        const Eigen::Matrix3d rt = PCCD::testing::uniform_random_rotation(engine);
        const Eigen::Vector3d shift(PCCD::uniform_real(engine, -1, 1), PCCD::uniform_real(engine, -1, 1),
                                    PCCD::uniform_real(engine, -1, 1));
        const Rigid_transform_3<double> torus(rt, shift);
        const Rigid_transform_3<double> sphere(rs, shift + rt * (distance * direction.normalized()));
        PCCD::Intersection_options options{.seed = 1000 + k};
        if (k % 5 == 3) options.max_f_evaluations = 50 + 13 * k; // some queries stop on the budget
        if (k % 7 == 5) options.refinement = PCCD::Refinement::sampling;
        queries.push_back({sphere, torus, k % 2 ? Policy::rst : Policy::isearch, (k / 2) % 2 == 0, options});
    }
    return queries;
}

using pccd_test::result_difference;

/// Answers the queries with `threads` threads; thread t answers the indices order[t], order[t +
/// threads], ... Exceptions are carried back to the caller.
std::vector<PCCD::Intersection_result> answer_concurrently(const std::vector<Query>& queries,
                                                           const std::vector<std::size_t>& order, unsigned threads)
{
    std::vector<PCCD::Intersection_result> results(queries.size());
    std::vector<std::exception_ptr> errors(threads);
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            try {
                for (std::size_t k = t; k < order.size(); k += threads) results[order[k]] = answer(queries[order[k]]);
            } catch (...) {
                errors[t] = std::current_exception();
            }
        });
    for (std::thread& w : workers) w.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
    return results;
}

} // namespace

// 200 queries in Release builds; 48 in Debug (sanitizer) builds, which are much slower.
constexpr std::size_t query_count = pccd_test::by_build<std::size_t>(200, 48);

TEST_CASE("Concurrent queries on shared objects equal the sequential answers bit for bit", "[threads][intersection]")
{
    const std::vector<Query> queries = make_queries(query_count);
    std::vector<PCCD::Intersection_result> sequential;
    for (const Query& q : queries) sequential.push_back(answer(q));

    // The mix is what the test claims: colliding and separate answers for both policies and modes.
    std::size_t kinds[2][2][2] = {};
    std::size_t budget_stops = 0;
    for (std::size_t k = 0; k < queries.size(); ++k) {
        ++kinds[int(queries[k].policy)][queries[k].first_hit][sequential[k].intersects];
        budget_stops += sequential[k].status == PCCD::Intersection_status::undecided;
    }
    for (int p = 0; p < 2; ++p)
        for (int m = 0; m < 2; ++m)
            for (int i = 0; i < 2; ++i) {
                INFO("policy " << p << ", first hit " << m << ", intersects " << i);
                CHECK(kinds[p][m][i] >= query_count / 40);
            }
    CHECK(budget_stops >= 1);

    std::vector<std::size_t> forward(queries.size()), reversed(queries.size());
    for (std::size_t k = 0; k < queries.size(); ++k) {
        forward[k] = k;
        reversed[k] = queries.size() - 1 - k;
    }
    for (const auto& [name, order] : {std::pair{"interleaved", forward}, std::pair{"reversed", reversed}}) {
        const auto concurrent = answer_concurrently(queries, order, 4);
        for (std::size_t k = 0; k < queries.size(); ++k) {
            INFO(name << " order, query " << k);
            CHECK(result_difference(concurrent[k], sequential[k]) == "");
        }
    }
}

TEST_CASE("Different seeds may give different answers, each reproducible from any thread", "[threads][intersection]")
{
    const Rigid_transform_3<double> torus;
    const Rigid_transform_3<double> sphere(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.2, 0.1));
    const std::size_t seeds = 8;
    std::vector<Query> queries;
    for (Policy policy : {Policy::isearch, Policy::rst})
        for (std::uint64_t seed = 0; seed < seeds; ++seed)
            queries.push_back({sphere, torus, policy, false, {.seed = seed, .refinement = PCCD::Refinement::none}});
    std::vector<PCCD::Intersection_result> first;
    for (const Query& q : queries) first.push_back(answer(q));
    std::vector<std::size_t> order(queries.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = order.size() - 1 - k;
    const auto again = answer_concurrently(queries, order, 3);
    for (std::size_t k = 0; k < queries.size(); ++k) {
        INFO("query " << k);
        CHECK(first[k].intersects);
        CHECK(result_difference(again[k], first[k]) == "");
    }
    // The seed matters: per policy, the seeds do not all give the same counters and points.
    for (std::size_t policy = 0; policy < 2; ++policy) {
        std::size_t distinct = 0;
        for (std::size_t s = 1; s < seeds; ++s)
            distinct += result_difference(first[policy * seeds + s], first[policy * seeds]) != "";
        INFO("policy " << policy);
        CHECK(distinct >= seeds / 2);
    }
}
