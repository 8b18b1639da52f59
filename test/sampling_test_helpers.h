// Statistics shared by the sampling tests (sample_triangle_mesh_test.cpp and testing/): chi-square
// and the expected mean nearest-neighbour spacing of uniform samples. Tests reject at significance
// level 0.001: the chi-square critical value is the Wilson-Hilferty approximation of the 0.999 quantile.
#pragma once

#include <PCCD/Point_cloud.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace sampling_test {

constexpr double pi = std::numbers::pi;

// 0.999 quantile of the chi-square distribution with `df` degrees of freedom (Wilson-Hilferty).
inline double chi_square_critical(double df)
{
    const double z = 3.0902; // standard normal 0.999 quantile
    const double a = 2.0 / (9.0 * df);
    return df * std::pow(1.0 - a + z * std::sqrt(a), 3);
}

inline double chi_square(const std::vector<double>& observed, const std::vector<double>& expected)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < observed.size(); ++i)
        sum += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    return sum;
}

// Expected mean nearest-neighbour distance of n uniform random points on a surface of area A:
// 0.5 sqrt(A / n). For a region with a border of length L, Donnelly's (1978) edge correction
// + (0.0514 + 0.041 / sqrt(n)) L / n accounts for the missing neighbours beyond the border.
inline double expected_spacing(double area, double n, double border_length = 0.0)
{
    return 0.5 * std::sqrt(area / n) + (0.0514 + 0.041 / std::sqrt(n)) * border_length / n;
}

/// The mean nearest-neighbour distance of the points (Point_cloud::mean_spacing()).
inline double measured_spacing(const Eigen::Matrix3Xd& points) { return PCCD::Point_cloud<>(points).mean_spacing(); }

} // namespace sampling_test
