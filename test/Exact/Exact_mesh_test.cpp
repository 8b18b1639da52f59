// Tests of PCCD/Exact/: the exact reference for posed triangle meshes and for two spheres.
// Independent truths: the analytic sphere-sphere answer (with tolerances derived from each mesh's
// radial shell), brute-force vertex-triangle / edge-edge distances written here in plain Eigen,
// a plane-side inside test for convex meshes, and CGAL's own Polygon_mesh_processing::do_intersect
// on explicitly transformed copies.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/IO/OFF.h>

#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_intersection.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/Exact/sphere_sphere_intersection.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/testing/pose_generator.h>
#include "build_helpers.h"
#include "data_helpers.h"
#include "exact_test_helpers.h"

namespace {

using PCCD::Exact_mesh;
using PCCD::Rigid_transform_3;
using PCCD::Triangle_mesh_data;
using Vector3 = Eigen::Vector3d;
using Pose = Rigid_transform_3<double>;

// --- Meshes ---------------------------------------------------------------------------------------

using pccd_test::icosphere;

/// A mesh of the libcgal-demo data set, or nothing when the data is not installed.
bool read_data_mesh(const std::string& name, Triangle_mesh_data& mesh)
{
    const std::string dir = PCCD_DATA_DIR;
    if (dir.empty()) return false;
    std::vector<Vector3> points;
    std::vector<std::vector<std::size_t>> polygons;
    std::vector<CGAL::Simple_cartesian<double>::Point_3> cgal_points;
    REQUIRE(CGAL::IO::read_OFF(dir + "/" + name, cgal_points, polygons));
    mesh = {};
    for (const auto& p : cgal_points) mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    for (const auto& polygon : polygons) {
        REQUIRE(polygon.size() == 3);
        mesh.triangles.push_back({std::uint32_t(polygon[0]), std::uint32_t(polygon[1]), std::uint32_t(polygon[2])});
    }
    return true;
}

/// The normalization of doc/manual/sampling.md applied to a mesh.
void normalize(Triangle_mesh_data& mesh)
{
    Eigen::Matrix3Xd coordinates(3, mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) coordinates.col(Eigen::Index(i)) = mesh.vertices[i];
    PCCD::normalize_to_unit_cube(coordinates);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) mesh.vertices[i] = coordinates.col(Eigen::Index(i));
}

Pose rotation_pose(double angle, const Vector3& axis, const Vector3& translation)
{
    return Pose(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(), translation);
}

// --- Brute-force geometry (independent of CGAL) -----------------------------------------------------

Vector3 closest_point_on_triangle(const Vector3& p, const Vector3& a, const Vector3& b, const Vector3& c)
{
    // Voronoi regions of the vertices, then the edges, then the interior.
    const Vector3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vector3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const Vector3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denominator = va + vb + vc;
    return a + vb / denominator * ab + vc / denominator * ac;
}

double segment_segment_distance(const Vector3& p1, const Vector3& q1, const Vector3& p2, const Vector3& q2)
{
    const Vector3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
    const double denominator = a * e - b * b;
    double s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
    double t = (b * s + f) / e;
    if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    return (p1 + s * d1 - (p2 + t * d2)).norm();
}

/// A mesh in world coordinates: vertices mapped by a pose.
struct World_mesh {
    std::vector<Vector3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

World_mesh place(const Triangle_mesh_data& mesh, const Pose& pose)
{
    World_mesh world{{}, mesh.triangles};
    for (const Vector3& p : mesh.vertices) world.vertices.push_back(pose.transform_point(p));
    return world;
}

double point_mesh_distance(const Vector3& p, const World_mesh& mesh)
{
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
        best = std::min(best, (p - closest_point_on_triangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                              mesh.vertices[t[2]])).norm());
    return best;
}

