// Test data of PCCD (doc/manual/sampling.md): analytic shapes, triangle-mesh sampling,
// normalization, rigid transforms and benchmark poses, each against an independent truth
// (analytic formulas, brute force over dense parametric grids, chi-square / Kolmogorov-Smirnov
// tests with fixed seeds).
//
// Statistical tests use fixed seeds and reject at significance level 0.001: the chi-square critical
// value is the Wilson-Hilferty approximation of the 0.999 quantile, the KS critical value 1.95/sqrt(N).
#include <PCCD/Point_cloud.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/Sampling/Parallel_sheets_shape.h>
#include <PCCD/Sampling/Plane_patch_shape.h>
#include <PCCD/Sampling/Sphere_shape.h>
#include <PCCD/Sampling/Torus_shape.h>
#include <PCCD/Sampling/Similarity_3.h>
#include <PCCD/Sampling/pose_generator.h>
#include <PCCD/Sampling/sample_triangle_mesh.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>
#include "data_helpers.h"

namespace {

using Eigen::Vector3d;
constexpr double pi = std::numbers::pi;

// --- statistics ------------------------------------------------------------------------------------

// 0.999 quantile of the chi-square distribution with `df` degrees of freedom (Wilson-Hilferty).
double chi_square_critical(double df)
{
    const double z = 3.0902; // standard normal 0.999 quantile
    const double a = 2.0 / (9.0 * df);
    return df * std::pow(1.0 - a + z * std::sqrt(a), 3);
}

double chi_square(const std::vector<double>& observed, const std::vector<double>& expected)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < observed.size(); ++i)
        sum += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    return sum;
}

// Expected mean nearest-neighbour distance of n uniform random points on a surface of area A:
// 0.5 sqrt(A / n). For a region with a border of length L, Donnelly's (1978) edge correction
// + (0.0514 + 0.041 / sqrt(n)) L / n accounts for the missing neighbours beyond the border.
double expected_spacing(double area, double n, double border_length = 0.0)
{
    return 0.5 * std::sqrt(area / n) + (0.0514 + 0.041 / std::sqrt(n)) * border_length / n;
}

double measured_spacing(const Eigen::Matrix3Xd& points) { return PCCD::Point_cloud<>(points).mean_spacing(); }

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

// --- meshes built in the test ----------------------------------------------------------------------

struct Mesh {
    std::vector<Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;
};

double triangle_area(const Mesh& m, std::size_t k)
{
    const auto& t = m.triangles[k];
    return 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
}

// An axis-aligned box [0, a] x [0, b] x [0, c], 12 outward triangles, followed by three degenerate
// triangles (a repeated vertex, three collinear vertices, a triangle of one vertex).
Mesh box_with_degenerate_triangles(double a, double b, double c)
{
    Mesh m;
    for (int i = 0; i < 8; ++i) m.vertices.emplace_back((i & 1) ? a : 0.0, (i & 2) ? b : 0.0, (i & 4) ? c : 0.0);
    m.vertices.emplace_back(a / 2, 0.0, 0.0); // vertex 8, the midpoint of edge 0-1
    m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5},
                   {0, 0, 3}, {0, 8, 1}, {5, 5, 5}};
    return m;
}

// An icosahedron subdivided `levels` times with its vertices pushed onto the unit sphere.
Mesh icosphere(int levels)
{
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Mesh m;
    for (const auto& v : {Vector3d(-1, t, 0), Vector3d(1, t, 0), Vector3d(-1, -t, 0), Vector3d(1, -t, 0),
                          Vector3d(0, -1, t), Vector3d(0, 1, t), Vector3d(0, -1, -t), Vector3d(0, 1, -t),
                          Vector3d(t, 0, -1), Vector3d(t, 0, 1), Vector3d(-t, 0, -1), Vector3d(-t, 0, 1)})
        m.vertices.push_back(v.normalized());
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> midpoint;
        auto middle = [&](int i, int j) {
            const auto key = std::minmax(i, j);
            const auto found = midpoint.find(key);
            if (found != midpoint.end()) return found->second;
            m.vertices.push_back((m.vertices[i] + m.vertices[j]).normalized());
            return midpoint[key] = int(m.vertices.size()) - 1;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto& [a, b, c] : m.triangles) {
            const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
            finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        m.triangles = finer;
    }
    return m;
}

