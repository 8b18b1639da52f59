// The analytic test shapes of PCCD/testing/ (Sphere_shape, Torus_shape, Plane_patch_shape,
// Parallel_sheets_shape; doc/manual/sampling.md), each against an independent truth: analytic
// formulas, brute force over dense parametric grids, chi-square / Kolmogorov-Smirnov tests with fixed
// seeds.
//
// Statistical tests use fixed seeds and reject at significance level 0.001: the chi-square critical
// value is the Wilson-Hilferty approximation of the 0.999 quantile, the KS critical value 1.95/sqrt(N).
#include <PCCD/Random.h>
#include <PCCD/testing/Parallel_sheets_shape.h>
#include <PCCD/testing/Plane_patch_shape.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "sampling_test_helpers.h"

namespace {

using Eigen::Vector3d;
using namespace sampling_test;

// --- dense parametric brute force ------------------------------------------------------------------

// A surface patch parametrized over [0, 1]^2.
using Parametrization = std::function<Vector3d(double, double)>;

// The smallest distance from x to points S(u, v): a 160 x 160 grid over [0, 1]^2, then six rounds of
// a 21 x 21 grid over +-1 cell around the best point so far (each round shrinks the cell tenfold).
// Every candidate is a surface point, so the result is an upper bound of the true distance; the
// refinement makes it tight to about 1e-8 of the parameter range.
double brute_force_distance(const Parametrization& surface, const Vector3d& x)
{
    double best = std::numeric_limits<double>::infinity(), best_u = 0.0, best_v = 0.0;
    auto scan = [&](double u0, double u1, double v0, double v1, int steps) {
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; j <= steps; ++j) {
                const double u = std::clamp(u0 + (u1 - u0) * i / steps, 0.0, 1.0);
                const double v = std::clamp(v0 + (v1 - v0) * j / steps, 0.0, 1.0);
                const double d = (surface(u, v) - x).norm();
                if (d < best) best = d, best_u = u, best_v = v;
            }
    };
    int steps = 160;
    scan(0.0, 1.0, 0.0, 1.0, steps);
    double cell = 1.0 / steps;
    for (int round = 0; round < 6; ++round) {
        const double u = best_u, v = best_v;
        scan(u - cell, u + cell, v - cell, v + cell, 20);
        cell /= 10.0;
    }
    return best;
}

// --- shapes under test -----------------------------------------------------------------------------

const PCCD::testing::Sphere_shape sphere(Vector3d(0.3, -0.2, 0.5), 1.5);
const PCCD::testing::Torus_shape torus(1.0, 0.35, Vector3d(0.1, 0.2, -0.3));
// A tilted rectangle 1.5 x 1: edge1 = (1.2, 0.9, 0), edge2 = (-0.36, 0.48, 0.8), perpendicular.
const PCCD::testing::Plane_patch_shape patch(Vector3d(-0.5, 0.1, 0.2), Vector3d(1.2, 0.9, 0.0), Vector3d(-0.36, 0.48, 0.8));
const PCCD::testing::Parallel_sheets_shape sheets(Vector3d(-1.0, -0.5, 0.0), Vector3d(2.0, 0.0, 0.0), Vector3d(0.0, 1.0, 0.0),
                                         0.3);

Parametrization sphere_parametrization()
{
    return [](double u, double v) {
        const double theta = pi * u, phi = 2 * pi * v;
        return Vector3d(sphere.centre() +
                        sphere.radius() * Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                                   std::cos(theta)));
    };
}

Parametrization torus_parametrization()
{
    return [](double u, double v) {
        const double a = 2 * pi * u, b = 2 * pi * v, ring = torus.major_radius() + torus.minor_radius() * std::cos(b);
        return Vector3d(torus.centre() + Vector3d(ring * std::cos(a), ring * std::sin(a), torus.minor_radius() * std::sin(b)));
    };
}

Parametrization patch_parametrization(const PCCD::testing::Plane_patch_shape& p)
{
    return [p](double s, double t) { return Vector3d(p.corner() + s * p.edge1() + t * p.edge2()); };
}

