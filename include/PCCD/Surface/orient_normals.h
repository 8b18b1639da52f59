// PCCD/Surface/orient_normals.h -- consistent orientation of the per-point normals that fix the
// sign of the implicit surface (doc/algorithms.md, "Normal orientation"): propagation along a
// minimum spanning tree of the proximity graph (Hoppe et al. 1992), whose edge weights and sign
// rule compare the two normals mirrored across the plane that bisects the edge, so that the two
// faces of a thin part keep opposite normals; one tree per connected component; the same with
// hints (normals read from a file, some of them possibly missing) that decide the sign where they
// exist; or orientation like a complete set of reference normals.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
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
    /// Number of normals whose sign was reversed (a normal filled in from a hint is not counted).
    std::size_t flipped = 0;
    /// Number of spanning trees the propagation grew: the connected components of the graph
    /// restricted to points with a normal and to non-virtual edges, less those in which every point
    /// has a hint (no propagation is needed there). All components for orient_normals(); 0 for
    /// orient_normals_like().
    std::size_t components = 0;
    /// Number of points without a normal (zero columns, and no hint to fill them), left unoriented.
    std::size_t unoriented = 0;
    /// Number of points whose normal took the sign of their own hint (or, where the point's own fit
    /// is undetermined, the normalized hint itself). All points for orient_normals_like(); 0 for
    /// orient_normals().
    std::size_t hints_used = 0;
    /// Number of hints that were zero or not finite, i.e. points that had no hint although hints
    /// were given. 0 when no hints were given.
    std::size_t hints_ignored = 0;
    /// Number of the components counted in `components` without any hint, oriented by the rule of
    /// orient_normals() (propagation, then the outward choice).
    std::size_t unhinted_components = 0;
};

namespace internal {

/// The normals after the hints, and what the propagation needs to know of them.
struct Hinted_normals {
    std::vector<char> has_hint, has_normal;
    Eigen::Vector3d centroid; // of all positions
};

/// Checks the normals, gives every hinted point its hint's side (or the hint itself where the fit
/// is undetermined), counts hints and unoriented points into `report`.
template <class Positions>
Hinted_normals apply_hints(const char* caller, const Eigen::MatrixBase<Positions>& positions, Eigen::Matrix3Xd& normals,
                           const Eigen::Matrix3Xd* hints, Orientation_report& report)
{
    const std::size_t n = std::size_t(normals.cols());
    Hinted_normals result{std::vector<char>(n, 0), std::vector<char>(n, 0), Eigen::Vector3d::Zero()};
    std::vector<char>& has_hint = result.has_hint;
    std::vector<char>& has_normal = result.has_normal;
    Eigen::Vector3d& centroid = result.centroid;
    for (std::size_t i = 0; i < n; ++i) {
        const auto column = normals.col(Eigen::Index(i));
        if (!internal::all_finite(column))
            throw Invalid_input(internal::concat(caller, ": normal ", i, " is not finite"));
        if (hints) {
            const auto hint = hints->col(Eigen::Index(i));
            has_hint[i] = internal::all_finite(hint) && !hint.isZero(0.0);
            if (!has_hint[i]) ++report.hints_ignored;
        }
        if (has_hint[i]) {
            ++report.hints_used;
            // Scaled before normalizing: a tiny or huge hint still gives a unit direction.
            const Eigen::Vector3d hint = hints->col(Eigen::Index(i)).stableNormalized();
            if (column.isZero(0.0))
                normals.col(Eigen::Index(i)) = hint; // undetermined fit: the hint itself
            else if (column.dot(hint) < 0.0)
                normals.col(Eigen::Index(i)) = -column;
        }
        has_normal[i] = !normals.col(Eigen::Index(i)).isZero(0.0);
        if (!has_normal[i]) ++report.unoriented;
        centroid += positions.col(Eigen::Index(i)).template cast<double>();
    }
    if (n > 0) centroid /= double(n);
    return result;
}

} // namespace internal

