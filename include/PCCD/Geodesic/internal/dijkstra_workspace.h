// PCCD/Geodesic/internal/dijkstra_workspace.h -- the state shared by both bounded Dijkstra
// routines that build the CPSP map (doc/manual/graphs.md, "The CPSP map"): the list being built for
// one source, the 4-ary heap of the hand-written search, and the per-thread scratch with one record
// per vertex, reset only where touched.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace PCCD::internal {

/// One source's list while it is being built.
struct Cpsp_list {
    std::vector<std::uint32_t> targets;
    std::vector<float> distances;
    std::vector<std::uint32_t> predecessors;
};

/// A 4-ary min-heap of (distance, vertex), ties broken by vertex; shallower than a binary heap, so
/// fewer comparisons and cache lines per pop (measured faster than std::push_heap/pop_heap here).
class Quaternary_heap {
public:
    using Item = std::pair<double, std::uint32_t>;
    bool empty() const { return m_items.empty(); }
    void clear() { m_items.clear(); }
    void push(Item item)
    {
        std::size_t i = m_items.size();
        m_items.push_back(item);
        while (i > 0) {
            const std::size_t parent = (i - 1) / 4;
            if (!(item < m_items[parent])) break;
            m_items[i] = m_items[parent];
            i = parent;
        }
        m_items[i] = item;
    }
    Item pop()
    {
        const Item top = m_items.front();
        const Item last = m_items.back();
        m_items.pop_back();
        const std::size_t n = m_items.size();
        if (n == 0) return top;
        std::size_t i = 0;
        for (;;) {
            const std::size_t child = 4 * i + 1;
            if (child >= n) break;
            std::size_t best = child;
            const std::size_t end = std::min(child + 4, n);
            for (std::size_t c = child + 1; c < end; ++c)
                if (m_items[c] < m_items[best]) best = c;
            if (!(m_items[best] < last)) break;
            m_items[i] = m_items[best];
            i = best;
        }
        m_items[i] = last;
        return top;
    }

private:
    std::vector<Item> m_items;
};

/// Per-thread scratch of the bounded Dijkstra: one record per vertex (one cache line touched per
/// visited vertex), reset only where touched.
struct Dijkstra_workspace {
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    struct Vertex_state {
        double distance = std::numeric_limits<double>::infinity();
        std::uint32_t position = none; // position in the current list once settled
        std::uint32_t parent = 0;      // hand-written: position of the parent; boost: parent vertex
    };
    std::vector<Vertex_state> state;
    std::vector<std::uint32_t> touched;
    Quaternary_heap heap; // hand-written: the queue (lazy deletion of superseded entries)

    void prepare(std::size_t n)
    {
        if (state.size() != n) state.assign(n, Vertex_state());
    }
    void reset()
    {
        for (std::uint32_t v : touched) state[v] = Vertex_state();
        touched.clear();
    }
};

} // namespace PCCD::internal
