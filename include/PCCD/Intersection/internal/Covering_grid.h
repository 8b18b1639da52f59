// PCCD/Intersection/internal/Covering_grid.h -- the samples a role of a walked first-hit query has
// taken, for the covering rule (doc/manual/hierarchy.md "Covering instead of random draws"): a point
// within the covering radius of a taken sample is covered and not sampled again. A hash grid of cells
// of that radius; internal to Interpolation_search.h.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace PCCD::internal {

/// Points (one object's local frame) and the question "is any within `radius` of x?". O(1)
/// expected per call for points spread over a surface (27 cells of the radius).
class Covering_grid {
public:
    explicit Covering_grid(double radius) : m_radius(radius) {}

    bool covers(const Eigen::Vector3d& x) const
    {
        const Cell c = cell_of(x);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = m_cells.find(key(Cell{c.x + dx, c.y + dy, c.z + dz}));
                    if (it == m_cells.end()) continue;
                    for (const Eigen::Vector3d& p : it->second)
                        if ((p - x).squaredNorm() <= m_radius * m_radius) return true;
                }
        return false;
    }

    void add(const Eigen::Vector3d& x) { m_cells[key(cell_of(x))].push_back(x); }

private:
    struct Cell {
        std::int64_t x, y, z;
    };
    Cell cell_of(const Eigen::Vector3d& x) const
    {
        return Cell{std::int64_t(std::floor(x.x() / m_radius)), std::int64_t(std::floor(x.y() / m_radius)),
                    std::int64_t(std::floor(x.z() / m_radius))};
    }
    static std::uint64_t key(const Cell& c)
    {
        // 21 bits per axis; a wrapped key only costs extra distance tests.
        const auto part = [](std::int64_t v) { return std::uint64_t(v) & ((std::uint64_t(1) << 21) - 1); };
        return part(c.x) | (part(c.y) << 21) | (part(c.z) << 42);
    }

    double m_radius;
    std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3d>> m_cells;
};

} // namespace PCCD::internal
