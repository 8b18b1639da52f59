// PCCD/Surface/orient_normals.h -- consistent orientation of the per-point normals that fix the
// sign of the implicit surface (ALGORITHMS.md section 1): propagation along a minimum spanning tree
// of the proximity graph with edge weight 1 - |n_i . n_j| (Hoppe et al. 1992), one tree per connected
// component, or orientation like normals the user gives (e.g. read from a PLY file).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <queue>
#include <tuple>
#include <type_traits>
#include <vector>

#include <Eigen/Core>
#include <boost/graph/graph_traits.hpp>

#include <PCCD/Error.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/concepts/ProximityGraph.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// What an orientation did.
struct Orientation_report {
    /// Number of normals whose sign was reversed.
    std::size_t flipped = 0;
    /// Number of spanning trees the propagation grew: the connected components of the graph
    /// restricted to points with a normal and to non-virtual edges. 0 for orient_normals_like().
    std::size_t components = 0;
    /// Number of points without a normal (zero columns), left unoriented.
    std::size_t unoriented = 0;
};

/// Orients `normals` consistently by propagation over the graph `g`.
///
/// In every connected component (ignoring virtual edges and points whose normal is zero), a
/// minimum spanning tree for the weight 1 - |n_i . n_j| is grown by Prim's algorithm from the
/// component's smallest index, and each normal takes the sign that agrees with its tree parent's:
/// orientation flows first across the edges where it is least ambiguous. Then the whole component
/// is flipped if sum_i n_i . (p_i - c) < 0, c the centroid of all points: for a closed surface this
/// sum approximates 3 volume / sampling density > 0 for outward normals, whatever c, so closed
/// components end up facing outward; open pieces (such as the two faces of a thin plate) face away
/// from the centroid of the whole cloud.
///
/// \tparam Graph a model of ProximityGraph (any weight map: only the structure is read); directed
///         models must store both directions of every edge.
/// \tparam Positions an Eigen 3 x N matrix expression (float or double).
/// \tparam VirtualMap a model of EdgeFlagMap (PCCD::No_virtual_edges for graphs without the mark).
/// \param normals 3 x N, modified in place (signs only); zero columns are left as they are.
/// \throws Invalid_input if the sizes of `g`, `positions` and `normals` differ or a normal is not
///         finite.
/// Complexity: O(E log E). Deterministic: ties between equal weights go to the smaller index.
/// Thread safety: reads `g` and `positions`, writes `normals` only.
template <class Graph, class Positions, class VirtualMap = No_virtual_edges>
    requires(!std::is_same_v<Graph, Proximity_graph>) && EdgeFlagMap<VirtualMap, Graph>
Orientation_report orient_normals(const Graph& g, const Eigen::MatrixBase<Positions>& positions,
                                  Eigen::Matrix3Xd& normals, const VirtualMap& is_virtual = {})
{
    const std::size_t n = num_vertices(g);
    if (std::size_t(positions.cols()) != n || std::size_t(normals.cols()) != n || positions.rows() != 3)
        throw Invalid_input(internal::concat("orient_normals: the graph has ", n, " vertices, the positions ",
                                             positions.cols(), " columns and the normals ", normals.cols()));
    Orientation_report report;
    std::vector<char> has_normal(n, 0);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
        const auto column = normals.col(Eigen::Index(i));
        if (!internal::all_finite(column))
            throw Invalid_input(internal::concat("orient_normals: normal ", i, " is not finite"));
        has_normal[i] = !column.isZero(0.0);
        if (!has_normal[i]) ++report.unoriented;
        centroid += positions.col(Eigen::Index(i)).template cast<double>();
    }
    if (n > 0) centroid /= double(n);
    const Eigen::Matrix3Xd original = normals;
    auto unit = [&](std::size_t i) { return Eigen::Vector3d(original.col(Eigen::Index(i)).normalized()); };

    // Heap of candidate tree edges (weight, vertex, parent); the smallest weight, then the smallest
    // vertex index, is taken first.
    using Candidate = std::tuple<double, std::uint32_t, std::uint32_t>;
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap;
    std::vector<char> in_tree(n, 0);
    std::vector<std::uint32_t> members;
    for (std::size_t root = 0; root < n; ++root) {
        if (in_tree[root] || !has_normal[root]) continue;
        ++report.components;
        members.clear();
        heap.emplace(0.0, std::uint32_t(root), std::uint32_t(root));
        while (!heap.empty()) {
            const auto [weight, v, parent] = heap.top();
            heap.pop();
            if (in_tree[v]) continue;
            in_tree[v] = 1;
            members.push_back(v);
            if (v != parent && normals.col(v).dot(normals.col(parent)) < 0.0) normals.col(v) = -normals.col(v);
            const Eigen::Vector3d nv = unit(v);
            for (auto [e, e_end] = out_edges(v, g); e != e_end; ++e) {
                if (get(is_virtual, *e)) continue;
                const auto w = static_cast<std::uint32_t>(target(*e, g));
                if (w == v || in_tree[w] || !has_normal[w]) continue;
                heap.emplace(1.0 - std::abs(nv.dot(unit(w))), w, v);
            }
        }
        double outwardness = 0.0;
        for (const std::uint32_t v : members)
            outwardness += normals.col(v).normalized().dot(positions.col(v).template cast<double>() - centroid);
        if (outwardness < 0.0)
            for (const std::uint32_t v : members) normals.col(v) = -normals.col(v);
    }
    for (std::size_t i = 0; i < n; ++i)
        if (has_normal[i] && normals.col(Eigen::Index(i)).dot(original.col(Eigen::Index(i))) < 0.0) ++report.flipped;
    return report;
}

/// Orients a Proximity_graph's points' normals (its virtual edges are not followed).
template <class Positions>
Orientation_report orient_normals(const Proximity_graph& graph, const Eigen::MatrixBase<Positions>& positions,
                                  Eigen::Matrix3Xd& normals)
{
    return orient_normals(graph.graph(), positions, normals, graph.virtual_map());
}

/// Orients each normal like the given reference normal of the same point (e.g. normals read from a
/// file): n_i is reversed when n_i . reference_i < 0. A zero column of `normals` (a point whose own
/// fit is undetermined) takes the normalized reference normal, so that the point still orients
/// the evaluations near it.
/// \throws Invalid_input if the sizes differ or a reference normal is zero or not finite (the
///         message names the point).
/// Complexity: O(N). Thread safety: writes `normals` only.
template <class Reference>
Orientation_report orient_normals_like(Eigen::Matrix3Xd& normals, const Eigen::MatrixBase<Reference>& reference)
{
    if (reference.cols() != normals.cols() || reference.rows() != 3)
        throw Invalid_input(internal::concat("orient_normals_like: ", reference.cols(), " reference normals for ",
                                             normals.cols(), " points"));
    Orientation_report report;
    for (Eigen::Index i = 0; i < normals.cols(); ++i) {
        const Eigen::Vector3d r = reference.col(i).template cast<double>();
        if (!internal::all_finite(r) || r.isZero(0.0))
            throw Invalid_input(internal::concat("orient_normals_like: the reference normal of point ", i, " (", r.x(),
                                                 ", ", r.y(), ", ", r.z(), ") is zero or not finite"));
        if (normals.col(i).isZero(0.0)) {
            normals.col(i) = r.normalized();
        } else if (normals.col(i).dot(r) < 0.0) {
            normals.col(i) = -normals.col(i);
            ++report.flipped;
        }
    }
    return report;
}

} // namespace PCCD
