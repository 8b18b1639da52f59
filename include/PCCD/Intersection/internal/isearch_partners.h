// PCCD/Intersection/internal/isearch_partners.h -- where the interpolation search finds the
// partners of a sample and the paths of its brackets (doc/manual/intersection.md, "The leaf
// intersector policies", and doc/algorithms.md, "Euclidean and geodesic distance"): for an object
// that keeps a CPSP map (GeodesicCollisionObject), the annulus of the sample's CPSP list and its
// stored or on-the-fly geodesic paths; for an object that keeps only its kd-tree
// (EuclideanCollisionObject, the lean objects of scene-scale scans), the Euclidean annulus from a
// radius query and the samples nearest to the chord between the two points. Internal to
// Interpolation_search.h (isearch_role.h reads the lists, isearch_walk.h the paths).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/Paths_on_the_fly.h>
#include <PCCD/Geodesic/Stored_paths.h>
#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/concepts/CollisionObject.h>

namespace PCCD::internal {

/// The CPSP lists of a geodesic object: the geodesic annulus of a point, read from the map.
class Geodesic_partner_lists {
public:
    using Index = std::uint32_t;
    explicit Geodesic_partner_lists(const Close_pairs_shortest_paths& map) : m_map(&map) {}
    /// The largest distance a list holds (the CPSP bound).
    double bound() const { return double(m_map->bound()); }
    std::span<const Index> targets(Index p) const { return m_map->targets(p); }
    std::pair<std::size_t, std::size_t> annulus(Index p, double inner, double outer) const
    {
        return m_map->annulus(p, inner, outer);
    }

private:
    const Close_pairs_shortest_paths* m_map;
};

/// The Euclidean lists of an object without a CPSP map: the points within `bound` (the surface's
/// support radius) of p, nearest first (entry 0 is p itself), from one radius query of the object's
/// kd-tree per point. The last list is kept, so the repeated reads of one sample cost one query.
/// One per role and thread (it owns its buffers).
template <class Cloud>
class Euclidean_partner_lists {
public:
    using Index = std::uint32_t;
    using FT = typename Cloud::FT;
    Euclidean_partner_lists(const Cloud& cloud, double bound) : m_cloud(&cloud), m_bound(bound) {}
    double bound() const { return m_bound; }
    std::span<const Index> targets(Index p) const
    {
        load(p);
        return m_targets;
    }
    std::pair<std::size_t, std::size_t> annulus(Index p, double inner, double outer) const
    {
        load(p);
        const auto first = std::lower_bound(m_distances.begin(), m_distances.end(), inner);
        if (outer < inner) return {std::size_t(first - m_distances.begin()), std::size_t(first - m_distances.begin())};
        const auto last = std::upper_bound(first, m_distances.end(), outer);
        return {std::size_t(first - m_distances.begin()), std::size_t(last - m_distances.begin())};
    }

private:
    void load(Index p) const
    {
        if (m_loaded && m_point == p) return;
        m_cloud->within_radius(m_cloud->position(p), FT(m_bound), m_found);
        m_targets.clear();
        m_distances.clear();
        // The query point first, as in a CPSP list (the kd-tree sorts ties by index).
        m_targets.push_back(p);
        m_distances.push_back(0.0);
        for (const auto& n : m_found) {
            if (n.index == p) continue;
            m_targets.push_back(n.index);
            m_distances.push_back(std::sqrt(double(n.squared_distance)));
        }
        m_point = p;
        m_loaded = true;
    }

