// PCCD/Intersection/Query_state.h -- the mutable state of one intersection query: counters,
// budget, random engine, and the sink that verifies candidates and collects the output points at
// the requested spacing (doc/manual/intersection.md, "Leaf intersectors"). do_intersect() makes
// one per query; a leaf intersector policy (the LeafIntersector concept) receives it and reports
// its candidates through offer().
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/internal/grid_cell.h>
#include <PCCD/internal/timing.h>

namespace PCCD {


/// Collects output points: keeps a point only if no kept point lies within `spacing` (a hash grid
/// of cell `spacing`), and tells the query to stop at the first point in first-hit mode.
class Point_sink {
public:
    Point_sink(bool first_hit, double spacing, std::vector<Intersection_point>& out)
        : m_first_hit(first_hit), m_spacing(spacing), m_out(&out)
    {
    }

    bool first_hit() const { return m_first_hit; }
    double spacing() const { return m_spacing; }
    bool done() const { return m_first_hit && !m_out->empty(); }
    std::size_t size() const { return m_out->size(); }

    /// True when a kept point lies within `radius` of x (always false in first-hit mode, where
    /// nothing is kept before the query stops).
    bool near(const Eigen::Vector3d& x, double radius) const
    {
        if (m_out->empty() || m_first_hit) return false;
        const int reach = int(std::ceil(radius / m_spacing));
        const internal::Grid_cell c = internal::grid_cell(x, m_spacing);
        if (reach > 2) { // a wide radius: scan the points (rare; only for huge radii)
            for (const Intersection_point& p : *m_out)
                if ((p.position - x).squaredNorm() <= radius * radius) return true;
            return false;
        }
        for (int dx = -reach; dx <= reach; ++dx)
            for (int dy = -reach; dy <= reach; ++dy)
                for (int dz = -reach; dz <= reach; ++dz) {
                    const auto it = m_grid.find(internal::grid_key({c.x + dx, c.y + dy, c.z + dz}));
                    if (it == m_grid.end()) continue;
                    for (std::uint32_t k : it->second)
                        if (((*m_out)[k].position - x).squaredNorm() <= radius * radius) return true;
                }
        return false;
    }

    /// Adds p unless a kept point is closer than the spacing. Returns true if it was kept.
    bool add(const Intersection_point& p)
    {
        if (done()) return false;
        if (!m_first_hit && near(p.position, m_spacing)) return false;
        m_grid[internal::grid_key(internal::grid_cell(p.position, m_spacing))].push_back(std::uint32_t(m_out->size()));
        m_out->push_back(p);
        return true;
    }

private:
    bool m_first_hit;
    double m_spacing;
    std::vector<Intersection_point>* m_out;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_grid;
};

/// Counters, budget, engine and sink of one query.
struct Query_state {
    /// Turns a candidate point into a verified contact (the projected point), or rejects it.
    using Verifier = std::function<std::optional<Intersection_point>(const Intersection_point&)>;

    Intersection_counters counters;
    std::optional<std::size_t> budget;
    /// Time budget: the query stops once the steady clock passes it.
    std::optional<internal::Steady_clock::time_point> deadline;
    bool budget_hit = false;
    /// The smallest |f_T(p)| over the samples p of the interpolation search where f_T was defined
    /// (p a point of one cloud, f_T the other surface); +infinity before any.
    double closest_sample = std::numeric_limits<double>::infinity();
    Random_engine engine;
    Point_sink sink;
    /// Empty: candidates are kept as they are (unverified).
    Verifier verifier;
    /// Told of the query's events (null: none).
    Intersection_visitor* visitor = nullptr;
    /// The posed object A of the query (to tell an evaluation of f_A from one of f_B).
    const void* posed_a = nullptr;
    /// The query's seed (the engine's state at the start).
    std::uint64_t seed;
    /// The policy's search sampled every point of the region within reach once in each role (the
    /// walk completed before a "separate"): no certification pass is needed.
    bool region_searched = false;
    /// Search as intersection_points() does (the whole sample of the region, no walk, no first-hit
    /// caps) even though the sink stops at the first point: the certification pass of a first hit
    /// (Intersection_options::certify_separation).
    bool search_all;
    /// A rejected crossing at a world point as the answer's point (kind approximate, f_A and f_B
    /// there), or nothing when a surface is undefined there, it lies outside a domain core, or a
    /// cloud has no point within its sampling radius of it (set with the verifier; counted as a
    /// verification step).
    std::function<std::optional<Intersection_point>(const Eigen::Vector3d&)> crossing_check;
    /// The first crossing (an AIP between two points of one cloud on opposite sides of the other
    /// surface) that the verification rejected in the current pass and crossing_check accepted.
    std::optional<Intersection_point> rejected_crossing;

    Query_state(std::uint64_t seed_, std::optional<std::size_t> max_f, bool first_hit, double spacing,
                std::vector<Intersection_point>& out)
        : budget(max_f), engine(seed_), sink(first_hit, spacing, out), seed(seed_), search_all(!first_hit)
    {
    }

    /// True while the search may take the first-hit shortcuts (the walk, the sample caps).
    bool first_hit_search() const { return sink.first_hit() && !search_all; }

    /// True (and remembered) once the budget is spent.
    bool out_of_budget()
    {
        if (budget && counters.f_evaluations >= *budget) budget_hit = true;
        if (deadline && !budget_hit && internal::Steady_clock::now() >= *deadline) budget_hit = true;
        return budget_hit;
    }
    /// The query should stop: first hit found or budget spent.
    bool stop() { return sink.done() || out_of_budget(); }

    /// A candidate point found by a policy: verified (when a verifier is set) and, if it passes,
    /// added to the sink. Returns true when a point was kept.
    /// `crossing`: the candidate is an AIP of a bracket (a sign change of the other surface's f
    /// between two points of one cloud), remembered in rejected_crossing when it is rejected.
    bool offer(const Intersection_point& candidate, bool crossing = false)
    {
        if (!verifier) return sink.add(candidate);
        const std::optional<Intersection_point> contact = verifier(candidate);
        if (!contact) {
            ++counters.candidates_rejected;
            if (crossing && !rejected_crossing && crossing_check) rejected_crossing = crossing_check(candidate.position);
            return false;
        }
        return sink.add(*contact);
    }

    /// f of `target` at the world point x, counted (and reported to the visitor).
    template <class Object>
    Surface_evaluation evaluate_world(const Posed_object<Object>& target, const Eigen::Vector3d& x)
    {
        ++counters.f_evaluations;
        const Surface_evaluation e = target.object->surface().evaluate(target.from_world.transform_point(x));
        if (visitor) visitor->evaluation(&target == posed_a ? Query_object::a : Query_object::b, x, e);
        return e;
    }
    /// f of `target` at the point x of its own frame, counted (and reported to the visitor).
    template <class Object>
    Surface_evaluation evaluate_local(const Posed_object<Object>& target, const Eigen::Vector3d& x)
    {
        ++counters.f_evaluations;
        const Surface_evaluation e = target.object->surface().evaluate(x);
        if (visitor)
            visitor->evaluation(&target == posed_a ? Query_object::a : Query_object::b, target.to_world.transform_point(x), e);
        return e;
    }
};

} // namespace PCCD
