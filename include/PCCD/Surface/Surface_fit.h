// PCCD/Surface/Surface_fit.h -- which local shape the implicit surface fits to the weighted
// neighbours of x (doc/manual/surface.md, "The fit: plane or sphere", "Sharp features"): the
// published plane, an algebraic sphere fitted to the points and their oriented normals, which
// follows curvature and so removes the plane's shrinkage on curved parts, or the mean of the
// neighbours' tangent planes (IMLS), which keeps sharp edges; the closed forms of the last two are
// here.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include <PCCD/Surface/surface_options.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// "plane", "sphere" or "imls".
inline const char* to_string(Surface_fit fit)
{
    switch (fit) {
    case Surface_fit::plane: return "plane";
    case Surface_fit::sphere: return "sphere";
    case Surface_fit::imls: return "imls";
    }
    return "unknown";
}

/// The fit to_string() names `name` ("plane", "sphere" or "imls"); nullopt for anything else.
inline std::optional<Surface_fit> surface_fit_from_string(std::string_view name)
{
    for (const auto fit : {Surface_fit::plane, Surface_fit::sphere, Surface_fit::imls})
        if (name == to_string(fit)) return fit;
    return std::nullopt;
}

namespace internal {

/// Sums of the sphere fit over the weighted neighbours that carry a normal, relative to the query
/// point x (offsets y_i = p_i - x): W = sum w_i, s = sum w_i y_i, q = sum w_i |y_i|^2,
/// m = sum w_i n_i, t = sum w_i y_i . n_i.
struct Sphere_sums {
    double weight = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    double squared = 0.0;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    double offset_dot_normal = 0.0;

    void add(const Eigen::Vector3d& offset, double w, const Eigen::Vector3d& n)
    {
        weight += w;
        first += w * offset;
        squared += w * offset.squaredNorm();
        normal += w * n;
        offset_dot_normal += w * offset.dot(n);
    }
};

/// Value and unit gradient of the fitted sphere at x.
struct Sphere_value {
    double value;
    Eigen::Vector3d normal;
};

/// The algebraic sphere s(y) = u0 + u . y + u4 |y|^2 (y = offset from x) fitted in two weighted
/// least-squares stages: u and u4 make the gradient match the normals (minimize
/// sum w_i |u + 2 u4 y_i - n_i|^2), then u0 puts the points on the zero set (minimizes
/// sum w_i s(y_i)^2). In closed form
///   u4 = (t/W - (s/W) . (m/W)) / (2 (q/W - |s/W|^2)),  u = m/W - 2 u4 s/W,  u0 = -u . s/W - u4 q/W.
/// Its signed distance at x (y = 0) is u0 / (|u|/2 + sqrt(|u|^2/4 - u0 u4)), which tends to the
/// plane's u0 / |u| as u4 -> 0 and has no cancellation. nullopt when the positions do not spread
/// (q/W - |s/W|^2 <= 0), when the sphere is imaginary, or when u points against `reference` (the
/// neighbours' normals disagree with the orientation at x).
inline std::optional<Sphere_value> fit_sphere(const Sphere_sums& sums, const Eigen::Vector3d& reference)
{
    if (!(sums.weight > 0.0)) return std::nullopt;
    const double inv = 1.0 / sums.weight;
    const Eigen::Vector3d mean = sums.first * inv;
    const Eigen::Vector3d mean_normal = sums.normal * inv;
    const double spread = sums.squared * inv - mean.squaredNorm();
    if (!(spread > 0.0)) return std::nullopt;
    const double u4 = 0.5 * (sums.offset_dot_normal * inv - mean.dot(mean_normal)) / spread;
    const Eigen::Vector3d u = mean_normal - 2.0 * u4 * mean;
    const double u0 = -u.dot(mean) - u4 * sums.squared * inv;
    const double length = u.norm();
    const double discriminant = 0.25 * length * length - u0 * u4;
    if (!(length > 0.0) || !(discriminant >= 0.0) || !(u.dot(reference) > 0.0)) return std::nullopt;
    const Sphere_value result{u0 / (0.5 * length + std::sqrt(discriminant)), u / length};
    if (!std::isfinite(result.value) || !all_finite(result.normal)) return std::nullopt;
    return result;
}

/// Shortest weighted mean normal |m| / W with which fit_imls() answers: below it the neighbours'
/// normals cancel (a part thinner than the kernel seen from its edge, or misoriented patches), f
/// would be divided by almost nothing and n(x) would be noise.
inline constexpr double imls_min_mean_normal = 0.1;

/// The IMLS value and normal at x from the same sums (Surface_fit::imls): with y_i = p_i - x,
/// f = -t / |m| (t = sum w_i y_i . n_i, m = sum w_i n_i), n = m / |m|. nullopt when |m| / W <
/// imls_min_mean_normal or m points against `reference`.
inline std::optional<Sphere_value> fit_imls(const Sphere_sums& sums, const Eigen::Vector3d& reference)
{
    if (!(sums.weight > 0.0)) return std::nullopt;
    const double length = sums.normal.norm();
    if (!(length >= imls_min_mean_normal * sums.weight) || !(sums.normal.dot(reference) > 0.0)) return std::nullopt;
    const Sphere_value result{-sums.offset_dot_normal / length, sums.normal / length};
    if (!std::isfinite(result.value) || !all_finite(result.normal)) return std::nullopt;
    return result;
}

} // namespace internal
} // namespace PCCD
