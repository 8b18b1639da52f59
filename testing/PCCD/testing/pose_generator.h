// PCCD/testing/pose_generator.h -- the random poses of the benchmark procedure (doc/algorithms.md,
// "Benchmark procedure"): two normalized objects, A rotated uniformly at random about the origin, B
// rotated independently and moved to (d, 0, 0): T_A = [R_A | 0], T_B = [R_B | (d, 0, 0)], for d =
// 0, 0.25, ..., 3 and many rotations per distance. Uniform rotations come from Shoemake's uniform
// quaternions.
//
// Reproducibility: the pose for (seed, d, i) is drawn from its own engine, seeded by a hash of the
// three, so it is the same whichever distances and how many rotations are asked for, on every
// platform.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>

namespace PCCD::testing {

/// The distances of the WSCG05 benchmark: 0, 0.25, 0.5, ..., 3 (13 values).
inline std::vector<double> default_benchmark_distances()
{
    std::vector<double> distances;
    for (int i = 0; i <= 12; ++i) distances.push_back(0.25 * i);
    return distances;
}

/// Options of generate_benchmark_poses.
struct Pose_options {
    /// The translations d of object B along x, in normalized units (objects fit [-1, 1]^3, so they
    /// cannot touch for d > 2 sqrt(3)). Default: default_benchmark_distances() (0 to 3, step 0.25).
    /// Each must be finite; the list must not be empty.
    std::vector<double> distances = default_benchmark_distances();
    /// Independent random rotation pairs (R_A, R_B) per distance. Default 100; must be >= 1.
    std::size_t rotations_per_distance = 100;
    /// Seed of all the poses. Default 1.
    std::uint64_t seed = 1;
};

/// One benchmark configuration: object A at `pose_a` = [R_A | 0], object B at `pose_b` =
/// [R_B | (distance, 0, 0)]; `rotation_index` numbers the rotation pairs of one distance.
struct Benchmark_pose {
    double distance;
    std::size_t rotation_index;
    Rigid_transform_3<double> pose_a;
    Rigid_transform_3<double> pose_b;
};

/// A unit quaternion uniformly distributed on S^3, i.e. a uniformly random rotation (Haar measure
/// on SO(3)), by Shoemake's method ("Uniform random rotations", Graphics Gems III, 1992): with u1,
/// u2, u3 uniform in [0, 1), q = (sqrt(1-u1) sin 2 pi u2, sqrt(1-u1) cos 2 pi u2, sqrt(u1) sin 2 pi u3,
/// sqrt(u1) cos 2 pi u3). Draws three uniforms. Normalized to unit length in double.
inline Eigen::Quaterniond uniform_random_quaternion(Random_engine& engine)
{
    const double u1 = uniform_01(engine);
    const double a2 = 2.0 * std::numbers::pi * uniform_01(engine);
    const double a3 = 2.0 * std::numbers::pi * uniform_01(engine);
    const double s1 = std::sqrt(1.0 - u1), s2 = std::sqrt(u1);
    // Eigen's constructor order is (w, x, y, z).
    return Eigen::Quaterniond(s2 * std::cos(a3), s1 * std::sin(a2), s1 * std::cos(a2), s2 * std::sin(a3))
        .normalized();
}

/// A uniformly random rotation matrix (from uniform_random_quaternion). Draws three uniforms.
inline Eigen::Matrix3d uniform_random_rotation(Random_engine& engine)
{
    return uniform_random_quaternion(engine).toRotationMatrix();
}

namespace detail {

/// SplitMix64's output function (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
constexpr std::uint64_t mix64(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

} // namespace detail

/// The engine of configuration (seed, distance, rotation_index): Random_engine seeded with
/// mix64(mix64(mix64(seed) ^ bits(distance)) ^ rotation_index), bits() the IEEE-754 bit pattern
/// (-0 counts as +0). Platform-independent.
inline Random_engine pose_engine(std::uint64_t seed, double distance, std::size_t rotation_index)
{
    const std::uint64_t distance_bits = std::bit_cast<std::uint64_t>(distance == 0.0 ? 0.0 : distance);
    return Random_engine(
        detail::mix64(detail::mix64(detail::mix64(seed) ^ distance_bits) ^ std::uint64_t(rotation_index)));
}

/// The configuration (seed, distance, rotation_index): R_A then R_B drawn from pose_engine(...).
/// \throws Invalid_input if `distance` is not finite. O(1).
inline Benchmark_pose benchmark_pose(std::uint64_t seed, double distance, std::size_t rotation_index)
{
    if (!std::isfinite(distance))
        throw Invalid_input(internal::concat("benchmark pose: distance ", distance, " is not finite"));
    Random_engine engine = pose_engine(seed, distance, rotation_index);
    const Eigen::Matrix3d rotation_a = uniform_random_rotation(engine);
    const Eigen::Matrix3d rotation_b = uniform_random_rotation(engine);
    return {distance, rotation_index, Rigid_transform_3<double>(rotation_a, Eigen::Vector3d::Zero()),
            Rigid_transform_3<double>(rotation_b, Eigen::Vector3d(distance, 0.0, 0.0))};
}

/// All configurations of the benchmark: for each distance of `options.distances` in order, the
/// rotation indices 0 .. rotations_per_distance - 1. Same seed, same poses.
/// \throws Invalid_input if the distance list is empty, a distance is not finite, or
///         rotations_per_distance is 0. Complexity: O(distances x rotations).
/// Thread safety: pure function.
inline std::vector<Benchmark_pose> generate_benchmark_poses(const Pose_options& options = {})
{
    if (options.distances.empty()) throw Invalid_input("pose options: the distance list is empty");
    if (options.rotations_per_distance == 0)
        throw Invalid_input("pose options: rotations_per_distance is 0; it must be at least 1");
    for (std::size_t i = 0; i < options.distances.size(); ++i)
        if (!std::isfinite(options.distances[i]))
            throw Invalid_input(internal::concat("pose options: distance ", i, " is ", options.distances[i],
                                                 "; distances must be finite"));
    std::vector<Benchmark_pose> poses;
    poses.reserve(options.distances.size() * options.rotations_per_distance);
    for (const double d : options.distances)
        for (std::size_t r = 0; r < options.rotations_per_distance; ++r) poses.push_back(benchmark_pose(options.seed, d, r));
    return poses;
}

} // namespace PCCD::testing
