// PCCD/testing/scenes/Random_motion_scene.h -- points in random linear motion (doc/manual/kinetic.md,
// "Scenes"), the setting of the O(n log n) event bound ("Flightplans"): each pair of flightplans
// crosses at most once per axis. Not library code (testing/, target PCCD::testing; never installed).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/testing/scenes/Kinetic_scene.h>
#include <PCCD/Random.h>

namespace PCCD::testing {

/// Options of make_random_motion_scene.
struct Random_motion_options {
    /// Number of points; default 1000.
    std::size_t points = 1000;
    /// Animation length; default 1.
    double duration = 1.0;
    /// Largest speed along each axis (velocities uniform in [-max_speed, max_speed]^3); default 1.
    double max_speed = 1.0;
    /// Seed; default 1.
    std::uint64_t seed = 1;
};

/// Points uniform in [-1, 1]^3 at t = 0, moving at constant random velocities until `duration`
/// (two key frames per point, at rest outside [0, duration]).
/// \throws Invalid_input if points == 0 or duration or max_speed is not positive.
inline Kinetic_scene<Kinetic_point> make_random_motion_scene(const Random_motion_options& o = {})
{
    if (o.points == 0 || !std::isgreater(o.duration, 0.0) || !std::isgreater(o.max_speed, 0.0))
        throw Invalid_input(internal::concat("make_random_motion_scene: points ", o.points, ", duration ", o.duration,
                                             " and max_speed ", o.max_speed, " must be > 0"));
    Random_engine rng(o.seed);
    Kinetic_scene<Kinetic_point> scene;
    scene.name = "random";
    scene.start_time = 0.0;
    scene.end_time = o.duration;
    const auto times = std::make_shared<const std::vector<double>>(std::vector<double>{0.0, o.duration});
    auto uniform3 = [&](double r) {
        return Eigen::Vector3d(uniform_real(rng, -r, r), uniform_real(rng, -r, r), uniform_real(rng, -r, r));
    };
    for (std::size_t i = 0; i < o.points; ++i) {
        const Eigen::Vector3d start = uniform3(1.0);
        const Eigen::Vector3d end = start + o.duration * uniform3(o.max_speed);
        scene.flightplans.emplace_back(times, std::vector<Eigen::Vector3d>{start, end});
        scene.primitives.push_back({std::uint32_t(i)});
    }
    return scene;
}

} // namespace PCCD::testing