// Independent on-surface tests (implicit equations), and the sign from the inside/outside test.
double torus_implicit(const Vector3d& x)
{
    const Vector3d d = x - torus.centre();
    const double rho = std::sqrt(d.x() * d.x() + d.y() * d.y());
    return (rho - torus.major_radius()) * (rho - torus.major_radius()) + d.z() * d.z() -
           torus.minor_radius() * torus.minor_radius();
}

bool on_patch(const PCCD::testing::Plane_patch_shape& p, const Vector3d& x, double tolerance)
{
    const Vector3d d = x - p.corner();
    const Vector3d n = p.edge1().cross(p.edge2()).normalized();
    const double s = d.dot(p.edge1()) / p.edge1().squaredNorm(), t = d.dot(p.edge2()) / p.edge2().squaredNorm();
    return std::abs(d.dot(n)) <= tolerance && s >= -tolerance && s <= 1 + tolerance && t >= -tolerance &&
           t <= 1 + tolerance;
}

template <class Shape>
void check_samples_on_shape(const Shape& shape, double size)
{
    PCCD::Random_engine rng(11);
    const PCCD::testing::Surface_sample s = shape.sample(4000, rng);
    REQUIRE(s.points.cols() == 4000);
    REQUIRE(s.normals.cols() == 4000);
    for (Eigen::Index i = 0; i < s.points.cols(); ++i) {
        const Vector3d p = s.points.col(i);
        REQUIRE(std::abs(shape.signed_distance(p)) < 1e-12 * size);
        REQUIRE((shape.closest_point(p) - p).norm() < 1e-12 * size);
        REQUIRE(std::abs(s.normals.col(i).norm() - 1.0) < 1e-12);
        REQUIRE((s.normals.col(i) - shape.normal(p)).norm() < 1e-9);
    }
}

} // namespace

// ==================================================================================================
// Analytic shapes
// ==================================================================================================

TEST_CASE("analytic shapes: noise-free samples lie on the shape with the shape's unit normal", "[sampling][shapes]")
{
    check_samples_on_shape(sphere, 1.5);
    check_samples_on_shape(torus, 1.35);
    check_samples_on_shape(patch, 1.5);
    check_samples_on_shape(sheets, 2.0);

    // Independent checks of the same samples: the implicit equations and the normals' formulas.
    PCCD::Random_engine rng(12);
    const auto ts = torus.sample(2000, rng);
    for (Eigen::Index i = 0; i < ts.points.cols(); ++i) {
        const Vector3d p = ts.points.col(i);
        REQUIRE(std::abs(torus_implicit(p)) < 1e-12);
        const Vector3d d = p - torus.centre();
        const Vector3d core = torus.centre() + torus.major_radius() * Vector3d(d.x(), d.y(), 0).normalized();
        REQUIRE((ts.normals.col(i) - (p - core) / torus.minor_radius()).norm() < 1e-12);
    }
    const auto ss = sheets.sample(2000, rng);
    int upper = 0;
    for (Eigen::Index i = 0; i < ss.points.cols(); ++i) {
        const double z = ss.points(2, i);
        REQUIRE((std::abs(z) < 1e-15 || std::abs(z - 0.3) < 1e-15));
        REQUIRE(ss.normals(2, i) == (z > 0.15 ? 1.0 : -1.0)); // outward: +z on top, -z below
        upper += z > 0.15;
    }
    // Each sheet is chosen with probability 1/2: binomial(2000, 1/2), 4 standard deviations = 89.
    CHECK(std::abs(upper - 1000) < 89);
}