// --- shapes under test -----------------------------------------------------------------------------

const PCCD::Sphere_shape sphere(Vector3d(0.3, -0.2, 0.5), 1.5);
const PCCD::Torus_shape torus(1.0, 0.35, Vector3d(0.1, 0.2, -0.3));
// A tilted rectangle 1.5 x 1: edge1 = (1.2, 0.9, 0), edge2 = (-0.36, 0.48, 0.8), perpendicular.
const PCCD::Plane_patch_shape patch(Vector3d(-0.5, 0.1, 0.2), Vector3d(1.2, 0.9, 0.0), Vector3d(-0.36, 0.48, 0.8));
const PCCD::Parallel_sheets_shape sheets(Vector3d(-1.0, -0.5, 0.0), Vector3d(2.0, 0.0, 0.0), Vector3d(0.0, 1.0, 0.0),
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

Parametrization patch_parametrization(const PCCD::Plane_patch_shape& p)
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

bool on_patch(const PCCD::Plane_patch_shape& p, const Vector3d& x, double tolerance)
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
    const PCCD::Surface_sample s = shape.sample(4000, rng);
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
    const PCCD::Plane_patch_shape square(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0));
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
    CHECK_THROWS_WITH(PCCD::Sphere_shape(Vector3d::Zero(), 0.0), Catch::Contains("radius"));
    CHECK_THROWS_AS(PCCD::Sphere_shape(Vector3d(nan, 0, 0), 1.0), PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::Torus_shape(0.5, 0.5), Catch::Contains("R > r > 0"));
    CHECK_THROWS_AS(PCCD::Torus_shape(1.0, -0.1), PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::Plane_patch_shape(Vector3d::Zero(), Vector3d(1, 0, 0), Vector3d(1, 1, 0)),
                      Catch::Contains("perpendicular"));
    CHECK_THROWS_WITH(PCCD::Plane_patch_shape(Vector3d::Zero(), Vector3d(1, 0, 0), Vector3d::Zero()),
                      Catch::Contains("edge2 has zero length"));
    CHECK_THROWS_WITH(PCCD::Parallel_sheets_shape(Vector3d::Zero(), Vector3d(1, 0, 0), Vector3d(0, 1, 0), 0.0),
                      Catch::Contains("gap"));
}

// ==================================================================================================
// Triangle meshes
// ==================================================================================================

TEST_CASE("mesh sampling: counts per triangle are proportional to area, degenerate ones never drawn", "[sampling][mesh][statistics]")
{
    for (const auto& [name, mesh, n] : {std::tuple{"box", box_with_degenerate_triangles(1.0, 2.0, 3.0), 60000},
                                        std::tuple{"icosphere", icosphere(2), 100000}}) {
        CAPTURE(name);
        PCCD::Random_engine rng(81);
        const auto s = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, std::size_t(n), rng);
        REQUIRE(s.triangles.size() == std::size_t(n));
        double total = 0.0;
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k) total += triangle_area(mesh, k);
        std::vector<double> observed, expected;
        std::vector<double> counts(mesh.triangles.size(), 0.0);
        for (const std::size_t k : s.triangles) counts.at(k) += 1;
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
            if (triangle_area(mesh, k) == 0.0) {
                CHECK(counts[k] == 0);
                continue;
            }
            observed.push_back(counts[k]);
            expected.push_back(n * triangle_area(mesh, k) / total);
        }
        const double x2 = chi_square(observed, expected);
        CAPTURE(x2, observed.size());
        CHECK(x2 < chi_square_critical(double(observed.size() - 1)));

        // Each point lies in its triangle and carries its (outward) normal.
        for (Eigen::Index i = 0; i < s.points.cols(); ++i) {
            const auto& t = mesh.triangles[s.triangles[std::size_t(i)]];
            const Vector3d a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
            const Vector3d normal = (b - a).cross(c - a).normalized();
            REQUIRE((s.normals.col(i) - normal).norm() < 1e-12);
            const Vector3d p = s.points.col(i);
            REQUIRE(std::abs((p - a).dot(normal)) < 1e-12);
            // Barycentric coordinates (areas of the sub-triangles, signed by the normal) all >= 0.
            for (int e = 0; e < 3; ++e) {
                const Vector3d q0 = mesh.vertices[t[e]], q1 = mesh.vertices[t[(e + 1) % 3]];
                REQUIRE((q1 - q0).cross(p - q0).dot(normal) >= -1e-12);
            }
            REQUIRE(normal.dot(p - (name == std::string("box") ? Vector3d(0.5, 1, 1.5) : Vector3d::Zero())) > 0);
        }
    }
}

