// PCCD/internal/parallel.h -- the parallel patterns PCCD's preprocessing needs (doc/design.md,
// "Beyond one core"): an unordered per-index loop, an ordered block pipeline whose output is
// consumed in index order, and two tasks at once (the halves of a hierarchy's build). With PCCD_HAS_TBB they run on TBB (inside an arena limited to the
// requested number of threads); without it they run sequentially. Every caller produces results
// that do not depend on the schedule, so both builds and every thread count give identical output.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>

#include <PCCD/Error.h>

#ifdef PCCD_HAS_TBB
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_invoke.h>
#include <oneapi/tbb/parallel_pipeline.h>
#include <oneapi/tbb/task_arena.h>
#endif

namespace PCCD::internal {

/// The most worker threads any option may ask for. TBB's arenas crash (rather than refuse) when
/// asked for hundreds of thousands of threads, so larger requests are rejected with a message.
inline constexpr unsigned max_worker_threads = 4096;

/// A thread count of an option: unset (std::nullopt) means all available threads.
using Thread_count = std::optional<unsigned>;

/// Throws Invalid_input unless `threads` is unset or in [1, max_worker_threads]; `what` names the option.
inline void check_threads(const Thread_count& threads, const char* what = "threads")
{
    if (!threads) return;
    if (*threads == 0)
        throw Invalid_input(concat(what, " = 0: a thread count must be >= 1 (leave it unset for all available threads)"));
    if (*threads > max_worker_threads)
        throw Invalid_input(concat(what, " = ", *threads, " exceeds the supported maximum of ", max_worker_threads,
                                   " worker threads (leave it unset for all available threads)"));
}

/// Runs `body()` with at most `threads` worker threads (unset: all available).
/// \throws Invalid_input if threads is 0 or > max_worker_threads.
template <class Body>
void with_threads(const Thread_count& threads, Body&& body)
{
    check_threads(threads);
#ifdef PCCD_HAS_TBB
    if (!threads) {
        body();
    } else {
        oneapi::tbb::task_arena arena(static_cast<int>(*threads));
        arena.execute([&] { body(); });
    }
#else
    body();
#endif
}

/// One instance of `T` per worker thread (a single one without TBB). `T` must be default
/// constructible; `local()` returns the calling thread's instance.
template <class T>
class Per_thread {
public:
    T& local()
    {
#ifdef PCCD_HAS_TBB
        return m_storage.local();
#else
        return m_storage;
#endif
    }

private:
#ifdef PCCD_HAS_TBB
    oneapi::tbb::enumerable_thread_specific<T> m_storage;
#else
    T m_storage;
#endif
};

/// Calls `body(begin, end)` on disjoint sub-ranges covering [0, n), in parallel when TBB is on.
/// Call it inside with_threads() to limit the thread count.
template <class Body>
void parallel_for_ranges(std::size_t n, std::size_t grain, const Body& body)
{
#ifdef PCCD_HAS_TBB
    oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::size_t>(0, n, std::max<std::size_t>(grain, 1)),
                              [&](const oneapi::tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
#else
    static_cast<void>(grain);
    if (n > 0) body(std::size_t(0), n);
#endif
}

/// Runs `first()` and `second()`, in parallel when TBB is on (sequentially, in that order, without).
/// Call it inside with_threads() to limit the thread count.
template <class First, class Second>
void parallel_invoke(const First& first, const Second& second)
{
#ifdef PCCD_HAS_TBB
    oneapi::tbb::parallel_invoke(first, second);
#else
    first();
    second();
#endif
}

/// Splits [0, n) into blocks of `block_size` indices, computes `compute(begin, end)` for the blocks
/// in parallel and hands each result to `consume(result)` in block order, one at a time (so
/// `consume` may append to shared output without locking). At most a few blocks per thread are in
/// flight, so memory stays bounded. Call it inside with_threads() to limit the thread count.
template <class Compute, class Consume>
void ordered_blocks(std::size_t n, std::size_t block_size, const Compute& compute, const Consume& consume)
{
    block_size = std::max<std::size_t>(block_size, 1);
#ifdef PCCD_HAS_TBB
    using Result = decltype(compute(std::size_t(0), std::size_t(0)));
    std::size_t next = 0;
    const std::size_t tokens = 4 * static_cast<std::size_t>(oneapi::tbb::this_task_arena::max_concurrency());
    oneapi::tbb::parallel_pipeline(
        tokens,
        oneapi::tbb::make_filter<void, std::pair<std::size_t, std::size_t>>(
            oneapi::tbb::filter_mode::serial_in_order,
            [&](oneapi::tbb::flow_control& control) -> std::pair<std::size_t, std::size_t> {
                if (next >= n) {
                    control.stop();
                    return {0, 0};
                }
                const std::size_t begin = next;
                next = std::min(n, next + block_size);
                return {begin, next};
            }) &
            oneapi::tbb::make_filter<std::pair<std::size_t, std::size_t>, Result>(
                oneapi::tbb::filter_mode::parallel,
                [&](std::pair<std::size_t, std::size_t> range) { return compute(range.first, range.second); }) &
            oneapi::tbb::make_filter<Result, void>(oneapi::tbb::filter_mode::serial_in_order,
                                                   [&](Result result) { consume(std::move(result)); }));
#else
    for (std::size_t begin = 0; begin < n; begin += block_size) consume(compute(begin, std::min(n, begin + block_size)));
#endif
}

} // namespace PCCD::internal
