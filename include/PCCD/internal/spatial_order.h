// PCCD/internal/spatial_order.h -- the order of a cloud's points along a Morton (Z-order) curve
// over their bounding box, and a matrix's columns gathered in such an order. Graph construction
// runs its kd-tree queries in this order, and Point_cloud_object stores its points in it, so that
// points near in space are near in memory (doc/manual/surface.md, "One call: Point_cloud_object").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace PCCD::internal {

/// The column indices of `c` sorted along a Morton (Z-order) curve over their bounding box.
/// Running the per-point kd-tree queries in this order instead of the cloud's (often random) order
/// keeps consecutive queries in the same tree nodes, which made graph construction several times
/// faster on random samples (doc/benchmarks.md). Deterministic; O(N log N).
template <class Coordinates>
std::vector<std::uint32_t> spatial_order(const Coordinates& c)
{
    const auto n = std::size_t(c.cols());
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    if (n == 0) return order;
    const Eigen::Vector3d lo = c.rowwise().minCoeff().template cast<double>();
    const Eigen::Vector3d hi = c.rowwise().maxCoeff().template cast<double>();
    // All points coincide (one point, or only duplicates): every order is a Morton order, and the
    // scale below would be (2^21 - 1) / 0.
    if ((hi.array() == lo.array()).all()) return order;
    // Grid cells per unit offset from `lo`, chosen without overflow or division by zero: halved, the
    // extent cannot overflow even when hi - lo would (coordinates beyond +-DBL_MAX / 2); an extent
    // below `tiny_extent` would overflow (2^21 - 1) / extent, so such clouds divide each offset by
    // the extent first. Every other cloud takes the `scale` path.
    constexpr double cells = double((1u << 21) - 1);
    constexpr double max_double = std::numeric_limits<double>::max();
    constexpr double tiny_extent = cells / max_double * 4.0;
    const double half_extent = (0.5 * hi - 0.5 * lo).maxCoeff();
    const bool huge = half_extent > max_double / 4.0;
    const double extent = huge ? 0.0 : (hi - lo).maxCoeff(); // > 0: some coordinate differs
    const bool tiny = !huge && extent < tiny_extent;
    const double scale = huge || tiny ? 0.0 : cells / extent;
    auto cell = [&](int d, double x) -> std::uint64_t { // in [0, 2^21 - 1]
        if (huge) return std::uint64_t((0.5 * x - 0.5 * lo[d]) / half_extent * cells);
        if (tiny) return std::uint64_t((x - lo[d]) / extent * cells);
        return std::uint64_t((x - lo[d]) * scale);
    };
    auto spread = [](std::uint64_t x) { // 21 bits -> every third of 63 bits
        x &= 0x1fffff;
        x = (x | x << 32) & 0x1f00000000ffffull;
        x = (x | x << 16) & 0x1f0000ff0000ffull;
        x = (x | x << 8) & 0x100f00f00f00f00full;
        x = (x | x << 4) & 0x10c30c30c30c30c3ull;
        x = (x | x << 2) & 0x1249249249249249ull;
        return x;
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t code = 0;
        for (int d = 0; d < 3; ++d)
            code |= spread(cell(d, double(c(d, Eigen::Index(i))))) << d;
        keys[i] = {code, std::uint32_t(i)};
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < n; ++i) order[i] = keys[i].second;
    return order;
}

/// The columns `order[0]`, `order[1]`, ... of `m`, in that order (a reordering or a subset).
template <class Matrix>
Matrix gather_columns(const Matrix& m, const std::vector<std::uint32_t>& order)
{
    Matrix out(m.rows(), Eigen::Index(order.size()));
    for (std::size_t i = 0; i < order.size(); ++i) out.col(Eigen::Index(i)) = m.col(Eigen::Index(order[i]));
    return out;
}

} // namespace PCCD::internal
