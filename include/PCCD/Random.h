// PCCD/Random.h -- reproducible randomness: one engine type and distribution functions whose output
// is the same on every platform and standard library (std::uniform_real_distribution and
// std::normal_distribution are implementation-defined, so PCCD does not use them).
//
// All stochastic parts of PCCD (sampling, root bracketing, RST, poses) take a Random_engine or a
// seed explicitly; there is no global random state.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include <PCCD/Error.h>

namespace PCCD {

/// The engine used throughout PCCD. std::mt19937_64's output sequence is fixed by the standard.
using Random_engine = std::mt19937_64;

/// Uniform double in [0, 1), from the top 53 bits of one engine output.
inline double uniform_01(Random_engine& engine)
{
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

/// Uniform double in [lo, hi).
inline double uniform_real(Random_engine& engine, double lo, double hi)
{
    return lo + (hi - lo) * uniform_01(engine);
}

/// Uniform integer in [0, n), unbiased (rejection of the incomplete top range).
/// \pre n > 0
inline std::uint64_t uniform_index(Random_engine& engine, std::uint64_t n)
{
    PCCD_precondition_msg(n > 0, "uniform_index needs a non-empty range");
    const std::uint64_t limit = std::uint64_t(-1) - (std::uint64_t(-1) % n + 1) % n;
    std::uint64_t value = engine();
    while (value > limit) value = engine();
    return value % n;
}

/// Standard normal variate (Box-Muller; uses two uniforms per call, keeps no state).
inline double standard_normal(Random_engine& engine)
{
    double u1 = uniform_01(engine);
    while (u1 <= 0.0) u1 = uniform_01(engine);
    const double u2 = uniform_01(engine);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

} // namespace PCCD