/// The minimum distance between two disjoint triangle meshes: all vertex-triangle and edge-edge pairs.
double brute_force_mesh_distance(const World_mesh& a, const World_mesh& b)
{
    double best = std::numeric_limits<double>::infinity();
    for (const Vector3& p : a.vertices) best = std::min(best, point_mesh_distance(p, b));
    for (const Vector3& p : b.vertices) best = std::min(best, point_mesh_distance(p, a));
    for (const auto& s : a.triangles)
        for (int i = 0; i < 3; ++i)
            for (const auto& t : b.triangles)
                for (int j = 0; j < 3; ++j)
                    best = std::min(best, segment_segment_distance(a.vertices[s[i]], a.vertices[s[(i + 1) % 3]],
                                                                   b.vertices[t[j]], b.vertices[t[(j + 1) % 3]]));
    return best;
}

/// Inside test for a convex mesh: on the centroid's side of every face plane.
bool inside_convex(const Vector3& p, const World_mesh& mesh)
{
    Vector3 centroid = Vector3::Zero();
    for (const Vector3& v : mesh.vertices) centroid += v;
    centroid /= double(mesh.vertices.size());
    for (const auto& t : mesh.triangles) {
        const Vector3& a = mesh.vertices[t[0]];
        const Vector3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
        if ((p - a).dot(n) * (centroid - a).dot(n) <= 0) return false;
    }
    return true;
}

/// The penetration depth of exact_separation by brute force, for two convex meshes.
double brute_force_penetration(const World_mesh& a, const World_mesh& b)
{
    double depth = 0.0;
    for (const Vector3& p : a.vertices)
        if (inside_convex(p, b)) depth = std::max(depth, point_mesh_distance(p, b));
    for (const Vector3& p : b.vertices)
        if (inside_convex(p, a)) depth = std::max(depth, point_mesh_distance(p, a));
    return depth;
}

/// The radial shell [inner, outer] around `centre` that holds a closed star-shaped mesh: inner is the
/// distance from the centre to the surface, outer the largest vertex distance.
std::pair<double, double> radial_shell(const Triangle_mesh_data& mesh, const Vector3& centre)
{
    const World_mesh world = place(mesh, Pose());
    double outer = 0.0;
    for (const Vector3& p : mesh.vertices) outer = std::max(outer, (p - centre).norm());
    return {point_mesh_distance(centre, world), outer};
}

/// CGAL's own test on explicitly transformed copies, as an independent path to the same truth.
bool pmp_do_intersect(const Exact_mesh& a, const Pose& pose_a, const Exact_mesh& b, const Pose& pose_b)
{
    Exact_mesh::Triangle_mesh ma = a.mesh(), mb = b.mesh();
    const auto pa = a.transformed_points(pose_a), pb = b.transformed_points(pose_b);
    for (const auto v : vertices(ma)) ma.point(v) = pa[v];
    for (const auto v : vertices(mb)) mb.point(v) = pb[v];
    return CGAL::Polygon_mesh_processing::do_intersect(ma, mb);
}

} // namespace

// --- Exact_mesh ------------------------------------------------------------------------------------

