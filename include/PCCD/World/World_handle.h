// PCCD/World/World_handle.h -- World_handle, the name of one posed instance in a Collision_world,
// and Collision_filter, the group/mask rule that decides which instances may collide
// (doc/manual/world.md, "Instances and filters").
#pragma once

#include <compare>
#include <cstdint>
#include <functional>
#include <limits>

namespace PCCD {

/// The name of one instance of a Collision_world: a slot index and the generation of that slot.
/// Erasing an instance makes its handle stale; a later instance in the same slot gets a new
/// generation, so a stale handle is recognized (the world throws Invalid_input for it) and never
/// names another instance. Plain value type, ordered by index then generation.
struct World_handle {
    static constexpr std::uint32_t no_index = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t index = no_index;
    std::uint32_t generation = 0;

    /// False for a default-constructed handle (it names no instance of any world).
    bool is_set() const { return index != no_index; }
    friend auto operator<=>(const World_handle&, const World_handle&) = default;
};

/// Which instances may collide: two instances a and b are tested only if
/// (a.group & b.mask) != 0 and (b.group & a.mask) != 0 (the rule of Bullet and FCL's users).
/// Default: group 1, mask all bits -- everything collides with everything.
struct Collision_filter {
    std::uint32_t group = 1;
    std::uint32_t mask = std::numeric_limits<std::uint32_t>::max();

    friend bool operator==(const Collision_filter&, const Collision_filter&) = default;
};

/// Whether instances with filters `a` and `b` may collide.
constexpr bool may_collide(const Collision_filter& a, const Collision_filter& b)
{
    return (a.group & b.mask) != 0 && (b.group & a.mask) != 0;
}

} // namespace PCCD

/// \cond
// World_handle as a key of unordered containers (hidden from Doxygen, which cannot place a
// specialization of std::hash).
template <>
struct std::hash<PCCD::World_handle> {
    std::size_t operator()(const PCCD::World_handle& h) const noexcept
    {
        return std::hash<std::uint64_t>()((std::uint64_t(h.generation) << 32) | h.index);
    }
};
/// \endcond