    const Cloud* m_cloud;
    double m_bound;
    mutable std::vector<typename Cloud::Neighbor> m_found;
    mutable std::vector<Index> m_targets;
    mutable std::vector<double> m_distances;
    mutable Index m_point = 0;
    mutable bool m_loaded = false;
};

/// PathSource of an object without a proximity graph: the points of the cloud nearest to the chord
/// from p_from to p_to, at steps of at most `step` (the sampling radius) along it, in order and
/// without repeats, `from` first and `to` last. On a surface sampled at spacing r the chord of two
/// points of one annulus (at most the support radius apart, a few r) stays within a fraction of r
/// of the surface where it is smooth, so these are the samples a geodesic path would visit; across a
/// gap or a fold they are the samples nearest to the chord, and the search along them brackets the
/// sign change of the other surface all the same (its end points do, and the search checks every
/// step it takes). O(length / step) nearest-point queries. Thread-safe.
template <class Cloud>
class Chord_paths {
public:
    using Index = std::uint32_t;
    using FT = typename Cloud::FT;
    Chord_paths(const Cloud& cloud, double step) : m_cloud(&cloud), m_step(step) {}

    bool path(Index from, Index to, std::vector<Index>& path) const
    {
        path.clear();
        path.push_back(from);
        if (from == to) return true;
        const Eigen::Vector3d a = m_cloud->position(from).template cast<double>();
        const Eigen::Vector3d b = m_cloud->position(to).template cast<double>();
        const double length = (b - a).norm();
        const std::size_t steps = std::min<std::size_t>(256, std::size_t(std::ceil(length / m_step)));
        for (std::size_t k = 1; k < steps; ++k) {
            const Eigen::Vector3d x = a + (double(k) / double(steps)) * (b - a);
            const Index nearest = m_cloud->nearest(x.template cast<FT>()).index;
            if (nearest != path.back() && nearest != to) path.push_back(nearest);
        }
        path.push_back(to);
        return true;
    }

private:
    const Cloud* m_cloud;
    double m_step;
};

/// The partner lists of the sampled object of a role: its CPSP lists when it keeps a CPSP map,
/// otherwise its Euclidean lists bounded at its surface's support radius.
template <class S>
auto partner_lists(const Posed_object<S>& sampled)
{
    if constexpr (GeodesicCollisionObject<S>) {
        return Geodesic_partner_lists(sampled.object->cpsp());
    } else {
        static_assert(EuclideanCollisionObject<S>,
                      "the interpolation search needs a GeodesicCollisionObject or a EuclideanCollisionObject");
        using Cloud = std::remove_cvref_t<decltype(sampled.object->cloud())>;
        return Euclidean_partner_lists<Cloud>(sampled.object->cloud(), sampled.support_radius());
    }
}

/// Calls `body(path_source)` with the path source of `sampled`: for a geodesic object the stored
/// CPSP paths or paths computed on the fly over the proximity graph, as `policy.paths` selects
/// (PathSource models); for a Euclidean object the chord paths (`policy.paths` does not apply).
template <class Policy, class S, class Body>
void with_path_source(const Policy& policy, const Posed_object<S>& sampled, const Body& body)
{
    if constexpr (GeodesicCollisionObject<S>) {
        const Close_pairs_shortest_paths& cpsp = sampled.object->cpsp();
        if (policy.paths == std::remove_cvref_t<decltype(policy.paths)>::stored) {
            body(Stored_paths(cpsp));
        } else {
            // The map's distances are floats: a bound a little above it keeps its farthest targets.
            const Proximity_graph& graph = sampled.object->graph();
            const auto& coordinates = sampled.object->cloud().coordinates();
            using FT = typename std::remove_cvref_t<decltype(coordinates)>::Scalar;
            body(Paths_on_the_fly<Proximity_graph::Graph, Proximity_graph::Length_map, Proximity_graph::Virtual_map, FT>(
                graph.graph(), graph.length_map(), coordinates, {.bound = double(cpsp.bound()) * (1.0 + 1e-6)},
                graph.virtual_map()));
        }
    } else {
        using Cloud = std::remove_cvref_t<decltype(sampled.object->cloud())>;
        body(Chord_paths<Cloud>(sampled.object->cloud(), sampled.sampling_radius()));
    }
}

} // namespace PCCD::internal
