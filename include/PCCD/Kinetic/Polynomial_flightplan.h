// PCCD/Kinetic/Polynomial_flightplan.h -- a Flightplan model made of polynomial pieces of degree
// <= 3 (doc/manual/kinetic.md, "Flightplans"): one cubic for all times, or a C1 cubic Hermite spline
// through key frames with given velocities (at rest outside the key range). Crossings are isolated
// robustly by next_crossing (next_crossing.h): critical points, then bisection on monotone pieces.
#pragma once

#include <algorithm>
#include <array>
#include <concepts>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Cubic.h>
#include <PCCD/Kinetic/internal/Piecewise_cubic.h>
#include <PCCD/Kinetic/next_crossing.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// A trajectory made of cubic pieces: piece k covers [begin_k, begin_k+1) and is
/// p(t) = c0 + c1 u + c2 u^2 + c3 u^3 with u = t - origin_k; the first piece extends to -infinity,
/// the last to +infinity. A model of Flightplan. Immutable; thread-safe.
class Polynomial_flightplan {
public:
    /// Coefficients c0..c3 of one piece (c_i multiplies u^i).
    using Coefficients = std::array<Eigen::Vector3d, 4>;

    /// A vertex at rest at the origin.
    Polynomial_flightplan() : Polynomial_flightplan(Coefficients{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                                 Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()})
    {
    }

    /// One polynomial for all times: p(t) = sum_i coefficients[i] (t - origin)^i.
    /// \throws Invalid_input if a coefficient or the origin is not finite.
    explicit Polynomial_flightplan(const Coefficients& coefficients, double origin = 0.0)
    {
        for (std::size_t i = 0; i < 4; ++i)
            if (!internal::all_finite(coefficients[i]))
                throw Invalid_input(internal::concat("Polynomial_flightplan: coefficient c", i, " is not finite"));
        if (!std::isfinite(origin)) throw Invalid_input("Polynomial_flightplan: origin is not finite");
        m_pieces.push_back({-internal::infinity, origin, coefficients});
    }

    /// The cubic Hermite spline through key frames (t_k, p_k) with velocities v_k: C1 inside
    /// [t_0, t_K-1], at rest at p_0 before and at p_K-1 after.
    /// \throws Invalid_input if the three vectors differ in size or are empty, if the times are not
    ///         finite and strictly increasing, or if a position or velocity is not finite.
    static Polynomial_flightplan hermite(const std::vector<double>& times, const std::vector<Eigen::Vector3d>& positions,
                                         const std::vector<Eigen::Vector3d>& velocities)
    {
        if (times.empty() || times.size() != positions.size() || times.size() != velocities.size())
            throw Invalid_input(internal::concat("Polynomial_flightplan::hermite: ", times.size(), " times, ",
                                                 positions.size(), " positions and ", velocities.size(),
                                                 " velocities (need the same non-zero number)"));
        for (std::size_t k = 0; k < times.size(); ++k) {
            if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1])))
                throw Invalid_input(internal::concat("Polynomial_flightplan::hermite: key time ", k, " (",
                                                     times[k], ") is not finite or not after the previous one"));
            if (!internal::all_finite(positions[k]) || !internal::all_finite(velocities[k]))
                throw Invalid_input(internal::concat("Polynomial_flightplan::hermite: key ", k,
                                                     " has a non-finite position or velocity"));
        }
        Polynomial_flightplan f;
        f.m_pieces.clear();
        const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
        f.m_pieces.push_back({-internal::infinity, times.front(), {positions.front(), zero, zero, zero}});
        for (std::size_t k = 0; k + 1 < times.size(); ++k) {
            const double h = times[k + 1] - times[k];
            const Eigen::Vector3d& p0 = positions[k];
            const Eigen::Vector3d& p1 = positions[k + 1];
            const Eigen::Vector3d& v0 = velocities[k];
            const Eigen::Vector3d& v1 = velocities[k + 1];
            const Eigen::Vector3d c2 = (3.0 * (p1 - p0) / h - 2.0 * v0 - v1) / h;
            const Eigen::Vector3d c3 = (2.0 * (p0 - p1) / h + v0 + v1) / (h * h);
            f.m_pieces.push_back({times[k], times[k], {p0, v0, c2, c3}});
        }
        if (times.size() > 1) f.m_pieces.push_back({times.back(), times.back(), {positions.back(), zero, zero, zero}});
        return f;
    }

    /// The same trajectory as another shipped flightplan (Linear_flightplan,
    /// Piecewise_linear_flightplan), so that one tree can mix kinds of motion.
    template <class F>
        requires requires(const F& g, std::size_t k) {
            { g.piece_cubic(k, 0) } -> std::same_as<Cubic>;
        }
    static Polynomial_flightplan from_pieces(const F& other)
    {
        Polynomial_flightplan f;
        f.m_pieces.clear();
        for (std::size_t k = 0; k < other.piece_count(); ++k) {
            Piece piece{other.piece_begin(k), other.piece_origin(k), {}};
            for (int axis = 0; axis < 3; ++axis) {
                const Cubic c = other.piece_cubic(k, axis);
                for (std::size_t i = 0; i < 4; ++i) piece.c[i][axis] = c.c[i];
            }
            f.m_pieces.push_back(piece);
        }
        return f;
    }

    /// Coordinate `axis` at time t. O(log pieces).
    double coordinate(int axis, double t) const
    {
        const std::size_t k = piece_at(t);
        return piece_cubic(k, axis)(t - m_pieces[k].origin);
    }
    /// Position at time t. O(log pieces).
    Eigen::Vector3d position(double t) const { return {coordinate(0, t), coordinate(1, t), coordinate(2, t)}; }

    /// inf{ s > t : coordinate(axis, s) < other.coordinate(axis, s) } or +infinity.
    /// O(log pieces + merged pieces scanned); per piece one quadratic solve and <= 3 bisections.
    double next_crossing(const Polynomial_flightplan& other, int axis, double t) const
    {
        return PCCD::next_crossing(*this, other, axis, t);
    }

    /// \cond PIECES
    std::size_t piece_count() const { return m_pieces.size(); }
    std::size_t piece_at(double t) const
    {
        const auto it = std::upper_bound(m_pieces.begin() + 1, m_pieces.end(), t,
                                         [](double s, const Piece& p) { return s < p.begin; });
        return std::size_t(it - m_pieces.begin()) - 1;
    }
    double piece_begin(std::size_t k) const { return m_pieces[k].begin; }
    double piece_end(std::size_t k) const { return k + 1 < m_pieces.size() ? m_pieces[k + 1].begin : internal::infinity; }
    double piece_origin(std::size_t k) const { return m_pieces[k].origin; }
    Cubic piece_cubic(std::size_t k, int axis) const
    {
        const Coefficients& c = m_pieces[k].c;
        return Cubic{{c[0][axis], c[1][axis], c[2][axis], c[3][axis]}};
    }
    /// \endcond

private:
    struct Piece {
        double begin;
        double origin;
        Coefficients c;
    };

    std::vector<Piece> m_pieces;
};

} // namespace PCCD
