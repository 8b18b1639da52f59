// PCCD/Kinetic/Piecewise_linear_flightplan.h -- a Flightplan model through key frames
// (doc/manual/kinetic.md, "Flightplans"): linear interpolation between consecutive key positions,
// at rest before the first and after the last key. This is what a simulation or a recorded
// animation produces (the scenes of testing/PCCD/testing/scenes/ record it).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/Kinetic/internal/Piecewise_cubic.h>
#include <PCCD/Kinetic/next_crossing.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// Linear interpolation through key frames (t_k, p_k), k = 0 .. K-1, constant outside [t_0, t_K-1].
///
/// The key times are held by a shared, immutable vector, so thousands of vertices animated by the
/// same simulation share one copy. A model of Flightplan. Immutable; thread-safe.
class Piecewise_linear_flightplan {
public:
    using Key_times = std::shared_ptr<const std::vector<double>>;

    /// A vertex at rest at the origin (one key frame at t = 0).
    Piecewise_linear_flightplan()
        : Piecewise_linear_flightplan(std::make_shared<const std::vector<double>>(1, 0.0),
                                      std::vector<Eigen::Vector3d>(1, Eigen::Vector3d::Zero()))
    {
    }

    /// \param times strictly increasing finite key times (shared); \param positions one finite
    /// position per key time.
    /// \throws Invalid_input if `times` is null or empty, not strictly increasing or not finite, if
    ///         the sizes differ, or if a position is not finite (the message names the key).
    Piecewise_linear_flightplan(Key_times times, std::vector<Eigen::Vector3d> positions)
        : m_times(std::move(times)), m_positions(std::move(positions))
    {
        if (!m_times || m_times->empty()) throw Invalid_input("Piecewise_linear_flightplan: no key frames");
        const std::vector<double>& ts = *m_times;
        if (ts.size() != m_positions.size())
            throw Invalid_input(internal::concat("Piecewise_linear_flightplan: ", ts.size(), " key times but ",
                                                 m_positions.size(), " key positions"));
        for (std::size_t k = 0; k < ts.size(); ++k) {
            if (!std::isfinite(ts[k]) || (k > 0 && !(ts[k] > ts[k - 1])))
                throw Invalid_input(internal::concat("Piecewise_linear_flightplan: key time ", k, " (", ts[k],
                                                     ") is not finite or not after the previous one"));
            if (!internal::all_finite(m_positions[k]))
                throw Invalid_input(internal::concat("Piecewise_linear_flightplan: key position ", k,
                                                     " is not finite"));
        }
        const std::size_t blocks = (ts.size() + block_size - 1) / block_size;
        m_blocks.resize(blocks);
        for (std::size_t j = 0; j < blocks; ++j) {
            const std::size_t end = std::min(ts.size(), (j + 1) * block_size);
            Block& block = m_blocks[j];
            block.min = block.max = m_positions[j * block_size];
            for (std::size_t k = j * block_size + 1; k < end; ++k) {
                block.min = block.min.cwiseMin(m_positions[k]);
                block.max = block.max.cwiseMax(m_positions[k]);
            }
        }
    }

    /// Convenience: copies `times` into a new shared vector.
    Piecewise_linear_flightplan(const std::vector<double>& times, std::vector<Eigen::Vector3d> positions)
        : Piecewise_linear_flightplan(std::make_shared<const std::vector<double>>(times), std::move(positions))
    {
    }

    /// Coordinate `axis` at time t. O(1) for evenly spaced key times, O(log K) otherwise.
    double coordinate(int axis, double t) const
    {
        const std::size_t k = piece_at(t);
        if (k == 0) return m_positions.front()[axis];
        if (k == m_positions.size()) return m_positions.back()[axis];
        return slope(k, axis) * (t - (*m_times)[k - 1]) + m_positions[k - 1][axis];
    }
    /// Position at time t. As coordinate() (bit for bit), with one key look-up for the three axes.
    Eigen::Vector3d position(double t) const
    {
        const std::size_t k = piece_at(t);
        if (k == 0) return m_positions.front();
        if (k == m_positions.size()) return m_positions.back();
        const double dt = (*m_times)[k] - (*m_times)[k - 1], s = t - (*m_times)[k - 1];
        Eigen::Vector3d p;
        for (int axis = 0; axis < 3; ++axis)
            p[axis] = (m_positions[k][axis] - m_positions[k - 1][axis]) / dt * s + m_positions[k - 1][axis];
        return p;
    }