TEST_CASE("analytic shapes: mean spacing matches 0.5 sqrt(A/N) within 5 %", "[sampling][shapes][spacing]")
{
    const double n = 20000;
    PCCD::Random_engine rng(21);
    struct Case {
        std::string name;
        Eigen::Matrix3Xd points;
        double expected;
    };
    // The patch and the sheets have a border: Donnelly's correction (see expected_spacing), applied
    // per sheet for the sheets (about n/2 points on each; their gap 0.3 is 40 spacings wide).
    const std::vector<Case> cases = {
        {"sphere", sphere.sample(std::size_t(n), rng).points, expected_spacing(sphere.area(), n)},
        {"torus", torus.sample(std::size_t(n), rng).points, expected_spacing(torus.area(), n)},
        {"patch", patch.sample(std::size_t(n), rng).points, expected_spacing(patch.area(), n, patch.perimeter())},
        {"sheets", sheets.sample(std::size_t(n), rng).points,
         expected_spacing(sheets.area() / 2, n / 2, sheets.sheet(0).perimeter())},
    };
    for (const auto& c : cases) {
        const double measured = measured_spacing(c.points);
        CAPTURE(c.name, measured, c.expected, measured / c.expected - 1.0);
        CHECK(std::abs(measured / c.expected - 1.0) < 0.05);
    }
}

TEST_CASE("analytic shapes: areas are the analytic ones", "[sampling][shapes]")
{
    CHECK(sphere.area() == Approx(4 * pi * 1.5 * 1.5).epsilon(1e-15));
    CHECK(torus.area() == Approx(4 * pi * pi * 1.0 * 0.35).epsilon(1e-15));
    CHECK(patch.area() == Approx(1.5).epsilon(1e-15));
    CHECK(sheets.area() == Approx(4.0).epsilon(1e-15));
}

TEST_CASE("sphere samples: z is uniform in [-r, r] (Archimedes), Kolmogorov-Smirnov", "[sampling][shapes][statistics]")
{
    PCCD::Random_engine rng(31);
    const std::size_t n = 50000;
    const auto s = sphere.sample(n, rng);
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) z[i] = (s.points(2, Eigen::Index(i)) - sphere.centre().z()) / sphere.radius();
    std::sort(z.begin(), z.end());
    double d = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double cdf = (z[i] + 1.0) / 2.0;
        d = std::max({d, std::abs(cdf - double(i) / n), std::abs(cdf - double(i + 1) / n)});
    }
    CAPTURE(d * std::sqrt(double(n)));
    CHECK(d < 1.95 / std::sqrt(double(n)));
    // The azimuth is uniform too (chi-square over 16 sectors).
    std::vector<double> sectors(16, 0.0), expected(16, double(n) / 16);
    for (std::size_t i = 0; i < n; ++i) {
        const Vector3d p = s.points.col(Eigen::Index(i)) - sphere.centre();
        const double phi = std::atan2(p.y(), p.x()) + pi;
        sectors[std::min<std::size_t>(15, std::size_t(phi / (2 * pi) * 16))] += 1;
    }
    CHECK(chi_square(sectors, expected) < chi_square_critical(15));
}

TEST_CASE("torus samples: poloidal density is proportional to R + r cos v", "[sampling][shapes][statistics]")
{
    PCCD::Random_engine rng(41);
    const std::size_t n = 60000;
    const int bins = 24;
    const auto s = torus.sample(n, rng);
    const double big_r = torus.major_radius(), small_r = torus.minor_radius();
    std::vector<double> counts(bins, 0.0), expected(bins), naive(bins, double(n) / bins);
    for (int b = 0; b < bins; ++b) {
        const double v0 = -pi + 2 * pi * b / bins, v1 = -pi + 2 * pi * (b + 1) / bins;
        // Integral of (R + r cos v) over the bin, divided by 2 pi R.
        expected[b] = double(n) * (big_r * (v1 - v0) + small_r * (std::sin(v1) - std::sin(v0))) / (2 * pi * big_r);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Vector3d d = s.points.col(Eigen::Index(i)) - torus.centre();
        const double v = std::atan2(d.z(), std::hypot(d.x(), d.y()) - big_r);
        counts[std::min(bins - 1, int((v + pi) / (2 * pi) * bins))] += 1;
    }
    const double x2 = chi_square(counts, expected);
    CAPTURE(x2, chi_square_critical(bins - 1));
    CHECK(x2 < chi_square_critical(bins - 1));
    // The test has power: the same counts are far from a uniform poloidal angle.
    CHECK(chi_square(counts, naive) > 10 * chi_square_critical(bins - 1));
}

