// PCCD/internal/keep_going.h -- keep_going(), how PCCD's callback queries call a user's callback
// that may return void (visit everything) or something convertible to bool (false stops the
// query): the collision world's queries and its broad-phase tree (doc/manual/world.md, "Queries").
#pragma once

#include <type_traits>
#include <utility>

namespace PCCD::internal {

/// Calls f(args...) and says whether the query goes on: true when f returns void, else bool(result).
template <class F, class... Args>
bool keep_going(F& f, Args&&... args)
{
    if constexpr (std::is_void_v<decltype(f(std::forward<Args>(args)...))>) {
        f(std::forward<Args>(args)...);
        return true;
    } else {
        return bool(f(std::forward<Args>(args)...));
    }
}

} // namespace PCCD::internal
