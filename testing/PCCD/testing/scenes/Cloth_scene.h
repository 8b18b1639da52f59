// PCCD/testing/scenes/Cloth_scene.h -- the talk's benchmark scene (doc/manual/kinetic.md, "Scenes";
// figures in doc/benchmarks.md, "Kinetic AABB tree"): a table cloth falling onto a table, simulated
// here by a small mass-spring model written for the benchmark, and recorded as key frames. Triangle
// counts near the talk's 1,684, 6,891 and 15,503 come from a rectangular grid of quads, two
// triangles each. Not library code (testing/, target PCCD::testing; never installed).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/testing/scenes/Kinetic_scene.h>

namespace PCCD::testing {

/// Options of make_cloth_scene. Lengths in metres, times in seconds.
struct Cloth_scene_options {
    /// Approximate number of cloth triangles (grid of a x b quads, aspect <= 1.35); default 1684.
    std::size_t triangles = 1684;
    /// Length of the animation, rounded up to whole key frames; default 4 s (fall, contact,
    /// draping, settling).
    double duration = 4.0;
    /// Key frames recorded per second (the flightplans interpolate linearly between them); default 60.
    double key_rate = 60.0;
    /// Side length of the cloth along its longer grid direction; default 2.
    double cloth_size = 2.0;
    /// Half width of the square table top (centred at the origin, top at z = 0); default 0.6.
    double table_half_width = 0.6;
    /// Height of the table (its legs are not modelled: a solid box); default 0.8.
    double table_height = 0.8;
    /// Initial height of the flat cloth above the table top; default 0.3.
    double drop_height = 0.3;
    /// Rotation of the cloth about z, in degrees, to avoid a symmetric fall; default 17.
    double rotation_degrees = 17.0;
    /// Initial tilt of the cloth, in degrees: its height rises along the horizontal direction at
    /// 30 degrees to the x axis (drop_height is the height of its centre); default 5, as a cloth
    /// is never dropped perfectly level. With 0 every particle has the same height until the first
    /// contact: exact ties, which any ripple then swaps back and forth (about 30 % more BV updates).
    double tilt_degrees = 5.0;
    /// Speed of elastic waves in the cloth (sets the spring stiffness per unit mass independently
    /// of the resolution; the time step is 0.25 spacing / wave_speed, smaller for spring_damping
    /// above 0.5); default 15 m/s.
    double wave_speed = 15.0;
    /// Damping of the springs as a fraction of the critical damping of a structural spring;
    /// default 1 (fabric barely rings).
    double spring_damping = 1.0;
    /// Air drag per unit mass (1/s); default 10: a light table cloth (about 0.1 kg/m^2) falling
    /// flat reaches about 1 m/s (g / 10), as a sheet of that weight does in air, and its hanging
    /// flaps stop swaying within about a second. Lower values give a cloth that keeps swinging
    /// (2 was the default before; it produces about 3 times as many events).
    double air_damping = 10.0;
    /// Fraction of the tangential velocity removed at every step in contact with the table; default 0.6.
    double friction = 0.6;
};

namespace detail {

/// The a x b quad grid with 2ab closest to `triangles` and aspect b/a <= 1.35 (squarer on ties).
inline std::pair<std::size_t, std::size_t> cloth_grid(std::size_t triangles)
{
    const std::size_t quads = std::max<std::size_t>(1, (triangles + 1) / 2);
    std::pair<std::size_t, std::size_t> best{1, quads};
    std::size_t best_error = std::size_t(-1);
    for (std::size_t a = 1; a * a <= quads + 2 * a + 1; ++a) {
        for (std::size_t b = std::max<std::size_t>(a, quads / a); b <= quads / a + 1; ++b) {
            if (double(b) > 1.35 * double(a)) continue;
            const std::size_t t = 2 * a * b;
            const std::size_t error = t > triangles ? t - triangles : triangles - t;
            if (error < best_error || (error == best_error && b - a < best.second - best.first)) {
                best = {a, b};
                best_error = error;
            }
        }
    }
    return best;
}

} // namespace detail

/// Simulates a table cloth falling onto a table and records it.
///
/// Model: a grid of particles (equal masses) joined by structural, shear and bending springs with
/// damping; symplectic Euler with a fixed step; the table is a solid box (contact projects the
/// particle out and applies Coulomb-like friction). The cloth starts flat and at rest, rotated about
/// z and tilted by tilt_degrees; with tilt_degrees = 0 its height is the same for every particle
/// until the first contact, exact ties that the tests use.
///
/// The returned scene has the cloth triangles over one flightplan per particle (key frames at
/// `key_rate`, shared key times) and the table's 12 triangles as a static obstacle.
/// \throws Invalid_input for non-positive sizes, duration, key rate or wave speed, a tilt of 90
///         degrees or more, or fewer than 2 triangles. Deterministic (no randomness). Complexity: O(V duration wave_speed / spacing).
inline Kinetic_scene<Kinetic_triangle> make_cloth_scene(const Cloth_scene_options& o = {})
{
    // Quiet comparisons: a NaN option is rejected without raising FE_INVALID.
    if (o.triangles < 2 || !std::isgreater(o.duration, 0.0) || !std::isgreater(o.key_rate, 0.0) ||
        !std::isgreater(o.cloth_size, 0.0) || !std::isgreater(o.table_half_width, 0.0) ||
        !std::isgreater(o.table_height, 0.0) || !std::isgreaterequal(o.drop_height, 0.0) ||
        !std::isgreater(o.wave_speed, 0.0) ||
        !std::isless(std::abs(o.tilt_degrees), 90.0))
        throw Invalid_input(internal::concat("make_cloth_scene: invalid options (triangles ", o.triangles, ", duration ",
                                             o.duration, ", key_rate ", o.key_rate, ", tilt ", o.tilt_degrees,
                                             " degrees; sizes and wave speed must be > 0, |tilt| < 90)"));
    const auto [qa, qb] = detail::cloth_grid(o.triangles);
    const std::size_t nx = qb + 1, ny = qa + 1; // vertices along the longer (x) and shorter (y) side
    const double h = o.cloth_size / double(qb);
    const std::size_t n = nx * ny;
    auto id = [nx](std::size_t i, std::size_t j) { return std::uint32_t(j * nx + i); };

    Kinetic_scene<Kinetic_triangle> scene;
    scene.name = "cloth";
    scene.start_time = 0.0;

    // Initial flat grid, centred, rotated about z.
    const double angle = o.rotation_degrees * std::numbers::pi / 180.0;
    const double ca = std::cos(angle), sa = std::sin(angle);
    const double slope = std::tan(o.tilt_degrees * std::numbers::pi / 180.0);
    const double slope_x = slope * std::cos(std::numbers::pi / 6.0), slope_y = slope * std::sin(std::numbers::pi / 6.0);
    std::vector<Eigen::Vector3d> x(n), v(n, Eigen::Vector3d::Zero());
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const double u = (double(i) - 0.5 * double(nx - 1)) * h, w = (double(j) - 0.5 * double(ny - 1)) * h;
            const double px = ca * u - sa * w, py = sa * u + ca * w;
            x[id(i, j)] = Eigen::Vector3d(px, py, o.drop_height + slope_x * px + slope_y * py);
        }
    for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i) {
            scene.primitives.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
            scene.primitives.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
        }

    // Springs: (a, b, rest length, stiffness per unit mass).
    struct Spring {
        std::uint32_t a, b;
        double rest, k;
    };
    std::vector<Spring> springs;
    const double k_struct = (o.wave_speed * o.wave_speed) / (h * h);
    auto add = [&](std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1, double scale) {
        if (i1 >= nx || j1 >= ny) return;
        const std::uint32_t a = id(i0, j0), b = id(i1, j1);
        springs.push_back({a, b, (x[a] - x[b]).norm(), scale * k_struct});
    };
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            add(i, j, i + 1, j, 1.0);
            add(i, j, i, j + 1, 1.0);
            add(i, j, i + 1, j + 1, 0.5);
            if (i > 0) add(i, j, i - 1, j + 1, 0.5);
            add(i, j, i + 2, j, 0.1);
            add(i, j, i, j + 2, 0.1);
        }

    // Explicit integration is stable for dt * omega <= 0.25 (omega = wave_speed / h) with damping up
    // to half the critical value; heavier damping needs proportionally smaller steps.
    const double dt_max = 0.25 * h / o.wave_speed * std::min(1.0, 0.5 / std::max(o.spring_damping, 1e-12));
    const double key_dt = 1.0 / o.key_rate;
    const auto keys = std::size_t(std::ceil(o.duration * o.key_rate - 1e-9)) + 1;
    const auto substeps = std::size_t(std::ceil(key_dt / dt_max));
    const double dt = key_dt / double(substeps);
    const double spring_damping = o.spring_damping * 2.0 * o.wave_speed / h; // critical: 2 sqrt(k/m)
    const double air_damping = o.air_damping;
    const double friction = o.friction;
    const Eigen::Vector3d gravity(0, 0, -9.81);
    const double half = o.table_half_width, bottom = -o.table_height;

    std::vector<std::vector<Eigen::Vector3d>> key_positions(n);
    for (auto& k : key_positions) k.reserve(keys);
    auto record = [&]() {
        for (std::size_t p = 0; p < n; ++p) key_positions[p].push_back(x[p]);
    };
    record();
    std::vector<Eigen::Vector3d> force(n);
    for (std::size_t key = 1; key < keys; ++key) {
        for (std::size_t step = 0; step < substeps; ++step) {
            std::fill(force.begin(), force.end(), gravity);
            for (const Spring& s : springs) {
                const Eigen::Vector3d d = x[s.b] - x[s.a];
                const double length = d.norm();
                if (length == 0.0) continue;
                const Eigen::Vector3d dir = d / length;
                const double stretch = length - s.rest;
                const double rate = (v[s.b] - v[s.a]).dot(dir);
                const Eigen::Vector3d f = (s.k * stretch + spring_damping * rate * (s.k / k_struct)) * dir;
                force[s.a] += f;
                force[s.b] -= f;
            }
            for (std::size_t p = 0; p < n; ++p) {
                v[p] += dt * (force[p] - air_damping * v[p]);
                x[p] += dt * v[p];
                // Contact with the table (a solid box): push out through the nearest face.
                const Eigen::Vector3d q = x[p];
                if (std::abs(q.x()) < half && std::abs(q.y()) < half && q.z() < 0.0 && q.z() > bottom) {
                    const double to_top = -q.z(), to_x = half - std::abs(q.x()), to_y = half - std::abs(q.y());
                    if (to_top <= to_x && to_top <= to_y) {
                        x[p].z() = 0.0;
                        v[p].z() = std::max(0.0, v[p].z());
                        v[p].x() *= 1.0 - friction;
                        v[p].y() *= 1.0 - friction;
                    } else if (to_x <= to_y) {
                        x[p].x() = std::copysign(half, q.x());
                        v[p].x() = 0.0;
                    } else {
                        x[p].y() = std::copysign(half, q.y());
                        v[p].y() = 0.0;
                    }
                }
            }
        }
        record();
    }

    auto times = std::make_shared<std::vector<double>>(keys);
    for (std::size_t k = 0; k < keys; ++k) (*times)[k] = double(k) * key_dt;
    scene.end_time = times->back();
    const Piecewise_linear_flightplan::Key_times shared = times;
    scene.flightplans.reserve(n);
    for (std::size_t p = 0; p < n; ++p) scene.flightplans.emplace_back(shared, std::move(key_positions[p]));

    // The table: a box [-half, half]^2 x [bottom, 0], 8 corners, 12 triangles, at rest.
    const auto rest = std::make_shared<const std::vector<double>>(1, 0.0);
    for (int c = 0; c < 8; ++c) {
        const Eigen::Vector3d corner((c & 1) ? half : -half, (c & 2) ? half : -half, (c & 4) ? 0.0 : bottom);
        scene.obstacle_flightplans.emplace_back(rest, std::vector<Eigen::Vector3d>{corner});
    }
    const std::array<std::array<std::uint32_t, 4>, 6> faces{{{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}}};
    for (const auto& f : faces) {
        scene.obstacle_triangles.push_back({{f[0], f[1], f[2]}});
        scene.obstacle_triangles.push_back({{f[0], f[2], f[3]}});
    }
    return scene;
}

} // namespace PCCD::testing