TEST_CASE("noise has the requested standard deviation and leaves normals exact", "[sampling][shapes][noise]")
{
    const double sigma = 0.01;
    const std::size_t n = 20000;
    auto check_noise = [&](const Eigen::Matrix3Xd& clean, const Eigen::Matrix3Xd& noisy) {
        const Eigen::ArrayXXd e = (noisy - clean).array();
        const double mean = e.mean();
        const double sd = std::sqrt((e - mean).square().sum() / double(e.size() - 1));
        const double within_one_sigma = (e.abs() < sigma).cast<double>().mean();
        CAPTURE(mean, sd, within_one_sigma);
        // 3n = 60000 values: the standard error of sd is sigma / sqrt(2 * 3n) ~ 0.3 %; of the mean
        // sigma / sqrt(3n) ~ 0.004 sigma; of the 1-sigma fraction ~ 0.002.
        CHECK(std::abs(sd / sigma - 1.0) < 0.015);
        CHECK(std::abs(mean) < 0.02 * sigma);
        CHECK(std::abs(within_one_sigma - 0.682689) < 0.01);
    };
    auto check_shape = [&](const auto& shape, std::uint64_t seed) {
        PCCD::Random_engine a(seed), b(seed);
        const auto clean = shape.sample(n, a);
        const auto noisy = shape.sample(n, b, {.noise_sigma = sigma});
        check_noise(clean.points, noisy.points);
        CHECK(noisy.normals == clean.normals);
    };
    check_shape(sphere, 51);
    check_shape(torus, 52);
    check_shape(patch, 53);
    check_shape(sheets, 54);

    // Independent of the clean sample: a horizontal square's noisy z is N(0, sigma^2), and a large
    // sphere's signed distance is nearly the normal component of the noise.
    PCCD::Random_engine rng(55);
    const PCCD::testing::Plane_patch_shape square(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0));
    const auto flat = square.sample(n, rng, {.noise_sigma = sigma});
    CHECK(std::abs(std::sqrt(flat.points.row(2).array().square().mean()) / sigma - 1.0) < 0.03);
    const auto noisy = sphere.sample(n, rng, {.noise_sigma = sigma});
    double sum2 = 0.0;
    for (Eigen::Index i = 0; i < noisy.points.cols(); ++i) sum2 += std::pow(sphere.signed_distance(noisy.points.col(i)), 2);
    CHECK(std::abs(std::sqrt(sum2 / double(n)) / sigma - 1.0) < 0.03);

    // Bad noise is rejected.
    CHECK_THROWS_WITH(sphere.sample(10, rng, {.noise_sigma = -1.0}), Catch::Contains("noise_sigma"));
    CHECK_THROWS_AS(sphere.sample(10, rng, {.noise_sigma = std::numeric_limits<double>::quiet_NaN()}),
                    PCCD::Invalid_input);
}

TEST_CASE("sampling is deterministic for a seed", "[sampling][shapes]")
{
    PCCD::Random_engine a(61), b(61), c(62);
    const auto sa = torus.sample(100, a, {.noise_sigma = 0.01});
    const auto sb = torus.sample(100, b, {.noise_sigma = 0.01});
    const auto sc = torus.sample(100, c, {.noise_sigma = 0.01});
    CHECK(sa.points == sb.points);
    CHECK(sa.normals == sb.normals);
    CHECK(sa.points != sc.points);
    CHECK(torus.sample(0, a).points.cols() == 0);
}

// ==================================================================================================
// Signed distance against brute force
// ==================================================================================================

