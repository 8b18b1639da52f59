// PCCD/testing/scenes/Tunnel_scene.h -- the scanned-tunnel clearance scene of benchmark/
// tunnel_clearance_benchmark.cpp (doc/benchmarks.md, "Clearance through a scanned tunnel"): the rail
// clearance (gauge) check of a wagon scan moved through a tunnel scan with a safety margin of a
// few centimetres. Everything is built as a triangle mesh first (the exact truth) and then sampled
// by area as a scanner would see it: the tunnel with Gaussian noise, clutter on the walls (cables,
// signal boxes), occlusion holes and a few outliers; the wagon with noise; and a path of rigid
// poses of the wagon along the tunnel's centre line, some of them pushed toward the wall on purpose
// so that the wagon comes closer than the margin. Lengths in metres; all parameters are fields of
// Tunnel_scene_options with their defaults; fixed seeds. write_tunnel_scene() puts the clouds
// (binary PLY), the meshes (OFF) and the poses (CSV) into a folder for the `pccd` tool.
// Not library code (testing/, target PCCD::testing; never installed). The writer needs CGAL.
//
// Geometry (defaults; world frame: z up, the track bed is the plane z = 0):
// - Centre line: a circular arc in the plane z = 0 of radius curve_radius (300 m), starting at the
//   origin heading +x and curving left, tunnel_length (50 m) long; c(s) = (Rc sin(s/Rc),
//   Rc (1 - cos(s/Rc)), 0), tangent t(s), left normal n(s) = e_z x t(s).
// - Cross-section (coordinates u along n, z up): a horseshoe, the circle of radius tunnel_radius
//   (3 m) about (0, vault_centre_height = 1.5 m) above the chord z = 0 (the flat track bed, 5.20 m
//   wide), the vault reaching z = 4.5 m. Swept along the arc in rings every ring_spacing (0.25 m);
//   the vault has vault_segments (160) edges over its 240 degrees, so the polygon lies within 0.3
//   mm of the circle. The tube is open at both ends.
// - Rails: two open box strips (sides and top; 0.07 m wide, 0.17 m high) on the bed, centred at
//   u = +-(gauge + rail width)/2 (standard gauge 1.435 m), swept with the tube.
// - Clutter: `cables` cables (open tubes of radius 0.04 m, 12-gons) along the walls at 0.9-1.35 m,
//   3 cm off the wall; `signals` signal boxes (0.3 x 0.2 x 0.4 m, closed) on the walls at 2.0-2.4
//   m, 3 cm off the wall, evenly spaced along the tunnel, on alternating sides.
// - Occlusion holes: `holes` rectangles of the walls in (s, z), hole_length (1.5 m) along the
//   tunnel by hole_height (0.8 m), at random s and at heights in [0.4, 2.2] m of a random side,
//   whose samples are dropped (the mesh keeps them: the truth is the real wall).
// - Outliers: `outliers` (20) points, each a wall point below 2.5 m moved along the wall's normal
//   by 0.1-0.5 m to either side (mixed returns; kept out of the vault, where the wagon passes, so
//   that no outlier lies in the wagon's path: cleaning a path is a scan-preparation matter).
// - Wagon (its frame: x along the track, y to the left, z up, origin on the bed below its centre):
//   a body 16 m long, 3.0 m wide, from z = 1.25 m to the eaves at 3.7 m, a circular roof rising to
//   4.0 m in the middle; two bogies at x = +-5 m, each two side beams (2.8 x 0.14 x 0.35 m) and
//   four wheels (radius 0.42 m, 0.14 m wide) lifted 0.2 m off the rails (the gauge check concerns
//   the body and the roof equipment: wheel-rail contact would set every clearance to 0); a
//   pantograph in the middle of the roof: a base frame, one arm (a 4 cm square bar) and the pan
//   head, a bar 1.6 m long, 0.1 m wide and 0.06 m thick with its top at 4.27 m. Its outer top
//   edge is the wagon's closest point to the vault: 0.117 m on the centre line.
// - Noise: isotropic Gaussian, sigma = noise * sqrt(area / points) (the nominal spacing; the mean
//   nearest-neighbour distance of a uniform sample is about half of it), for each cloud.
// - Path: `poses` poses with the wagon's centre at s from 10 m to 40 m (its ends stay 2 m inside
//   the tube), tangent-aligned (rotation [t(s) n(s) e_z]), moved sideways by a hunting sway
//   sway_amplitude sin(2 pi s / sway_wavelength) (4 cm, 7.3 m); every offset_every-th pose (6;
//   poses 3, 9, 15, ...) is moved sideways instead by the offset that puts the pan head's outer top
//   edge at a target clearance from the vault circle, offset_clearances in turn (1, 2.5, 4 and 7
//   cm) on alternating sides: the first three below the 5 cm margin, the last just above. The
//   vault polygon lies inside the circle, so the exact clearance is at most the target.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/IO/write_points.h>
#include <PCCD/IO/write_triangle_mesh.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/sample_triangle_mesh.h>

