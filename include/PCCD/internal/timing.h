// PCCD/internal/timing.h -- elapsed wall time on std::chrono::steady_clock, in milliseconds,
// microseconds or seconds, for the stage timings the library reports (Point_cloud_object's
// timings(), doc/manual/surface.md; the kinetic scenes' frame times, doc/manual/kinetic.md). The
// benchmark and tool helpers (testing/PCCD/testing/timing.h) reuse these rather than keep copies.
#pragma once

#include <chrono>

namespace PCCD::internal {

/// The clock of every PCCD timing: monotonic, unaffected by changes of the system time.
using Steady_clock = std::chrono::steady_clock;

/// Wall time elapsed since `start`, in milliseconds.
inline double ms_since(Steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Steady_clock::now() - start).count();
}

/// Wall time elapsed since `start`, in microseconds.
inline double us_since(Steady_clock::time_point start)
{
    return std::chrono::duration<double, std::micro>(Steady_clock::now() - start).count();
}

/// Wall time elapsed since `start`, in seconds.
inline double seconds_since(Steady_clock::time_point start)
{
    return std::chrono::duration<double>(Steady_clock::now() - start).count();
}

} // namespace PCCD::internal
