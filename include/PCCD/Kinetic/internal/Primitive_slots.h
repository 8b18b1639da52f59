// PCCD/Kinetic/internal/Primitive_slots.h -- the primitive bookkeeping shared by Kinetic_AABB_tree
// and Refit_AABB_tree (doc/algorithms.md, "Kinetic AABB tree": "insertions and deletions at run time"): primitives
// live in indexed slots; removing one frees its slot, and the next insertion reuses the most
// recently freed slot, so indices stay small and stable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <PCCD/Error.h>

namespace PCCD::internal {

/// Indexed slots of primitives of type `P`, each live or free.
template <class P>
class Primitive_slots {
public:
    using Index = std::uint32_t;
    /// Indices stay below 2^31.
    static constexpr std::size_t max_capacity = std::size_t(1) << 31;

    /// All `primitives` live, at indices 0..size-1. \throws Invalid_input if there are 2^31 or more.
    explicit Primitive_slots(std::vector<P> primitives, const char* owner)
        : m_primitives(std::move(primitives)), m_alive(m_primitives.size(), 1)
    {
        if (m_primitives.size() >= max_capacity)
            throw Invalid_input(internal::concat(owner, ": too many primitives (2^31 or more)"));
    }

    /// One past the largest index ever used (live or free).
    std::size_t capacity() const { return m_primitives.size(); }
    /// Number of live primitives.
    std::size_t live_count() const { return m_primitives.size() - m_free.size(); }
    bool contains(Index i) const { return i < m_primitives.size() && m_alive[i]; }
    const P& operator[](Index i) const { return m_primitives[i]; }

    /// Stores `p` in the most recently freed slot, or in a new one; returns its index.
    /// \throws Invalid_input (naming `owner`) if a new slot would be the 2^31-th.
    Index insert(const P& p, const char* owner)
    {
        if (!m_free.empty()) {
            const Index i = m_free.back();
            m_free.pop_back();
            m_primitives[i] = p;
            m_alive[i] = 1;
            return i;
        }
        if (m_primitives.size() + 1 >= max_capacity)
            throw Invalid_input(internal::concat(owner, "::insert: too many primitives"));
        m_primitives.push_back(p);
        m_alive.push_back(1);
        return Index(m_primitives.size() - 1);
    }

    /// Frees the slot of live primitive `i` (its value stays readable until the slot is reused).
    /// \pre contains(i)
    void remove(Index i)
    {
        PCCD_precondition(contains(i));
        m_alive[i] = 0;
        m_free.push_back(i);
    }

private:
    std::vector<P> m_primitives;
    std::vector<char> m_alive;
    std::vector<Index> m_free;
};

} // namespace PCCD::internal
