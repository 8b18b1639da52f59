// PCCD/internal/cell_grid.h -- a uniform grid of cubic cells over a cloud's points, the point
// indices stored cell by cell, which answers radius queries exactly for radii up to the cell's
// side: the few cells a query ball meets are independent look-ups in a hash table, where a kd-tree
// descends about log2(N) levels one after the other. Kd_tree::within_radius() uses it when one is
// laid; the lean object lays one for the neighbours of its surface's evaluations
// (doc/algorithms.md, "Euclidean and geodesic distance"; doc/manual/surface.md, "The lean object").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include <PCCD/internal/grid_cell.h>

namespace PCCD::internal {

/// Cells of side `cell()` over the points of a 3 x N coordinate matrix that the caller keeps alive
/// and unchanged (the grid stores indices into it, not coordinates). Memory: 4 bytes per point and
/// 16 bytes per table slot (at most 8 / 3 slots per non-empty cell). Immutable after construction;
/// queries are const and safe for concurrent readers.
template <class FT>
class Cell_grid {
public:
    using Coordinates = Eigen::Matrix<FT, 3, Eigen::Dynamic>;

    /// The most cells a query may meet to be answered here (3 per axis); beyond it within_radius()
    /// declines.
    static constexpr std::int64_t most_cells = 27;

    /// Whether a grid of side `cell` can be laid over `c`: `cell` finite and normal, and fewer than
    /// 2^21 cells along each axis of the points' bounding box (keys pack 21 bits per axis).
    static bool fits(const Coordinates& c, double cell)
    {
        // Quiet comparisons (`cell > 0.0` would raise FE_INVALID on NaN, a trap in Debug test
        // builds), a normal side (its inverse is finite), and halves that cannot overflow.
        if (!std::isgreaterequal(cell, std::numeric_limits<double>::min()) || !std::isfinite(cell) || c.cols() == 0)
            return false;
        for (int d = 0; d < 3; ++d) {
            const double half_extent = 0.5 * double(c.row(d).maxCoeff()) - 0.5 * double(c.row(d).minCoeff());
            if (!(half_extent / double(max_cells_per_axis - 1) < 0.5 * cell)) return false;
        }
        return true;
    }

    /// Lays the grid over `c`. O(N) expected (two passes of hash look-ups, no sort, no copy of the
    /// points). \pre fits(c, cell)
    Cell_grid(const Coordinates& c, double cell) : m_cell(cell), m_inverse(1.0 / cell)
    {
        for (int d = 0; d < 3; ++d) m_lo[d] = double(c.row(d).minCoeff());
        for (int d = 0; d < 3; ++d)
            m_cells[d] = std::int64_t(std::floor((double(c.row(d).maxCoeff()) - m_lo[d]) * m_inverse)) + 1;
        const auto n = std::size_t(c.cols());
        // Pass 1: the points per cell (the table grows to keep its load at most three quarters).
        resize_table(64);
        std::size_t used = 0;
        for (std::size_t i = 0; i < n; ++i) {
            Slot& slot = insert(key_of_point(c, i), used);
            ++slot.count;
        }
        // Each cell's range in m_points, in the table's order; then pass 2 fills them, each cell's
        // points in increasing index order.
        std::uint32_t first = 0;
        for (Slot& slot : m_slots) {
            if (slot.key == empty) continue;
            slot.first = first;
            first += slot.count;
            slot.count = 0;
        }
        m_points.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            Slot& slot = m_slots[find(key_of_point(c, i))];
            m_points[slot.first + slot.count++] = std::uint32_t(i);
        }
    }

    double cell() const { return m_cell; }

    /// Heap bytes: the point indices and the table.
    std::size_t memory_bytes() const
    {
        return m_points.capacity() * sizeof(std::uint32_t) + m_slots.capacity() * sizeof(Slot);
    }

