// PCCD/Similarity_3.h -- Similarity_3 and the unit-cube normalization of an object, the first step
// of the benchmark procedure (doc/manual/sampling.md, "Normalization") and the rescaling that the
// input checks of Point_cloud and the proximity graphs suggest for clouds too large for their
// arithmetic: translate the bounding-box centre to the origin, then scale uniformly by
// 2 / (longest bounding-box side), so that the object fits [-1, 1]^3 and touches two opposite faces.
// The applied similarity is returned, so that a mesh and the cloud sampled from it can be
// normalized identically.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <ranges>
#include <type_traits>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Identity_point_map.h>
#include <PCCD/Point_traits.h>
#include <PCCD/concepts/ReadablePointMap.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// The similarity without rotation x -> scale (x - centre): a translation by -centre followed by a
/// uniform scaling about the origin (equivalently x -> scale x + translation()). Plain value type.
struct Similarity_3 {
    /// The uniform scale factor (> 0).
    double scale = 1.0;
    /// The point mapped to the origin.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();

    /// The translation of the form x -> scale x + translation: -scale * centre.
    Eigen::Vector3d translation() const { return -scale * centre; }

    /// scale (p - centre), computed in double (subtracting first keeps the result exact to a few ulps
    /// for objects far from the origin).
    template <class Derived>
    Eigen::Matrix<typename Derived::Scalar, 3, 1> transform_point(const Eigen::MatrixBase<Derived>& p) const
    {
        return (scale * (p.template cast<double>() - centre)).template cast<typename Derived::Scalar>();
    }

    /// scale (p - centre) for every column p of a 3 x N matrix. O(N).
    template <class Derived>
    Eigen::Matrix<typename Derived::Scalar, 3, Eigen::Dynamic> transform_points(const Eigen::MatrixBase<Derived>& points) const
    {
        return (scale * (points.template cast<double>().colwise() - centre)).template cast<typename Derived::Scalar>();
    }
};

namespace internal {

/// Accumulates a bounding box point by point and turns it into the unit-cube normalization.
class Unit_cube_bbox {
public:
    void add(double x, double y, double z)
    {
        const Eigen::Vector3d p(x, y, z);
        if (!internal::all_finite(p))
            throw Invalid_input(concat("normalization: point ", m_count, " (", x, ", ", y, ", ", z,
                                       ") is not finite"));
        m_min = m_min.cwiseMin(p);
        m_max = m_max.cwiseMax(p);
        ++m_count;
    }

    Similarity_3 normalization() const
    {
        if (m_count == 0) throw Invalid_input("normalization: the object has no points");
        if ((m_max.array() == m_min.array()).all())
            throw Invalid_input(concat("normalization: all ", m_count,
                                       " points coincide (zero extent); they cannot be scaled to [-1, 1]^3"));
        // The range checks come before the arithmetic they protect, which would otherwise overflow
        // (and trap when floating-point exceptions are enabled). Halved, the extent cannot overflow:
        // max - min overflows exactly when half of it exceeds DBL_MAX / 2.
        constexpr double max_double = std::numeric_limits<double>::max();
        const double half_longest = (0.5 * m_max - 0.5 * m_min).maxCoeff();
        const auto out_of_range = [&](double longest) {
            return Invalid_input(concat("normalization: the longest bounding-box side ", longest,
                                        " gives a scale factor outside the range of double"));
        };
        if (half_longest > max_double / 2.0) throw out_of_range(std::numeric_limits<double>::infinity());
        const double longest = (m_max - m_min).maxCoeff(); // > 0: some coordinate differs
        double scale = 0.0;
        if (longest >= std::numeric_limits<double>::min()) {
            scale = 2.0 / longest; // <= 2^1023
        } else {
            // Subnormal side: 2 / longest may overflow. Scaled by 2^54 (exactly) the quotient is
            // normal and rounds as the unscaled one would; it fits a double iff it is at most
            // DBL_MAX / 2^54.
            const double scaled = 2.0 / (longest * 0x1p54);
            if (scaled > max_double * 0x1p-54) throw out_of_range(longest);
            scale = scaled * 0x1p54;
        }
        // The midpoint as min + half the extent stays inside [min, max] even for huge coordinates.
        return Similarity_3{scale, m_min + 0.5 * (m_max - m_min)};
    }

private:
    Eigen::Vector3d m_min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d m_max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
    std::size_t m_count = 0;
};

} // namespace internal

/// The normalization of doc/manual/sampling.md for the points in the columns of a 3 x N matrix:
/// centre = bounding-box centre, scale = 2 / longest bounding-box side.
/// \throws Invalid_input if there is no point, a coordinate is not finite (the message names the
///         point), or all points coincide (zero extent). Complexity: O(N).
template <class Derived>
Similarity_3 compute_unit_cube_normalization(const Eigen::MatrixBase<Derived>& coordinates)
{
    if (coordinates.rows() != 3)
        throw Invalid_input(internal::concat("normalization: the coordinate matrix has ", coordinates.rows(),
                                             " rows, not 3"));
    internal::Unit_cube_bbox bbox;
    for (Eigen::Index i = 0; i < coordinates.cols(); ++i)
        bbox.add(double(coordinates(0, i)), double(coordinates(1, i)), double(coordinates(2, i)));
    return bbox.normalization();
}

/// The same for a range of items read through a point map.
/// \tparam Range an input range of items. \tparam PointMap a model of ReadablePointMap (identity by
/// default). \throws Invalid_input as above. Complexity: O(N).
template <std::ranges::input_range Range, class PointMap = Identity_point_map<std::ranges::range_value_t<Range>>>
    requires ReadablePointMap<PointMap, std::ranges::range_value_t<Range>>
Similarity_3 compute_unit_cube_normalization(const Range& items, const PointMap& point_map = PointMap())
{
    internal::Unit_cube_bbox bbox;
    for (const auto& item : items) {
        const auto& p = get(point_map, item);
        using P = std::remove_cvref_t<decltype(p)>;
        bbox.add(double(Point_traits<P>::x(p)), double(Point_traits<P>::y(p)), double(Point_traits<P>::z(p)));
    }
    return bbox.normalization();
}

/// Normalizes the points in the columns of `coordinates` in place and returns the similarity applied.
/// Afterwards the bounding box is centred at the origin and its longest side is 2 (to a few ulps).
/// \throws Invalid_input as compute_unit_cube_normalization (and then leaves `coordinates` unchanged).
/// Complexity: O(N).
template <std::floating_point FT>
Similarity_3 normalize_to_unit_cube(Eigen::Matrix<FT, 3, Eigen::Dynamic>& coordinates)
{
    const Similarity_3 similarity = compute_unit_cube_normalization(coordinates);
    coordinates = similarity.transform_points(coordinates);
    return similarity;
}

} // namespace PCCD
