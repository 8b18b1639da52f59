// PCCD/Exact/sphere_sphere_intersection.h -- the analytic exact reference for two spheres
// (doc/design.md, "Exact checks"): whether their surfaces intersect, decided exactly in rational
// arithmetic, the intersection circle, points sampled on it, and the closed-form separation or
// penetration that classifies a pose as in doc/algorithms.md, "Benchmark procedure" (same
// definitions as exact_separation for meshes, so the two can be compared).
//
// Uses CGAL's exact rational number type only (no Polygon_mesh_processing).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include <CGAL/Exact_rational.h>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// A circle in space: the points at distance `radius` from `centre` in the plane through `centre`
/// orthogonal to the unit vector `normal`. A radius of 0 is a single point. Plain value type; all
/// member functions are const, O(1) (points: O(n)) and thread-safe.
struct Circle_3 {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    /// Unit normal of the circle's plane.
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    double radius = 0.0;

    /// A unit vector orthogonal to `normal` (the direction of angle 0 in point()); the same for the
    /// same normal.
    Eigen::Vector3d first_axis() const
    {
        const Eigen::Vector3d helper =
            std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
        return normal.cross(helper).normalized();
    }

    /// The point at `angle` (radians) from first_axis(), counterclockwise about `normal`.
    Eigen::Vector3d point(double angle) const
    {
        const Eigen::Vector3d u = first_axis();
        const Eigen::Vector3d v = normal.cross(u);
        return centre + radius * (std::cos(angle) * u + std::sin(angle) * v);
    }

    /// `n` points evenly spaced on the circle, starting at angle 0 (n copies of the centre when the
    /// radius is 0).
    std::vector<Eigen::Vector3d> points(std::size_t n) const
    {
        std::vector<Eigen::Vector3d> result;
        result.reserve(n);
        for (std::size_t i = 0; i < n; ++i) result.push_back(point(2.0 * std::numbers::pi * double(i) / double(n)));
        return result;
    }

    /// The distance from `x` to the nearest point of the circle.
    double distance(const Eigen::Vector3d& x) const
    {
        const Eigen::Vector3d d = x - centre;
        const double height = d.dot(normal);
        const double in_plane = (d - height * normal).norm();
        return std::hypot(height, in_plane - radius);
    }
};

/// How two spheres' surfaces meet (exact classification).
enum class Sphere_sphere_relation {
    /// Apart, neither inside the other: |c1 c2| > r1 + r2.
    disjoint,
    /// Touching from outside at one point: |c1 c2| = r1 + r2.
    externally_tangent,
    /// Crossing along a circle: |r1 - r2| < |c1 c2| < r1 + r2.
    intersecting,
    /// Touching from inside at one point: 0 < |c1 c2| = |r1 - r2|.
    internally_tangent,
    /// One strictly inside the other without contact: |c1 c2| < |r1 - r2|.
    nested,
    /// The same sphere.
    coincident
};

/// The result of exact_sphere_sphere_intersection.
struct Sphere_sphere_intersection {
    /// The exact relation of the two surfaces.
    Sphere_sphere_relation relation = Sphere_sphere_relation::disjoint;
    /// The intersection curve: a circle for `intersecting`, a circle of radius 0 at the contact
    /// point for the tangent relations; empty for disjoint, nested and coincident spheres.
    std::optional<Circle_3> circle;
    /// Same definition as Exact_separation for meshes. Surfaces apart (disjoint, nested): the gap
    /// between them, r1 + r2 - |c1 c2| or |r1 - r2| - |c1 c2| in absolute value. Surfaces meeting:
    /// the largest depth of a point of one sphere inside the other, max(r2 - | |c1 c2| - r1 |,
    /// r1 - | |c1 c2| - r2 |) (0 for tangent and coincident spheres).
    double distance = 0.0;
    double penetration_depth = 0.0;

    /// Whether the two surfaces have a common point.
    bool surfaces_intersect() const
    {
        return relation != Sphere_sphere_relation::disjoint && relation != Sphere_sphere_relation::nested;
    }
    /// `distance` when apart, `-penetration_depth` when the surfaces meet.
    double signed_measure() const { return surfaces_intersect() ? -penetration_depth : distance; }
};