TEST_CASE("mesh sampling: mean spacing matches 0.5 sqrt(A/N) within 5 %", "[sampling][mesh][spacing]")
{
    const std::size_t n = 20000;
    for (const auto& [name, mesh] : {std::pair{"box", box_with_degenerate_triangles(1.0, 2.0, 3.0)},
                                     std::pair{"icosphere", icosphere(3)}}) {
        PCCD::Random_engine rng(91);
        double area = 0.0;
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k) area += triangle_area(mesh, k);
        const double measured = measured_spacing(PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, rng).points);
        const double expected = expected_spacing(area, double(n));
        CAPTURE(name, measured, expected, measured / expected - 1.0);
        CHECK(std::abs(measured / expected - 1.0) < 0.05);
    }
}

TEST_CASE("mesh sampling: the bunny (libcgal-demo data), generic point and face types", "[sampling][mesh][data]")
{
    const std::string dir = PCCD_DATA_DIR;
    if (dir.empty()) {
        PCCD_SKIP_TEST("bunny00.off of libcgal-demo not found (PCCD_DATA_DIR is empty); the procedural meshes are tested elsewhere");
    }
    // CGAL points and std::vector<std::size_t> faces, as CGAL's polygon-soup reader gives them.
    using Point = CGAL::Simple_cartesian<double>::Point_3;
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> faces;
    REQUIRE(CGAL::IO::read_OFF(dir + "/bunny00.off", points, faces));
    REQUIRE(points.size() == 37706);
    double area = 0.0;
    for (const auto& f : faces) area += std::sqrt(CGAL::squared_area(points[f[0]], points[f[1]], points[f[2]]));

    const std::size_t n = 40000;
    PCCD::Random_engine rng(101);
    const auto s = PCCD::sample_triangle_mesh(points, faces, n, rng);
    const double measured = measured_spacing(s.points);
    const double expected = expected_spacing(area, double(n));
    CAPTURE(area, measured, expected, measured / expected - 1.0);
    CHECK(std::abs(measured / expected - 1.0) < 0.05);
    for (Eigen::Index i = 0; i < s.points.cols(); ++i) {
        const auto& f = faces[s.triangles[std::size_t(i)]];
        const Vector3d a(points[f[0]].x(), points[f[0]].y(), points[f[0]].z());
        REQUIRE(std::abs((s.points.col(i) - a).dot(s.normals.col(i))) < 1e-12);
    }
}

TEST_CASE("mesh sampling: vertices as std::array, noise and determinism", "[sampling][mesh]")
{
    const Mesh m = icosphere(1);
    std::vector<std::array<double, 3>> arrays;
    for (const auto& v : m.vertices) arrays.push_back({v.x(), v.y(), v.z()});
    PCCD::Random_engine a(111), b(111), c(111);
    const auto from_eigen = PCCD::sample_triangle_mesh(m.vertices, m.triangles, 500, a);
    const auto from_arrays = PCCD::sample_triangle_mesh(arrays, m.triangles, 500, b);
    CHECK(from_eigen.points == from_arrays.points);
    CHECK(from_eigen.triangles == from_arrays.triangles);
    const auto noisy = PCCD::sample_triangle_mesh(m.vertices, m.triangles, 500, c, {.noise_sigma = 0.5});
    CHECK(noisy.triangles == from_eigen.triangles); // noise is drawn after the points
    CHECK(noisy.normals == from_eigen.normals);
    CHECK((noisy.points - from_eigen.points).norm() > 1.0);
}

