// Shared helpers of the bad-input catalogue (test/robustness, doc/reliability.md): small clouds
// built without randomness, checks that an input is rejected with the exact exception type and a
// message naming the problem, and a scratch directory per test executable.
#pragma once

#include <PCCD/Error.h>

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <typeinfo>
#include <vector>

#include "error_test_helpers.h"

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

/// A path in this executable's own scratch directory under PCCD_TEST_TMP_DIR.
inline std::string scratch_path(const std::string& directory, const std::string& name)
{
    const std::filesystem::path dir = std::filesystem::path(PCCD_TEST_TMP_DIR) / directory;
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

inline std::string read_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_bytes(const std::string& path, const std::string& bytes)
{
    // Removed first: on ext4, truncating and rewriting a file forces a flush to the disk on close.
    std::filesystem::remove(path);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    REQUIRE(out.good());
}

} // namespace pccd_robustness
