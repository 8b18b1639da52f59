// PCCD/Proximity/contacts.h -- the contact regions of an intersecting pose, each with a
// representative point, a normal and a depth, as a physics engine consumes them (doc/algorithms.md
// "Proximity queries"; doc/manual/proximity.md "Contacts"). The points of each cloud inside the
// other object are grouped into regions (points closer than twice the larger sampling radius
// belong together); each region's deepest points give its local depth, witnesses and normal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Proximity/Distance_options.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Proximity/internal/penetration.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/internal/grid_cell.h>

namespace PCCD {
namespace internal {

/// Union-find over n items (path halving, union by index).
class Disjoint_sets {
public:
    explicit Disjoint_sets(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }
    std::size_t find(std::size_t i)
    {
        while (m_parent[i] != i) i = m_parent[i] = m_parent[m_parent[i]];
        return i;
    }
    void join(std::size_t i, std::size_t j)
    {
        i = find(i);
        j = find(j);
        if (i != j) m_parent[std::max(i, j)] = std::min(i, j);
    }

private:
    std::vector<std::size_t> m_parent;
};

/// Region labels (0, 1, ... in order of first appearance) of world points: two points closer than
/// `link` are in one region. A hash grid of cell `link`.
inline std::vector<std::size_t> link_regions(const std::vector<Eigen::Vector3d>& points, double link)
{
    Disjoint_sets sets(points.size());
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    for (std::size_t i = 0; i < points.size(); ++i) grid[grid_key(grid_cell(points[i], link))].push_back(std::uint32_t(i));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Grid_cell c = grid_cell(points[i], link);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find(grid_key({c.x + dx, c.y + dy, c.z + dz}));
                    if (it == grid.end()) continue;
                    for (std::uint32_t j : it->second)
                        if (j > i && (points[j] - points[i]).squaredNorm() <= link * link) sets.join(i, j);
                }
    }
    std::vector<std::size_t> label(points.size());
    std::unordered_map<std::size_t, std::size_t> index;
    for (std::size_t i = 0; i < points.size(); ++i) label[i] = index.try_emplace(sets.find(i), index.size()).first->second;
    return label;
}

} // namespace internal

/// The contact regions of the surfaces of `a` posed by `pose_a` and `b` posed by `pose_b`, deepest
/// first, at most options.max_contacts (Contact_result). The status is do_intersect()'s with
/// options.intersection; only intersecting poses have contacts. A region whose crossing is shallower
/// than the sampling (no sample of either cloud inside the other object) is reported at the
/// intersection query's point with depth 0 and the normal of the crossing.
///
/// \tparam A, B models of ProximityObject.
/// \throws Invalid_input as distance().
/// Thread safety and determinism: as distance(). Complexity: that of do_intersect(), plus one
/// nearest-point query per point of each cloud inside the other's box and a few tens of f
/// evaluations per region.
template <ProximityObject A, ProximityObject B>
Contact_result contacts(const A& a, const Rigid_transform_3<double>& pose_a, const B& b,
                        const Rigid_transform_3<double>& pose_b, const Distance_options& options = {})
{
    const char* function = "contacts";
    internal::check_options(options, function);
    internal::check_pose(pose_a, "pose_a", function);
    internal::check_pose(pose_b, "pose_b", function);
    Contact_result result;
    internal::Proximity_query<A, B> q(a, pose_a, b, pose_b, options, result.counters);
    const Intersection_result decided = q.decide();
    result.status = decided.status;
    if (decided.status != Intersection_status::intersecting) return result;

    const std::vector<internal::Inside_point> in_a = internal::points_inside(q.pa, q.pb, q.state); // A's points in B
    const std::vector<internal::Inside_point> in_b = internal::points_inside(q.pb, q.pa, q.state); // B's points in A
    std::vector<Eigen::Vector3d> world;
    world.reserve(in_a.size() + in_b.size());
    for (const auto& p : in_a) world.push_back(p.world);
    for (const auto& p : in_b) world.push_back(p.world);
    const double link = 2.0 * std::max(q.pa.sampling_radius(), q.pb.sampling_radius());
    const std::vector<std::size_t> label = internal::link_regions(world, link);
    const std::size_t regions = label.empty() ? 0 : *std::max_element(label.begin(), label.end()) + 1;

    std::vector<std::vector<internal::Inside_point>> region_a(regions), region_b(regions);
    for (std::size_t i = 0; i < in_a.size(); ++i) region_a[label[i]].push_back(in_a[i]);
    for (std::size_t i = 0; i < in_b.size(); ++i) region_b[label[in_a.size() + i]].push_back(in_b[i]);
    const std::size_t tries = 2;
    for (std::size_t k = 0; k < regions && !q.state.out_of_budget(); ++k) {
        const auto da = internal::deepest(q.pa, q.pb, region_a[k], tries, q.tolerance, q.max_step, q.state);
        const auto db = internal::deepest(q.pb, q.pa, region_b[k], tries, q.tolerance, q.max_step, q.state);
        Contact c;
        c.points_inside = region_a[k].size() + region_b[k].size();
        if (da && (!db || da->depth >= db->depth)) {
            c.point_a = da->deep.x;
            c.point_b = da->surface.x;
            c.normal = -da->surface.normal;
            c.depth = da->depth;
        } else if (db) {
            c.point_a = db->surface.x;
            c.point_b = db->deep.x;
            c.normal = db->surface.normal;
            c.depth = db->depth;
        } else {
            continue; // no witness could be projected (e.g. only outliers inside)
        }
        c.position = 0.5 * (c.point_a + c.point_b);
        result.contacts.push_back(c);
    }
    // The intersection query's point, when no region holds it: a crossing shallower than the sampling.
    for (const Intersection_point& p : decided.points) {
        const bool covered = std::any_of(world.begin(), world.end(),
                                         [&](const Eigen::Vector3d& w) { return (w - p.position).norm() <= link; });
        if (covered) continue;
        Contact c;
        c.position = c.point_a = c.point_b = p.position;
        c.depth = 0.0;
        c.normal = q.crossing_normal(p.position);
        result.contacts.push_back(c);
    }
    result.regions = result.contacts.size();
    std::stable_sort(result.contacts.begin(), result.contacts.end(),
                     [](const Contact& l, const Contact& r) { return l.depth > r.depth; });
    if (result.contacts.size() > options.max_contacts) result.contacts.resize(options.max_contacts);
    return result;
}

} // namespace PCCD
