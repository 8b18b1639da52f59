// PCCD/concepts/PathSource.h -- concept of the path policies the interpolation search reads its
// shortest paths from (doc/algorithms.md, "Close-pairs shortest paths", "Paths on the fly" and
// "Search along a path"): stored (CPSP map) or computed on the fly.
#pragma once

#include <concepts>
#include <cstdint>
#include <vector>

namespace PCCD {

/// \concept PathSource
/// Gives shortest paths in a proximity graph between two points of the cloud.
///
/// Requirement, for `const P& source`, point indices `from`, `to` and a
/// `std::vector<std::uint32_t>& path`: `source.path(from, to, path)` returns true and writes the
/// points of a shortest path from `from` to `to` (both included, consecutive points adjacent in the
/// graph), or returns false with `path` empty when the policy has no such path (beyond its bound or
/// not connected). Must be safe to call concurrently.
///
/// Models: PCCD::Stored_paths (reads a Close_pairs_shortest_paths map) and PCCD::Paths_on_the_fly
/// (WSCG05 Algorithm 2, stores nothing).
template <class P>
concept PathSource = requires(const P& source, std::uint32_t from, std::uint32_t to, std::vector<std::uint32_t>& path) {
    { source.path(from, to, path) } -> std::convertible_to<bool>;
};

} // namespace PCCD