namespace {

// For a query x: closest_point lies on the shape (checked by `on_shape`), |x - closest_point| equals
// |signed_distance|, no point of the dense parametric sample is nearer than |signed_distance|, the
// nearest refined one is at most 1e-7 farther, and the sign is `expected_negative`.
template <class Shape, class On_shape>
void check_distance(const Shape& shape, const std::vector<Parametrization>& surfaces, const Vector3d& x,
                    bool expected_negative, const On_shape& on_shape)
{
    const double sd = shape.signed_distance(x);
    const Vector3d cp = shape.closest_point(x);
    double brute = std::numeric_limits<double>::infinity();
    for (const auto& s : surfaces) brute = std::min(brute, brute_force_distance(s, x));
    CAPTURE(x.transpose(), sd, brute, cp.transpose());
    REQUIRE(on_shape(cp));
    REQUIRE(std::abs((x - cp).norm() - std::abs(sd)) < 1e-12);
    REQUIRE(std::abs(sd) <= brute + 1e-12);
    REQUIRE(brute - std::abs(sd) < 1e-7);
    if (std::abs(sd) > 1e-12) REQUIRE((sd < 0) == expected_negative);
    REQUIRE(std::abs(shape.normal(x).norm() - 1.0) < 1e-12);
}

// Random queries in the box [lo, hi]^3 around `centre`.
std::vector<Vector3d> random_queries(const Vector3d& centre, double half_width, int count, std::uint64_t seed)
{
    PCCD::Random_engine rng(seed);
    std::vector<Vector3d> q;
    for (int i = 0; i < count; ++i)
        q.push_back(centre + Vector3d(PCCD::uniform_real(rng, -half_width, half_width),
                                      PCCD::uniform_real(rng, -half_width, half_width),
                                      PCCD::uniform_real(rng, -half_width, half_width)));
    return q;
}

} // namespace

TEST_CASE("sphere: signed distance and closest point against brute force", "[sampling][shapes][distance]")
{
    auto queries = random_queries(sphere.centre(), 3.0, 150, 71);
    queries.push_back(sphere.centre()); // every point is nearest: the convention +z
    for (double offset : {-1e-3, 1e-3, -0.7, 0.7}) queries.push_back(sphere.centre() + (1.5 + offset) * Vector3d(0.6, 0, 0.8));
    for (const Vector3d& x : queries)
        check_distance(sphere, {sphere_parametrization()}, x, (x - sphere.centre()).norm() < 1.5,
                       [](const Vector3d& p) { return std::abs((p - sphere.centre()).norm() - 1.5) < 1e-12; });
    CHECK(sphere.closest_point(sphere.centre()) == sphere.centre() + Vector3d(0, 0, 1.5));
}

TEST_CASE("torus: signed distance and closest point against brute force, near the axis too", "[sampling][shapes][distance]")
{
    auto queries = random_queries(torus.centre(), 2.0, 150, 72);
    const Vector3d c = torus.centre();
    // On and near the axis (all meridians tie on it), inside the hole, inside the tube, on the core
    // circle (all tube points tie) and just off the surface.
    for (double z : {-0.8, -0.2, 0.0, 0.1, 0.5})
        for (double rho : {0.0, 1e-9, 1e-3, 0.2})
            queries.push_back(c + Vector3d(rho * 0.6, rho * 0.8, z));
    for (double angle : {0.3, 2.0, 4.0}) {
        const Vector3d radial(std::cos(angle), std::sin(angle), 0);
        queries.push_back(c + 1.0 * radial);                           // on the core circle
        queries.push_back(c + 1.1 * radial + Vector3d(0, 0, 0.1));     // inside the tube
        queries.push_back(c + (1.35 + 1e-4) * radial);                 // just outside
        queries.push_back(c + (0.65 - 1e-4) * radial);                 // just outside, hole side
        queries.push_back(c + (0.65 + 1e-4) * radial);                 // just inside, hole side
    }
    for (const Vector3d& x : queries)
        check_distance(torus, {torus_parametrization()}, x, torus_implicit(x) < 0,
                       [](const Vector3d& p) { return std::abs(torus_implicit(p)) < 1e-12; });
    // Conventions where the nearest point is not unique.
    CHECK((torus.closest_point(c) - (c + Vector3d(0.65, 0, 0))).norm() < 1e-15);
    CHECK((torus.closest_point(c + Vector3d(0, 1, 0)) - (c + Vector3d(0, 1.35, 0))).norm() < 1e-15);
}

