// PCCD/testing/scenes/Bunny_contact_scene.h -- the deforming contact scene of `pccd kinetic-bench
// --scene bunny-contact`, the deforming-cloud tests and examples/deforming_contact.cpp
// (doc/manual/kinetic.md, "Deforming point clouds"): a cloud area-sampled from a mesh (CGAL's
// bunny00.off, or a procedural bumpy sphere without it) twists about its vertical axis, breathes
// (scales periodically) and sways sideways into and out of a rigid sphere cloud, so that contact
// switches on and off. The exact verdict of every frame comes from the mesh deformed by the same
// map against the analytic sphere. Not library code (testing/, target PCCD::testing; never installed).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Surface_sample.h>
#include <PCCD/sample_triangle_mesh.h>

namespace PCCD::testing {

/// Options of make_bunny_contact_scene.
struct Bunny_contact_options {
    /// OFF file of the deforming shape (e.g. bunny00.off); "" uses a procedural bumpy sphere mesh.
    std::string off_file = "";
    /// Points sampled (by area) on the shape; default 5000.
    std::size_t points = 5000;
    /// Points sampled on the obstacle sphere; default 2000.
    std::size_t obstacle_points = 2000;
    /// Animation length in seconds (>= 0; 0 is one frame); default 4.
    double duration = 4.0;
    /// Frames per second; default 30.
    double frame_rate = 30.0;
    /// Twist of the top relative to the bottom at full amplitude, radians; default 0.5.
    double twist = 0.5;
    /// Relative amplitude of the breathing (scale 1 + a sin(2 pi f t)); default 0.08.
    double breathing = 0.08;
    /// Frequency of twist and breathing in Hz; default 1.
    double frequency = 1.0;
    /// Sideways sway x(t) = sway sin(2 pi sway_frequency t), towards the obstacle at +x; default 0.35.
    double sway = 0.35;
    /// Default 0.5 Hz (two strokes in 4 s).
    double sway_frequency = 0.5;
    /// Seed of both samples; default 1.
    std::uint64_t seed = 1;
};

/// Whether the deformed shape's surface meets the obstacle sphere at one frame, exactly (mesh
/// against the analytic sphere).
struct Contact_truth {
    /// Smallest and largest distance from the sphere's centre to the deformed mesh.
    double min_distance = 0.0;
    double max_distance = 0.0;
    /// The surfaces meet iff min_distance <= radius <= max_distance (the mesh is connected).
    bool intersecting = false;
    /// |min_distance - radius| or |max_distance - radius|, whichever is smaller: how far the frame
    /// is from a change of verdict.
    double margin = 0.0;
};

/// The deforming shape (mesh and cloud at rest), its motion and the rigid obstacle.
struct Bunny_contact_scene {
    std::string name;
    /// The rest mesh, centred, its longest side along z scaled to 2 (z in [-1, 1]).
    std::vector<Eigen::Vector3d> mesh_vertices;
    std::vector<std::array<std::uint32_t, 3>> mesh_triangles;
    /// The rest cloud: `points` area samples of the rest mesh.
    Eigen::Matrix3Xd rest_points;
    /// The obstacle and its sample (rigid, world frame).
    Sphere_shape obstacle{Eigen::Vector3d(1.35, 0.0, 0.0), 0.45};
    Eigen::Matrix3Xd obstacle_points;
    Bunny_contact_options options;

    std::size_t frames() const { return std::size_t(std::floor(options.duration * options.frame_rate + 1e-9)) + 1; }
    double time_of(std::size_t frame) const { return double(frame) / options.frame_rate; }

    /// The motion of a rest point: twist about z growing with height, breathing about the origin,
    /// then the sway along x.
    Eigen::Vector3d deform(const Eigen::Vector3d& p, double t) const
    {
        const Bunny_contact_options& o = options;
        const double phase = 2.0 * std::numbers::pi * o.frequency * t;
        const double s = 1.0 + o.breathing * std::sin(phase);
        const double a = o.twist * std::sin(0.5 * phase) * 0.5 * (p.z() + 1.0);
        const double c = std::cos(a), sn = std::sin(a);
        const double sway = o.sway * std::sin(2.0 * std::numbers::pi * o.sway_frequency * t);
        return s * Eigen::Vector3d(c * p.x() - sn * p.y(), sn * p.x() + c * p.y(), p.z()) +
               Eigen::Vector3d(sway, 0.0, 0.0);
    }

    /// The cloud at time t (column i: rest point i moved).
    Eigen::Matrix3Xd points_at(double t) const
    {
        Eigen::Matrix3Xd out(3, rest_points.cols());
        for (Eigen::Index i = 0; i < rest_points.cols(); ++i) out.col(i) = deform(rest_points.col(i), t);
        return out;
    }

    /// The exact verdict at time t (brute force over the deformed mesh's triangles).
    Contact_truth truth_at(double t) const
    {
        std::vector<Eigen::Vector3d> moved(mesh_vertices.size());
        for (std::size_t v = 0; v < moved.size(); ++v) moved[v] = deform(mesh_vertices[v], t);
        const Eigen::Vector3d c = obstacle.centre();
        Contact_truth truth;
        truth.min_distance = std::numeric_limits<double>::infinity();
        for (const auto& v : moved) truth.max_distance = std::max(truth.max_distance, (v - c).norm());
        for (const auto& f : mesh_triangles)
            truth.min_distance = std::min(truth.min_distance, distance_to_triangle(c, moved[f[0]], moved[f[1]], moved[f[2]]));
        const double r = obstacle.radius();
        truth.intersecting = truth.min_distance <= r && r <= truth.max_distance;
        truth.margin = std::min(std::abs(truth.min_distance - r), std::abs(truth.max_distance - r));
        return truth;
    }

