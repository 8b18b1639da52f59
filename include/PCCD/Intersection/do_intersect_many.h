// PCCD/Intersection/do_intersect_many.h -- batch queries: do_intersect_many() and
// intersection_points_many() answer a list of (object, pose, object, pose) pairs, in parallel on TBB
// when it is available, with the results in the order of the pairs and bit for bit those of the
// sequential calls, whatever the number of threads. Each pair gets its own seed, derived from the
// options' seed and the pair's index by pair_seed() (a time budget, Intersection_options::max_time_us,
// makes answers depend on timing, and then on the thread count). Implements
// doc/manual/intersection.md, "Many pairs at once".
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Intersection/Interpolation_search.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/concepts/LeafIntersector.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// One query of a batch: object `a` posed by `pose_a` against object `b` posed by `pose_b`. The
/// objects are referred to, not copied: they must outlive the batch call. The same object may
/// appear in any number of pairs (and on both sides of one pair).
template <CollisionObject A, CollisionObject B = A>
struct Posed_pair {
    const A* a = nullptr;
    Rigid_transform_3<double> pose_a;
    const B* b = nullptr;
    Rigid_transform_3<double> pose_b;
};

/// How a batch runs; the results never depend on it.
struct Batch_options {
    /// The largest `threads` accepted: TBB crashes when asked for an arena of a few hundred thousand
    /// threads, so absurd requests are refused with Invalid_input instead.
    static constexpr unsigned max_threads = internal::max_worker_threads;
    /// Worker threads, in [1, max_threads]. Unset (default): all available. Ignored without TBB
    /// (the pairs are then answered one after the other).
    std::optional<unsigned> threads = std::nullopt;
    /// The index of the first pair in a larger batch that was split into chunks (e.g. to spread it
    /// over several machines): pair i of the call is seeded as pair first_index + i of the whole,
    /// so the chunks' results together equal those of the whole batch. Default 0.
    std::uint64_t first_index = 0;
};

