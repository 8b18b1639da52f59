// PCCD/Kinetic/internal/Kinetic_event_loop.h -- how the kinetic AABB tree follows time
// (doc/manual/kinetic.md, "Building and advancing"): all certificates computed from scratch at one
// time (construction, or advance_to an earlier time), and advance_to's loop over the events before
// t in order of (time, node, bound), each swapping one extreme, rescheduling its certificate and
// propagating the change up the tree while parents' extremes change.
#pragma once

#include <cstdint>
#include <vector>

#include <PCCD/Kinetic/internal/AABB_tree_build.h>
#include <PCCD/Kinetic/internal/Kinetic_certificates.h>
#include <PCCD/Kinetic/internal/Kinetic_tree_state.h>

namespace PCCD::internal {

/// Recomputes every certificate at time t, children before parents.
template <class F, class P, class Queue>
void initialize_at(Kinetic_tree_state<F, P, Queue>& s, double t)
{
    s.now = t;
    s.queue.clear();
    std::vector<std::uint32_t> order;
    postorder(s.nodes, s.root, order);
    for (const std::uint32_t n : order)
        if (!s.nodes[n].is_leaf())
            for (int b = 0; b < s.bound_count; ++b) update_bound(s, n, b);
}

/// After bound b of node n changed: updates bound b of the ancestors while their extremes change.
template <class F, class P, class Queue>
void propagate(Kinetic_tree_state<F, P, Queue>& s, std::uint32_t n, int b)
{
    for (std::uint32_t p = s.nodes[n].parent; p != no_node; p = s.nodes[p].parent) {
        if (!update_bound(s, p, b)) break;
        count_update(s, p);
    }
}

/// Processes every event with time < t in order (one update round), then sets now to t.
/// \pre t >= s.now
template <class F, class P, class Queue>
void process_events_before(Kinetic_tree_state<F, P, Queue>& s, double t)
{
    next_update_round(s);
    while (!s.queue.empty() && s.queue.top_time() < t) {
        s.now = s.queue.top_time();
        const typename Queue::Id id = s.queue.top_id();
        ++s.stats.events;
        const std::uint32_t n = id / s.bound_count;
        const int b = int(id % s.bound_count);
        if (update_bound(s, n, b, s.overtaker[id])) {
            count_update(s, n);
            propagate(s, n, b);
        }
    }
    s.now = t;
}

} // namespace PCCD::internal