TEST_CASE("exact mesh: construction facts and invalid input", "[exact][mesh]")
{
    const Exact_mesh sphere(icosphere(2));
    CHECK(sphere.number_of_vertices() == 162);
    CHECK(sphere.number_of_triangles() == 320);
    CHECK(sphere.is_closed());
    CHECK_FALSE(sphere.is_self_intersecting());
    CHECK(sphere.encloses_volume());
    CHECK(sphere.component_representatives().size() == 1);
    CHECK(sphere.bounded_side({0.1, 0.2, 0.3}) == CGAL::ON_BOUNDED_SIDE);
    CHECK(sphere.bounded_side({1.5, 0.0, 0.0}) == CGAL::ON_UNBOUNDED_SIDE);

    // Two tetrahedra sharing one vertex: a non-manifold vertex, split into two; two components.
    Triangle_mesh_data bowtie;
    bowtie.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    bowtie.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
    const Exact_mesh split(bowtie);
    CHECK(split.number_of_vertices() == 8);
    CHECK(split.is_closed());
    CHECK(split.component_representatives().size() == 2);

    // An open mesh: one triangle. Intersection works; volume queries refuse.
    Triangle_mesh_data single{{{-2, -2, 0}, {2, -2, 0}, {0, 3, 0}}, {{0, 1, 2}}};
    const Exact_mesh open(single);
    CHECK_FALSE(open.is_closed());
    CHECK_FALSE(open.encloses_volume());
    CHECK(PCCD::exact_do_intersect(open, Pose(), sphere, Pose()));
    CHECK_FALSE(PCCD::exact_do_intersect(open, Pose(), sphere, rotation_pose(0.3, {1, 1, 0}, {0, 0, 1.5})));
    CHECK_THROWS_AS(PCCD::exact_separation(open, Pose(), sphere, Pose()), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::exact_containment(sphere, Pose(), open, Pose()), PCCD::Invalid_input);
    CHECK_THROWS_AS(open.bounded_side({0, 0, 0}), PCCD::Invalid_input);

    // Two overlapping spheres in one soup: closed but self-intersecting.
    Triangle_mesh_data doubled = icosphere(1);
    const Triangle_mesh_data other = icosphere(1, {0.5, 0.1, 0.2});
    const auto offset = std::uint32_t(doubled.vertices.size());
    doubled.vertices.insert(doubled.vertices.end(), other.vertices.begin(), other.vertices.end());
    for (auto t : other.triangles) doubled.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const Exact_mesh self_intersecting(doubled);
    CHECK(self_intersecting.is_closed());
    CHECK(self_intersecting.is_self_intersecting());
    CHECK_FALSE(self_intersecting.encloses_volume());
    CHECK_THROWS_AS(PCCD::exact_intersection_polylines(self_intersecting, Pose(), sphere, Pose()), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::exact_separation(sphere, Pose(), self_intersecting, Pose()), PCCD::Invalid_input);

    SECTION("invalid input throws Invalid_input")
    {
        const Triangle_mesh_data good = icosphere(0);
        Triangle_mesh_data bad = good;
        bad.vertices.clear();
        CHECK_THROWS_AS(Exact_mesh(bad), PCCD::Invalid_input);
        bad = good;
        bad.triangles.clear();
        CHECK_THROWS_AS(Exact_mesh(bad), PCCD::Invalid_input);
        bad = good;
        bad.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_WITH(Exact_mesh(bad), Catch::Contains("vertex 3"));
        bad = good;
        bad.vertices[5].z() = std::numeric_limits<double>::infinity();
        CHECK_THROWS_AS(Exact_mesh(bad), PCCD::Invalid_input);
        bad = good;
        bad.triangles[2][1] = 12;
        CHECK_THROWS_WITH(Exact_mesh(bad), Catch::Contains("triangle 2"));
        bad = good;
        bad.triangles[4] = {1, 1, 2};
        CHECK_THROWS_AS(Exact_mesh(bad), PCCD::Invalid_input);
        bad = good;
        bad.vertices.push_back((bad.vertices[0] + bad.vertices[1]) / 2.0);
        bad.triangles.push_back({0, 1, 12});
        CHECK_THROWS_WITH(Exact_mesh(bad), Catch::Contains("collinear"));
    }
    SECTION("a repeated triangle is repaired into a valid but self-intersecting mesh")
    {
        Triangle_mesh_data repeated = icosphere(0);
        repeated.triangles.push_back(repeated.triangles[0]);
        repeated.triangles.push_back(repeated.triangles[0]);
        const Exact_mesh mesh(repeated);
        CHECK(mesh.number_of_triangles() == 22);
        CHECK(mesh.is_self_intersecting());
        CHECK_FALSE(mesh.encloses_volume());
    }
}

// --- Two spheres: analytic --------------------------------------------------------------------------

