// PCCD/internal/grid_cell.h -- the cells of a uniform 3D hash grid: the cell of a point for a given
// cell width and a 64-bit hash key per cell (21 bits per axis, wrapping). Shared by the grids that
// answer "is a kept point within r of x?" (the covering rule of the walked first-hit search, the
// sink that keeps intersection points apart; doc/manual/hierarchy.md "Covering instead of random
// draws", doc/manual/intersection.md "Curve points").
#pragma once

#include <cmath>
#include <cstdint>

#include <Eigen/Core>

namespace PCCD::internal {

/// Integer coordinates of a cell of a uniform grid.
struct Grid_cell {
    std::int64_t x, y, z;
};

/// The cell of width `width` (> 0) holding x: floor(x / width) per axis.
inline Grid_cell grid_cell(const Eigen::Vector3d& x, double width)
{
    return Grid_cell{std::int64_t(std::floor(x.x() / width)), std::int64_t(std::floor(x.y() / width)),
                     std::int64_t(std::floor(x.z() / width))};
}

/// A hash key of a cell: 21 bits per axis. Cells of bounded objects of finite coordinates rarely
/// wrap; a wrapped key only merges two cells' lists (an extra distance test, never a wrong answer).
inline std::uint64_t grid_key(const Grid_cell& c)
{
    const auto part = [](std::int64_t v) { return std::uint64_t(v) & ((std::uint64_t(1) << 21) - 1); };
    return part(c.x) | (part(c.y) << 21) | (part(c.z) << 42);
}

} // namespace PCCD::internal
