// Shared helpers of the bad-input catalogue (test/robustness, doc/reliability.md): small clouds
// built without randomness, checks that an input is rejected with the exact exception type and a
// message naming the problem, and a scratch directory per test executable.
#pragma once

#include <PCCD/Error.h>

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <typeinfo>
#include <vector>

#include "error_test_helpers.h"
#include "file_helpers.h"

namespace pccd_robustness {

using Points = std::vector<Eigen::Vector3d>;

/// `n` points spread evenly over the sphere of radius `radius` about `centre` (a Fibonacci lattice:
/// deterministic, no two points coincide).
inline Points fibonacci_sphere(std::size_t n, double radius = 1.0, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero())
{
    Points points;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (double(i) + 0.5) / double(n);
        const double r = std::sqrt(1.0 - z * z);
        const double angle = golden * double(i);
        points.push_back(centre + radius * Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), z));
    }
    return points;
}

/// An n x n grid of spacing `step` in the plane z = 0, starting at `origin`.
inline Points flat_grid(int n, double step, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero())
{
    Points points;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) points.push_back(origin + Eigen::Vector3d(i * step, j * step, 0.0));
    return points;
}

using pccd_test::require_file_error;
using pccd_test::require_invalid_input;

using pccd_test::read_bytes;
using pccd_test::scratch_path;
using pccd_test::write_bytes;

} // namespace pccd_robustness