/// How consistently two oriented normals n_v, n_w at points joined by the edge d = p_w - p_v
/// continue each other: n_w . R n_v, where R n = n - 2 (n . e) e reflects across the plane that
/// bisects the edge (e = d / |d|). The normals of a surface that bends along the edge are mirror
/// images in that plane (exactly so on a circle through both points), so the value is near 1 when
/// they agree, near -1 when one is reversed; for edges in the tangent plane it is n_v . n_w. Across
/// a sheet thinner than the edge (the two faces of an ear or a plate, e along the normals), outward
/// normals are opposite and the value is +1, where n_v . n_w (-1) would call them inconsistent
/// and propagation would turn one face inside out. A zero-length edge gives n_v . n_w.
inline double orientation_agreement(const Eigen::Vector3d& nv, const Eigen::Vector3d& nw, const Eigen::Vector3d& d)
{
    const double length = d.norm();
    if (!(length > 0.0)) return nv.dot(nw);
    const Eigen::Vector3d e = d / length;
    return nv.dot(nw) - 2.0 * nv.dot(e) * nw.dot(e);
}

/// How much the weight of an edge grows with its slope out of the tangent planes (see
/// orientation_edge_weight()). Measured on 8,000-point area samples of 13 closed models of
/// libcgal-demo, clean and with noise of 0.3 mean spacings (doc/benchmarks.md "Normal
/// orientation"): with 0.5 at most 0.15 % of the normals were reversed on 10 of them (0.45-2.4 % on
/// the helmet and the armadillo); without the term, up to 3.7 % (the noisy anchor; 0.06 % with
/// it); 1 and 2 did no better than 0.5.
inline constexpr double orientation_slope_weight = 0.5;

/// The weight of the edge d = p_w - p_v in the spanning tree of the orientation: 1 - |agreement|
/// (orientation_agreement()), plus orientation_slope_weight times the mean of |n_v . e| and
/// |n_w . e| (e = d / |d|), so that edges within the surface, which the agreement judges best, go
/// first, and edges across a thin part or a gap (whose direction is noisy against the normals)
/// only where the surface offers no other way.
inline double orientation_edge_weight(const Eigen::Vector3d& nv, const Eigen::Vector3d& nw, const Eigen::Vector3d& d)
{
    const double length = d.norm();
    const double slope = length > 0.0 ? 0.5 * (std::abs(nv.dot(d)) + std::abs(nw.dot(d))) / length : 0.0;
    return 1.0 - std::abs(orientation_agreement(nv, nw, d)) + orientation_slope_weight * slope;
}