TEST_CASE("mesh sampling rejects empty, degenerate and malformed meshes", "[sampling][mesh][errors]")
{
    PCCD::Random_engine rng(121);
    const std::vector<Vector3d> v = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(2, 0, 0)};
    using Faces = std::vector<std::array<int, 3>>;
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(v, Faces{}, 10, rng), Catch::Contains("no triangles"));
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(std::vector<Vector3d>{}, Faces{}, 10, rng),
                      Catch::Contains("no triangles"));
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(v, Faces{{0, 1, 3}, {2, 2, 2}}, 10, rng),
                      Catch::Contains("all 2 mesh triangles are degenerate"));
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(v, Faces{{0, 1, 2}, {0, 1, 4}}, 10, rng),
                      Catch::Contains("face 1 refers to vertex 4; the mesh has 4 vertices"));
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(v, Faces{{0, -1, 2}}, 10, rng), Catch::Contains("vertex -1"));
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(v, std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}}, 10, rng),
                      Catch::Contains("face 0 has 4 vertices"));
    std::vector<Vector3d> bad = v;
    bad[2].y() = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(PCCD::sample_triangle_mesh(bad, Faces{{0, 1, 2}}, 10, rng), Catch::Contains("vertex 2"));
    CHECK_THROWS_AS(PCCD::sample_triangle_mesh(v, Faces{{0, 1, 2}}, 10, rng, {.noise_sigma = -1}), PCCD::Invalid_input);
    CHECK(PCCD::sample_triangle_mesh(v, Faces{{0, 1, 2}}, 0, rng).points.cols() == 0);
}

// ==================================================================================================
// Normalization
// ==================================================================================================

TEST_CASE("normalize: bounding box centred, longest side exactly 2", "[sampling][normalize]")
{
    PCCD::Random_engine rng(131);
    const Vector3d offset(1000.0, -250.0, 3.0), extent(3.0, 0.5, 7.0);
    Eigen::Matrix3Xd c(3, 5000);
    for (Eigen::Index i = 0; i < c.cols(); ++i)
        for (int k = 0; k < 3; ++k) c(k, i) = offset[k] + extent[k] * PCCD::uniform_01(rng);
    const Eigen::Matrix3Xd original = c;
    const PCCD::Similarity_3 s = PCCD::normalize_to_unit_cube(c);
    const Vector3d lo = c.rowwise().minCoeff(), hi = c.rowwise().maxCoeff();
    CAPTURE(lo.transpose(), hi.transpose());
    CHECK(((lo + hi) / 2).norm() < 1e-12);
    CHECK(std::abs((hi - lo).maxCoeff() - 2.0) < 1e-12);
    CHECK(std::abs(hi.z() - 1.0) < 1e-12); // z is the longest side: it touches both faces
    CHECK(std::abs(lo.z() + 1.0) < 1e-12);
    CHECK((c.array().abs() <= 1.0 + 1e-12).all());
    CHECK(s.scale == Approx(2.0 / (original.row(2).maxCoeff() - original.row(2).minCoeff())).epsilon(1e-15));

    // The returned similarity reproduces the result, point by point and in affine form.
    for (Eigen::Index i = 0; i < c.cols(); i += 97) {
        CHECK((s.transform_point(original.col(i)) - c.col(i)).norm() < 1e-15);
        CHECK((s.scale * original.col(i) + s.translation() - c.col(i)).norm() < 1e-9);
    }
    // The point-range overload (CGAL points, std::array) gives the same similarity.
    std::vector<CGAL::Simple_cartesian<double>::Point_3> cgal_points;
    std::vector<std::array<double, 3>> arrays;
    for (Eigen::Index i = 0; i < original.cols(); ++i) {
        cgal_points.emplace_back(original(0, i), original(1, i), original(2, i));
        arrays.push_back({original(0, i), original(1, i), original(2, i)});
    }
    for (const PCCD::Similarity_3& t :
         {PCCD::compute_unit_cube_normalization(cgal_points), PCCD::compute_unit_cube_normalization(arrays)}) {
        CHECK(t.scale == s.scale);
        CHECK(t.centre == s.centre);
    }

    // float coordinates.
    Eigen::Matrix3Xf f = original.cast<float>();
    PCCD::normalize_to_unit_cube(f);
    CHECK(std::abs((f.rowwise().maxCoeff() - f.rowwise().minCoeff()).maxCoeff() - 2.0f) < 1e-5f);
}