/// The intersection of the spheres |x - c1| = r1 and |x - c2| = r2.
///
/// The relation is decided exactly: the squared centre distance and (r1 +- r2)^2 are compared in
/// CGAL::Exact_rational from the given doubles, so touching spheres are recognized as such. The
/// circle, the distance and the depth are then computed in double (closed form, a few ulps): circle
/// centre c1 + a n with n = (c2 - c1) / |c2 - c1|, a = (|c1 c2|^2 + r1^2 - r2^2) / (2 |c1 c2|), radius
/// sqrt(r1^2 - a^2), normal n.
/// \throws Invalid_input if a centre is not finite or a radius is not finite and > 0.
/// Complexity: O(1). Thread-safe.
inline Sphere_sphere_intersection exact_sphere_sphere_intersection(const Eigen::Vector3d& c1, double r1,
                                                                   const Eigen::Vector3d& c2, double r2)
{
    if (!internal::all_finite(c1) || !internal::all_finite(c2))
        throw Invalid_input("exact_sphere_sphere_intersection: a sphere centre is not finite");
    if (!(std::isfinite(r1) && r1 > 0.0) || !(std::isfinite(r2) && r2 > 0.0))
        throw Invalid_input(internal::concat("exact_sphere_sphere_intersection: radii ", r1, " and ", r2,
                                             " must be finite and > 0"));
    using Q = CGAL::Exact_rational;
    Q squared_distance(0);
    for (int i = 0; i < 3; ++i) {
        const Q difference = Q(c2[i]) - Q(c1[i]);
        squared_distance += difference * difference;
    }
    const Q sum = Q(r1) + Q(r2);
    const Q difference = Q(r1) - Q(r2);
    const CGAL::Comparison_result outer = CGAL::compare(squared_distance, sum * sum);
    const CGAL::Comparison_result inner = CGAL::compare(squared_distance, difference * difference);

    Sphere_sphere_intersection result;
    const double d = (c2 - c1).norm();
    if (CGAL::is_zero(squared_distance)) {
        // Concentric: the same sphere or strictly nested.
        result.relation = CGAL::is_zero(difference) ? Sphere_sphere_relation::coincident : Sphere_sphere_relation::nested;
        result.distance = result.relation == Sphere_sphere_relation::nested ? std::abs(r1 - r2) : 0.0;
        return result;
    }
    if (outer == CGAL::LARGER) {
        result.relation = Sphere_sphere_relation::disjoint;
        result.distance = std::max(0.0, d - r1 - r2);
        return result;
    }
    if (inner == CGAL::SMALLER) {
        result.relation = Sphere_sphere_relation::nested;
        result.distance = std::max(0.0, std::abs(r1 - r2) - d);
        return result;
    }
    const Eigen::Vector3d n = (c2 - c1) / d;
    Circle_3 circle;
    circle.normal = n;
    if (outer == CGAL::EQUAL || inner == CGAL::EQUAL) {
        result.relation = outer == CGAL::EQUAL ? Sphere_sphere_relation::externally_tangent
                                               : Sphere_sphere_relation::internally_tangent;
        // The contact point lies on the centre line, on the side of c2 from c1 unless sphere 1 is
        // the inner one (internal tangency with r1 < r2).
        const double side = (result.relation == Sphere_sphere_relation::internally_tangent && r1 < r2) ? -1.0 : 1.0;
        circle.centre = c1 + side * r1 * n;
        circle.radius = 0.0;
    } else {
        result.relation = Sphere_sphere_relation::intersecting;
        const double a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
        circle.centre = c1 + a * n;
        circle.radius = std::sqrt(std::max(0.0, r1 * r1 - a * a));
        result.penetration_depth = std::max({0.0, r2 - std::abs(d - r1), r1 - std::abs(d - r2)});
    }
    result.circle = circle;
    return result;
}

} // namespace PCCD
