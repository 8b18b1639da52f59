// PCCD/internal/removal.h -- the renumbering of the points of a cloud when some are taken out
// (doc/manual/surface.md, "Scans: where the surface is defined, noise and outliers": the outliers
// are removed, and the kd-tree and the local spacing follow without being built again).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <PCCD/Error.h>

namespace PCCD::internal {

/// The index renumber_without() gives a removed point.
inline constexpr std::uint32_t removed_point = std::numeric_limits<std::uint32_t>::max();

/// The new index of each of n points when the points `removed` (sorted indices, each once) are
/// taken out and the others keep their order (point i becomes i minus the number removed before
/// it); removed points get removed_point.
/// \throws Invalid_input (naming `what`) if `removed` is not sorted, repeats an index or holds
/// one >= n.
inline std::vector<std::uint32_t> renumber_without(std::size_t n, const std::vector<std::uint32_t>& removed,
                                                   const char* what)
{
    std::vector<std::uint32_t> renumbered(n);
    std::size_t next_removed = 0;
    std::uint32_t next_index = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (next_removed < removed.size() && removed[next_removed] == i) {
            renumbered[i] = removed_point;
            ++next_removed;
        } else {
            renumbered[i] = next_index++;
        }
    }
    if (next_removed != removed.size())
        throw Invalid_input(concat(what, ": the ", removed.size(), " points to remove must be sorted indices below ", n,
                                   ", each once"));
    return renumbered;
}

} // namespace PCCD::internal
