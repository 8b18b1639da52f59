// PCCD/testing/timing.h -- wall-time helpers of the benchmarks, the pccd tool and the test
// harnesses: elapsed time on std::chrono::steady_clock in ms, us or s. They are the library's own
// (PCCD/internal/timing.h), re-exported here so that programs name them without `internal`. Part of
// no manual chapter: the figures they time are in doc/benchmarks.md.
#pragma once

#include <PCCD/internal/timing.h>

namespace PCCD::testing {

using Clock = PCCD::internal::Steady_clock;
using PCCD::internal::ms_since;
using PCCD::internal::seconds_since;
using PCCD::internal::us_since;

} // namespace PCCD::testing