TEST_CASE("normalize: a mesh and its sample are normalized identically", "[sampling][normalize][mesh]")
{
    Mesh m = box_with_degenerate_triangles(4.0, 1.0, 2.0);
    for (auto& v : m.vertices) v += Vector3d(5, 6, 7);
    PCCD::Random_engine rng(141);
    const auto sample = PCCD::sample_triangle_mesh(m.vertices, m.triangles, 1000, rng);
    const PCCD::Similarity_3 s = PCCD::compute_unit_cube_normalization(m.vertices);
    CHECK(s.scale == 0.5);
    CHECK((s.centre - Vector3d(7, 6.5, 8)).norm() == 0.0);
    const Eigen::Matrix3Xd normalized = s.transform_points(sample.points);
    CHECK((normalized.array().abs() <= 1.0 + 1e-12).all());
}

TEST_CASE("normalize rejects degenerate input", "[sampling][normalize][errors]")
{
    Eigen::Matrix3Xd same(3, 4);
    same.colwise() = Vector3d(1, 2, 3);
    CHECK_THROWS_WITH(PCCD::normalize_to_unit_cube(same), Catch::Contains("all 4 points coincide"));
    Eigen::Matrix3Xd empty(3, 0);
    CHECK_THROWS_WITH(PCCD::normalize_to_unit_cube(empty), Catch::Contains("no points"));
    Eigen::Matrix3Xd with_nan = Eigen::Matrix3Xd::Zero(3, 5);
    with_nan.row(0).setLinSpaced(5, 0.0, 1.0);
    with_nan(1, 3) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(PCCD::normalize_to_unit_cube(with_nan), Catch::Contains("point 3"));
    CHECK_THROWS_AS(PCCD::compute_unit_cube_normalization(std::vector<Vector3d>{}), PCCD::Invalid_input);
}

// ==================================================================================================
// Rigid_transform_3
// ==================================================================================================

namespace {

Eigen::Matrix3d some_rotation()
{
    return Eigen::AngleAxisd(0.7, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
}

} // namespace

TEST_CASE("Rigid_transform_3: construction, application, composition and inverse", "[sampling][transform]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(0.5, -1.0, 2.0);
    const PCCD::Rigid_transform_3<> a(r, t);
    CHECK((a.rotation() - r).norm() < 1e-15);
    CHECK(a.translation() == t);
    const Vector3d x(0.3, 0.2, -0.7);
    CHECK((a.transform_point(x) - (r * x + t)).norm() < 1e-15);
    CHECK((a.transform_vector(x) - r * x).norm() < 1e-15);

    // From 12 numbers, row-major [R | t].
    std::array<double, 12> rows{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) rows[4 * i + j] = r(i, j);
        rows[4 * i + 3] = t[i];
    }
    const PCCD::Rigid_transform_3<> from_rows(rows);
    CHECK((from_rows.matrix() - a.matrix()).norm() == 0.0);
    const PCCD::Rigid_transform_3<> shift({1, 0, 0, 4, 0, 1, 0, 5, 0, 0, 1, 6});
    CHECK(shift.transform_point(Vector3d(1, 1, 1)) == Vector3d(5, 6, 7));

