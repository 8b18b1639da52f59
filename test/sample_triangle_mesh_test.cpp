// Triangle-mesh sampling and the normalization of the benchmark objects (PCCD/sample_triangle_mesh.h,
// PCCD/Similarity_3.h; doc/manual/sampling.md), against independent truths:
// triangle areas, chi-square tests of the counts per triangle with fixed seeds, the expected spacing
// of uniform samples, bounding boxes.
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "data_helpers.h"
#include "sampling_test_helpers.h"

namespace {

using Eigen::Vector3d;
using namespace sampling_test;

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

} // namespace

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
