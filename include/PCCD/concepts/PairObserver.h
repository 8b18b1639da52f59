// PCCD/concepts/PairObserver.h -- concept of the observers the hierarchy traversals report their
// node pairs and leaf pairs to (doc/manual/hierarchy.md, "Watching a query"), and its model that
// ignores them (the traversals' default).
#pragma once

#include <cstdint>

namespace PCCD {

/// \concept PairObserver
/// Told of every node pair a traversal of two hierarchies s and t tests and every leaf pair it
/// hands to its visit function.
///
/// Requirements, for `O& observer` and node indices `i` (of s) and `j` (of t):
/// `observer.node_pair(i, j)` and `observer.leaf_pair(i, j)` are valid (results ignored). Called on
/// the traversal's thread, in the order of the traversal; must not throw.
///
/// Models: PCCD::Ignore_pairs (nothing), internal::Visitor_pairs (forwards to an
/// Intersection_visitor, swapping the indices back into A and B when s is B's hierarchy), and
/// Intersection_visitor itself.
template <class O>
concept PairObserver = requires(O& observer, std::uint32_t i, std::uint32_t j) {
    observer.node_pair(i, j);
    observer.leaf_pair(i, j);
};

/// The PairObserver that ignores every pair.
struct Ignore_pairs {
    void node_pair(std::uint32_t, std::uint32_t) const noexcept {}
    void leaf_pair(std::uint32_t, std::uint32_t) const noexcept {}
};

} // namespace PCCD