    /// inf{ s > t : coordinate(axis, s) < other.coordinate(axis, s) } or +infinity.
    /// O(log K + number of merged key intervals scanned until the crossing). When both flightplans
    /// share their key times (as in recorded scenes) the scan compares key positions only: a key
    /// interval whose two end differences are >= 0 holds no crossing, and the crossing inside an
    /// interval with a sign change is the root of the line through them (computed the same way for
    /// both orders of the two flightplans, so their crossings coincide bit for bit). Blocks of
    /// block_size keys where this flightplan's smallest key coordinate is >= the other's largest
    /// are skipped whole: every difference in them is >= 0, so the result is that of the plain scan.
    double next_crossing(const Piecewise_linear_flightplan& other, int axis, double t) const
    {
        if (m_times != other.m_times) return PCCD::next_crossing(*this, other, axis, t);
        const std::vector<double>& ts = *m_times;
        const std::size_t keys = ts.size();
        std::size_t k = piece_at(t); // t in [t_k-1, t_k)
        double d0 = m_positions[k == 0 ? 0 : k - 1][axis] - other.m_positions[k == 0 ? 0 : k - 1][axis];
        if (k == 0) {
            // At rest before the first key: negative there means negative right after t.
            if (d0 < 0.0) return t;
            k = 1;
        }
        for (; k < keys; ++k) {
            if (k % block_size == 0 && d0 >= 0.0) {
                std::size_t j = k / block_size;
                while (j < m_blocks.size() && m_blocks[j].min[axis] >= other.m_blocks[j].max[axis]) ++j;
                if (j * block_size > k) {
                    k = std::min(j * block_size, keys);
                    d0 = m_positions[k - 1][axis] - other.m_positions[k - 1][axis];
                    if (k == keys) break;
                }
            }
            const double d1 = m_positions[k][axis] - other.m_positions[k][axis];
            if (d0 >= 0.0 && d1 >= 0.0) {
                d0 = d1;
                continue;
            }
            const double lo = ts[k - 1], hi = ts[k];
            if (d0 < 0.0 && d1 < 0.0) return std::max(lo, t);
            const double root = lo + (hi - lo) * (d0 / (d0 - d1));
            if (d0 >= 0.0) { // negative on (root, hi)
                if (hi > t) return std::max(root, t);
            } else if (root > t) { // negative on (lo, root)
                return std::max(lo, t);
            }
            d0 = d1;
        }
        return d0 < 0.0 ? std::max(ts.back(), t) : internal::infinity; // at rest after the last key
    }

    const Key_times& key_times() const { return m_times; }
    const std::vector<Eigen::Vector3d>& key_positions() const { return m_positions; }

    /// \cond PIECES -- piece 0 before the first key, piece k in [t_k-1, t_k), piece K after the last.
    std::size_t piece_count() const { return m_positions.size() + 1; }
    std::size_t piece_at(double t) const
    {
        // Interpolation guess (exact for evenly spaced keys, as recorded animations have), a few
        // steps of correction, and binary search when the keys are far from even.
        const std::vector<double>& ts = *m_times;
        const std::size_t n = ts.size();
        if (!(t >= ts.front())) return 0;
        if (t >= ts.back()) return n;
        auto k = std::size_t(double(n - 1) * ((t - ts.front()) / (ts.back() - ts.front())));
        k = std::min(k, n - 2) + 1; // candidate: ts[k-1] <= t < ts[k]
        for (int step = 0; step < 3; ++step) {
            if (ts[k - 1] > t)
                --k;
            else if (ts[k] <= t)
                ++k;
            else
                return k;
        }
        return std::size_t(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
    }
    double piece_begin(std::size_t k) const { return k == 0 ? -internal::infinity : (*m_times)[k - 1]; }
    double piece_end(std::size_t k) const { return k < m_times->size() ? (*m_times)[k] : internal::infinity; }
    double piece_origin(std::size_t k) const { return k == 0 ? m_times->front() : (*m_times)[k - 1]; }
    Cubic piece_cubic(std::size_t k, int axis) const
    {
        if (k == 0) return Cubic{{m_positions.front()[axis], 0.0, 0.0, 0.0}};
        if (k == m_positions.size()) return Cubic{{m_positions.back()[axis], 0.0, 0.0, 0.0}};
        return Cubic{{m_positions[k - 1][axis], slope(k, axis), 0.0, 0.0}};
    }
    /// \endcond

private:
    /// Keys per block of the per-axis key bounds that next_crossing skips by.
    static constexpr std::size_t block_size = 8;

    double slope(std::size_t k, int axis) const
    {
        return (m_positions[k][axis] - m_positions[k - 1][axis]) / ((*m_times)[k] - (*m_times)[k - 1]);
    }

    Key_times m_times;
    std::vector<Eigen::Vector3d> m_positions;
    /// The smallest and largest key coordinates of a block of block_size consecutive keys.
    struct Block {
        Eigen::Vector3d min, max;
    };
    std::vector<Block> m_blocks;
};

} // namespace PCCD
