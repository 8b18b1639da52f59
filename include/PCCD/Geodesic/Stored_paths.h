// PCCD/Geodesic/Stored_paths.h -- the Stored_paths path policy: the geodesic paths of the surface
// read from a CPSP map (doc/manual/graphs.md, "The CPSP map"), as opposed to Paths_on_the_fly
// ("Paths without storage"). Models PathSource (PCCD/concepts/PathSource.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>

namespace PCCD {

/// Path policy reading the shortest paths stored in a CPSP map (doc/manual/graphs.md, "The CPSP map"). Models
/// PathSource. Cheap to copy; refers to the map, which must outlive it.
class Stored_paths {
public:
    using Index = std::uint32_t;
    explicit Stored_paths(const Close_pairs_shortest_paths& map) : m_map(&map) {}

    /// Writes the stored shortest path from `from` to `to` (both included) into `path` and returns
    /// true, or returns false (path cleared) when `to` is beyond the CPSP bound of `from`.
    /// O(list length + path length). Thread-safe.
    bool path(Index from, Index to, std::vector<Index>& path) const
    {
        const std::size_t entry = m_map->find(from, to);
        if (entry == Close_pairs_shortest_paths::npos) {
            path.clear();
            return false;
        }
        m_map->path(from, entry, path);
        return true;
    }

private:
    const Close_pairs_shortest_paths* m_map;
};

} // namespace PCCD