TEST_CASE("exact sphere-sphere: exact relation, circle and measure", "[exact][analytic]")
{
    using Relation = PCCD::Sphere_sphere_relation;
    const Vector3 o = Vector3::Zero();

    const auto crossing = PCCD::exact_sphere_sphere_intersection(o, 1.0, {1.0, 0.0, 0.0}, 1.0);
    REQUIRE(crossing.relation == Relation::intersecting);
    REQUIRE(crossing.circle);
    CHECK(crossing.circle->centre.isApprox(Vector3(0.5, 0, 0)));
    CHECK(crossing.circle->radius == Approx(std::sqrt(3.0) / 2.0));
    CHECK(std::abs(crossing.circle->normal.dot(Vector3::UnitX())) == Approx(1.0));
    CHECK(crossing.penetration_depth == Approx(1.0)); // sphere 2 passes through c1
    CHECK(crossing.signed_measure() == Approx(-1.0));

    // Points sampled on a general circle lie on both spheres.
    const Vector3 c1(0.3, -0.2, 0.7), c2(1.1, 0.4, 0.2);
    const auto general = PCCD::exact_sphere_sphere_intersection(c1, 0.9, c2, 0.6);
    REQUIRE(general.relation == Relation::intersecting);
    for (const Vector3& p : general.circle->points(17)) {
        CHECK(std::abs((p - c1).norm() - 0.9) < 1e-14);
        CHECK(std::abs((p - c2).norm() - 0.6) < 1e-14);
        CHECK(general.circle->distance(p) < 1e-14);
    }
    const double d = (c2 - c1).norm();
    CHECK(general.penetration_depth == Approx(std::max(0.6 - std::abs(d - 0.9), 0.9 - std::abs(d - 0.6))));

    // Exact tangency, and one ulp either side of it.
    const auto external = PCCD::exact_sphere_sphere_intersection(o, 1.0, {2.0, 0.0, 0.0}, 1.0);
    CHECK(external.relation == Relation::externally_tangent);
    CHECK(external.surfaces_intersect());
    CHECK(external.circle->radius == 0.0);
    CHECK(external.circle->centre == Vector3(1.0, 0.0, 0.0));
    CHECK(external.signed_measure() == 0.0);
    CHECK(PCCD::exact_sphere_sphere_intersection(o, 1.0, {std::nextafter(2.0, 3.0), 0.0, 0.0}, 1.0).relation ==
          Relation::disjoint);
    CHECK(PCCD::exact_sphere_sphere_intersection(o, 1.0, {std::nextafter(2.0, 1.0), 0.0, 0.0}, 1.0).relation ==
          Relation::intersecting);
    // 0.1 + 0.2 > 0.3 in exact arithmetic on these doubles: the spheres cross.
    CHECK(PCCD::exact_sphere_sphere_intersection(o, 0.1, {0.3, 0.0, 0.0}, 0.2).relation == Relation::intersecting);

    const auto internal_big_first = PCCD::exact_sphere_sphere_intersection(o, 1.0, {0.5, 0.0, 0.0}, 0.5);
    CHECK(internal_big_first.relation == Relation::internally_tangent);
    CHECK(internal_big_first.circle->centre == Vector3(1.0, 0.0, 0.0));
    const auto internal_small_first = PCCD::exact_sphere_sphere_intersection({0.5, 0.0, 0.0}, 0.5, o, 1.0);
    CHECK(internal_small_first.relation == Relation::internally_tangent);
    CHECK(internal_small_first.circle->centre == Vector3(1.0, 0.0, 0.0));

    const auto nested = PCCD::exact_sphere_sphere_intersection(o, 1.0, {0.2, 0.0, 0.0}, 0.3);
    CHECK(nested.relation == Relation::nested);
    CHECK_FALSE(nested.surfaces_intersect());
    CHECK_FALSE(nested.circle);
    CHECK(nested.distance == Approx(0.5));
    const auto apart = PCCD::exact_sphere_sphere_intersection(o, 1.0, {0.0, 3.0, 0.0}, 0.5);
    CHECK(apart.relation == Relation::disjoint);
    CHECK(apart.signed_measure() == Approx(1.5));
    CHECK(PCCD::exact_sphere_sphere_intersection(o, 1.0, o, 1.0).relation == Relation::coincident);
    CHECK(PCCD::exact_sphere_sphere_intersection(o, 1.0, o, 2.0).relation == Relation::nested);

    CHECK_THROWS_AS(PCCD::exact_sphere_sphere_intersection(o, 0.0, o, 1.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::exact_sphere_sphere_intersection(o, 1.0, Vector3(std::nan(""), 0, 0), 1.0),
                    PCCD::Invalid_input);
}

// --- Two sphere meshes vs the analytic answer ----------------------------------------------------------

namespace {

/// Checks two copies of a sphere-like mesh (radius `radius`, centred at the origin) at centre
/// distances around tangency against the analytic answer, with the tolerances of the mesh's radial
/// shell [inner, outer]: the surfaces surely cross for outer - inner < d < 2 inner and are surely
/// apart for d > 2 outer; the distance of apart meshes lies in [d - 2 outer, d - 2 inner].
void check_sphere_meshes_against_analytic(const Triangle_mesh_data& data, double radius)
{
    const Exact_mesh mesh(data);
    const auto [inner, outer] = radial_shell(data, Vector3::Zero());
    CAPTURE(inner, outer, mesh.longest_edge_length());
    REQUIRE(inner < radius);
    REQUIRE(outer >= radius - 1e-4);
    PCCD::Random_engine engine(7);
    const double diameter = 2.0 * radius;
    for (const double factor : {0.3, 0.6, 0.95, 0.99, 1.0, 1.01, 1.05, 1.4}) {
        for (int trial = 0; trial < 3; ++trial) {
            const double d = factor * diameter;
            const Vector3 direction = Vector3(PCCD::standard_normal(engine), PCCD::standard_normal(engine),
                                              PCCD::standard_normal(engine)).normalized();
            const Pose pose_a = Pose(PCCD::testing::uniform_random_rotation(engine), Vector3::Zero());
            const Pose pose_b = Pose(PCCD::testing::uniform_random_rotation(engine), d * direction);
            const auto analytic = PCCD::exact_sphere_sphere_intersection(Vector3::Zero(), radius, d * direction, radius);
            const bool meshes = PCCD::exact_do_intersect(mesh, pose_a, mesh, pose_b);
            const auto separation = PCCD::exact_separation(mesh, pose_a, mesh, pose_b);
            CAPTURE(d, analytic.signed_measure(), separation.signed_measure());
            CHECK(separation.surfaces_intersect == meshes);
            CHECK(PCCD::exact_containment(mesh, pose_a, mesh, pose_b) == PCCD::Containment::none);
            if (d > outer - inner && d < 2.0 * inner) {
                CHECK(analytic.surfaces_intersect());
                CHECK(meshes);
                // Vertex estimate: within one edge length plus the shell thickness of the analytic depth.
                CHECK(std::abs(separation.penetration_depth - analytic.penetration_depth) <=
                      mesh.longest_edge_length() + (outer - inner));
            } else if (d > 2.0 * outer) {
                CHECK_FALSE(analytic.surfaces_intersect());
                CHECK_FALSE(meshes);
                CHECK(separation.distance >= d - 2.0 * outer - 1e-12);
                CHECK(separation.distance <= d - 2.0 * inner + 1e-12);
            }
            // The grazing band: at tangency (up to the rounding of d * direction) the analytic
            // measure vanishes and the mesh's is within the shell, so a sampling radius of a few
            // shell thicknesses classifies the pose as grazing either way.
            if (factor == 1.0) {
                const double sampling_radius = 4.0 * (outer - inner) + mesh.longest_edge_length();
                CHECK(std::abs(analytic.signed_measure()) < 1e-12);
                CHECK(PCCD::classify_pose(separation, sampling_radius) == PCCD::Pose_class::grazing);
            }
        }
    }
}

} // namespace

TEST_CASE("exact meshes: icospheres vs the analytic sphere-sphere answer", "[exact][mesh][analytic]")
{
    check_sphere_meshes_against_analytic(icosphere(3), 1.0);
    check_sphere_meshes_against_analytic(icosphere(2, Vector3::Zero(), 0.7), 0.7);
}

TEST_CASE("exact meshes: CGAL's sphere.off vs the analytic answer", "[exact][mesh][analytic][data]")
{
    Triangle_mesh_data data;
    if (!read_data_mesh("sphere.off", data)) {
        PCCD_SKIP_TEST("sphere.off of libcgal-demo not found (PCCD_DATA_DIR is empty)");
    }
    // sphere.off: radius 0.5 about the origin, coordinates given to 4-5 digits.
    check_sphere_meshes_against_analytic(data, 0.5);
}

TEST_CASE("exact meshes: intersection polylines of two sphere meshes", "[exact][mesh][polyline]")
{
    const Triangle_mesh_data data = icosphere(3);
    const Exact_mesh mesh(data);
    const auto [inner, outer] = radial_shell(data, Vector3::Zero());
    const double d = 1.0;
    const Vector3 c2 = d * Vector3(1.0, 0.3, -0.2).normalized();
    const Pose pose_a = rotation_pose(0.4, {0.2, 1.0, 0.5}, Vector3::Zero());
    const Pose pose_b = rotation_pose(1.3, {1.0, -0.4, 0.3}, c2);
    const auto polylines = PCCD::exact_intersection_polylines(mesh, pose_a, mesh, pose_b);
    REQUIRE(polylines.size() == 1);
    const auto& line = polylines.front();
    REQUIRE(line.size() > 20);
    CHECK((line.front() - line.back()).norm() == 0.0); // closed

    const auto analytic = PCCD::exact_sphere_sphere_intersection(Vector3::Zero(), 1.0, c2, 1.0);
    REQUIRE(analytic.circle);
    // The curve lies on both meshes, hence in both radial shells; a point of the two shells is within
    // 2 (outer - inner) / sin(theta) of the circle to first order, theta being the angle between the
    // spheres' normals along it (60 degrees at d = 1); 1.5 times that covers the second order.
    const double sin_theta = std::sqrt(3.0) / 2.0;
    const double tolerance = 1.5 * 2.0 * (outer - inner) / sin_theta;
    const World_mesh world_a = place(data, pose_a), world_b = place(data, pose_b);
    double worst_a = 0.0, worst_b = 0.0, worst_circle = 0.0;
    for (const Vector3& p : line) {
        worst_a = std::max(worst_a, point_mesh_distance(p, world_a));
        worst_b = std::max(worst_b, point_mesh_distance(p, world_b));
        worst_circle = std::max(worst_circle, analytic.circle->distance(p));
    }
    CAPTURE(inner, outer, tolerance, worst_circle);
    CHECK(worst_a < 1e-12);
    CHECK(worst_b < 1e-12);
    CHECK(worst_circle < tolerance);
    // The curve goes all the way round: every point of the circle is near the polyline.
    double longest_segment = 0.0;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) longest_segment = std::max(longest_segment, (line[i + 1] - line[i]).norm());
    for (const Vector3& q : analytic.circle->points(64)) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Vector3& p : line) nearest = std::min(nearest, (p - q).norm());
        CHECK(nearest <= tolerance + longest_segment);
    }

    CHECK(PCCD::exact_intersection_polylines(mesh, pose_a, mesh, rotation_pose(0.2, {0, 0, 1}, {2.5, 0, 0})).empty());
}

