// Shared helpers of the graph and geodesic tests: small random clouds (uniform, clustered with
// duplicates, sphere samples) from PCCD's platform-independent RNG, and a brute-force evaluation of
// the proximity graph definitions (independent of the kd-tree and of the builders).
#pragma once

#include <PCCD/Point_cloud.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Random.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace pccd_test {

using Cloud = PCCD::Point_cloud<>;
using Coordinates = Cloud::Coordinates;

inline Coordinates uniform_cube(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine rng(seed);
    Coordinates c(3, Eigen::Index(n));
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) c(d, Eigen::Index(i)) = PCCD::uniform_real(rng, -1.0, 1.0);
    return c;
}

inline Eigen::Vector3d random_unit_vector(PCCD::Random_engine& rng)
{
    Eigen::Vector3d v;
    do {
        v = Eigen::Vector3d(PCCD::standard_normal(rng), PCCD::standard_normal(rng), PCCD::standard_normal(rng));
    } while (v.norm() < 1e-12);
    return v.normalized();
}

/// Area-uniform random sample of the unit sphere.
inline Coordinates sphere_sample(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine rng(seed);
    Coordinates c(3, Eigen::Index(n));
    for (std::size_t i = 0; i < n; ++i) c.col(Eigen::Index(i)) = random_unit_vector(rng);
    return c;
}

/// Gaussian clusters of very different spreads, some points on a coarse grid (exact ties in
/// distances) and exact duplicates (pairs and one group of five copies).
inline Coordinates clustered_with_duplicates(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine rng(seed);
    std::vector<Eigen::Vector3d> points;
    const Eigen::Vector3d centres[3] = {{0, 0, 0}, {3, 0, 0}, {0, 4, 1}};
    const double spreads[3] = {0.05, 0.5, 0.01};
    while (points.size() < n * 8 / 10) {
        const auto k = PCCD::uniform_index(rng, 3);
        points.push_back(centres[k] + spreads[k] * Eigen::Vector3d(PCCD::standard_normal(rng),
                                                                   PCCD::standard_normal(rng),
                                                                   PCCD::standard_normal(rng)));
    }
    for (int i = 0; points.size() < n * 9 / 10; ++i) points.emplace_back(i % 7, (i / 7) % 7, 5.0 + i / 49);
    while (points.size() + 5 < n) points.push_back(points[PCCD::uniform_index(rng, points.size())]);
    while (points.size() < n) points.push_back(points[0]);
    // Shuffle so that copies are not adjacent in index order.
    for (std::size_t i = points.size() - 1; i > 0; --i) std::swap(points[i], points[PCCD::uniform_index(rng, i + 1)]);
    Coordinates c(3, Eigen::Index(n));
    for (std::size_t i = 0; i < n; ++i) c.col(Eigen::Index(i)) = points[i];
    return c;
}

inline double distance(const Coordinates& c, std::size_t a, std::size_t b)
{
    const double dx = c(0, Eigen::Index(a)) - c(0, Eigen::Index(b));
    const double dy = c(1, Eigen::Index(a)) - c(1, Eigen::Index(b));
    const double dz = c(2, Eigen::Index(a)) - c(2, Eigen::Index(b));
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// Undirected edge set: (smaller index, larger index) -> float length.
using Edge_set = std::map<std::pair<std::uint32_t, std::uint32_t>, float>;

inline Edge_set edge_set(const PCCD::Proximity_graph& g)
{
    Edge_set edges;
    const auto& rows = g.row_offsets();
    for (std::uint32_t u = 0; u + 1 < rows.size(); ++u)
        for (auto e = rows[u]; e < rows[u + 1]; ++e) {
            const std::uint32_t v = g.targets()[e];
            if (u < v) edges[{u, v}] = g.edge_property(e).length;
        }
    return edges;
}

/// Representatives of exact duplicates: the smallest index at the same position. O(N^2).
inline std::vector<std::uint32_t> brute_force_representatives(const Coordinates& c)
{
    std::vector<std::uint32_t> rep(std::size_t(c.cols()));
    for (std::uint32_t i = 0; i < rep.size(); ++i) {
        rep[i] = i;
        for (std::uint32_t j = 0; j < i; ++j)
            if (c.col(j) == c.col(i)) {
                rep[i] = j;
                break;
            }
    }
    return rep;
}

/// The documented definition, evaluated over all pairs: over distinct positions, kind SIG (r) or
/// k-NN (k), plus a zero-length edge from every copy to its representative.
inline Edge_set brute_force_graph(const Coordinates& c, PCCD::Graph_kind kind, unsigned parameter)
{
    const auto rep = brute_force_representatives(c);
    std::vector<std::uint32_t> unique;
    for (std::uint32_t i = 0; i < rep.size(); ++i)
        if (rep[i] == i) unique.push_back(i);
    const std::size_t m = unique.size();
    Edge_set edges;
    std::vector<double> radius(m, 0.0);
    std::vector<std::vector<std::pair<double, std::uint32_t>>> sorted(m);
    for (std::size_t a = 0; a < m; ++a) {
        for (std::size_t b = 0; b < m; ++b)
            if (a != b) sorted[a].emplace_back(distance(c, unique[a], unique[b]), std::uint32_t(b));
        std::sort(sorted[a].begin(), sorted[a].end());
        if (!sorted[a].empty()) radius[a] = sorted[a][std::min<std::size_t>(parameter, sorted[a].size()) - 1].first;
    }
    auto add = [&](std::uint32_t a, std::uint32_t b, double length) {
        edges[{std::min(a, b), std::max(a, b)}] = float(length);
    };
    for (std::size_t a = 0; a < m; ++a) {
        if (kind == PCCD::Graph_kind::knn) {
            for (std::size_t t = 0; t < std::min<std::size_t>(parameter, sorted[a].size()); ++t)
                add(unique[a], unique[sorted[a][t].second], sorted[a][t].first);
        } else {
            for (std::size_t b = a + 1; b < m; ++b) {
                const double d = distance(c, unique[a], unique[b]);
                if (d <= radius[a] + radius[b]) add(unique[a], unique[b], d);
            }
        }
    }
    for (std::uint32_t i = 0; i < rep.size(); ++i)
        if (rep[i] != i) add(rep[i], i, 0.0);
    return edges;
}

} // namespace pccd_test
