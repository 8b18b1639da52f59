// PCCD/testing/scenes/Deforming_cloud_scene.h -- a deforming point cloud for the kinetic AABB tree
// (doc/manual/kinetic.md, "Scenes"; the tree over Kinetic_point primitives of "Building and
// advancing"): a shape that twists about its vertical axis and breathes (scales periodically),
// recorded as key frames. The shape is the vertex set of an OFF mesh read by
// PCCD::IO::read_triangle_mesh (e.g. CGAL's bunny00.off) or, without a file, a procedural bumpy
// sphere. Not library code (target PCCD::testing, with CGAL::CGAL linked for the reader; never
// installed).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Random.h>

#include <PCCD/testing/scenes/Kinetic_scene.h>

namespace PCCD::testing {

/// Options of make_deforming_cloud_scene.
struct Deforming_cloud_options {
    /// OFF file of a triangle mesh whose vertices (all of them, in file order; the faces are
    /// ignored) form the cloud; "" (default) uses the procedural bumpy sphere.
    std::string off_file = "";
    /// Number of points: a random subset of the file's vertices (all when 0 or larger than the file),
    /// or the size of the procedural cloud (0 means 2000); default 0.
    std::size_t points = 0;
    /// Animation length in seconds; default 2.
    double duration = 2.0;
    /// Key frames per second; default 60.
    double key_rate = 60.0;
    /// Twist at the top of the shape relative to its bottom at full amplitude, in radians; default 1.2.
    double twist = 1.2;
    /// Relative amplitude of the breathing (uniform scaling 1 + a sin(2 pi f t)); default 0.15.
    double breathing = 0.15;
    /// Breathing and twisting frequency in Hz; default 1.
    double frequency = 1.0;
    /// Seed of the subset choice and of the procedural shape; default 1.
    std::uint64_t seed = 1;
};

namespace detail {

/// n points on a sphere of radius 1 with smooth radial bumps (Fibonacci spiral + random jitter).
inline std::vector<Eigen::Vector3d> bumpy_sphere(std::size_t n, Random_engine& rng)
{
    std::vector<Eigen::Vector3d> points(n);
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (double(i) + uniform_01(rng)) / double(n);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = golden * double(i) + 0.1 * uniform_01(rng);
        const Eigen::Vector3d d(r * std::cos(phi), r * std::sin(phi), z);
        const double bump = 1.0 + 0.15 * std::sin(3.0 * d.x()) * std::cos(4.0 * d.y()) + 0.1 * d.z() * d.z();
        points[i] = bump * d;
    }
    return points;
}

} // namespace detail

/// A point cloud that twists and breathes, recorded as key frames (Kinetic_point primitives).
/// The shape is centred and scaled to height 2; the twist angle grows linearly with height and
/// oscillates in time, so the extreme points change many times along every axis.
/// \throws File_error if `off_file` is given but unusable (with read_triangle_mesh's messages);
///         Invalid_input for non-positive duration, key rate or frequency.
inline Kinetic_scene<Kinetic_point> make_deforming_cloud_scene(const Deforming_cloud_options& o = {})
{
    if (!std::isgreater(o.duration, 0.0) || !std::isgreater(o.key_rate, 0.0) || !std::isgreater(o.frequency, 0.0))
        throw Invalid_input(internal::concat("make_deforming_cloud_scene: duration ", o.duration, ", key_rate ",
                                             o.key_rate, " and frequency ", o.frequency, " must be > 0"));
    Random_engine rng(o.seed);
    std::vector<Eigen::Vector3d> shape;
    Kinetic_scene<Kinetic_point> scene;
    if (o.off_file.empty()) {
        shape = detail::bumpy_sphere(o.points == 0 ? 2000 : o.points, rng);
        scene.name = "bumpy sphere";
    } else {
        shape = IO::read_triangle_mesh(o.off_file, IO::Format::off).vertices;
        if (o.points > 0 && o.points < shape.size()) {
            for (std::size_t i = 0; i < o.points; ++i)
                std::swap(shape[i], shape[i + std::size_t(uniform_index(rng, shape.size() - i))]);
            shape.resize(o.points);
        }
        scene.name = "bunny";
    }
    Eigen::Vector3d lo = shape.front(), hi = shape.front();
    for (const auto& p : shape) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    // The longest side becomes the vertical (twist) axis z, scaled to length 2.
    int up = 0;
    (hi - lo).maxCoeff(&up);
    const double scale = 2.0 / std::max((hi - lo)[up], 1e-300);
    for (auto& p : shape) {
        Eigen::Vector3d q = (p - centre) * scale;
        if (up != 2) std::swap(q[up], q[2]);
        p = q;
    }

    const double key_dt = 1.0 / o.key_rate;
    const auto keys = std::size_t(std::ceil(o.duration * o.key_rate - 1e-9)) + 1;
    auto times = std::make_shared<std::vector<double>>(keys);
    std::vector<std::vector<Eigen::Vector3d>> key_positions(shape.size(), std::vector<Eigen::Vector3d>(keys));
    for (std::size_t k = 0; k < keys; ++k) {
        const double t = double(k) * key_dt;
        (*times)[k] = t;
        const double phase = 2.0 * std::numbers::pi * o.frequency * t;
        const double s = 1.0 + o.breathing * std::sin(phase);
        const double twist = o.twist * std::sin(0.5 * phase);
        for (std::size_t i = 0; i < shape.size(); ++i) {
            const Eigen::Vector3d& p = shape[i];
            const double a = twist * 0.5 * (p.z() + 1.0);
            const double c = std::cos(a), sn = std::sin(a);
            key_positions[i][k] = s * Eigen::Vector3d(c * p.x() - sn * p.y(), sn * p.x() + c * p.y(), p.z());
        }
    }
    scene.start_time = 0.0;
    scene.end_time = times->back();
    const Piecewise_linear_flightplan::Key_times shared = times;
    for (std::size_t i = 0; i < shape.size(); ++i) {
        scene.flightplans.emplace_back(shared, std::move(key_positions[i]));
        scene.primitives.push_back({std::uint32_t(i)});
    }
    return scene;
}

} // namespace PCCD::testing
