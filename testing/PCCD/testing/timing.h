// PCCD/testing/timing.h -- wall-time helpers of the benchmarks, the pccd tool and the test
// harnesses: elapsed time on std::chrono::steady_clock in ms, us or s. They are the library's own
// (PCCD/internal/timing.h), re-exported here so that programs name them without `internal`; and the
// thread's CPU time, on which the query benchmarks time their queries. Part of
// no manual chapter: the figures they time are in doc/benchmarks.md.
#pragma once

#include <ctime>

#include <PCCD/internal/timing.h>

namespace PCCD::testing {

using Clock = PCCD::internal::Steady_clock;
using PCCD::internal::ms_since;
using PCCD::internal::seconds_since;
using PCCD::internal::us_since;

/// This thread's CPU time in microseconds (CLOCK_THREAD_CPUTIME_ID): what the query benchmarks
/// time on a shared machine, where wall time also counts the other processes' turns.
inline double thread_cpu_us()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e6 + double(t.tv_nsec) * 1e-3;
}

} // namespace PCCD::testing