namespace internal {

/// Propagates the signs over each connected component of `g` (the rule of
/// orient_normals_with_hints()), counting components into `report`.
template <class Graph, class Positions, class VirtualMap>
void propagate_signs(const Graph& g, const Eigen::MatrixBase<Positions>& positions, Eigen::Matrix3Xd& normals,
                     const Hinted_normals& state, const VirtualMap& is_virtual, Orientation_report& report)
{
    const std::size_t n = std::size_t(normals.cols());
    const std::vector<char>& has_hint = state.has_hint;
    const std::vector<char>& has_normal = state.has_normal;
    const Eigen::Vector3d& centroid = state.centroid;
    // Unit normals for the weights, normalized where they are read (no copy of the N normals: the
    // weight ignores their signs, and a normal's sign changes only by an exact negation).
    const auto unit = [&](std::uint32_t v) -> Eigen::Vector3d { return normals.col(Eigen::Index(v)).normalized(); };
    const auto followed = [&](const auto& e, std::uint32_t from) -> std::uint32_t {
        if (get(is_virtual, e)) return from;
        return static_cast<std::uint32_t>(target(e, g));
    };
    // The edge from v to w, p_w - p_v (orientation_agreement() and orientation_edge_weight() read it).
    const auto edge = [&](std::uint32_t v, std::uint32_t w) -> Eigen::Vector3d {
        return positions.col(w).template cast<double>() - positions.col(v).template cast<double>();
    };

    // One connected component at a time, from its smallest index: first, when any point has a
    // hint, its members (breadth-first), then a minimum spanning forest for
    // orientation_edge_weight() grown by Prim's algorithm from all its hinted points at once, or,
    // without hints, from its smallest index. The heap holds candidate
    // tree edges (weight, vertex, parent); the smallest weight, then the smallest vertex index, then
    // the smallest parent index, is taken first.
    // A candidate heavier than one already in the heap for the same vertex is never taken first, so
    // it is not pushed (`lightest`: the lightest candidate weight pushed for each vertex): the same
    // tree, with a heap a few times smaller (on flat scans, whose weights are all near 0, Prim's
    // frontier grows wide and the heap's cache misses were most of the orientation's time).
    using Candidate = std::tuple<double, std::uint32_t, std::uint32_t>;
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap;
    std::vector<char> seen, in_tree(n, 0);
    std::vector<double> lightest(n, std::numeric_limits<double>::infinity());
    std::vector<std::uint32_t> members, hinted, order;
    const auto push_edges = [&](std::uint32_t v) {
        const Eigen::Vector3d unit_v = unit(v);
        for (auto [e, e_end] = out_edges(v, g); e != e_end; ++e) {
            const std::uint32_t w = followed(*e, v);
            if (w == v || in_tree[w] || !has_normal[w]) continue;
            const double weight = orientation_edge_weight(unit_v, unit(w), edge(v, w));
            if (weight > lightest[w]) continue;
            lightest[w] = weight;
            heap.emplace(weight, w, v);
        }
    };
    // Without any hint, a component's members are the vertices its tree reaches (in_tree): no
    // breadth-first pass is needed.
    const bool any_hint = std::any_of(has_hint.begin(), has_hint.end(), [](char h) { return h != 0; });
    if (any_hint) seen.assign(n, 0);
    for (std::size_t root = 0; root < n; ++root) {
        if ((any_hint && seen[root]) || in_tree[root] || !has_normal[root]) continue;
        hinted.clear();
        if (any_hint) {
            members.assign(1, std::uint32_t(root));
            seen[root] = 1;
            for (std::size_t next = 0; next < members.size(); ++next)
                for (auto [e, e_end] = out_edges(members[next], g); e != e_end; ++e) {
                    const std::uint32_t w = followed(*e, members[next]);
                    if (seen[w] || !has_normal[w]) continue;
                    seen[w] = 1;
                    members.push_back(w);
                }
            for (const std::uint32_t v : members)
                if (has_hint[v]) hinted.push_back(v);
            if (hinted.size() == members.size()) continue; // every sign is given: no tree to grow
        }
        ++report.components;
        std::sort(hinted.begin(), hinted.end());
        order.clear();
        if (hinted.empty()) {
            ++report.unhinted_components;
            heap.emplace(0.0, std::uint32_t(root), std::uint32_t(root));
        } else {
            for (const std::uint32_t v : hinted) in_tree[v] = 1;
            for (const std::uint32_t v : hinted) push_edges(v);
        }
        while (!heap.empty()) {
            const auto [weight, v, parent] = heap.top();
            heap.pop();
            if (in_tree[v]) continue;
            in_tree[v] = 1;
            order.push_back(v);
            if (v != parent && orientation_agreement(normals.col(parent), normals.col(v), edge(parent, v)) < 0.0)
                normals.col(v) = -normals.col(v);
            push_edges(v);
        }
        if (!hinted.empty()) continue;
        // No hint in this component: face away from the centroid of the whole cloud.
        double outwardness = 0.0;
        for (const std::uint32_t v : order)
            outwardness += normals.col(v).normalized().dot(positions.col(v).template cast<double>() - centroid);
        if (outwardness < 0.0)
            for (const std::uint32_t v : order) normals.col(v) = -normals.col(v);
    }
}

/// Orientation over the graph with optional hints (`hints` null: none; else 3 x N, a zero or
/// non-finite column meaning no hint). The rule is documented at orient_normals_with_hints().
template <class Graph, class Positions, class VirtualMap>
Orientation_report orient_normals_over_graph(const char* caller, const Graph& g,
                                             const Eigen::MatrixBase<Positions>& positions, Eigen::Matrix3Xd& normals,
                                             const Eigen::Matrix3Xd* hints, const VirtualMap& is_virtual)
{
    const std::size_t n = num_vertices(g);
    if (std::size_t(positions.cols()) != n || std::size_t(normals.cols()) != n || positions.rows() != 3)
        throw Invalid_input(internal::concat(caller, ": the graph has ", n, " vertices, the positions ",
                                             positions.cols(), " columns and the normals ", normals.cols()));
    if (hints && std::size_t(hints->cols()) != n)
        throw Invalid_input(internal::concat(caller, ": ", hints->cols(), " hints for ", n,
                                             " points (need one per point, or none)"));
    Orientation_report report;
    // Of each given nonzero normal, the sign of its largest coordinate, + or - (axis + 1): every later
    // change of a nonzero normal is an exact negation, so it ends up flipped (opposite to the given
    // one) iff that coordinate changed sign. (One byte a point instead of a copy of the normals.)
    std::vector<std::int8_t> original(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const auto column = normals.col(Eigen::Index(i));
        Eigen::Index axis = 0;
        column.cwiseAbs().maxCoeff(&axis);
        if (column(axis) != 0.0) original[i] = std::int8_t((axis + 1) * (column(axis) > 0.0 ? 1 : -1));
    }
    const Hinted_normals state = apply_hints(caller, positions, normals, hints, report);
    propagate_signs(g, positions, normals, state, is_virtual, report);
    for (std::size_t i = 0; i < n; ++i) {
        if (original[i] == 0) continue;
        const double now = normals(std::abs(original[i]) - 1, Eigen::Index(i));
        if (original[i] > 0 ? now < 0.0 : now > 0.0) ++report.flipped;
    }
    return report;
}

} // namespace internal