    // Composition: (b * a)(x) = b(a(x)); inverse.
    const PCCD::Rigid_transform_3<> b(Eigen::AngleAxisd(-1.9, Vector3d::UnitZ()).toRotationMatrix(), Vector3d(3, 0, 1));
    CHECK(((b * a).transform_point(x) - b.transform_point(a.transform_point(x))).norm() < 1e-14);
    CHECK(((a * a.inverse()).matrix() - PCCD::Rigid_transform_3<>::identity().matrix()).norm() < 1e-14);
    CHECK(((a.inverse() * a).transform_point(x) - x).norm() < 1e-14);
    CHECK((a.inverse().inverse().matrix() - a.matrix()).norm() < 1e-14);
    CHECK(PCCD::Rigid_transform_3<>().matrix() == PCCD::Rigid_transform_3<>::identity().matrix());

    Eigen::Matrix3Xd many(3, 20);
    for (Eigen::Index i = 0; i < many.cols(); ++i) many.col(i) << 0.1 * double(i), 1.0 - 0.3 * double(i), 2.0;
    const Eigen::Matrix3Xd moved = a.transform_points(many);
    for (Eigen::Index i = 0; i < many.cols(); ++i) CHECK((moved.col(i) - a.transform_point(many.col(i))).norm() < 1e-15);

    // float.
    const PCCD::Rigid_transform_3<float> af(r.cast<float>(), t.cast<float>());
    CHECK((af.transform_point(x.cast<float>()) - (r * x + t).cast<float>()).norm() < 1e-5f);
}

