// PCCD/sample_triangle_mesh.h -- uniform (area-weighted) random points on a triangle mesh given as
// a vertex range and index triples, with each sample's triangle normal and triangle index, and the
// sampling options (optional Gaussian noise): how PCCD turns the scanned meshes of the benchmarks
// (doc/algorithms.md, "Benchmark procedure") into point clouds, and how a user turns a mesh into a
// test cloud.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <ranges>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Point_traits.h>
#include <PCCD/Random.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// Options of the surface samplers (sample_triangle_mesh).
struct Sample_options {
    /// Standard deviation of the isotropic Gaussian noise added to each sampled point: every
    /// coordinate gets an independent N(0, noise_sigma^2) offset (length unit of the shape).
    /// Normals are not perturbed: they stay the exact normals at the noise-free point.
    /// Default 0 (points exactly on the surface). Must be finite and >= 0.
    double noise_sigma = 0.0;
};

/// A sample of N points of a triangle mesh: column i of `points` is point i, column i of `normals`
/// the unit normal of the triangle it was drawn from (right-hand rule on the triangle's vertex order),
/// and `triangles[i]` that triangle's position in the input range.
struct Triangle_mesh_sample {
    Eigen::Matrix3Xd points;
    Eigen::Matrix3Xd normals;
    std::vector<std::size_t> triangles;
};

namespace internal {

inline void check_sample_options(const Sample_options& options)
{
    if (!(std::isfinite(options.noise_sigma) && options.noise_sigma >= 0.0))
        throw Invalid_input(concat("sample options: noise_sigma is ", options.noise_sigma,
                                   "; it must be finite and >= 0"));
}

/// Adds N(0, sigma^2) to every coordinate, column after column. Draws nothing when sigma is 0, so the
/// noise-free positions of a sample do not depend on sigma for a given seed.
inline void add_gaussian_noise(Eigen::Matrix3Xd& points, double sigma, Random_engine& engine)
{
    if (sigma == 0.0) return;
    for (Eigen::Index i = 0; i < points.cols(); ++i)
        for (int k = 0; k < 3; ++k) points(k, i) += sigma * standard_normal(engine);
}

/// Concept helper: a face given as a sized range of integral vertex indices (std::array<int, 3>,
/// std::vector<std::size_t> as in CGAL's polygon soups, ...). Its size must be 3 at run time.
template <class F>
concept Index_range = std::ranges::sized_range<F> && std::integral<std::ranges::range_value_t<F>>;

} // namespace internal

/// Draws `n` points uniformly by area from the union of the mesh's triangles.
///
/// A triangle is chosen with probability proportional to its area (cumulative-area table and
/// binary search), then a point uniformly inside it (a + sqrt(u1) ((1 - u2)(b - a) + u2 (c - a))).
/// Degenerate triangles (zero area: repeated or collinear vertices) are never chosen. The mesh need
/// not be closed, manifold or consistently oriented. Noise as in Sample_options, added after all
/// points are drawn (so for one seed the noise-free positions do not depend on `noise_sigma`).
///
/// \tparam Vertices an input range of points modelling Point3 (Eigen::Vector3d, CGAL::Point_3,
///         std::array<double, 3>, ...).
/// \tparam Triangles an input range of faces, each a sized range of 3 integral vertex indices.
/// \throws Invalid_input if a vertex is not finite, a face does not have 3 vertices, an index is
///         negative or not below the number of vertices, the mesh has no triangle, every triangle is
///         degenerate, or the options are invalid. The message names the vertex or face.
/// Complexity: O(V + T + n log T) time, O(V + T) extra memory. Deterministic for a given engine
/// state. Thread safety: reads its inputs only; concurrent calls need distinct engines.
template <std::ranges::input_range Vertices, std::ranges::input_range Triangles>
    requires Point3<std::ranges::range_value_t<Vertices>> &&
             internal::Index_range<std::ranges::range_value_t<Triangles>>
Triangle_mesh_sample sample_triangle_mesh(const Vertices& vertices, const Triangles& triangles, std::size_t n,
                                          Random_engine& engine, const Sample_options& options = {})
{
    using Point = std::ranges::range_value_t<Vertices>;
    internal::check_sample_options(options);

    std::vector<Eigen::Vector3d> positions;
    for (const Point& p : vertices) {
        const Eigen::Vector3d v(double(Point_traits<Point>::x(p)), double(Point_traits<Point>::y(p)),
                                double(Point_traits<Point>::z(p)));
        if (!internal::all_finite(v))
            throw Invalid_input(internal::concat("mesh vertex ", positions.size(), " (", v.x(), ", ", v.y(), ", ",
                                                 v.z(), ") is not finite"));
        positions.push_back(v);
    }

    std::vector<std::array<std::size_t, 3>> corners;
    std::vector<Eigen::Vector3d> normals;
    std::vector<double> cumulative_area; // cumulative_area[k] = area of triangles 0..k
    double total_area = 0.0;
    for (const auto& face : triangles) {
        const std::size_t k = corners.size();
        if (std::ranges::size(face) != 3)
            throw Invalid_input(internal::concat("mesh face ", k, " has ", std::ranges::size(face),
                                                 " vertices; only triangles can be sampled"));
        std::array<std::size_t, 3> c{};
        std::size_t j = 0;
        for (const auto index : face) {
            if (std::cmp_less(index, 0) || std::cmp_greater_equal(index, positions.size()))
                throw Invalid_input(internal::concat("mesh face ", k, " refers to vertex ", index, "; the mesh has ",
                                                     positions.size(), " vertices"));
            c[j++] = std::size_t(index);
        }
        const Eigen::Vector3d cross =
            (positions[c[1]] - positions[c[0]]).cross(positions[c[2]] - positions[c[0]]);
        const double twice_area = cross.norm();
        corners.push_back(c);
        normals.push_back(twice_area > 0.0 ? Eigen::Vector3d(cross / twice_area) : Eigen::Vector3d::Zero());
        total_area += 0.5 * twice_area;
        cumulative_area.push_back(total_area);
    }
    if (corners.empty()) throw Invalid_input("mesh has no triangles");
    if (!(total_area > 0.0))
        throw Invalid_input(internal::concat("all ", corners.size(), " mesh triangles are degenerate (zero area)"));

    Triangle_mesh_sample sample{Eigen::Matrix3Xd(3, Eigen::Index(n)), Eigen::Matrix3Xd(3, Eigen::Index(n)), {}};
    sample.triangles.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        // u < total_area (uniform_01 < 1), so triangle k with cumulative_area[k-1] <= u <
        // cumulative_area[k] is found; a zero-area triangle owns an empty interval. Searching all but
        // the last entry returns the last triangle when u lies beyond the others.
        const double u = uniform_01(engine) * total_area;
        const std::size_t k =
            std::size_t(std::upper_bound(cumulative_area.begin(), cumulative_area.end() - 1, u) - cumulative_area.begin());
        const double s = std::sqrt(uniform_01(engine));
        const double t = uniform_01(engine);
        const Eigen::Vector3d& a = positions[corners[k][0]];
        const Eigen::Vector3d& b = positions[corners[k][1]];
        const Eigen::Vector3d& c = positions[corners[k][2]];
        sample.points.col(Eigen::Index(i)) = a + s * ((1.0 - t) * (b - a) + t * (c - a));
        sample.normals.col(Eigen::Index(i)) = normals[k];
        sample.triangles[i] = k;
    }
    internal::add_gaussian_noise(sample.points, options.noise_sigma, engine);
    return sample;
}

} // namespace PCCD