/// The seed of pair `index` of a batch whose options carry `seed`: the SplitMix64 output function
/// applied to seed + (index + 1) * 0x9e3779b97f4a7c15 (mod 2^64). Neighbouring indices thus get
/// unrelated seeds, and the seed of a pair depends on its index only, not on the schedule.
/// Pair i of do_intersect_many(pairs, batch, options, policy) is answered exactly as
/// do_intersect(*a, pose_a, *b, pose_b, options', policy) with options' = options except
/// options'.seed = pair_seed(options.seed, i); likewise for intersection_points_many().
constexpr std::uint64_t pair_seed(std::uint64_t seed, std::uint64_t index)
{
    std::uint64_t z = seed + (index + 1) * 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

namespace internal {

/// The checks every batch makes before any work (threads, null objects).
template <class A, class B>
void check_batch(std::span<const Posed_pair<A, B>> pairs, const Batch_options& batch, const char* function)
{
    if (batch.threads && *batch.threads > Batch_options::max_threads)
        throw Invalid_input(concat(function, ": threads ", *batch.threads, " exceeds the limit ", Batch_options::max_threads,
                                   " (leave it unset for all available threads)"));
    if (batch.threads && *batch.threads == 0)
        throw Invalid_input(concat(function, ": threads = 0; a thread count must be >= 1 (leave it unset for all available threads)"));
    for (std::size_t i = 0; i < pairs.size(); ++i)
        if (pairs[i].a == nullptr || pairs[i].b == nullptr)
            throw Invalid_input(concat(function, ": pair ", i, " has no object ", pairs[i].a == nullptr ? "a" : "b",
                                       " (null pointer)"));
}

/// Runs `answer(pair, seed_index)` for every pair on `batch.threads` threads into a vector of
/// results in the pairs' order (seed_index = batch.first_index + i). A pair that throws does not
/// stop the others; afterwards the exception of the first such pair in input order is rethrown,
/// the one the sequential loop would have thrown.
template <class Result, class A, class B, class Answer>
std::vector<Result> run_batch(std::span<const Posed_pair<A, B>> pairs, const Batch_options& batch, const char* function,
                              Answer answer)
{
    check_batch(pairs, batch, function);
    std::vector<Result> results(pairs.size());
    std::vector<std::exception_ptr> errors(pairs.size());
    const auto run = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            try {
                results[i] = answer(pairs[i], batch.first_index + i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    // Grain 1: queries differ in cost by orders of magnitude (a first hit vs a near miss).
    with_threads(batch.threads, [&] { parallel_for_ranges(pairs.size(), 1, run); });
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
    return results;
}

template <class A, class B, class Policy>
std::vector<Intersection_result> run_many(std::span<const Posed_pair<A, B>> pairs, const Batch_options& batch,
                                          const Intersection_options& options, const Policy& policy,
                                          bool first_hit, const char* function)
{
    // Everything that does not depend on the pair is checked once, before any work.
    check_options(options, function);
    if (options.visitor)
        throw Invalid_input(concat(function, ": options.visitor is set; the batch runs its queries on several threads at "
                                             "once, so a visitor is taken by the single queries only"));
    policy.check();
    return run_batch<Intersection_result>(pairs, batch, function, [&](const Posed_pair<A, B>& p, std::uint64_t index) {
        Intersection_options pair_options = options;
        pair_options.seed = pair_seed(options.seed, index);
        return run_query(*p.a, p.pose_a, *p.b, p.pose_b, pair_options, policy, first_hit, function);
    });
}

} // namespace internal

/// do_intersect() for every pair of `pairs`: result i answers pair i, with the seed
/// pair_seed(options.seed, batch.first_index + i) (see there), and is bit for bit the result of that sequential call
/// (answer, status, points, counters), for any `batch.threads` and with or without TBB.
///
/// \tparam A, B models of CollisionObject (Point_cloud_object<K>).
/// \tparam Policy a model of LeafIntersector for A and B: Interpolation_search (default) or
///         Randomized_sampling.
/// \throws Invalid_input for invalid options or policy parameters, options.visitor set (the
///         queries run on several threads), more than
///         Batch_options::max_threads threads, or a pair with a null object (naming its index),
///         before any query runs; an exception thrown by the query of a pair is
///         rethrown after the other pairs are done (the one of the lowest index if several threw).
/// Thread safety: the objects are only read; the call may run concurrently with other queries on
/// the same objects. Complexity: the sum of the queries' costs, divided among the threads; one
/// result vector.
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
std::vector<Intersection_result> do_intersect_many(std::span<const Posed_pair<A, B>> pairs,
                                                   const Batch_options& batch = {},
                                                   const Intersection_options& options = {},
                                                   const Policy& policy = Policy())
{
    return internal::run_many(pairs, batch, options, policy, true, "do_intersect_many");
}

/// The same for a vector of pairs.
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
std::vector<Intersection_result> do_intersect_many(const std::vector<Posed_pair<A, B>>& pairs,
                                                   const Batch_options& batch = {},
                                                   const Intersection_options& options = {},
                                                   const Policy& policy = Policy())
{
    return internal::run_many(std::span<const Posed_pair<A, B>>(pairs), batch, options, policy, true,
                              "do_intersect_many");
}

/// intersection_points() for every pair of `pairs`, with the same seeds, order and guarantees as
/// do_intersect_many().
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
std::vector<Intersection_result> intersection_points_many(std::span<const Posed_pair<A, B>> pairs,
                                                          const Batch_options& batch = {},
                                                          const Intersection_options& options = {},
                                                          const Policy& policy = Policy())
{
    return internal::run_many(pairs, batch, options, policy, false, "intersection_points_many");
}

/// The same for a vector of pairs.
template <CollisionObject A, CollisionObject B, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, A, B>
std::vector<Intersection_result> intersection_points_many(const std::vector<Posed_pair<A, B>>& pairs,
                                                          const Batch_options& batch = {},
                                                          const Intersection_options& options = {},
                                                          const Policy& policy = Policy())
{
    return internal::run_many(std::span<const Posed_pair<A, B>>(pairs), batch, options, policy, false,
                              "intersection_points_many");
}

} // namespace PCCD