// --- Brute force on small meshes ------------------------------------------------------------------------

TEST_CASE("exact separation: distance and penetration vs brute force", "[exact][mesh][separation]")
{
    const Triangle_mesh_data ellipsoid = icosphere(3, Vector3::Zero(), 1.0, {1.0, 0.6, 0.35});
    const Triangle_mesh_data ball = icosphere(2, {0.1, -0.05, 0.02}, 0.5);
    const Exact_mesh a(ellipsoid), b(ball);
    PCCD::Random_engine engine(2024);
    int apart = 0, crossing = 0;
    // Debug builds: the first 8 poses (the brute-force references are slow there).
    const int trials = pccd_test::by_build(24, 8);
    for (int trial = 0; trial < trials; ++trial) {
        const Pose pose_a(PCCD::testing::uniform_random_rotation(engine), Vector3::Zero());
        const double d = 0.3 + 1.5 * PCCD::uniform_01(engine);
        const Pose pose_b(PCCD::testing::uniform_random_rotation(engine), Vector3(d, 0.2 * PCCD::uniform_01(engine), 0.0));
        const World_mesh wa = place(ellipsoid, pose_a), wb = place(ball, pose_b);
        const auto separation = PCCD::exact_separation(a, pose_a, b, pose_b);
        CAPTURE(trial, d, separation.signed_measure());
        REQUIRE(separation.surfaces_intersect == PCCD::exact_do_intersect(a, pose_a, b, pose_b));
        REQUIRE(separation.surfaces_intersect == pmp_do_intersect(a, pose_a, b, pose_b));
        if (separation.surfaces_intersect) {
            ++crossing;
            CHECK(separation.penetration_depth == Approx(brute_force_penetration(wa, wb)).margin(1e-12));
            CHECK(separation.distance == 0.0);
        } else {
            ++apart;
            CHECK(separation.distance == Approx(brute_force_mesh_distance(wa, wb)).epsilon(1e-12).margin(1e-14));
            CHECK(separation.penetration_depth == 0.0);
        }
        // The same pair seen the other way round.
        const auto swapped = PCCD::exact_separation(b, pose_b, a, pose_a);
        CHECK(swapped.surfaces_intersect == separation.surfaces_intersect);
        CHECK(swapped.signed_measure() == Approx(separation.signed_measure()).margin(1e-12));
    }
    CHECK(apart >= trials / 5);
    CHECK(crossing >= trials / 5);
}

