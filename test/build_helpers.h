// pccd_test::debug_build: true in builds without NDEBUG (Debug: assertions on, little or no
// optimization; CI's sanitizer build), where the library runs several to a hundred times slower
// than in Release. Tests whose checks repeat over many shapes, sizes or poses run fewer
// repetitions there (pccd_test::by_build): the same assertions on fewer inputs; Release runs them
// all.
#pragma once

namespace pccd_test {

#ifdef NDEBUG
inline constexpr bool debug_build = false;
#else
inline constexpr bool debug_build = true;
#endif

/// `release` in builds with NDEBUG, `debug` in the others.
template <class T>
constexpr T by_build(T release, T debug)
{
    return debug_build ? debug : release;
}

} // namespace pccd_test
