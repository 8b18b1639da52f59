// Tests of max_speed() (PCCD/Kinetic/flightplan_speed.h) on the three shipped flightplans against
// their speed measured by central differences on a fine grid: the bound is never below it, and at
// most sqrt(3) times above it (one coordinate maximum per axis).
#include <PCCD/Kinetic/flightplan_speed.h>

#include <catch2/catch.hpp>

#include <PCCD/Error.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Kinetic/Piecewise_linear_flightplan.h>
#include <PCCD/Kinetic/Polynomial_flightplan.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

static_assert(PCCD::PiecewiseCubicFlightplan<PCCD::Linear_flightplan>);
static_assert(PCCD::PiecewiseCubicFlightplan<PCCD::Piecewise_linear_flightplan>);
static_assert(PCCD::PiecewiseCubicFlightplan<PCCD::Polynomial_flightplan>);

namespace {

/// The largest speed of f over [t0, t1], by central differences at 4,001 times.
template <class F>
double measured_speed(const F& f, double t0, double t1)
{
    double best = 0.0;
    const double h = 1e-6 * (t1 - t0);
    for (int i = 0; i <= 4000; ++i) {
        const double t = std::clamp(t0 + (t1 - t0) * i / 4000.0, t0 + h, t1 - h);
        best = std::max(best, (f.position(t + h) - f.position(t - h)).norm() / (2.0 * h));
    }
    return best;
}

} // namespace

TEST_CASE("max_speed: linear, piecewise linear and cubic flightplans", "[kinetic]")
{
    const PCCD::Linear_flightplan line(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.3, -0.4, 1.2), 0.5);
    CHECK(PCCD::max_speed(line, -2.0, 7.0) == Approx(1.3).epsilon(1e-14));
    CHECK(PCCD::max_speed(line, 1.0, 1.0) == Approx(1.3).epsilon(1e-14));

    // Key frames: 1 unit along x in [0, 1], 3 units along y in [1, 2], at rest after t = 2 and before 0.
    const auto times = std::make_shared<const std::vector<double>>(std::vector<double>{0.0, 1.0, 2.0});
    const PCCD::Piecewise_linear_flightplan keys(times, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 3, 0)});
    CHECK(PCCD::max_speed(keys, 0.1, 0.9) == Approx(1.0).epsilon(1e-12));
    CHECK(PCCD::max_speed(keys, 0.5, 1.5) == Approx(3.0).epsilon(1e-12));
    CHECK(PCCD::max_speed(keys, 2.5, 4.0) == 0.0);
    CHECK(PCCD::max_speed(keys, -3.0, -1.0) == 0.0);
    CHECK(PCCD::max_speed(keys, -1.0, 5.0) == Approx(3.0).epsilon(1e-12));

    // A cubic Hermite spline with turns: the bound lies between the measured speed and sqrt(3) times it.
    const PCCD::Polynomial_flightplan spline = PCCD::Polynomial_flightplan::hermite(
        {0.0, 0.7, 1.5, 2.0}, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 2, 1), Eigen::Vector3d(-1, 0, 0)},
        {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(-1, 0, 2), Eigen::Vector3d(0, 0, 0)});
    for (const auto& [t0, t1] : std::vector<std::pair<double, double>>{{0.0, 2.0}, {0.2, 0.5}, {0.6, 1.7}, {1.9, 3.0}}) {
        const double bound = PCCD::max_speed(spline, t0, t1);
        const double measured = measured_speed(spline, t0, t1);
        INFO("[" << t0 << ", " << t1 << "]: bound " << bound << ", measured " << measured);
        CHECK(bound >= measured * (1.0 - 1e-6));
        CHECK(bound <= std::sqrt(3.0) * measured * (1.0 + 1e-6));
    }

    // Bad intervals.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(PCCD::max_speed(line, 1.0, 0.5), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::max_speed(line, nan, 1.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::max_speed(keys, 0.0, std::numeric_limits<double>::infinity()), PCCD::Invalid_input);
}
