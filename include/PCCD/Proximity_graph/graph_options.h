// PCCD/Proximity_graph/graph_options.h -- what the proximity graph builders can be told: the kind of
// graph (Graph_kind), the k-NN and r-SIG options and the long-edge test that marks edges virtual
// (doc/algorithms.md "Proximity graphs", doc/manual/graphs.md). Options only: it includes no
// implementation.
#pragma once

#include <cstdint>
#include <optional>

namespace PCCD {

/// How a proximity graph was built.
enum class Graph_kind : std::uint8_t {
    /// Symmetric k-nearest-neighbour graph: (i, j) when j is among the k nearest of i or vice versa.
    knn = 0,
    /// (r-)sphere-of-influence graph: (i, j) when |p_i - p_j| <= d_i + d_j, d_i the distance of p_i
    /// to its r-th nearest neighbour (r = 1: the plain SIG).
    sphere_of_influence = 1,
};

/// Options of the long-edge test.
struct Long_edge_options {
    /// An edge (u, v) of length l is long when l > factor * min(S_u, S_v). The local scale S_x is a
    /// two-step median: m_x = median length of the positive-length edges at x, then S_x = median
    /// of m_y over x and its neighbours y. The second median keeps one clump of random points
    /// (whose own edges are all short) from flagging its ordinary edges, and makes an isolated
    /// point or a sparse bridge between clusters take the scale of the surface it hangs on, so its
    /// edges to that surface come out long. Default 4: on area-uniform samples of the Stanford
    /// bunny (10^5 points, r-SIG with r = 3) it marks 12 of 577,000 edges clean and 7 with noise of
    /// 0.3 spacings, and the r-SIG stays one component; factor 3 marked 94 and cut 8 points off in 2
    /// fragments; an edge from a surface to an isolated outlier or across a bridge of sparse points
    /// is typically 10 times the scale (doc/manual/graphs.md). +infinity turns the test off. Must be
    /// > 0 and not NaN.
    double factor = 4.0;
};

/// Options of knn_graph().
struct Knn_graph_options {
    /// Number of nearest neighbours each point is joined to. Default 8. Must be >= 1.
    unsigned k = 8;
    /// The long-edge test marking edges virtual (default factor 4).
    Long_edge_options long_edges = {};
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

/// Options of sphere_of_influence_graph().
struct Sphere_of_influence_graph_options {
    /// The radius of influence of a point is its distance to its r-th nearest neighbour (r = 1: the
    /// plain SIG). Default 3, the smaller of the two values the paper recommends: on noisy bunny
    /// scans r = 3 already gives one component per piece while r = 4 costs a third more edges and
    /// CPSP time (doc/manual/graphs.md). Must be >= 1.
    unsigned r = 3;
    /// The long-edge test marking edges virtual (default factor 4).
    Long_edge_options long_edges = {};
    /// Worker threads, >= 1. Unset (default): all available threads; as a stage of
    /// Point_cloud_object, the object's `threads`. Ignored without TBB. The result does not depend
    /// on it.
    std::optional<unsigned> threads = std::nullopt;
};

} // namespace PCCD