TEST_CASE("exact containment: a small sphere inside a big one is contained, not intersecting", "[exact][mesh]")
{
    const Triangle_mesh_data big_data = icosphere(3);
    const Triangle_mesh_data small_data = icosphere(2, Vector3::Zero(), 0.3);
    const Exact_mesh big(big_data), small(small_data);
    const auto [inner, outer] = radial_shell(big_data, Vector3::Zero());
    const Pose pose_big = rotation_pose(0.7, {1, 2, 3}, {0.5, 0.5, 0.5});
    const Pose pose_small = rotation_pose(-0.4, {3, 1, 0}, Vector3(0.5, 0.5, 0.5) + Vector3(0.2, 0.0, 0.0));

    CHECK_FALSE(PCCD::exact_do_intersect(big, pose_big, small, pose_small));
    CHECK(PCCD::exact_containment(big, pose_big, small, pose_small) == PCCD::Containment::second_inside_first);
    CHECK(PCCD::exact_containment(small, pose_small, big, pose_big) == PCCD::Containment::first_inside_second);
    const auto separation = PCCD::exact_separation(small, pose_small, big, pose_big);
    CHECK_FALSE(separation.surfaces_intersect);
    CHECK(separation.containment == PCCD::Containment::first_inside_second);
    // Analytic gap 1 - 0.3 - 0.2 = 0.5, up to both meshes' shells.
    const auto analytic = PCCD::exact_sphere_sphere_intersection(Vector3::Zero(), 1.0, {0.2, 0, 0}, 0.3);
    CHECK(analytic.relation == PCCD::Sphere_sphere_relation::nested);
    CHECK(separation.distance == Approx(analytic.distance).margin(outer - inner + 0.3 * (outer - inner)));
    CHECK(PCCD::classify_pose(separation, 0.1) == PCCD::Pose_class::separated);

    // Not nested: apart or crossing.
    CHECK(PCCD::exact_containment(big, pose_big, small, rotation_pose(0.0, {0, 0, 1}, {3, 0, 0})) ==
          PCCD::Containment::none);
    CHECK(PCCD::exact_containment(big, pose_big, small, rotation_pose(0.0, {0, 0, 1}, {1.5, 0.5, 0.5})) ==
          PCCD::Containment::none);
}