namespace PCCD::testing {

/// Parameters of make_tunnel_scene (lengths in metres). See the header comment for the layout.
struct Tunnel_scene_options {
    /// Points of the tunnel cloud (outliers included), >= 1000. Default 10^6.
    std::size_t scene_points = 1'000'000;
    /// Points of the wagon cloud, >= 1000. Default 10^5.
    std::size_t wagon_points = 100'000;
    /// Poses of the path, >= 2. Default 60.
    std::size_t poses = 60;
    /// Length of the tunnel along its centre line; default 50 m (>= wagon_length + 8).
    double tunnel_length = 50.0;
    /// Radius of the centre line (a circular arc curving left); default 300 m (>= 50).
    double curve_radius = 300.0;
    /// Radius of the vault; default 3 m.
    double tunnel_radius = 3.0;
    /// Height of the vault's centre above the track bed; default 1.5 m (in (0, tunnel_radius)).
    double vault_centre_height = 1.5;
    /// Edges of the vault polygon (240 degrees of the circle); default 160.
    std::size_t vault_segments = 160;
    /// Distance between the rings of the sweep along the centre line; default 0.25 m.
    double ring_spacing = 0.25;
    /// Rail gauge (inner distance between the rails), rail width and height; defaults 1.435, 0.07, 0.17 m.
    double gauge = 1.435;
    double rail_width = 0.07;
    double rail_height = 0.17;
    /// Cables along the walls (0 .. 4); default 3.
    std::size_t cables = 3;
    /// Signal boxes on the walls; default 4.
    std::size_t signals = 4;
    /// Occlusion holes in the walls; default 6, each hole_length along the tunnel by hole_height.
    std::size_t holes = 6;
    double hole_length = 1.5;
    double hole_height = 0.8;
    /// Outliers of the tunnel cloud; default 20, moved 0.1 .. 0.5 m off the wall.
    std::size_t outliers = 20;
    double outlier_min_offset = 0.1;
    double outlier_max_offset = 0.5;
    /// Gaussian noise of both clouds: sigma = noise * sqrt(area / points); default 0.1 (>= 0).
    double noise = 0.1;
    /// Wagon body: length and width; defaults 16 m and 3 m.
    double wagon_length = 16.0;
    double wagon_width = 3.0;
    /// Sideways hunting sway of the path: amplitude and wavelength; defaults 0.04 m and 7.3 m.
    double sway_amplitude = 0.04;
    double sway_wavelength = 7.3;
    /// Every offset_every-th pose (indices offset_every/2, +offset_every, ...) is pushed toward the
    /// wall; default 6 (0: none).
    std::size_t offset_every = 6;
    /// The target clearances of those poses (pan head to the vault circle), used in turn; default
    /// 1, 2.5, 4 and 7 cm. Each must be in (0, the centred clearance).
    std::vector<double> offset_clearances = {0.01, 0.025, 0.04, 0.07};
    /// Seed of the samples, holes and outliers; default 1. The wagon's cloud is drawn from an engine
    /// of its own (seed + 0x5741474f4e), so it is the same whatever the tunnel's options.
    std::uint64_t seed = 1;
};

/// A wall patch in the tunnel's coordinates whose samples are dropped: s (arc length) in
/// [s_begin, s_end], z in [z_begin, z_end], on the side `side` (+1 left, -1 right).
struct Tunnel_hole {
    double s_begin, s_end, z_begin, z_end;
    int side;
};

/// One pose of the wagon on the path.
struct Tunnel_pose {
    /// Wagon frame to world: rotation [t(s) n(s) e_z], translation c(s) + lateral n(s).
    Rigid_transform_3<double> pose;
    /// Arc length of the wagon's centre and its sideways offset (left positive).
    double s = 0.0;
    double lateral = 0.0;
    /// Whether the pose was pushed toward the wall on purpose, and to which clearance of the pan
    /// head from the vault circle (NaN when not).
    bool deliberate = false;
    double target_clearance = std::numeric_limits<double>::quiet_NaN();
};

/// The scene: meshes, clouds and path.
struct Tunnel_scene {
    Tunnel_scene_options options;
    /// The tunnel (tube, rails, cables, signal boxes) in world coordinates, and the wagon in its frame.
    Triangle_mesh_data tunnel_mesh;
    Triangle_mesh_data wagon_mesh;
    /// The triangles of tunnel_mesh that belong to the tube's walls (the vault; not the bed):
    /// [0, wall_triangles) of tunnel_mesh.triangles.
    std::size_t wall_triangles = 0;
    /// The clouds: tunnel (world) and wagon (wagon frame), 3 x N.
    Eigen::Matrix3Xd tunnel_points;
    Eigen::Matrix3Xd wagon_points;
    /// The columns of tunnel_points that are outliers (the last `outliers` columns).
    std::size_t first_outlier = 0;
    /// Noise of the two clouds (metres) and their nominal spacings sqrt(area / points).
    double tunnel_sigma = 0.0, wagon_sigma = 0.0;
    double tunnel_nominal_spacing = 0.0, wagon_nominal_spacing = 0.0;
    /// Surface areas of the two meshes (m^2).
    double tunnel_area = 0.0, wagon_area = 0.0;
    std::vector<Tunnel_hole> holes;
    std::vector<Tunnel_pose> path;

