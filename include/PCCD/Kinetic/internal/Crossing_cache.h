// PCCD/Kinetic/internal/Crossing_cache.h -- a small direct-mapped cache of certificate failure
// times for the kinetic AABB tree (doc/manual/kinetic.md, "Cost of an event"). On the cloth about
// half of the next_crossing evaluations after construction ask again for a pair whose answer is
// already known (counted with an unbounded table), e.g. when a swaying pair of vertices hands a
// node's extreme back and forth, or when a node is repaired after one child changed and its
// champion is compared once more with the unchanged candidates; this small table catches most of
// the recent ones (a quarter to a third of all requests there).
//
// Why a reused answer is exact: let r = inf{ s > t0 : x is beaten by y at s } be the failure time
// computed at t0. For any t with t0 <= t < r, inf{ s > t : x is beaten by y at s } = r as well: no
// s in (t0, r) belongs to the set, so cutting it at t removes nothing below r. A cached entry
// (x, y, bound, t0, r) therefore answers every request for the same ordered pair and bound at a
// time t in [t0, r); outside that window it is recomputed. For Piecewise_linear_flightplan a
// fresh computation at t gives r bit for bit, as the scan depends on t only through where it
// starts (the tests check every scheduled certificate against one); for the cubic pieces' root
// isolation a fresh value may differ from r by rounding, r being the one the definition gives.
// The cache must be cleared when a flightplan changes (the tree does so in set_flightplan).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace PCCD::internal {

/// Direct-mapped cache of (x, y, bound) -> (t0, r) as described above. Not thread-safe: it is
/// written only by the tree's non-const updates.
class Crossing_cache {
public:
    /// Sizes the cache for about `certificates` certificates: a power of two between 2^10 and 2^12
    /// entries (at most 128 KiB, small enough to stay in a core's cache; most hits are for recent
    /// evaluations, and 2^16 entries answered only a few more requests without being faster).
    void reset(std::size_t certificates)
    {
        std::size_t size = std::size_t(1) << 10;
        while (size < certificates / 4 && size < (std::size_t(1) << 12)) size *= 2;
        m_entries.assign(size, Entry{});
        m_mask = size - 1;
    }
    /// Forgets every entry (after a flightplan changed). O(1): entries of older epochs are ignored.
    void clear()
    {
        if (++m_epoch == 0) { // after 2^32 clears: wipe, so no stale entry matches the new epoch
            m_entries.assign(m_entries.size(), Entry{});
            m_epoch = 1;
        }
    }

    /// Whether (x, y, bound) has a cached failure time valid for a request at time t; if so it is
    /// written to `result`.
    bool find(std::uint32_t x, std::uint32_t y, int bound, double t, double& result) const
    {
        if (m_entries.empty()) return false;
        const Entry& e = m_entries[slot(x, y, bound)];
        if (e.x != x || e.y != y || e.bound != bound || e.epoch != m_epoch || !(e.from <= t && t < e.until))
            return false;
        result = e.until;
        return true;
    }
    /// Records that (x, y, bound) computed at `from` fails at `until`.
    void store(std::uint32_t x, std::uint32_t y, int bound, double from, double until)
    {
        if (m_entries.empty() || !(until > from)) return;
        m_entries[slot(x, y, bound)] = Entry{x, y, bound, m_epoch, from, until};
    }

private:
    struct Entry {
        std::uint32_t x = no_vertex, y = no_vertex;
        int bound = -1;
        std::uint32_t epoch = 0;
        double from = 0.0, until = 0.0;
    };
    static constexpr std::uint32_t no_vertex = 0xffffffffu;

    std::size_t slot(std::uint32_t x, std::uint32_t y, int bound) const
    {
        const std::uint64_t h = (std::uint64_t(x) * 0x9E3779B97F4A7C15ULL) ^
                                (std::uint64_t(y) * 0xC2B2AE3D27D4EB4FULL) ^ std::uint64_t(bound);
        return std::size_t((h ^ (h >> 29)) & m_mask);
    }

    std::vector<Entry> m_entries;
    std::size_t m_mask = 0;
    std::uint32_t m_epoch = 1;
};

} // namespace PCCD::internal