    /// Appends to `out` every point j of `c` (the matrix the grid was laid over) with
    /// |query - p_j|^2 <= radius^2, the squared distance computed as the kd-tree computes it (the
    /// coordinates' differences squared and summed in axis order, in FT), so that the set and the
    /// distances equal nanoflann's; unsorted. Returns false, appending nothing, when the query's
    /// ball meets more than most_cells cells (the caller asks the kd-tree instead).
    /// \pre radius >= 0 and the query finite.
    template <class Neighbor>
    bool within_radius(const Coordinates& c, const Eigen::Matrix<FT, 3, 1>& query, FT radius,
                       std::vector<Neighbor>& out) const
    {
        std::int64_t from[3], to[3];
        std::int64_t count = 1;
        for (int d = 0; d < 3; ++d) {
            const double q = double(query[d]), r = double(radius);
            // A margin far above the rounding of these operations and of the distance test in FT
            // keeps every cell the ball meets (a cell too many costs a look-up, never a wrong answer).
            const double margin = 16.0 * double(std::numeric_limits<FT>::epsilon()) * (std::abs(q) + std::abs(m_lo[d]) + r) +
                                  1e-9 * m_cell;
            // The ball's extent from the grid's corner, compared with the grid's before it is
            // divided into cells: a far query would overflow the division or the integers.
            const double low = q - r - margin - m_lo[d], high = q + r + margin - m_lo[d];
            const double span = double(m_cells[d]) * m_cell;
            if (high < 0.0 || low >= span) return true; // the ball misses the points' box
            from[d] = low <= 0.0 ? 0 : std::min<std::int64_t>(m_cells[d] - 1, std::int64_t(std::floor(low * m_inverse)));
            to[d] = high >= span ? m_cells[d] - 1 : std::min<std::int64_t>(m_cells[d] - 1, std::int64_t(std::floor(high * m_inverse)));
            count *= to[d] - from[d] + 1;
            if (count > most_cells) return false;
        }
        const FT bound = radius * radius;
        for (std::int64_t z = from[2]; z <= to[2]; ++z)
            for (std::int64_t y = from[1]; y <= to[1]; ++y)
                for (std::int64_t x = from[0]; x <= to[0]; ++x) {
                    const std::size_t s = find(key(x, y, z));
                    if (s == none) continue;
                    const Slot& slot = m_slots[s];
                    for (std::uint32_t k = slot.first; k < slot.first + slot.count; ++k) {
                        const std::uint32_t j = m_points[k];
                        FT squared = FT();
                        for (Eigen::Index a = 0; a < 3; ++a) {
                            const FT diff = query[a] - c(a, Eigen::Index(j));
                            squared += diff * diff;
                        }
                        if (squared <= bound) out.push_back(Neighbor{j, squared});
                    }
                }
        return true;
    }

private:
    static constexpr std::int64_t max_cells_per_axis = std::int64_t(1) << 21;
    static constexpr std::uint64_t empty = ~std::uint64_t(0); // no key has bit 63 set
    static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

    struct Slot {
        std::uint64_t key;
        std::uint32_t first, count;
    };

    // Cells are counted from the points' box corner, so within [0, 2^21) per axis: no key wraps.
    static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) { return grid_key(Grid_cell{x, y, z}); }
    std::uint64_t key_of_point(const Coordinates& c, std::size_t i) const
    {
        std::int64_t cell[3];
        for (int d = 0; d < 3; ++d) {
            const auto k = std::int64_t(std::floor((double(c(d, Eigen::Index(i))) - m_lo[d]) * m_inverse));
            cell[d] = std::clamp<std::int64_t>(k, 0, m_cells[d] - 1);
        }
        return key(cell[0], cell[1], cell[2]);
    }
    static std::size_t hash(std::uint64_t k)
    {
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdULL;
        k ^= k >> 33;
        return std::size_t(k);
    }
    std::size_t find(std::uint64_t k) const
    {
        for (std::size_t s = hash(k) & m_mask;; s = (s + 1) & m_mask) {
            if (m_slots[s].key == k) return s;
            if (m_slots[s].key == empty) return none;
        }
    }
    Slot& insert(std::uint64_t k, std::size_t& used)
    {
        std::size_t s = hash(k) & m_mask;
        for (; m_slots[s].key != empty; s = (s + 1) & m_mask)
            if (m_slots[s].key == k) return m_slots[s];
        if (4 * (used + 1) > 3 * m_slots.size()) {
            resize_table(2 * m_slots.size());
            return insert(k, used);
        }
        ++used;
        m_slots[s] = Slot{k, 0, 0};
        return m_slots[s];
    }
    void resize_table(std::size_t size)
    {
        std::vector<Slot> old = std::move(m_slots);
        m_slots.assign(size, Slot{empty, 0, 0});
        m_slots.shrink_to_fit();
        m_mask = size - 1;
        for (const Slot& slot : old) {
            if (slot.key == empty) continue;
            std::size_t s = hash(slot.key) & m_mask;
            while (m_slots[s].key != empty) s = (s + 1) & m_mask;
            m_slots[s] = slot;
        }
    }

    double m_cell, m_inverse;
    double m_lo[3];
    std::int64_t m_cells[3];
    std::vector<Slot> m_slots;
    std::size_t m_mask = 0;
    std::vector<std::uint32_t> m_points;
};

} // namespace PCCD::internal