    /// The centre line at arc length s, its unit tangent and left normal (z = 0).
    Eigen::Vector3d centre(double s) const
    {
        const double a = s / options.curve_radius;
        return {options.curve_radius * std::sin(a), options.curve_radius * (1.0 - std::cos(a)), 0.0};
    }
    Eigen::Vector3d tangent(double s) const
    {
        const double a = s / options.curve_radius;
        return {std::cos(a), std::sin(a), 0.0};
    }
    Eigen::Vector3d normal(double s) const
    {
        const double a = s / options.curve_radius;
        return {-std::sin(a), std::cos(a), 0.0};
    }
};

namespace tunnel_detail {

using Mesh = Triangle_mesh_data;

inline std::uint32_t add_vertex(Mesh& m, const Eigen::Vector3d& p)
{
    m.vertices.push_back(p);
    return std::uint32_t(m.vertices.size() - 1);
}

inline void add_quad(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d)
{
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
}

/// Sweeps a polyline profile (closed or open) through `frames` (each maps the profile's (u, z) to
/// a point): a strip of quads between consecutive frames. Returns the index of the first vertex.
template <class Map>
std::uint32_t sweep(Mesh& m, const std::vector<Eigen::Vector2d>& profile, bool closed, std::size_t frames, const Map& map)
{
    const std::uint32_t first = std::uint32_t(m.vertices.size());
    const std::size_t p = profile.size();
    for (std::size_t k = 0; k < frames; ++k)
        for (const Eigen::Vector2d& q : profile) add_vertex(m, map(k, q));
    const std::size_t edges = closed ? p : p - 1;
    for (std::size_t k = 0; k + 1 < frames; ++k)
        for (std::size_t j = 0; j < edges; ++j) {
            const auto v = [&](std::size_t kk, std::size_t jj) { return std::uint32_t(first + kk * p + jj % p); };
            add_quad(m, v(k, j), v(k + 1, j), v(k + 1, j + 1), v(k, j + 1));
        }
    return first;
}

/// Closes a ring of `count` vertices starting at `first` by a fan from their centroid (convex rings).
inline void cap(Mesh& m, std::uint32_t first, std::size_t count, bool flip)
{
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (std::size_t j = 0; j < count; ++j) c += m.vertices[first + j];
    const std::uint32_t centre = add_vertex(m, c / double(count));
    for (std::size_t j = 0; j < count; ++j) {
        const std::uint32_t a = std::uint32_t(first + j), b = std::uint32_t(first + (j + 1) % count);
        if (flip) m.triangles.push_back({centre, b, a});
        else m.triangles.push_back({centre, a, b});
    }
}

/// A closed box: centre, three orthonormal axes (columns of `axes`) and half extents.
inline void add_box(Mesh& m, const Eigen::Vector3d& centre, const Eigen::Matrix3d& axes, const Eigen::Vector3d& half)
{
    const std::uint32_t first = std::uint32_t(m.vertices.size());
    for (int i = 0; i < 8; ++i) {
        const Eigen::Vector3d sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
        add_vertex(m, centre + axes * sign.cwiseProduct(half));
    }
    const auto v = [&](int i) { return std::uint32_t(first + i); };
    add_quad(m, v(0), v(2), v(3), v(1)); // -z
    add_quad(m, v(4), v(5), v(7), v(6)); // +z
    add_quad(m, v(0), v(1), v(5), v(4)); // -y
    add_quad(m, v(2), v(6), v(7), v(3)); // +y
    add_quad(m, v(0), v(4), v(6), v(2)); // -x
    add_quad(m, v(1), v(3), v(7), v(5)); // +x
}

/// A box along the segment from a to b with a square cross-section of side `side`.
inline void add_bar(Mesh& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double side)
{
    const Eigen::Vector3d x = (b - a).normalized();
    const Eigen::Vector3d y = Eigen::Vector3d::UnitY().cross(x).norm() > 1e-6 ? Eigen::Vector3d(Eigen::Vector3d::UnitY())
                                                                               : Eigen::Vector3d(Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d z = x.cross(y).normalized();
    Eigen::Matrix3d axes;
    axes << x, z.cross(x), z;
    add_box(m, 0.5 * (a + b), axes, Eigen::Vector3d(0.5 * (b - a).norm(), 0.5 * side, 0.5 * side));
}

/// A closed cylinder (24-gon, capped) with its axis along y, centre c, radius r, half width h.
inline void add_wheel(Mesh& m, const Eigen::Vector3d& c, double r, double h)
{
    std::vector<Eigen::Vector2d> circle;
    for (int j = 0; j < 24; ++j) {
        const double a = 2.0 * std::numbers::pi * j / 24.0;
        circle.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    const std::uint32_t first = sweep(m, circle, true, 2, [&](std::size_t k, const Eigen::Vector2d& q) {
        return Eigen::Vector3d(c.x() + q.x(), c.y() + (k == 0 ? -h : h), c.z() + q.y());
    });
    cap(m, first, 24, false);
    cap(m, std::uint32_t(first + 24), 24, true);
}

inline double mesh_area(const Mesh& m)
{
    double area = 0.0;
    for (const auto& t : m.triangles)
        area += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
    return area;
}

inline void append(Mesh& to, const Mesh& from)
{
    const std::uint32_t offset = std::uint32_t(to.vertices.size());
    to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
    for (auto t : from.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

/// The wall's half width u_w(z) = sqrt(R^2 - (z - h)^2) at height z.
inline double wall_half_width(const Tunnel_scene_options& o, double z)
{
    const double dz = z - o.vault_centre_height;
    return std::sqrt(std::max(0.0, o.tunnel_radius * o.tunnel_radius - dz * dz));
}

// The wagon's fixed dimensions (see the header comment).
inline constexpr double body_bottom = 1.25, eaves = 3.7, roof_top = 4.0;
inline constexpr double head_half_length = 0.8, head_top = 4.27, head_thickness = 0.06, head_width = 0.1;

inline void check(const Tunnel_scene_options& o)
{
    const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
    if (o.scene_points < 1000 || o.wagon_points < 1000)
        throw Invalid_input("tunnel scene: scene_points and wagon_points must be >= 1000");
    if (o.poses < 2) throw Invalid_input("tunnel scene: at least 2 poses");
    if (o.outliers >= o.scene_points / 10) throw Invalid_input("tunnel scene: outliers must be below 10 % of scene_points");
    if (!positive(o.tunnel_radius) || !positive(o.vault_centre_height) || o.vault_centre_height >= o.tunnel_radius)
        throw Invalid_input("tunnel scene: need 0 < vault_centre_height < tunnel_radius");
    if (!(o.tunnel_radius > 2.0 && o.vault_centre_height + o.tunnel_radius > head_top + 0.1))
        throw Invalid_input("tunnel scene: the vault must clear the wagon (tunnel_radius > 2 m, crown above 4.37 m)");
    if (!positive(o.curve_radius) || o.curve_radius < 50.0) throw Invalid_input("tunnel scene: curve_radius must be >= 50 m");
    if (!positive(o.wagon_length) || !positive(o.wagon_width) || o.wagon_width > 2.0 * wall_half_width(o, eaves) - 0.2)
        throw Invalid_input("tunnel scene: the wagon must fit the tunnel");
    if (!(o.tunnel_length >= o.wagon_length + 8.0)) throw Invalid_input("tunnel scene: tunnel_length must be >= wagon_length + 8");
    if (!positive(o.ring_spacing) || o.vault_segments < 16) throw Invalid_input("tunnel scene: ring_spacing > 0, vault_segments >= 16");
    if (!(std::isfinite(o.noise) && o.noise >= 0.0)) throw Invalid_input("tunnel scene: noise must be finite and >= 0");
    if (o.cables > 4) throw Invalid_input("tunnel scene: at most 4 cables");
    if (!(positive(o.outlier_min_offset) && o.outlier_max_offset >= o.outlier_min_offset))
        throw Invalid_input("tunnel scene: need 0 < outlier_min_offset <= outlier_max_offset");
    if (!(positive(o.hole_length) && positive(o.hole_height) && o.hole_length < o.tunnel_length - 4.0))
        throw Invalid_input("tunnel scene: hole sizes must be > 0 and fit the tunnel");
    if (!(std::isfinite(o.sway_amplitude) && std::abs(o.sway_amplitude) < 0.2 && positive(o.sway_wavelength)))
        throw Invalid_input("tunnel scene: |sway_amplitude| < 0.2 m, sway_wavelength > 0");
    const double centred = o.tunnel_radius - std::hypot(head_half_length, head_top - o.vault_centre_height);
    for (const double c : o.offset_clearances)
        if (!(std::isfinite(c) && c > 0.0 && c < centred))
            throw Invalid_input(PCCD::internal::concat("tunnel scene: offset clearance ", c, " must be in (0, ", centred, ")"));
    if (o.offset_every > 0 && o.offset_clearances.empty())
        throw Invalid_input("tunnel scene: offset_every > 0 needs offset_clearances");
}

/// Samples `n` points of `mesh` by area, dropping those `keep` rejects, until n are kept; adds
/// N(0, sigma^2) noise per coordinate. Samples are drawn in rounds of the missing count.
template <class Keep>
Eigen::Matrix3Xd sample_kept(const Mesh& mesh, std::size_t n, double sigma, Random_engine& engine, const Keep& keep)
{
    Eigen::Matrix3Xd out(3, Eigen::Index(n));
    std::size_t kept = 0;
    while (kept < n) {
        const Triangle_mesh_sample s = sample_triangle_mesh(mesh.vertices, mesh.triangles, n - kept, engine);
        for (Eigen::Index i = 0; i < s.points.cols() && kept < n; ++i)
            if (keep(Eigen::Vector3d(s.points.col(i)), s.triangles[std::size_t(i)])) out.col(Eigen::Index(kept++)) = s.points.col(i);
    }
    if (sigma > 0.0)
        for (Eigen::Index i = 0; i < out.cols(); ++i)
            for (int k = 0; k < 3; ++k) out(k, i) += sigma * standard_normal(engine);
    return out;
}

} // namespace tunnel_detail

/// The (s, z, side) coordinates of a point of the tube's wall: s from the angle about the arc's
/// centre, z its height, side the sign of its offset along n(s).
inline std::array<double, 3> tunnel_coordinates(const Tunnel_scene& scene, const Eigen::Vector3d& p)
{
    const double rc = scene.options.curve_radius;
    const Eigen::Vector3d centre_of_arc(0.0, rc, 0.0);
    const Eigen::Vector3d d = p - centre_of_arc;
    const double angle = std::atan2(d.x(), -d.y()); // 0 at the start, growing along the tunnel
    const double s = rc * angle;
    const double u = (p - scene.centre(s)).dot(scene.normal(s));
    return {s, p.z(), u >= 0.0 ? 1.0 : -1.0};
}

/// Builds the scene of `options` (see the header comment). Deterministic for given options.
/// \throws Invalid_input for options outside their stated ranges.
inline Tunnel_scene make_tunnel_scene(const Tunnel_scene_options& options = {})
{
    using namespace tunnel_detail;
    check(options);
    const Tunnel_scene_options& o = options;
    Tunnel_scene scene;
    scene.options = options;
    Random_engine engine(o.seed);

    const std::size_t rings = std::size_t(std::ceil(o.tunnel_length / o.ring_spacing)) + 1;
    const double ds = o.tunnel_length / double(rings - 1);
    const auto to_world = [&](double s, double u, double z) { return Eigen::Vector3d(scene.centre(s) + u * scene.normal(s) + Eigen::Vector3d(0, 0, z)); };

    // The tube: the vault (walls) first, then the bed, as two strips sharing their boundary rings.
    const double h = o.vault_centre_height, r = o.tunnel_radius;
    const double a0 = std::asin(-h / r); // the angle of the bed's right end (u > 0 side) measured from +u
    const double half_bed = r * std::cos(a0);
    std::vector<Eigen::Vector2d> vault; // from the right end of the bed over the crown to the left end
    for (std::size_t j = 0; j <= o.vault_segments; ++j) {
        const double a = a0 + (std::numbers::pi - 2.0 * a0) * double(j) / double(o.vault_segments);
        vault.emplace_back(r * std::cos(a), h + r * std::sin(a));
    }
    vault.front() = {half_bed, 0.0};
    vault.back() = {-half_bed, 0.0};
    const std::size_t bed_segments = std::max<std::size_t>(4, std::size_t(std::ceil(2.0 * half_bed / 0.25)));
    std::vector<Eigen::Vector2d> tube = vault; // closed profile: vault, then the bed back to the start
    for (std::size_t j = 1; j < bed_segments; ++j)
        tube.emplace_back(-half_bed + 2.0 * half_bed * double(j) / double(bed_segments), 0.0);
    Mesh& tunnel = scene.tunnel_mesh;
    sweep(tunnel, tube, true, rings, [&](std::size_t k, const Eigen::Vector2d& q) { return to_world(double(k) * ds, q.x(), q.y()); });
    // Reorder: the quads of the vault edges (j < vault_segments) first.
    {
        std::vector<std::array<std::uint32_t, 3>> walls, rest;
        const std::size_t p = tube.size();
        for (std::size_t t = 0; t < tunnel.triangles.size(); ++t) {
            const std::size_t j = (t / 2) % p;
            (j < o.vault_segments ? walls : rest).push_back(tunnel.triangles[t]);
        }
        scene.wall_triangles = walls.size();
        walls.insert(walls.end(), rest.begin(), rest.end());
        tunnel.triangles = std::move(walls);
    }
    // Rails: open strips (outer side, top, inner side).
    for (const double side : {-1.0, 1.0}) {
        const double uc = side * 0.5 * (o.gauge + o.rail_width), w = 0.5 * o.rail_width;
        const std::vector<Eigen::Vector2d> rail{{uc - w, 0.0}, {uc - w, o.rail_height}, {uc + w, o.rail_height}, {uc + w, 0.0}};
        sweep(tunnel, rail, false, rings, [&](std::size_t k, const Eigen::Vector2d& q) { return to_world(double(k) * ds, q.x(), q.y()); });
    }
    // Cables: open 12-gon tubes 3 cm off the wall.
    for (std::size_t c = 0; c < o.cables; ++c) {
        const double side = c % 2 == 0 ? 1.0 : -1.0, zc = 0.9 + 0.45 * double(c / 2), rad = 0.04;
        const double uc = side * (wall_half_width(o, zc) - 0.03 - rad - 0.02); // 2 cm for the wall's slope
        std::vector<Eigen::Vector2d> ring;
        for (int j = 0; j < 12; ++j) {
            const double a = 2.0 * std::numbers::pi * j / 12.0;
            ring.emplace_back(uc + rad * std::cos(a), zc + rad * std::sin(a));
        }
        sweep(tunnel, ring, true, rings, [&](std::size_t k, const Eigen::Vector2d& q) { return to_world(double(k) * ds, q.x(), q.y()); });
    }
    // Signal boxes: 0.3 (along) x 0.2 (deep) x 0.4 (high), z in [2.0, 2.4], 3 cm off the wall.
    for (std::size_t k = 0; k < o.signals; ++k) {
        const double s = o.tunnel_length * double(k + 1) / double(o.signals + 1), side = k % 2 == 0 ? 1.0 : -1.0;
        const double outer = wall_half_width(o, 2.4) - 0.03; // the wall is nearest at the box's top
        Eigen::Matrix3d axes;
        axes << scene.tangent(s), scene.normal(s), Eigen::Vector3d::UnitZ();
        add_box(tunnel, to_world(s, side * (outer - 0.1), 2.2), axes, Eigen::Vector3d(0.15, 0.1, 0.2));
    }

    // Wagon (its own frame).
    Mesh& wagon = scene.wagon_mesh;
    {
        const double hw = 0.5 * o.wagon_width, sag = roof_top - eaves;
        const double roof_radius = (hw * hw + sag * sag) / (2.0 * sag);
        std::vector<Eigen::Vector2d> body{{-hw, body_bottom}, {hw, body_bottom}};
        const double half_angle = std::asin(hw / roof_radius);
        for (int j = 0; j <= 16; ++j) {
            const double a = -half_angle + 2.0 * half_angle * j / 16.0; // from the right eave to the left one
            body.emplace_back(roof_radius * std::sin(-a), roof_top - roof_radius + roof_radius * std::cos(a));
        }
        body[2] = {hw, eaves};
        body.back() = {-hw, eaves};
        const std::size_t sections = std::size_t(std::ceil(o.wagon_length)) + 1;
        const std::uint32_t first = sweep(wagon, body, true, sections, [&](std::size_t k, const Eigen::Vector2d& q) {
            return Eigen::Vector3d(-0.5 * o.wagon_length + o.wagon_length * double(k) / double(sections - 1), q.x(), q.y());
        });
        cap(wagon, first, body.size(), true);
        cap(wagon, std::uint32_t(first + (sections - 1) * body.size()), body.size(), false);
        // Bogies: side beams and wheels (lifted 0.2 m off the rails).
        const double wheel_r = 0.42, wheel_z = o.rail_height + 0.2 + wheel_r;
        for (const double xb : {-0.5 * o.wagon_length + 3.0, 0.5 * o.wagon_length - 3.0}) {
            for (const double side : {-1.0, 1.0}) {
                add_box(wagon, Eigen::Vector3d(xb, side * 0.95, 0.8), Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.4, 0.07, 0.175));
                for (const double xa : {-1.25, 1.25})
                    add_wheel(wagon, Eigen::Vector3d(xb + xa, side * 0.5 * (o.gauge + o.rail_width), wheel_z), wheel_r, 0.07);
            }
        }
        // Pantograph: base frame, arm, pan head.
        add_box(wagon, Eigen::Vector3d(0.0, 0.0, 4.05), Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.6, 0.5, 0.03));
        add_bar(wagon, Eigen::Vector3d(-0.45, 0.0, 4.11), Eigen::Vector3d(0.0, 0.0, 4.19), 0.04);
        add_box(wagon, Eigen::Vector3d(0.0, 0.0, head_top - 0.5 * head_thickness), Eigen::Matrix3d::Identity(),
                Eigen::Vector3d(0.5 * head_width, head_half_length, 0.5 * head_thickness));
    }

    // Holes on the walls.
    for (std::size_t k = 0; k < o.holes; ++k) {
        const double s0 = uniform_real(engine, 2.0, o.tunnel_length - 2.0 - o.hole_length);
        const double z0 = uniform_real(engine, 0.4, 2.2);
        const int side = uniform_01(engine) < 0.5 ? -1 : 1;
        scene.holes.push_back({s0, s0 + o.hole_length, z0, z0 + o.hole_height, side});
    }
    const auto in_hole = [&](const Eigen::Vector3d& p) {
        const auto [s, z, side] = tunnel_coordinates(scene, p);
        for (const Tunnel_hole& hole : scene.holes)
            if (int(side) == hole.side && s >= hole.s_begin && s <= hole.s_end && z >= hole.z_begin && z <= hole.z_end) return true;
        return false;
    };

    // Clouds.
    scene.tunnel_area = mesh_area(tunnel);
    scene.wagon_area = mesh_area(wagon);
    scene.tunnel_nominal_spacing = std::sqrt(scene.tunnel_area / double(o.scene_points));
    scene.wagon_nominal_spacing = std::sqrt(scene.wagon_area / double(o.wagon_points));
    scene.tunnel_sigma = o.noise * scene.tunnel_nominal_spacing;
    scene.wagon_sigma = o.noise * scene.wagon_nominal_spacing;
    const std::size_t surface_points = o.scene_points - o.outliers;
    const Eigen::Matrix3Xd surface = sample_kept(tunnel, surface_points, scene.tunnel_sigma, engine,
                                                 [&](const Eigen::Vector3d& p, std::size_t t) { return t >= scene.wall_triangles || !in_hole(p); });
    scene.tunnel_points.resize(3, Eigen::Index(o.scene_points));
    scene.tunnel_points.leftCols(Eigen::Index(surface_points)) = surface;
    scene.first_outlier = surface_points;
    // Outliers: wall points below 2.5 m (outside holes), moved along the wall's normal.
    std::size_t made = 0;
    while (made < o.outliers) {
        const Triangle_mesh_sample s = sample_triangle_mesh(tunnel.vertices, tunnel.triangles, 1, engine);
        const Eigen::Vector3d p = s.points.col(0);
        const double sign = uniform_01(engine) < 0.5 ? -1.0 : 1.0;
        const double offset = uniform_real(engine, o.outlier_min_offset, o.outlier_max_offset);
        if (s.triangles[0] >= scene.wall_triangles || p.z() > 2.5 || in_hole(p)) continue;
        scene.tunnel_points.col(Eigen::Index(surface_points + made++)) = p + sign * offset * Eigen::Vector3d(s.normals.col(0));
    }
    // The wagon has an engine of its own, so that its cloud does not depend on the tunnel's options.
    Random_engine wagon_engine(o.seed + 0x5741474f4eULL);
    scene.wagon_points = sample_kept(wagon, o.wagon_points, scene.wagon_sigma, wagon_engine,
                                     [](const Eigen::Vector3d&, std::size_t) { return true; });

    // Path.
    const double s_begin = 0.5 * o.wagon_length + 2.0, s_end = o.tunnel_length - 0.5 * o.wagon_length - 2.0;
    std::size_t deliberate = 0;
    for (std::size_t i = 0; i < o.poses; ++i) {
        Tunnel_pose pose;
        pose.s = s_begin + (s_end - s_begin) * double(i) / double(o.poses - 1);
        pose.lateral = o.sway_amplitude * std::sin(2.0 * std::numbers::pi * pose.s / o.sway_wavelength);
        if (o.offset_every > 0 && i % o.offset_every == o.offset_every / 2) {
            pose.deliberate = true;
            pose.target_clearance = o.offset_clearances[deliberate % o.offset_clearances.size()];
            const double reach = std::sqrt(std::pow(r - pose.target_clearance, 2) - std::pow(head_top - h, 2));
            pose.lateral = (deliberate % 2 == 0 ? 1.0 : -1.0) * (reach - head_half_length);
            ++deliberate;
        }
        Eigen::Matrix3d rotation;
        rotation << scene.tangent(pose.s), scene.normal(pose.s), Eigen::Vector3d::UnitZ();
        pose.pose = Rigid_transform_3<double>(rotation, Eigen::Vector3d(scene.centre(pose.s) + pose.lateral * scene.normal(pose.s)));
        scene.path.push_back(pose);
    }
    return scene;
}

/// Writes the scene into the folder `dir` (created if missing) for the `pccd` tool:
/// tunnel.ply and wagon.ply (the clouds, binary PLY, no normals: a scan has none), tunnel.off and
/// wagon.off (the meshes), poses.csv (a header, then per pose the 12 numbers of the wagon's
/// 3 x 4 [R | t] row by row) and cases.csv (per pose 24 numbers, the wagon's pose and then the
/// tunnel's, the identity: the `--cases` file of `pccd distance wagon.ply tunnel.ply`).
/// \throws File_error when a file cannot be written.
inline void write_tunnel_scene(const Tunnel_scene& scene, const std::string& dir)
{
    std::filesystem::create_directories(dir);
    const auto path = [&](const char* name) { return (std::filesystem::path(dir) / name).string(); };
    const auto cloud = [](const Eigen::Matrix3Xd& points) {
        Point_data data;
        data.points.reserve(std::size_t(points.cols()));
        for (Eigen::Index i = 0; i < points.cols(); ++i) data.points.emplace_back(points.col(i));
        return data;
    };
    IO::write_points(path("tunnel.ply"), cloud(scene.tunnel_points), {.binary = true});
    IO::write_points(path("wagon.ply"), cloud(scene.wagon_points), {.binary = true});
    IO::write_triangle_mesh(path("tunnel.off"), scene.tunnel_mesh);
    IO::write_triangle_mesh(path("wagon.off"), scene.wagon_mesh);
    std::ofstream poses(path("poses.csv")), cases(path("cases.csv"));
    if (!poses || !cases) throw File_error(dir, "cannot write poses.csv or cases.csv");
    poses.precision(17);
    cases.precision(17);
    poses << "r00,r01,r02,t0,r10,r11,r12,t1,r20,r21,r22,t2\n";
    for (const Tunnel_pose& p : scene.path) {
        const Eigen::Matrix3d& r = p.pose.rotation();
        const Eigen::Vector3d& t = p.pose.translation();
        for (int i = 0; i < 3; ++i) {
            const char* end = i == 2 ? "" : ",";
            poses << r(i, 0) << ',' << r(i, 1) << ',' << r(i, 2) << ',' << t(i) << end;
            cases << r(i, 0) << ',' << r(i, 1) << ',' << r(i, 2) << ',' << t(i) << ',';
        }
        poses << '\n';
        cases << "1,0,0,0,0,1,0,0,0,0,1,0\n";
    }
    if (!poses || !cases) throw File_error(dir, "writing poses.csv or cases.csv failed");
}

} // namespace PCCD::testing
