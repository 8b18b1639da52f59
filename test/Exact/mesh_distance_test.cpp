// Tests of PCCD/Exact/mesh_distance.h: exact_distance and exact_max_depth against analytic truth.
// Boxes: face-face, corner-corner and a pure edge-edge configuration (two cubes turned by 45
// degrees about perpendicular axes, whose closest features are two crossing edges), and a box
// pushed into a box with known depths on each side (different, so the deeper side's normal is
// checked). Spheres: icospheres, whose surface lies in the radial shell [inradius, radius] measured
// here, so that the distance and the depth are known to within the shell's width. A box whose face
// dips into a sphere while its corners stay outside: only the area samples see that depth. Every
// configuration is also seen through a random rigid motion of the whole scene (the answers move
// with it) and with the two meshes swapped.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_distance.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/Random.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/testing/pose_generator.h>
#include "build_helpers.h"
#include "exact_test_helpers.h"

namespace {

using PCCD::Exact_mesh;
using Vector3 = Eigen::Vector3d;
using Pose = PCCD::Rigid_transform_3<double>;
using pccd_test::box_mesh;
using pccd_test::icosphere;

Pose rotation_pose(double angle, const Vector3& axis, const Vector3& translation)
{
    return Pose(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(), translation);
}

/// The distance from the world point x to the surface of `mesh` placed by `pose` (CGAL's AABB tree,
/// not the code under test).
double surface_distance(const Exact_mesh& mesh, const Pose& pose, const Vector3& x)
{
    const Vector3 p = pose.inverse().transform_point(x);
    return std::sqrt(mesh.tree().squared_distance(Exact_mesh::Point_3(p.x(), p.y(), p.z())));
}

/// The distance from the centre of an icosphere to its surface (the inradius of the polyhedron):
/// the surface lies in the shell [inner, radius].
double icosphere_inner_radius(const PCCD::Triangle_mesh_data& data, const Vector3& centre)
{
    const Exact_mesh mesh(data);
    return surface_distance(mesh, Pose(), centre);
}

double angle_degrees(const Vector3& u, const Vector3& v)
{
    return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

/// Random rigid motions of the whole scene (the identity first).
std::vector<Pose> scene_motions(std::uint64_t seed, int count)
{
    PCCD::Random_engine engine(seed);
    std::vector<Pose> motions{Pose()};
    for (int i = 1; i < count; ++i) {
        Vector3 t;
        for (int d = 0; d < 3; ++d) t(d) = PCCD::uniform_real(engine, -3.0, 3.0);
        motions.emplace_back(PCCD::testing::uniform_random_rotation(engine), t);
    }
    return motions;
}

/// exact_distance of (a, pose_a) and (b, pose_b) checked against the expected distance and
/// witnesses (world, before `motion`), in both orders; `tolerance` on the witnesses.
void check_distance(const Exact_mesh& a, const Pose& pose_a, const Exact_mesh& b, const Pose& pose_b, double expected,
                    const Vector3& expected_a, const Vector3& expected_b, const Pose& motion)
{
    const Pose ma = motion * pose_a, mb = motion * pose_b;
    const PCCD::Exact_distance d = PCCD::exact_distance(a, ma, b, mb);
    REQUIRE_FALSE(d.surfaces_intersect);
    CHECK(d.distance == Approx(expected).margin(1e-12));
    CHECK((d.point_a - motion.transform_point(expected_a)).norm() < 1e-9);
    CHECK((d.point_b - motion.transform_point(expected_b)).norm() < 1e-9);
    CHECK((d.point_a - d.point_b).norm() == Approx(d.distance).margin(1e-12));
    CHECK(PCCD::exact_separation(a, ma, b, mb).distance == Approx(d.distance).margin(1e-12));
    const PCCD::Exact_distance swapped = PCCD::exact_distance(b, mb, a, ma);
    CHECK(swapped.distance == Approx(expected).margin(1e-12));
    CHECK((swapped.point_a - d.point_b).norm() < 1e-9);
    CHECK((swapped.point_b - d.point_a).norm() < 1e-9);
}

} // namespace

TEST_CASE("exact_distance: boxes face to face, corner to corner and edge to edge", "[exact][distance][analytic]")
{
    const Exact_mesh unit(box_mesh(Vector3::Zero(), Vector3::Constant(0.5)));
    for (const Pose& motion : scene_motions(11, 6)) {
        SECTION("face to face: the gap between the faces, witnesses on the common normal")
        {
            // B spans x in [1.5, 2.5], y in [-0.2, 0.8], z in [-0.6, 0.4]: the faces x = 0.5 and
            // x = 1.5 overlap in y, z over [-0.2, 0.5] x [-0.5, 0.4]; the witnesses are not unique
            // there, so only their x and the distance are checked.
            const Pose pose_b(Eigen::Matrix3d::Identity(), Vector3(2.0, 0.3, -0.1));
            const PCCD::Exact_distance d = PCCD::exact_distance(unit, motion, unit, motion * pose_b);
            REQUIRE_FALSE(d.surfaces_intersect);
            CHECK(d.distance == Approx(1.0).margin(1e-12));
            const Vector3 a_local = motion.inverse().transform_point(d.point_a);
            const Vector3 b_local = motion.inverse().transform_point(d.point_b);
            CHECK(a_local.x() == Approx(0.5).margin(1e-12));
            CHECK(b_local.x() == Approx(1.5).margin(1e-12));
            CHECK(a_local.y() >= -0.2 - 1e-12);
            CHECK(a_local.z() <= 0.4 + 1e-12);
            CHECK((d.point_a - d.point_b).norm() == Approx(1.0).margin(1e-12));
        }
        SECTION("corner to corner: sqrt(3) times the gap per axis, at the two corners")
        {
            const Pose pose_b(Eigen::Matrix3d::Identity(), Vector3(2.0, 2.0, 2.0));
            check_distance(unit, Pose(), unit, pose_b, std::sqrt(3.0), Vector3::Constant(0.5), Vector3::Constant(1.5), motion);
        }
        SECTION("edge to edge: two crossing edges, no vertex involved")
        {
            // A turned by 45 degrees about z: its edge nearest +x is {x = sqrt(2)/2, y = 0, z in
            // [-1/2, 1/2]}. B turned by 45 degrees about y and moved to x = D: its edge nearest -x
            // is {x = D - sqrt(2)/2, z = 0, y in [-1/2, 1/2]}. The edges cross in projection at
            // y = z = 0, so the distance is D - sqrt(2), between their midpoints; the nearest
            // vertices (the ends of those edges) are sqrt((D - sqrt(2))^2 + 1/4) from the other
            // mesh.
            const double D = 2.1;
            const Pose pose_a = rotation_pose(std::numbers::pi / 4, Vector3::UnitZ(), Vector3::Zero());
            const Pose pose_b = rotation_pose(std::numbers::pi / 4, Vector3::UnitY(), Vector3(D, 0, 0));
            const double h = std::sqrt(2.0) / 2;
            check_distance(unit, pose_a, unit, pose_b, D - std::sqrt(2.0), Vector3(h, 0, 0), Vector3(D - h, 0, 0), motion);
            // The vertex-based distance is clearly larger: the edge pair is what the answer rests on.
            double vertex_best = std::numeric_limits<double>::infinity();
            for (const auto v : vertices(unit.mesh())) {
                const auto& p = unit.mesh().point(v);
                const Vector3 x(p.x(), p.y(), p.z());
                vertex_best = std::min(vertex_best, surface_distance(unit, pose_b, pose_a.transform_point(x)));
                vertex_best = std::min(vertex_best, surface_distance(unit, pose_a, pose_b.transform_point(x)));
            }
            CHECK(vertex_best > D - std::sqrt(2.0) + 0.1);
        }
    }
}

TEST_CASE("exact_distance: random poses of an ellipsoid and a box, witnesses on the surfaces", "[exact][distance]")
{
    // No closed form here: the witnesses must lie on their surfaces, realize the distance, and no
    // pair of surface points (vertices and 400 random area points of each, after the motion) may
    // be closer than the distance.
    const PCCD::Triangle_mesh_data ellipsoid_data = icosphere(3, Vector3::Zero(), 1.0, {1.0, 0.6, 0.35});
    const PCCD::Triangle_mesh_data box_data = box_mesh(Vector3(0.1, 0.0, 0.0), Vector3(0.3, 0.5, 0.2));
    const Exact_mesh a(ellipsoid_data), b(box_data);
    const auto area_points = [](const PCCD::Triangle_mesh_data& data, const Pose& pose, PCCD::Random_engine& engine) {
        std::vector<Vector3> points;
        for (const Vector3& v : data.vertices) points.push_back(pose.transform_point(v));
        for (int i = 0; i < 400; ++i) {
            const auto& t = data.triangles[std::size_t(PCCD::uniform_01(engine) * double(data.triangles.size()))];
            double u = PCCD::uniform_01(engine), w = PCCD::uniform_01(engine);
            if (u + w > 1) u = 1 - u, w = 1 - w;
            points.push_back(pose.transform_point(data.vertices[t[0]] + u * (data.vertices[t[1]] - data.vertices[t[0]]) +
                                                  w * (data.vertices[t[2]] - data.vertices[t[0]])));
        }
        return points;
    };
    PCCD::Random_engine engine(77);
    int apart = 0, crossing = 0;
    const int trials = pccd_test::by_build(30, 8);
    for (int trial = 0; trial < trials; ++trial) {
        const Pose pose_a(PCCD::testing::uniform_random_rotation(engine), Vector3::Zero());
        const Pose pose_b(PCCD::testing::uniform_random_rotation(engine), Vector3(0.6 + 1.4 * PCCD::uniform_01(engine), 0.3, 0));
        const PCCD::Exact_distance d = PCCD::exact_distance(a, pose_a, b, pose_b);
        CAPTURE(trial, d.distance);
        REQUIRE(d.surfaces_intersect == PCCD::exact_do_intersect(a, pose_a, b, pose_b));
        if (d.surfaces_intersect) {
            ++crossing;
            CHECK(d.distance == 0.0);
            CHECK(d.point_a.hasNaN());
            CHECK(d.point_b.hasNaN());
            continue;
        }
        ++apart;
        CHECK(surface_distance(a, pose_a, d.point_a) < 1e-12);
        CHECK(surface_distance(b, pose_b, d.point_b) < 1e-12);
        CHECK((d.point_a - d.point_b).norm() == Approx(d.distance).margin(1e-12));
        CHECK(d.distance == Approx(PCCD::exact_separation(a, pose_a, b, pose_b).distance).margin(1e-14));
        const auto pa = area_points(ellipsoid_data, pose_a, engine), pb = area_points(box_data, pose_b, engine);
        double sampled = std::numeric_limits<double>::infinity();
        for (const Vector3& p : pa)
            for (const Vector3& q : pb) sampled = std::min(sampled, (p - q).norm());
        CHECK(d.distance <= sampled + 1e-12);
        // The closest point of B to the witness on A is the witness on B's distance away, no closer.
        CHECK(surface_distance(b, pose_b, d.point_a) == Approx(d.distance).margin(1e-12));
        CHECK(surface_distance(a, pose_a, d.point_b) == Approx(d.distance).margin(1e-12));
    }
    CHECK(apart >= trials / 4);
    CHECK(crossing >= 1);
}

TEST_CASE("exact_distance: icospheres vs |c1 - c2| - r1 - r2 within the tessellation shell", "[exact][distance][analytic]")
{
    const double r1 = 0.8, r2 = 0.5;
    const PCCD::Triangle_mesh_data s1 = icosphere(4, Vector3::Zero(), r1), s2 = icosphere(3, Vector3::Zero(), r2);
    const double inner1 = icosphere_inner_radius(s1, Vector3::Zero()), inner2 = icosphere_inner_radius(s2, Vector3::Zero());
    REQUIRE(inner1 < r1);
    REQUIRE(inner1 > 0.995 * r1);
    REQUIRE(inner2 > 0.98 * r2);
    const Exact_mesh a(s1), b(s2);
    PCCD::Random_engine engine(5);
    for (int trial = 0; trial < 20; ++trial) {
        const Pose pose_a(PCCD::testing::uniform_random_rotation(engine), Vector3(0.1, -0.2, 0.3));
        const Vector3 direction = PCCD::testing::uniform_random_rotation(engine).col(0);
        const double centre_distance = r1 + r2 + 0.05 + 1.0 * PCCD::uniform_01(engine);
        const Pose pose_b(PCCD::testing::uniform_random_rotation(engine), pose_a.translation() + centre_distance * direction);
        const PCCD::Exact_distance d = PCCD::exact_distance(a, pose_a, b, pose_b);
        CAPTURE(trial, centre_distance, d.distance);
        REQUIRE_FALSE(d.surfaces_intersect);
        // The surfaces lie in the shells [inner, r]: the distance between them is between the
        // distances of the shells.
        CHECK(d.distance >= centre_distance - r1 - r2 - 1e-12);
        CHECK(d.distance <= centre_distance - inner1 - inner2 + 1e-12);
        // The witnesses lie in the shells, and near the line of the centres.
        const double ra = (d.point_a - pose_a.translation()).norm(), rb = (d.point_b - pose_b.translation()).norm();
        CHECK(ra >= inner1 - 1e-12);
        CHECK(ra <= r1 + 1e-12);
        CHECK(rb >= inner2 - 1e-12);
        CHECK(rb <= r2 + 1e-12);
        CHECK(angle_degrees(d.point_b - d.point_a, direction) < 10.0);
    }
}

TEST_CASE("exact_max_depth: a box pushed into a box, different depths on each side", "[exact][depth][analytic]")
{
    // A = [-1, 1]^3. B = [0.6, 1.1] x [-0.5, 0.5]^2. Points of B's surface inside A: the face x = 0.6
    // is 0.4 from A's face x = 1 (and at least 0.5 from the others), the side faces less: depth_b =
    // 0.4, deepest_b anywhere on x = 0.6, closest_a its projection on x = 1, normal_b =
    // closest_a - deepest_b = +x (B leaves A by moving +x). Points of A's surface inside B: the
    // patch of x = 1 with |y|, |z| < 0.5, 0.1 from B's face x = 1.1 at best: depth_a = 0.1,
    // deepest_a = (1, y, z), closest_b = (1.1, y, z), normal_a = deepest_a - closest_b = -x (B
    // leaves that point of A by moving -x by 0.1, which is the shallow side). depth = 0.4 with
    // contact_normal = +x.
    const Exact_mesh a(box_mesh(Vector3::Zero(), Vector3::Ones()));
    const Exact_mesh b(box_mesh(Vector3(0.85, 0, 0), Vector3(0.25, 0.5, 0.5)));
    for (const Pose& motion : scene_motions(3, 5)) {
        const Eigen::Matrix3d R = motion.rotation();
        for (const double spacing : {0.5, 0.05}) {
            const PCCD::Exact_depth d = PCCD::exact_max_depth(a, motion, b, motion, spacing);
            CAPTURE(spacing, d.depth_a, d.depth_b);
            CHECK(d.surfaces_intersect);
            CHECK(d.sample_spacing == spacing);
            CHECK(d.depth_a == Approx(0.1).margin(1e-12));
            CHECK(d.depth_b == Approx(0.4).margin(1e-12));
            CHECK(d.depth == Approx(0.4).margin(1e-12));
            CHECK((d.normal_a - R * -Vector3::UnitX()).norm() < 1e-9);
            CHECK((d.normal_b - R * Vector3::UnitX()).norm() < 1e-9);
            CHECK((d.contact_normal - R * Vector3::UnitX()).norm() < 1e-9);
            const Vector3 deepest_a = motion.inverse().transform_point(d.deepest_a);
            const Vector3 closest_b = motion.inverse().transform_point(d.closest_b);
            const Vector3 deepest_b = motion.inverse().transform_point(d.deepest_b);
            const Vector3 closest_a = motion.inverse().transform_point(d.closest_a);
            CHECK(deepest_a.x() == Approx(1.0).margin(1e-12));
            CHECK(closest_b.x() == Approx(1.1).margin(1e-12));
            CHECK(deepest_b.x() == Approx(0.6).margin(1e-12));
            CHECK(closest_a.x() == Approx(1.0).margin(1e-12));
            CHECK((d.deepest_a - d.closest_b).norm() == Approx(d.depth_a).margin(1e-12));
            CHECK((d.deepest_b - d.closest_a).norm() == Approx(d.depth_b).margin(1e-12));
            // Moving B by depth along the contact normal undoes the deeper penetration: the deepest
            // point of B lands on A's surface.
            CHECK(surface_distance(a, motion, d.deepest_b + d.depth * d.contact_normal) < 1e-12);
            // Swapped roles: depths swap, and the normals flip (now A must move to leave B).
            const PCCD::Exact_depth s = PCCD::exact_max_depth(b, motion, a, motion, spacing);
            CHECK(s.depth_a == Approx(0.4).margin(1e-12));
            CHECK(s.depth_b == Approx(0.1).margin(1e-12));
            CHECK((s.contact_normal + d.contact_normal).norm() < 1e-9);
        }
    }
}

TEST_CASE("exact_max_depth: a box face dipping into a sphere, found by the area samples", "[exact][depth][analytic]")
{
    // A: a sphere of radius 1 at the origin (icosphere, surface in the shell [inner, 1]). B: the box
    // [0.8, 1.8] x [-0.5, 0.5]^2, whose corners (0.8, +-0.5, +-0.5) are at 1.07 > 1 from the
    // origin: no vertex of B is inside A, but the middle of its face x = 0.8 is. The points of B's
    // surface inside A are at >= 0.8 from the origin, and the point (0.8, 0, 0) is inside at
    // depth >= inner - 0.8: depth_b is in [inner - 0.8 - spacing, 1 - 0.8] (the sampling bound),
    // with normal_b near +x (B leaves A by moving +x).
    const PCCD::Triangle_mesh_data sphere = icosphere(4);
    const double inner = icosphere_inner_radius(sphere, Vector3::Zero());
    REQUIRE(inner > 0.995);
    const Exact_mesh a(sphere);
    const Exact_mesh b(box_mesh(Vector3(1.3, 0, 0), Vector3::Constant(0.5)));
    for (const Pose& motion : scene_motions(9, 4)) {
        const Eigen::Matrix3d R = motion.rotation();
        // The vertex-based estimate of exact_separation sees only A's vertices inside B: at most 0.2.
        const PCCD::Exact_separation vertex_estimate = PCCD::exact_separation(a, motion, b, motion);
        REQUIRE(vertex_estimate.surfaces_intersect);
        for (const double spacing : {0.1, 0.02, 0.005}) {
            const PCCD::Exact_depth d = PCCD::exact_max_depth(a, motion, b, motion, spacing);
            CAPTURE(spacing, d.depth_a, d.depth_b, inner);
            CHECK(d.depth_b >= inner - 0.8 - spacing - 1e-12);
            CHECK(d.depth_b <= 0.2 + 1e-12);
            CHECK(angle_degrees(d.normal_b, R * Vector3::UnitX()) < 10.0);
            // deepest_b on B's face x = 0.8 near its middle (within the sampling error and the shell).
            const Vector3 deepest_b = motion.inverse().transform_point(d.deepest_b);
            CHECK(deepest_b.x() == Approx(0.8).margin(1e-12));
            CHECK(deepest_b.tail<2>().norm() < 0.15);
            // A's surface inside B: the cap x > 0.8, whose points are <= 1 - 0.8 from B's face
            // x = 0.8; the pole region reaches >= inner - 0.8 (minus the sampling error).
            CHECK(d.depth_a >= inner - 0.8 - spacing - 1e-12);
            CHECK(d.depth_a <= 0.2 + 1e-12);
            CHECK(angle_degrees(d.normal_a, R * Vector3::UnitX()) < 10.0);
            // A sampled depth is that of an actual point: its witness is on the surface, inside.
            CHECK(surface_distance(b, motion, d.deepest_b) < 1e-12);
            CHECK(a.bounded_side([&] {
                const Vector3 p = motion.inverse().transform_point(d.deepest_b);
                return Exact_mesh::Point_3(p.x(), p.y(), p.z());
            }()) == CGAL::ON_BOUNDED_SIDE);
            CHECK(surface_distance(a, motion, d.closest_a) < 1e-12);
            CHECK(surface_distance(a, motion, d.deepest_b) == Approx(d.depth_b).margin(1e-12));
        }
    }
}

TEST_CASE("exact_max_depth: a sphere into a box, and spheres into spheres", "[exact][depth][analytic]")
{
    // A: the box [-1, 1]^3; B: a sphere of radius 0.5 centred at (1.2, y0, 0), |y0| <= 0.2, so its
    // leftmost point (0.7, y0, 0) is 0.3 inside A's face x = 1 (0.8 or more from the others):
    // depth_b in [0.3 - (0.5 - inner), 0.3] (the leftmost point of the mesh is a vertex, so the
    // samples hold it), and normal_b is exactly +x (its closest point is on A's face x = 1).
    const Exact_mesh box(box_mesh(Vector3::Zero(), Vector3::Ones()));
    const PCCD::Triangle_mesh_data small = icosphere(3, Vector3::Zero(), 0.5);
    const double inner_small = icosphere_inner_radius(small, Vector3::Zero());
    const Exact_mesh ball(small);
    PCCD::Random_engine engine(21);
    for (int trial = 0; trial < 6; ++trial) {
        const double y0 = PCCD::uniform_real(engine, -0.2, 0.2);
        const Pose pose_b(PCCD::testing::uniform_random_rotation(engine), Vector3(1.2, y0, 0));
        const PCCD::Exact_depth d = PCCD::exact_max_depth(box, Pose(), ball, pose_b, 0.01);
        CAPTURE(trial, y0, d.depth_b);
        CHECK(d.depth_b <= 0.3 + 1e-12);
        CHECK(d.depth_b >= 0.3 - (0.5 - inner_small) - 0.01);
        CHECK(angle_degrees(d.normal_b, Vector3::UnitX()) < 1e-4); // the closest point is on A's face x = 1
        CHECK(d.closest_a.x() == Approx(1.0).margin(1e-12));
    }

    // Spheres: A radius 1 at the origin, B radius 0.6 at (1.3, 0, 0). A point of B's sphere at
    // angle t from -x is p = (1.3 - 0.6 cos t, 0.6 sin t, 0); inside A its depth is 1 - |p|, largest
    // where |p| is smallest: |p|^2 = 1.69 + 0.36 - 1.56 cos t, smallest at t = 0: |p| = 0.7, depth_b =
    // 0.3 at (0.7, 0, 0) with normal +x. A's surface inside B: its points are at >= 0.7 from B's
    // centre... the deepest is (1, 0, 0), at 0.3 from B's centre, so 0.6 - 0.3 = 0.3 from B's
    // surface, normal_a = deepest_a - closest_b = (1,0,0) - (0.7,0,0) direction +x. The meshes differ
    // from the spheres by their shells: each depth is within (r - inner) of both spheres' widths.
    const PCCD::Triangle_mesh_data big = icosphere(4, Vector3::Zero(), 1.0), medium = icosphere(4, Vector3::Zero(), 0.6);
    const double inner_big = icosphere_inner_radius(big, Vector3::Zero());
    const double inner_medium = icosphere_inner_radius(medium, Vector3::Zero());
    const double shell = (1.0 - inner_big) + (0.6 - inner_medium);
    const Exact_mesh sa(big), sb(medium);
    for (int trial = 0; trial < 6; ++trial) {
        const Pose pose_a(PCCD::testing::uniform_random_rotation(engine), Vector3::Zero());
        const Pose pose_b(PCCD::testing::uniform_random_rotation(engine), Vector3(1.3, 0, 0));
        const PCCD::Exact_depth d = PCCD::exact_max_depth(sa, pose_a, sb, pose_b, 0.01);
        CAPTURE(trial, d.depth_a, d.depth_b, shell);
        CHECK(d.depth_a == Approx(0.3).margin(shell + 0.01));
        CHECK(d.depth_b == Approx(0.3).margin(shell + 0.01));
        CHECK(angle_degrees(d.normal_a, Vector3::UnitX()) < 8.0);
        CHECK(angle_degrees(d.normal_b, Vector3::UnitX()) < 8.0);
        CHECK(angle_degrees(d.contact_normal, Vector3::UnitX()) < 8.0);
        CHECK(d.depth == std::max(d.depth_a, d.depth_b));
    }
}

TEST_CASE("exact_max_depth: poses without penetration, nesting, invalid input", "[exact][depth]")
{
    const Exact_mesh unit(box_mesh(Vector3::Zero(), Vector3::Constant(0.5)));
    SECTION("apart: no depth, NaN witnesses")
    {
        const PCCD::Exact_depth d = PCCD::exact_max_depth(unit, Pose(), unit, Pose(Eigen::Matrix3d::Identity(), Vector3(1.2, 0, 0)), 0.1);
        CHECK_FALSE(d.surfaces_intersect);
        CHECK(d.depth == 0.0);
        CHECK(d.depth_a == 0.0);
        CHECK(d.depth_b == 0.0);
        CHECK(d.deepest_a.hasNaN());
        CHECK(d.contact_normal.hasNaN());
    }
    SECTION("nested without contact: the inner surface's depth, the surfaces do not intersect")
    {
        const Exact_mesh big(box_mesh(Vector3::Zero(), Vector3::Ones()));
        const PCCD::Exact_depth d = PCCD::exact_max_depth(unit, Pose(), big, Pose(), 0.1);
        CHECK_FALSE(d.surfaces_intersect);
        CHECK(d.depth_a == Approx(0.5).margin(1e-12)); // every point of the unit box's surface is 0.5 from the big one
        CHECK(d.depth_b == 0.0);
    }
    SECTION("invalid input")
    {
        PCCD::Triangle_mesh_data open = box_mesh(Vector3::Zero(), Vector3::Ones());
        open.triangles.pop_back();
        const Exact_mesh open_mesh(open);
        CHECK_THROWS_AS(PCCD::exact_max_depth(open_mesh, Pose(), unit, Pose(), 0.1), PCCD::Invalid_input);
        CHECK_THROWS_AS(PCCD::exact_max_depth(unit, Pose(), open_mesh, Pose(), 0.1), PCCD::Invalid_input);
        for (const double spacing : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            CHECK_THROWS_AS(PCCD::exact_max_depth(unit, Pose(), unit, Pose(), spacing), PCCD::Invalid_input);
        CHECK_THROWS_AS(PCCD::exact_max_depth(unit, Pose(), unit, Pose(), 1e-9), PCCD::Invalid_input);
        // The distance needs no volume: an open mesh is fine.
        const PCCD::Exact_distance d = PCCD::exact_distance(open_mesh, Pose(), unit, Pose(Eigen::Matrix3d::Identity(), Vector3(3, 0, 0)));
        CHECK(d.distance == Approx(1.5).margin(1e-12));
    }
}