/// Orients `normals` consistently by propagation over the graph `g`.
///
/// In every connected component (ignoring virtual edges and points whose normal is zero), a
/// minimum spanning tree for the weight orientation_edge_weight() is grown by Prim's algorithm from
/// the component's smallest index, and each normal takes the sign that agrees with its tree
/// parent's (orientation_agreement() > 0): orientation flows first across the edges where it is
/// least ambiguous, and the two faces of a part thinner than the graph's edges, down to about 5
/// mean spacings, keep opposite normals (the plain rule n_i . n_j > 0 of Hoppe et al. turns one of
/// them inside out; doc/benchmarks.md "Normal orientation"). Then the whole component
/// is flipped if sum_i n_i . (p_i - c) < 0, c the centroid of all points: for a closed surface this
/// sum approximates 3 volume / sampling density > 0 for outward normals, whatever c, so closed
/// components end up facing outward; open pieces (such as the two faces of a thin plate) face away
/// from the centroid of the whole cloud.
///
/// \tparam Graph a model of PointGraph (only the structure is read); directed
///         models must store both directions of every edge.
/// \tparam Positions an Eigen 3 x N matrix expression (float or double).
/// \tparam VirtualMap a model of EdgeFlagMap (PCCD::No_virtual_edges for graphs without the mark).
/// \param normals 3 x N, modified in place (signs only); zero columns are left as they are.
/// \throws Invalid_input if the sizes of `g`, `positions` and `normals` differ or a normal is not
///         finite.
/// Complexity: O(E log E). Deterministic: ties between equal weights go to the smaller index.
/// Thread safety: reads `g` and `positions`, writes `normals` only.
template <class Graph, class Positions, class VirtualMap = No_virtual_edges>
    requires(!std::is_same_v<Graph, Proximity_graph>) && PointGraph<Graph> && EdgeFlagMap<VirtualMap, Graph>
Orientation_report orient_normals(const Graph& g, const Eigen::MatrixBase<Positions>& positions,
                                  Eigen::Matrix3Xd& normals, const VirtualMap& is_virtual = {})
{
    return internal::orient_normals_over_graph("orient_normals", g, positions, normals, nullptr, is_virtual);
}