TEST_CASE("classify_pose: the grazing rule", "[exact][separation]")
{
    PCCD::Exact_separation s;
    s.distance = 0.05;
    CHECK(PCCD::classify_pose(s, 0.1) == PCCD::Pose_class::grazing);
    CHECK(PCCD::classify_pose(s, 0.05) == PCCD::Pose_class::separated);
    s = {};
    s.surfaces_intersect = true;
    s.penetration_depth = 0.2;
    CHECK(PCCD::classify_pose(s, 0.1) == PCCD::Pose_class::intersecting);
    CHECK(PCCD::classify_pose(s, 0.3) == PCCD::Pose_class::grazing);
    s.penetration_depth = 0.0;
    CHECK(PCCD::classify_pose(s, 1e-9) == PCCD::Pose_class::grazing);
    CHECK_THROWS_AS(PCCD::classify_pose(s, 0.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::classify_pose(s, std::numeric_limits<double>::infinity()), PCCD::Invalid_input);
}

// --- The bunny -------------------------------------------------------------------------------------------

TEST_CASE("exact meshes: the bunny against copies of itself", "[exact][mesh][data]")
{
    Triangle_mesh_data data;
    // Without the data the case is skipped, not run on a stand-in: it is the bunny's test (the
    // procedural meshes have their own cases above).
    if (!read_data_mesh("bunny00.off", data))
        PCCD_SKIP_TEST("bunny00.off of libcgal-demo not found (PCCD_DATA_DIR is empty)");
    normalize(data);
    const Exact_mesh bunny(data);
    REQUIRE(bunny.encloses_volume());

    // Coincident copies touch everywhere; far copies do not.
    CHECK(PCCD::exact_do_intersect(bunny, Pose(), bunny, Pose()));
    CHECK_FALSE(PCCD::exact_do_intersect(bunny, Pose(), bunny, Pose(Eigen::Matrix3d::Identity(), Vector3(2.5, 0, 0))));
    CHECK(PCCD::exact_intersection_polylines(bunny, Pose(), bunny, Pose(Eigen::Matrix3d::Identity(), Vector3(2.5, 0, 0)))
              .empty());
    const Pose rotated = rotation_pose(std::numbers::pi / 2.0, {0, 0, 1}, {0.3, 0, 0});
    CHECK(PCCD::exact_do_intersect(bunny, Pose(), bunny, rotated));
    CHECK(PCCD::exact_do_intersect(bunny, Pose(), bunny, rotated) == pmp_do_intersect(bunny, Pose(), bunny, rotated));

    // The benchmark poses of doc/manual/sampling.md, one rotation pair per distance, against CGAL's
    // do_intersect on transformed copies; the separation's sign agrees with the decision.
    int hits = 0, misses = 0;
    for (const auto& pose : PCCD::testing::generate_benchmark_poses({.rotations_per_distance = 1, .seed = 3})) {
        CAPTURE(pose.distance);
        const bool exact = PCCD::exact_do_intersect(bunny, pose.pose_a, bunny, pose.pose_b);
        CHECK(exact == pmp_do_intersect(bunny, pose.pose_a, bunny, pose.pose_b));
        (exact ? hits : misses)++;
    }
    CHECK(hits >= 3);
    CHECK(misses >= 3);

    // A crossing pose has intersection curves on both surfaces.
    const auto polylines = PCCD::exact_intersection_polylines(bunny, Pose(), bunny, rotated);
    REQUIRE_FALSE(polylines.empty());
    const Exact_mesh::AABB_tree& tree = bunny.tree();
    double worst = 0.0;
    for (const auto& line : polylines)
        for (const Vector3& p : line) {
            const Vector3 q = rotated.inverse().transform_point(p);
            worst = std::max({worst, std::sqrt(tree.squared_distance({p.x(), p.y(), p.z()})),
                              std::sqrt(tree.squared_distance({q.x(), q.y(), q.z()}))});
        }
    CHECK(worst < 1e-12);
}
