// PCCD/Intersection/internal/Position_set.h -- the points a role of a walked first-hit query has
// already considered (doc/manual/hierarchy.md, "Covering instead of random draws"), as positions in
// hierarchy order: one 64-bit mask per block of 64 consecutive positions, the blocks in an
// open-addressing table. A leaf's points are consecutive, so the walk reads which of them are done
// with one or two look-ups and skips a leaf pair whose points are all done in both roles. Internal to
// Interpolation_search.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace PCCD::internal {

/// A set of positions (std::uint32_t), with the masks of runs of at most 64 positions.
class Position_set {
public:
    /// Adds `k`; true if it was not in the set.
    bool insert(std::uint32_t k)
    {
        std::uint64_t& mask = block(k >> 6);
        const std::uint64_t bit = std::uint64_t(1) << (k & 63);
        if (mask & bit) return false;
        mask |= bit;
        return true;
    }

    /// Bit i set: position first + i is in the set, for i < count. \pre count <= 64.
    std::uint64_t mask(std::uint32_t first, std::uint32_t count) const
    {
        if (count == 0 || m_used == 0) return 0;
        const std::uint32_t shift = first & 63;
        std::uint64_t bits = find(first >> 6) >> shift;
        if (shift != 0 && shift + count > 64) bits |= find((first >> 6) + 1) << (64 - shift);
        return count == 64 ? bits : bits & ((std::uint64_t(1) << count) - 1);
    }

private:
    struct Slot {
        std::uint32_t key = empty;
        std::uint64_t mask = 0;
    };
    static constexpr std::uint32_t empty = 0xffffffffu; // no block index reaches it (positions < 2^32)

    static std::size_t hash(std::uint32_t key)
    {
        return std::size_t((std::uint64_t(key) * 0x9e3779b97f4a7c15ull) >> 32); // Fibonacci hashing
    }

    /// The slot holding `key`, or the free slot where it would go. \pre m_slots is not empty.
    std::size_t slot_of(std::uint32_t key) const
    {
        const std::size_t wrap = m_slots.size() - 1;
        std::size_t i = hash(key) & wrap;
        while (m_slots[i].key != key && m_slots[i].key != empty) i = (i + 1) & wrap;
        return i;
    }

    std::uint64_t find(std::uint32_t key) const { return m_slots.empty() ? 0 : m_slots[slot_of(key)].mask; }

    std::uint64_t& block(std::uint32_t key)
    {
        if (2 * (m_used + 1) > m_slots.size()) grow();
        Slot& slot = m_slots[slot_of(key)];
        if (slot.key == empty) {
            ++m_used;
            slot.key = key;
        }
        return slot.mask;
    }

    void grow()
    {
        std::vector<Slot> old = std::move(m_slots);
        m_slots.assign(old.empty() ? 16 : 2 * old.size(), Slot{});
        for (const Slot& s : old)
            if (s.key != empty) m_slots[slot_of(s.key)] = s;
    }

    std::vector<Slot> m_slots;
    std::size_t m_used = 0;
};

} // namespace PCCD::internal
