// PCCD/Intersection/internal/Covering_grid.h -- the samples a role of a walked first-hit query has
// taken, for the covering rule (doc/manual/hierarchy.md "Covering instead of random draws"): a point
// within the covering radius of a taken sample is covered and not sampled again. A hash grid of cells
// of twice that radius; internal to Interpolation_search.h.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include <PCCD/internal/grid_cell.h>

namespace PCCD::internal {

/// Points (one object's local frame) and the question "is any within `radius` of x?". Cells are
/// twice the radius wide, so the ball of radius `radius` about x meets at most two cells per axis:
/// x's own and the neighbour on the side x lies nearer to. O(1) expected per call for points spread
/// over a surface (8 cells).
class Covering_grid {
public:
    explicit Covering_grid(double radius) : m_radius(radius), m_cell(2.0 * radius) {}

    bool covers(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d u = x / m_cell;
        const Eigen::Vector3d lower = u.array().floor();
        const Grid_cell c{std::int64_t(lower.x()), std::int64_t(lower.y()), std::int64_t(lower.z())};
        // +1 where x lies in the upper half of its cell, -1 in the lower half.
        const Eigen::Vector3d frac = u - lower;
        const std::int64_t sx = frac.x() < 0.5 ? -1 : 1, sy = frac.y() < 0.5 ? -1 : 1, sz = frac.z() < 0.5 ? -1 : 1;
        const double r2 = m_radius * m_radius;
        for (int i = 0; i < 8; ++i) {
            const auto it = m_cells.find(grid_key(Grid_cell{c.x + (i & 1 ? sx : 0), c.y + (i & 2 ? sy : 0), c.z + (i & 4 ? sz : 0)}));
            if (it == m_cells.end()) continue;
            for (const Eigen::Vector3d& p : it->second)
                if ((p - x).squaredNorm() <= r2) return true;
        }
        return false;
    }

    void add(const Eigen::Vector3d& x) { m_cells[grid_key(grid_cell(x, m_cell))].push_back(x); }

private:
    double m_radius;
    double m_cell;
    std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3d>> m_cells;
};

} // namespace PCCD::internal