TEST_CASE("Rigid_transform_3: accepts rotations up to the tolerance and projects them", "[sampling][transform]")
{
    const Eigen::Matrix3d r = some_rotation();
    Eigen::Matrix3d perturbed = r;
    perturbed(0, 1) += 1e-8;
    perturbed(2, 2) -= 2e-8;
    const PCCD::Rigid_transform_3<> a(perturbed, Vector3d::Zero());
    // Orthonormal and proper to a few ulps (the polar factor), where the input was off by 1e-8.
    CHECK((a.rotation().transpose() * a.rotation() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 2e-15);
    CHECK(std::abs(a.rotation().determinant() - 1.0) < 2e-15);
    CHECK((a.rotation() - r).norm() < 1e-7);
    perturbed(0, 1) += 1e-4;
    CHECK_THROWS_AS(PCCD::Rigid_transform_3<>(perturbed, Vector3d::Zero()), PCCD::Invalid_input);
    CHECK_NOTHROW(PCCD::Rigid_transform_3<>(perturbed, Vector3d::Zero(), 1e-3)); // explicit looser tolerance
}

TEST_CASE("Rigid_transform_3 rejects scaling, shear, reflection and non-finite entries", "[sampling][transform][errors]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(1, 2, 3);
    using T = PCCD::Rigid_transform_3<>;
    CHECK_THROWS_WITH(T(1.01 * r, t), Catch::Contains("scales"));
    CHECK_THROWS_WITH(T(Eigen::Matrix3d(Eigen::Vector3d(1, 1, 2).asDiagonal()), t), Catch::Contains("scales"));
    Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
    shear(0, 1) = 0.1;
    CHECK_THROWS_WITH(T(shear, t), Catch::Contains("shears"));
    CHECK_THROWS_WITH(T(Eigen::Matrix3d(Eigen::Vector3d(1, 1, -1).asDiagonal()), t), Catch::Contains("reflection"));
    CHECK_THROWS_WITH(T(-r, t), Catch::Contains("reflection"));
    Eigen::Matrix3d with_nan = r;
    with_nan(1, 2) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(T(with_nan, t), Catch::Contains("rotation entry (1, 2)"));
    CHECK_THROWS_WITH(T(r, Vector3d(0, std::numeric_limits<double>::infinity(), 0)),
                      Catch::Contains("translation entry (1, 3)"));
    CHECK_THROWS_WITH(T(Eigen::MatrixXd::Identity(2, 2), t), Catch::Contains("not 3 x 3"));
    CHECK_THROWS_WITH(T(r, t, -1.0), Catch::Contains("tolerance"));
    CHECK_THROWS_AS(T({2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}), PCCD::Invalid_input);
    static_assert(!std::is_constructible_v<T, int>);
    static_assert(!std::is_constructible_v<T, Eigen::Matrix3d>);
}

TEST_CASE("Rigid_transform_3 from CGAL::Aff_transformation_3 (inexact and exact kernels)", "[sampling][transform][cgal]")
{
    const Eigen::Matrix3d r = some_rotation();
    const Vector3d t(0.25, -0.5, 4.0);
    using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
    const CGAL::Aff_transformation_3<Epick> rigid(r(0, 0), r(0, 1), r(0, 2), t[0], r(1, 0), r(1, 1), r(1, 2), t[1],
                                                  r(2, 0), r(2, 1), r(2, 2), t[2], 1.0);
    const PCCD::Rigid_transform_3<> a(rigid);
    CHECK((a.matrix() - PCCD::Rigid_transform_3<>(r, t).matrix()).norm() < 1e-15);
    const Epick::Point_3 p(0.3, 0.2, -0.7);
    const Epick::Point_3 q = rigid.transform(p);
    CHECK((a.transform_point(Vector3d(0.3, 0.2, -0.7)) - Vector3d(q.x(), q.y(), q.z())).norm() < 1e-14);

    CHECK_NOTHROW(PCCD::Rigid_transform_3<>(CGAL::Aff_transformation_3<Epick>(CGAL::TRANSLATION, Epick::Vector_3(1, 2, 3))));
    CHECK_THROWS_WITH(PCCD::Rigid_transform_3<>(CGAL::Aff_transformation_3<Epick>(CGAL::SCALING, 2.0)),
                      Catch::Contains("scales"));
    CHECK_THROWS_WITH(PCCD::Rigid_transform_3<>(CGAL::Aff_transformation_3<Epick>(-1, 0, 0, 0, 1, 0, 0, 0, 1)),
                      Catch::Contains("reflection"));

    // Exact kernel: entries converted with CGAL::to_double, found by ADL.
    const CGAL::Aff_transformation_3<Epeck> quarter_turn(0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0, 1);
    const PCCD::Rigid_transform_3<> b(quarter_turn);
    CHECK(b.transform_point(Vector3d(1, 0, 0)) == Vector3d(5, 1, 0));
}

// ==================================================================================================
// Benchmark poses
// ==================================================================================================

TEST_CASE("poses: layout of the benchmark configurations", "[sampling][poses]")
{
    const auto poses = PCCD::generate_benchmark_poses({.rotations_per_distance = 20, .seed = 7});
    REQUIRE(poses.size() == 13 * 20);
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const auto& p = poses[i];
        CHECK(p.distance == 0.25 * double(i / 20));
        CHECK(p.rotation_index == i % 20);
        CHECK(p.pose_a.translation() == Vector3d::Zero());
        CHECK(p.pose_b.translation() == Vector3d(p.distance, 0, 0));
        for (const auto* pose : {&p.pose_a, &p.pose_b}) {
            const Eigen::Matrix3d& r = pose->rotation();
            CHECK((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-14);
            CHECK(std::abs(r.determinant() - 1.0) < 1e-14);
        }
        CHECK((p.pose_a.rotation() - p.pose_b.rotation()).norm() > 1e-6); // independent rotations
    }
    const auto default_poses = PCCD::generate_benchmark_poses();
    CHECK(default_poses.size() == 13 * 100);
    CHECK(PCCD::default_benchmark_distances().back() == 3.0);
}

TEST_CASE("poses: deterministic for a seed, independent of the distances asked for", "[sampling][poses]")
{
    const auto full = PCCD::generate_benchmark_poses({.rotations_per_distance = 10, .seed = 42});
    const auto again = PCCD::generate_benchmark_poses({.rotations_per_distance = 10, .seed = 42});
    const auto subset = PCCD::generate_benchmark_poses({.distances = {1.5}, .rotations_per_distance = 3, .seed = 42});
    const auto other_seed = PCCD::generate_benchmark_poses({.rotations_per_distance = 10, .seed = 43});
    REQUIRE(full.size() == again.size());
    for (std::size_t i = 0; i < full.size(); ++i) {
        CHECK(full[i].pose_a.matrix() == again[i].pose_a.matrix());
        CHECK(full[i].pose_b.matrix() == again[i].pose_b.matrix());
        CHECK(full[i].pose_a.matrix() != other_seed[i].pose_a.matrix());
    }
    // distance 1.5 is index 6 of the default list.
    for (std::size_t r = 0; r < 3; ++r) {
        CHECK(subset[r].pose_a.matrix() == full[60 + r].pose_a.matrix());
        CHECK(subset[r].pose_b.matrix() == full[60 + r].pose_b.matrix());
        const auto single = PCCD::benchmark_pose(42, 1.5, r);
        CHECK(single.pose_b.matrix() == full[60 + r].pose_b.matrix());
    }
    // Different distances and indices get different rotations.
    CHECK(full[0].pose_a.matrix() != full[1].pose_a.matrix());
    CHECK(full[0].pose_a.matrix() != full[10].pose_a.matrix());
    CHECK(PCCD::benchmark_pose(42, -0.0, 0).pose_a.matrix() == full[0].pose_a.matrix());
}

TEST_CASE("poses: random rotations are uniform (Haar)", "[sampling][poses][statistics]")
{
    PCCD::Random_engine rng(151);
    const int m = 20000;
    Eigen::Matrix3d mean = Eigen::Matrix3d::Zero(), mean_square = Eigen::Matrix3d::Zero();
    const int bins = 18;
    std::vector<double> angles(bins, 0.0), expected(bins);
    for (int i = 0; i < m; ++i) {
        const Eigen::Matrix3d r = PCCD::uniform_random_rotation(rng);
        mean += r / m;
        mean_square += r.cwiseAbs2() / m;
        const double angle = std::acos(std::clamp((r.trace() - 1.0) / 2.0, -1.0, 1.0));
        angles[std::min(bins - 1, int(angle / pi * bins))] += 1;
    }
    // Each entry of a Haar rotation is a coordinate of a uniform unit vector: mean 0, variance 1/3
    // (standard error of the mean sqrt(1/(3m)) = 0.0041); its square has mean 1/3 and standard
    // deviation 0.298 (standard error 0.0021). Tolerance 5 standard errors.
    CAPTURE(mean, mean_square);
    CHECK(mean.cwiseAbs().maxCoeff() < 5 * std::sqrt(1.0 / (3.0 * m)));
    CHECK((mean_square.array() - 1.0 / 3.0).abs().maxCoeff() < 5 * 0.298 / std::sqrt(double(m)));
    // The rotation angle has density (1 - cos a) / pi on [0, pi], CDF (a - sin a) / pi.
    for (int b = 0; b < bins; ++b) {
        const double a0 = pi * b / bins, a1 = pi * (b + 1) / bins;
        expected[b] = m * ((a1 - std::sin(a1)) - (a0 - std::sin(a0))) / pi;
    }
    CHECK(chi_square(angles, expected) < chi_square_critical(bins - 1));
}

TEST_CASE("poses: invalid options are rejected", "[sampling][poses][errors]")
{
    CHECK_THROWS_WITH(PCCD::generate_benchmark_poses({.distances = {}}), Catch::Contains("distance list is empty"));
    CHECK_THROWS_WITH(PCCD::generate_benchmark_poses({.rotations_per_distance = 0}),
                      Catch::Contains("rotations_per_distance"));
    CHECK_THROWS_WITH(PCCD::generate_benchmark_poses({.distances = {0.0, std::numeric_limits<double>::infinity()}}),
                      Catch::Contains("distance 1 is inf"));
    CHECK_THROWS_AS(PCCD::benchmark_pose(1, std::numeric_limits<double>::quiet_NaN(), 0), PCCD::Invalid_input);
}
