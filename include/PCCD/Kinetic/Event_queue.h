// PCCD/Kinetic/Event_queue.h -- the priority queue of certificate failure times of the kinetic AABB
// tree (doc/algorithms.md, "Kinetic AABB tree"): an indexed d-ary min-heap over a fixed set of certificate ids with
// insert, decrease-key, increase-key and removal by id, all in O(log n).
//
// Keys are (time, id), compared lexicographically, so simultaneous events come out in a fixed order
// (smaller id first) and the tree's behaviour at exact ties is deterministic. A certificate that
// never fails (time +infinity) is not stored at all, which keeps the heap small: in most scenes the
// large majority of certificates never fail.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <PCCD/Error.h>

namespace PCCD {

/// Indexed min-heap of (time, id) for ids in [0, capacity()).
/// \tparam Arity children per heap node; 2 (a binary heap) by default. Binary and 4-ary heaps
///         were measured on the cloth scene (benchmark/kinetic_benchmark.cpp, doc/benchmarks.md):
///         no significant difference, each faster in about half of the configurations; the heap is
///         a small part of an event's cost.
/// Not thread-safe for concurrent modification; const members may be called concurrently.
template <unsigned Arity = 2>
class Event_queue {
    static_assert(Arity >= 2, "a heap needs at least two children per node");

public:
    using Id = std::uint32_t;
    static constexpr double never = std::numeric_limits<double>::infinity();

    explicit Event_queue(std::size_t capacity = 0) : m_position(capacity, absent) {}

    /// Number of ids the queue can hold. Growing keeps the entries; shrinking requires that no
    /// id >= new capacity is queued.
    std::size_t capacity() const { return m_position.size(); }
    void resize(std::size_t capacity)
    {
        for (std::size_t id = capacity; id < m_position.size(); ++id)
            PCCD_precondition_msg(m_position[id] == absent, "shrinking the event queue over a queued id");
        m_position.resize(capacity, absent);
    }

    bool empty() const { return m_heap.empty(); }
    std::size_t size() const { return m_heap.size(); }
    bool contains(Id id) const { return id < m_position.size() && m_position[id] != absent; }
    /// The scheduled time of `id`, +infinity if it is not queued.
    double time(Id id) const { return contains(id) ? m_heap[m_position[id]].time : never; }

    /// The earliest (time, id). \pre !empty()
    double top_time() const
    {
        PCCD_debug_precondition(!empty());
        return m_heap.front().time;
    }
    Id top_id() const
    {
        PCCD_debug_precondition(!empty());
        return m_heap.front().id;
    }

    /// Schedules `id` at `time` (insert, decrease-key or increase-key); +infinity removes it.
    /// \pre id < capacity(), time is not NaN. O(log n).
    void set(Id id, double time)
    {
        PCCD_debug_precondition(id < m_position.size() && !std::isnan(time));
        if (time == never) {
            erase(id);
            return;
        }
        std::size_t i = m_position[id];
        if (i == absent) {
            i = m_heap.size();
            m_heap.push_back({time, id});
            m_position[id] = i;
            sift_up(i);
            return;
        }
        const Entry old = m_heap[i];
        m_heap[i].time = time;
        if (less(m_heap[i], old))
            sift_up(i);
        else
            sift_down(i);
    }

    /// Removes `id` if it is queued. O(log n).
    void erase(Id id)
    {
        if (!contains(id)) return;
        const std::size_t i = m_position[id];
        m_position[id] = absent;
        const Entry last = m_heap.back();
        m_heap.pop_back();
        if (i == m_heap.size()) return;
        m_heap[i] = last;
        m_position[last.id] = i;
        if (i > 0 && less(m_heap[i], m_heap[(i - 1) / Arity]))
            sift_up(i);
        else
            sift_down(i);
    }

    /// Removes the earliest entry. \pre !empty()
    void pop() { erase(top_id()); }

    /// Removes everything (capacity is kept). O(size).
    void clear()
    {
        for (const Entry& e : m_heap) m_position[e.id] = absent;
        m_heap.clear();
    }

private:
    struct Entry {
        double time;
        Id id;
    };
    static constexpr std::size_t absent = std::numeric_limits<std::size_t>::max();

    static bool less(const Entry& a, const Entry& b) { return a.time < b.time || (a.time == b.time && a.id < b.id); }

    void place(std::size_t i, const Entry& e)
    {
        m_heap[i] = e;
        m_position[e.id] = i;
    }

    void sift_up(std::size_t i)
    {
        const Entry e = m_heap[i];
        while (i > 0) {
            const std::size_t parent = (i - 1) / Arity;
            if (!less(e, m_heap[parent])) break;
            place(i, m_heap[parent]);
            i = parent;
        }
        place(i, e);
    }

    void sift_down(std::size_t i)
    {
        const Entry e = m_heap[i];
        const std::size_t n = m_heap.size();
        for (;;) {
            const std::size_t first = Arity * i + 1;
            if (first >= n) break;
            std::size_t best = first;
            const std::size_t last = first + Arity < n ? first + Arity : n;
            for (std::size_t c = first + 1; c < last; ++c)
                if (less(m_heap[c], m_heap[best])) best = c;
            if (!less(m_heap[best], e)) break;
            place(i, m_heap[best]);
            i = best;
        }
        place(i, e);
    }

    std::vector<Entry> m_heap;
    std::vector<std::size_t> m_position;
};

} // namespace PCCD
