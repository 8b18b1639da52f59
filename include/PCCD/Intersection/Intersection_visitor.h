// PCCD/Intersection/Intersection_visitor.h -- the events of one intersection query, for users who
// want to watch or instrument it (doc/manual/hierarchy.md, "Watching a query"): each node pair and
// leaf pair of the two hierarchies the walked traversals test (separation test, walk, reach regions),
// each bracket the interpolation search finds, each evaluation of f. In the spirit of Boost.Graph's
// visitors: one member per event point, all doing nothing by default.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include <PCCD/Surface/WLS_surface.h>

namespace PCCD {

/// Which object's surface an evaluation of f belongs to.
enum class Query_object : std::uint8_t { a = 0, b = 1 };

/// The events of a query (do_intersect(), intersection_points()). Derive, override the events of
/// interest and pass a pointer in Intersection_options::visitor (default nullptr: no events, no
/// cost beyond one test per event point). The query calls the members on its own thread, in the
/// order the events happen; they must not throw. A visitor does not change the query's answer.
///
/// Which events each traversal reports:
/// - node_pair and leaf_pair: under the walked traversals (Traversal::depth_first,
///   Traversal::likelihood), every pair the query counts: the separation test (verified contacts),
///   the first-hit walk and the reach regions of intersection_points() (Interpolation_search), with
///   node indices into a.hierarchy().nodes() and b.hierarchy().nodes(). The flat traversal's box
///   regions (and Randomized_sampling's, under any traversal) pair leaves with inner nodes and
///   count their pairs in the result's counters without reporting them one by one.
/// - bracket: every bracket of the interpolation search (either traversal).
/// - evaluation: every evaluation of f by every policy and traversal (one per counted
///   Intersection_counters::f_evaluations).
struct Intersection_visitor {
    virtual ~Intersection_visitor() = default;
    /// A pair of nodes tested: node `a` of A's hierarchy, node `b` of B's.
    virtual void node_pair(std::uint32_t a, std::uint32_t b) { (void)a, (void)b; }
    /// A pair of leaves whose points are examined (after its node pair passed the tests).
    virtual void leaf_pair(std::uint32_t a, std::uint32_t b) { (void)a, (void)b; }
    /// f of the tested surface changes sign between the sampled cloud's points at `from` and `to`
    /// (world coordinates): the interpolation search then searches the path between them.
    virtual void bracket(const Eigen::Vector3d& from, const Eigen::Vector3d& to) { (void)from, (void)to; }
    /// f of `object`'s surface evaluated at the world point x, with its result.
    virtual void evaluation(Query_object object, const Eigen::Vector3d& x, const Surface_evaluation& result)
    {
        (void)object, (void)x, (void)result;
    }
};

namespace internal {

/// The pair events of a traversal of the hierarchies s and t forwarded to a visitor (none when
/// null), as (node of A, node of B): s is A's hierarchy unless `s_is_b` (the role that samples B's
/// points). A model of the traversals' pair observer.
struct Visitor_pairs {
    Intersection_visitor* visitor = nullptr;
    bool s_is_b = false;

    void node_pair(std::uint32_t s_node, std::uint32_t t_node) const
    {
        if (visitor) s_is_b ? visitor->node_pair(t_node, s_node) : visitor->node_pair(s_node, t_node);
    }
    void leaf_pair(std::uint32_t s_node, std::uint32_t t_node) const
    {
        if (visitor) s_is_b ? visitor->leaf_pair(t_node, s_node) : visitor->leaf_pair(s_node, t_node);
    }
};

} // namespace internal
} // namespace PCCD