TEST_CASE("plane patch: signed distance against brute force, near the boundary too", "[sampling][shapes][distance]")
{
    const Vector3d n = patch.edge1().cross(patch.edge2()).normalized();
    const Vector3d centre = patch.corner() + 0.5 * (patch.edge1() + patch.edge2());
    auto queries = random_queries(centre, 2.0, 150, 73);
    const Vector3d u = patch.edge1().normalized(), v = patch.edge2().normalized();
    // Points near each edge and corner: just inside / outside laterally, just above / below.
    for (double s : {-1e-3, 0.0, 1e-3, 0.5, 1.0 - 1e-3, 1.0, 1.0 + 1e-3})
        for (double h : {-1e-3, 1e-3, 0.2}) {
            queries.push_back(patch.corner() + s * patch.edge1() - 1e-3 * v + h * n);
            queries.push_back(patch.corner() + s * patch.edge1() + patch.edge2() + 1e-3 * v + h * n);
            queries.push_back(patch.corner() + s * patch.edge2() - 1e-3 * u + h * n);
            queries.push_back(patch.corner() + s * patch.edge2() + patch.edge1() + 2e-3 * u - h * n);
        }
    for (const Vector3d& x : queries)
        check_distance(patch, {patch_parametrization(patch)}, x, (x - patch.corner()).dot(n) < 0,
                       [](const Vector3d& p) { return on_patch(patch, p, 1e-12); });
    CHECK(patch.normal(centre + n) == n);
}

TEST_CASE("parallel sheets: signed distance to the nearer sheet against brute force", "[sampling][shapes][distance]")
{
    auto queries = random_queries(Vector3d(0, 0, 0.15), 1.5, 150, 74);
    for (double z : {-1e-3, 1e-3, 0.1, 0.2, 0.3 - 1e-3, 0.3 + 1e-3})
        for (const Vector3d& lateral : {Vector3d(0.2, 0.1, 0), Vector3d(1.0 + 1e-3, 0.5, 0), Vector3d(-1.2, 0.0, 0),
                                         Vector3d(0.0, 0.5 + 1e-3, 0)})
            queries.push_back(lateral + Vector3d(0, 0, z));
    const std::vector<Parametrization> both = {patch_parametrization(sheets.sheet(0)),
                                               patch_parametrization(sheets.sheet(1))};
    for (const Vector3d& x : queries)
        // Outward normals: negative exactly between the two planes z = 0 and z = 0.3.
        check_distance(sheets, both, x, x.z() > 0.0 && x.z() < 0.3, [](const Vector3d& p) {
            return on_patch(sheets.sheet(0), p, 1e-12) || on_patch(sheets.sheet(1), p, 1e-12);
        });
    CHECK(sheets.normal(Vector3d(0, 0, 0.1)) == Vector3d(0, 0, -1));
    CHECK(sheets.normal(Vector3d(0, 0, 0.2)) == Vector3d(0, 0, 1));
}

TEST_CASE("analytic shapes reject invalid parameters", "[sampling][shapes][errors]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(PCCD::testing::Sphere_shape(Vector3d::Zero(), 0.0), Catch::Contains("radius"));
    CHECK_THROWS_AS(PCCD::testing::Sphere_shape(Vector3d(nan, 0, 0), 1.0), PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::testing::Torus_shape(0.5, 0.5), Catch::Contains("R > r > 0"));
    CHECK_THROWS_AS(PCCD::testing::Torus_shape(1.0, -0.1), PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::testing::Plane_patch_shape(Vector3d::Zero(), Vector3d(1, 0, 0), Vector3d(1, 1, 0)),
                      Catch::Contains("perpendicular"));
    CHECK_THROWS_WITH(PCCD::testing::Plane_patch_shape(Vector3d::Zero(), Vector3d(1, 0, 0), Vector3d::Zero()),
                      Catch::Contains("edge2 has zero length"));
    CHECK_THROWS_WITH(PCCD::testing::Parallel_sheets_shape(Vector3d::Zero(), Vector3d(1, 0, 0), Vector3d(0, 1, 0), 0.0),
                      Catch::Contains("gap"));
}