    /// Distance from x to the triangle (a, b, c): the nearest point is found in the Voronoi region
    /// of the face, an edge or a vertex. A degenerate triangle falls back to its edges.
    static double distance_to_triangle(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c)
    {
        const Eigen::Vector3d n = (b - a).cross(c - a);
        const double nn = n.squaredNorm();
        if (nn > 0.0) {
            // Inside the prism over the face iff x projects inside every edge.
            const Eigen::Vector3d y = x - (n.dot(x - a) / nn) * n;
            if (n.dot((b - a).cross(y - a)) >= 0.0 && n.dot((c - b).cross(y - b)) >= 0.0 &&
                n.dot((a - c).cross(y - c)) >= 0.0)
                return (x - y).norm();
        }
        return std::min({distance_to_segment(x, a, b), distance_to_segment(x, b, c), distance_to_segment(x, c, a)});
    }

    static double distance_to_segment(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
    {
        const Eigen::Vector3d d = b - a;
        const double dd = d.squaredNorm();
        const double s = dd > 0.0 ? std::clamp(d.dot(x - a) / dd, 0.0, 1.0) : 0.0;
        return (x - (a + s * d)).norm();
    }
};

namespace detail {

/// A closed lat-long mesh of a bumpy sphere (radius 1 modulated by smooth bumps), `rings` x
/// `sectors` quads split into triangles, with one vertex at each pole.
inline void bumpy_sphere_mesh(std::size_t rings, std::size_t sectors, std::vector<Eigen::Vector3d>& vertices,
                              std::vector<std::array<std::uint32_t, 3>>& triangles)
{
    const auto radial = [](const Eigen::Vector3d& d) {
        return (1.0 + 0.15 * std::sin(3.0 * d.x()) * std::cos(4.0 * d.y()) + 0.1 * d.z() * d.z()) * d;
    };
    vertices.clear();
    triangles.clear();
    vertices.push_back(radial(Eigen::Vector3d(0, 0, 1)));
    for (std::size_t r = 1; r < rings; ++r) {
        const double theta = std::numbers::pi * double(r) / double(rings);
        for (std::size_t s = 0; s < sectors; ++s) {
            const double phi = 2.0 * std::numbers::pi * double(s) / double(sectors);
            vertices.push_back(radial(Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                                      std::cos(theta))));
        }
    }
    vertices.push_back(radial(Eigen::Vector3d(0, 0, -1)));
    const auto ring = [&](std::size_t r, std::size_t s) { return std::uint32_t(1 + (r - 1) * sectors + s % sectors); };
    const auto south = std::uint32_t(vertices.size() - 1);
    for (std::size_t s = 0; s < sectors; ++s) {
        triangles.push_back({0, ring(1, s), ring(1, s + 1)});
        for (std::size_t r = 1; r + 1 < rings; ++r) {
            triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
            triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
        }
        triangles.push_back({ring(rings - 1, s), south, ring(rings - 1, s + 1)});
    }
}

} // namespace detail

/// Builds the scene.
/// \throws File_error if `off_file` is given but unusable; Invalid_input for a negative duration, a
///         frame rate or frequency that is not > 0, or fewer than 100 points on either cloud.
inline Bunny_contact_scene make_bunny_contact_scene(const Bunny_contact_options& o = {})
{
    if (!(std::isfinite(o.duration) && o.duration >= 0.0) || !std::isgreater(o.frame_rate, 0.0) ||
        !std::isgreater(o.frequency, 0.0) ||
        !std::isgreater(o.sway_frequency, 0.0))
        throw Invalid_input(internal::concat("make_bunny_contact_scene: duration ", o.duration, " must be >= 0, frame_rate ",
                                             o.frame_rate, " and the frequencies > 0"));
    if (o.points < 100 || o.obstacle_points < 100)
        throw Invalid_input("make_bunny_contact_scene: both clouds need at least 100 points");
    Bunny_contact_scene scene;
    scene.options = o;
    if (o.off_file.empty()) {
        detail::bumpy_sphere_mesh(48, 96, scene.mesh_vertices, scene.mesh_triangles);
        scene.name = "bumpy sphere contact";
    } else {
        auto mesh = IO::read_triangle_mesh(o.off_file, IO::Format::off);
        scene.mesh_vertices = std::move(mesh.vertices);
        scene.mesh_triangles = std::move(mesh.triangles);
        scene.name = "bunny contact";
    }
    auto& shape = scene.mesh_vertices;
    Eigen::Vector3d lo = shape.front(), hi = shape.front();
    for (const auto& p : shape) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    int up = 0;
    (hi - lo).maxCoeff(&up);
    const double scale = 2.0 / std::max((hi - lo)[up], 1e-300);
    for (auto& p : shape) {
        Eigen::Vector3d q = (p - centre) * scale;
        if (up != 2) std::swap(q[up], q[2]);
        p = q;
    }
    Random_engine engine(o.seed);
    scene.rest_points = sample_triangle_mesh(scene.mesh_vertices, scene.mesh_triangles, o.points, engine).points;
    Random_engine obstacle_engine(o.seed + 1);
    scene.obstacle_points = scene.obstacle.sample(o.obstacle_points, obstacle_engine).points;
    return scene;
}

} // namespace PCCD::testing