/// Orients a Proximity_graph's points' normals (its virtual edges are not followed).
template <class Positions>
Orientation_report orient_normals(const Proximity_graph& graph, const Eigen::MatrixBase<Positions>& positions,
                                  Eigen::Matrix3Xd& normals)
{
    return orient_normals(graph.graph(), positions, normals, graph.virtual_map());
}

/// Orients `normals` with hints: normals known up to quality, such as those read from a file, which
/// decide the sign where they exist, while the graph decides it elsewhere.
///
/// A point's hint is the column of `hints`; a zero or non-finite column means "no hint for that
/// point" (files often store 0 0 0 for an unknown normal). Then:
/// - a point with a hint takes the hint's sign: n_i is reversed when n_i . hint_i < 0; if its own
///   fit is undetermined (zero column of `normals`), it takes the normalized hint instead, so that
///   it still orients the evaluations near it;
/// - in a connected component of the graph (ignoring virtual edges and points without a normal)
///   that holds hinted points, the points without a hint get their sign by propagation along a
///   minimum spanning forest for the weight orientation_edge_weight() grown by Prim's algorithm from all the
///   hinted points at once (as one tree whose root is the set of hinted points): each takes the
///   sign that agrees with its tree parent's;
/// - a component without any hint is oriented as orient_normals() does it (a tree from its smallest
///   index, then the outward choice against the centroid of the whole cloud).
/// With no hint at all (`hints` with 0 columns, or only zero columns) the result is exactly
/// orient_normals()'s; with a hint for every point, exactly orient_normals_like()'s.
///
/// \tparam Graph, Positions, VirtualMap as for orient_normals().
/// \tparam Hints an Eigen 3 x N matrix expression (float or double), or 3 x 0 for no hints.
/// \param normals 3 x N, modified in place (signs, and the columns filled from hints).
/// \throws Invalid_input if the sizes of `g`, `positions`, `normals` and `hints` (unless empty)
///         differ or a normal is not finite. Hints are never an error.
/// Complexity: O(E log E). Deterministic: ties between equal weights go to the smaller index.
/// Thread safety: reads `g`, `positions` and `hints`, writes `normals` only.
template <class Graph, class Positions, class Hints, class VirtualMap = No_virtual_edges>
    requires(!std::is_same_v<Graph, Proximity_graph>) && PointGraph<Graph> && EdgeFlagMap<VirtualMap, Graph>
Orientation_report orient_normals_with_hints(const Graph& g, const Eigen::MatrixBase<Positions>& positions,
                                             Eigen::Matrix3Xd& normals, const Eigen::MatrixBase<Hints>& hints,
                                             const VirtualMap& is_virtual = {})
{
    if (hints.rows() != 3 && hints.cols() != 0)
        throw Invalid_input(internal::concat("orient_normals_with_hints: the hints have ", hints.rows(),
                                             " rows, expected 3"));
    if (hints.cols() == 0)
        return internal::orient_normals_over_graph("orient_normals_with_hints", g, positions, normals, nullptr,
                                                   is_virtual);
    const Eigen::Matrix3Xd given = hints.template cast<double>();
    return internal::orient_normals_over_graph("orient_normals_with_hints", g, positions, normals, &given, is_virtual);
}

/// Orients a Proximity_graph's points' normals with hints (its virtual edges are not followed).
template <class Positions, class Hints>
Orientation_report orient_normals_with_hints(const Proximity_graph& graph,
                                             const Eigen::MatrixBase<Positions>& positions, Eigen::Matrix3Xd& normals,
                                             const Eigen::MatrixBase<Hints>& hints)
{
    return orient_normals_with_hints(graph.graph(), positions, normals, hints, graph.virtual_map());
}

/// Orients each normal like the given reference normal of the same point (e.g. normals read from a
/// file): n_i is reversed when n_i . reference_i < 0. A zero column of `normals` (a point whose own
/// fit is undetermined) takes the normalized reference normal, so that the point still orients
/// the evaluations near it. Strict: every point needs a usable reference normal. It is the
/// graph-free special case of orient_normals_with_hints() with a hint for every point; normals that
/// may be missing for some points (as in many files) go to orient_normals_with_hints() instead.
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
    report.hints_used = std::size_t(normals.cols());
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
