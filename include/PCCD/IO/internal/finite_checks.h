// PCCD/IO/internal/finite_checks.h -- the NaN and infinity tests of PCCD's file checks and writers
// (doc/manual/io.md, "Errors": a NaN or infinite coordinate or normal is refused on reading and on
// writing). They look at the bits, so that they raise no floating-point exception even for a
// signaling NaN. This header does not include CGAL.
#pragma once

#include <PCCD/IO/internal/text_scanner.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>

namespace PCCD::IO::internal {

/// Finiteness and NaN tests on the bits, which raise no floating-point exception even for a
/// signaling NaN (PCCD's Debug tests trap floating-point exceptions).
inline bool is_finite(double x) noexcept
{
    return (std::bit_cast<std::uint64_t>(x) & 0x7FF0000000000000u) != 0x7FF0000000000000u;
}
inline bool is_nan(double x) noexcept
{
    return !is_finite(x) && (std::bit_cast<std::uint64_t>(x) & 0x000FFFFFFFFFFFFFu) != 0;
}
/// True when the three coordinates of `v` (anything with `v[0]`, `v[1]`, `v[2]`) are finite.
template <class Vector3>
bool is_finite(const Vector3& v) noexcept
{
    return is_finite(static_cast<double>(v[0])) && is_finite(static_cast<double>(v[1])) &&
           is_finite(static_cast<double>(v[2]));
}

/// Throws when one of the three values is NaN or infinite: "<what> <index> (line L) has a NaN <kind>".
inline void check_finite(const std::string& path, const double* xyz, const char* what, std::uint64_t index,
                         std::size_t line, const char* kind)
{
    for (int k = 0; k < 3; ++k) {
        if (is_nan(xyz[k])) fail(path, concat(what, ' ', index, at_line(line), " has a NaN ", kind));
        if (!is_finite(xyz[k])) fail(path, concat(what, ' ', index, at_line(line), " has an infinite ", kind));
    }
}

} // namespace PCCD::IO::internal
