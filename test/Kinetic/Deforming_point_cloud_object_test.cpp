// Tests of PCCD/Kinetic/Deforming_point_cloud_object.h (and Deformation.h): the deformed surface
// against one rebuilt from the moved points at random times (normals, f, zero set; fixed seeds,
// stated tolerances), exact invariance under rigid motions, the verdicts of the contact scene
// against a rebuild, the stretch rule, and bad input.
// Also covers Kinetic/Deformation.h: the test cases below exercise what it declares.
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/Kinetic/Deformation.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Random.h>

#include <catch2/catch.hpp>

#include <PCCD/testing/scenes/Bunny_contact_scene.h>
#include <PCCD/testing/scenes/run_contact_scene.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "../build_helpers.h"
#include "../data_helpers.h"

using Catch::Matchers::Contains;
using Object = PCCD::Deforming_point_cloud_object<>;
static_assert(PCCD::CollisionObject<Object>);
static_assert(PCCD::CollisionObject<PCCD::Deforming_point_cloud_object<PCCD::Eigen_kernel<float>>>);
static_assert(PCCD::ProximityObject<Object>);
static_assert(PCCD::ProximityObject<PCCD::Deforming_point_cloud_object<PCCD::Eigen_kernel<float>>>);

namespace {

// Debug (sanitizer) builds play fewer frames and times: the same checks, less work.
constexpr double contact_frame_rate = pccd_test::by_build(10.0, 5.0); // 21 or 11 frames over 2 s
constexpr int random_times = pccd_test::by_build(3, 1);

/// The procedural contact scene (no data needed), small enough for a unit test.
PCCD::testing::Bunny_contact_scene small_scene(std::size_t points = 2000)
{
    return PCCD::testing::make_bunny_contact_scene({.points = points, .obstacle_points = 1000});
}

/// Every point kept, in the order given: point i of a rebuilt object is point i of the deforming one.
PCCD::Point_cloud_object_options no_outliers()
{
    PCCD::Point_cloud_object_options o;
    o.outliers.remove = false;
    o.spatial_order = false;
    return o;
}

/// The rebuilt reference: the whole preprocessing on the moved points.
PCCD::Point_cloud_object<> rebuild(const Eigen::Matrix3Xd& points)
{
    std::vector<std::size_t> items(std::size_t(points.cols()));
    for (std::size_t i = 0; i < items.size(); ++i) items[i] = i;
    return PCCD::Point_cloud_object<>(items, PCCD::testing::detail::Matrix_column_map{&points}, no_outliers());
}

double quantile(std::vector<double> v, double q)
{
    REQUIRE(!v.empty());
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

/// The true normal of the deformed shape at the image of rest point p with rest normal n: the
/// image of the tangent plane under the scene's map (central differences), crossed.
Eigen::Vector3d true_normal(const PCCD::testing::Bunny_contact_scene& scene, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                            double t)
{
    const Eigen::Vector3d helper = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d t1 = n.cross(helper).normalized(), t2 = n.cross(t1);
    const double h = 1e-6;
    const Eigen::Vector3d a = scene.deform(p + h * t1, t) - scene.deform(p - h * t1, t);
    const Eigen::Vector3d b = scene.deform(p + h * t2, t) - scene.deform(p - h * t2, t);
    return a.cross(b).normalized();
}

/// Root of f along x + s d, s in [-r, r], by bisection (nullopt if f is undefined at an end or has
/// one sign there).
template <class Surface>
std::optional<double> root_along(const Surface& surface, const Eigen::Vector3d& x, const Eigen::Vector3d& d, double r)
{
    double lo = -r, hi = r;
    const auto flo = surface.value(x + lo * d), fhi = surface.value(x + hi * d);
    if (!flo || !fhi || (*flo > 0.0) == (*fhi > 0.0)) return std::nullopt;
    const bool rising = *fhi > 0.0;
    for (int k = 0; k < 40; ++k) {
        const double mid = 0.5 * (lo + hi);
        const auto f = surface.value(x + mid * d);
        if (!f) return std::nullopt;
        if ((*f > 0.0) == rising) hi = mid;
        else lo = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace

TEST_CASE("At its rest positions the deforming object is its rest object", "[kinetic][deforming]")
{
    const auto scene = small_scene(1500);
    Object object(scene.rest_points);
    const auto& report = object.set_positions(scene.rest_points);
    CHECK(report.frame == 1);
    CHECK(report.min_stretch == 1.0);
    CHECK(report.max_stretch == 1.0);
    CHECK(object.sampling_radius() == object.rest().sampling_radius());
    // The transported normal of the identity map is the rest normal (to rounding).
    for (Eigen::Index i = 0; i < object.normals().cols(); ++i)
        CHECK((object.normals().col(i) - object.rest().normals().col(i)).norm() <= 1e-9);
    PCCD::Random_engine engine(3);
    const double r = object.sampling_radius();
    for (int k = 0; k < 200; ++k) {
        const auto i = Eigen::Index(PCCD::uniform_index(engine, object.size()));
        const Eigen::Vector3d x = scene.rest_points.col(i) + r * Eigen::Vector3d(PCCD::uniform_real(engine, -1, 1),
                                                                                 PCCD::uniform_real(engine, -1, 1),
                                                                                 PCCD::uniform_real(engine, -1, 1));
        const auto a = object.surface().evaluate(x);
        const auto b = object.rest().surface().evaluate(x);
        REQUIRE(a.status == b.status);
        if (a.defined()) CHECK(std::abs(a.value - b.value) <= 1e-9);
    }
}

TEST_CASE("Under a rigid motion the deformed surface is the rest surface moved", "[kinetic][deforming]")
{
    const auto scene = small_scene(1500);
    Object object(scene.rest_points);
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    const Eigen::Vector3d shift(3.0, -1.0, 0.25);
    const Eigen::Matrix3Xd moved = (rotation * scene.rest_points).colwise() + shift;
    const auto& report = object.set_positions(moved);
    CHECK(report.max_stretch == Approx(1.0).margin(1e-12));
    CHECK(report.min_stretch == Approx(1.0).margin(1e-12));
    // A rotation of 2.5 rad: the normals turn with it, orientation kept (no rest normal would do).
    for (Eigen::Index i = 0; i < object.normals().cols(); ++i)
        CHECK((object.normals().col(i) - rotation * object.rest().normals().col(i)).norm() <= 1e-9);
    PCCD::Random_engine engine(4);
    const double r = object.rest().sampling_radius();
    for (int k = 0; k < 200; ++k) {
        const auto i = Eigen::Index(PCCD::uniform_index(engine, object.size()));
        const Eigen::Vector3d x = scene.rest_points.col(i) + r * Eigen::Vector3d(PCCD::uniform_real(engine, -1, 1),
                                                                                 PCCD::uniform_real(engine, -1, 1),
                                                                                 PCCD::uniform_real(engine, -1, 1));
        const auto a = object.surface().evaluate(rotation * x + shift);
        const auto b = object.rest().surface().evaluate(x);
        REQUIRE(a.status == b.status);
        if (a.defined()) CHECK(std::abs(a.value - b.value) <= 1e-9);
    }
}

TEST_CASE("At random times the deformed surface matches one rebuilt from the moved points", "[kinetic][deforming]")
{
    const auto scene = small_scene(2000);
    PCCD::Random_engine sampling(scene.options.seed); // the scene's own draw: its triangle normals
    const auto sample = PCCD::sample_triangle_mesh(scene.mesh_vertices, scene.mesh_triangles, 2000, sampling);
    REQUIRE(sample.points == scene.rest_points);
    PCCD::Random_engine engine(11);
    for (const auto mode : {PCCD::Normal_update::transport, PCCD::Normal_update::refit}) {
        Object object(scene.rest_points, {}, {.normals = mode});
        for (int trial = 0; trial < random_times; ++trial) {
            const double t = PCCD::uniform_real(engine, 0.0, 4.0);
            const Eigen::Matrix3Xd points = scene.points_at(t);
            object.set_positions(points);
            const auto rebuilt = rebuild(points);
            const double r = rebuilt.sampling_radius();
            INFO("normals " << int(mode) << ", t = " << t);

            // Normals, as lines: against the rebuild's.
            std::vector<double> angle;
            std::size_t agree = 0, oriented = 0;
            for (Eigen::Index i = 0; i < points.cols(); ++i) {
                const Eigen::Vector3d a = object.normals().col(i), b = rebuilt.normals().col(i);
                if (a.isZero(0.0) || b.isZero(0.0)) continue;
                angle.push_back(std::acos(std::min(1.0, std::abs(a.dot(b)))) * 180.0 / std::numbers::pi);
                // Orientation: against the true normal of the deformed mesh.
                const Eigen::Vector3d truth = true_normal(scene, scene.rest_points.col(i), sample.normals.col(i), t);
                ++oriented;
                if (a.dot(truth) > 0.0) ++agree;
            }
            REQUIRE(angle.size() >= std::size_t(0.99 * double(points.cols())));
            // Measured on this scene: median 0.2-0.5 deg, 99th percentile below 2.5 deg for both.
            CHECK(quantile(angle, 0.5) < 2.0);
            CHECK(quantile(angle, 0.95) < 8.0);
            // One orientation for (nearly) all: the mesh's triangles may all face inwards.
            CHECK(double(std::max(agree, oriented - agree)) >= 0.99 * double(oriented));

            // f near the surface and its zero set along the true normal, against the rebuild's.
            std::vector<double> df, root_gap, root_offset;
            std::size_t both_defined = 0, tried = 0;
            for (Eigen::Index i = 0; i < points.cols(); i += 5) {
                const Eigen::Vector3d n = true_normal(scene, scene.rest_points.col(i), sample.normals.col(i), t);
                for (const double s : {-0.5, 0.5}) {
                    ++tried;
                    const auto a = object.surface().evaluate(points.col(i) + s * r * n);
                    const auto b = rebuilt.surface().evaluate(points.col(i) + s * r * n);
                    if (!a.defined() || !b.defined()) continue;
                    ++both_defined;
                    df.push_back(std::abs(std::abs(a.value) - std::abs(b.value)) / r); // orientation aside
                }
                const auto ra = root_along(object.surface(), points.col(i), n, 0.5 * r);
                const auto rb = root_along(rebuilt.surface(), points.col(i), n, 0.5 * r);
                if (ra && rb) {
                    root_gap.push_back(std::abs(*ra - *rb) / r);
                    root_offset.push_back(std::abs(*ra) / r); // the moved point lies on the true surface
                }
            }
            CHECK(double(both_defined) >= 0.95 * double(tried));
            CHECK(quantile(df, 0.5) < 0.05);
            CHECK(quantile(df, 0.95) < 0.3);
            REQUIRE(root_gap.size() >= std::size_t(0.9 * double(points.cols() / 5)));
            CHECK(quantile(root_gap, 0.5) < 0.05);
            CHECK(quantile(root_gap, 0.95) < 0.3);
            CHECK(quantile(root_offset, 0.5) < 0.1);
        }
    }
}

TEST_CASE("On the contact scene the deforming verdicts agree with a rebuild", "[kinetic][deforming]")
{
    auto options = PCCD::testing::Bunny_contact_options{
        .points = 2000, .obstacle_points = 1000, .duration = 2.0, .frame_rate = contact_frame_rate};
    const auto check_run = [](const PCCD::testing::Bunny_contact_scene& scene) {
        const PCCD::testing::Contact_run run = PCCD::testing::run_contact_scene(scene);
        const auto frames = std::size_t(2.0 * contact_frame_rate) + 1;
        REQUIRE(run.frames.size() == frames);
        // Contact switches on and off over the animation.
        CHECK(run.contact_frames > 0);
        CHECK(run.contact_frames < run.frames.size());
        REQUIRE(run.compared >= frames * 2 / 3);
        CHECK(run.agreement() >= 0.99);
        CHECK(run.kinetic_exact == run.compared);
    };
    SECTION("procedural shape") { check_run(PCCD::testing::make_bunny_contact_scene(options)); }
    SECTION("bunny")
    {
        const std::string data = PCCD_DATA_DIR;
        if (data.empty()) PCCD_SKIP_TEST("PCCD_DATA_DIR is empty (libcgal-demo's meshes are absent)");
        options.off_file = data + "/bunny00.off";
        check_run(PCCD::testing::make_bunny_contact_scene(options));
    }
}

TEST_CASE("A deforming object intersects another deforming object", "[kinetic][deforming]")
{
    const auto scene = small_scene(1500);
    Object a(scene.rest_points), b(scene.obstacle_points);
    for (const double t : {0.5, 1.5}) {
        const Eigen::Matrix3Xd points = scene.points_at(t);
        a.set_positions(points);
        b.set_positions(scene.obstacle_points); // the rigid obstacle, as a deforming object at rest
        const bool truth = scene.truth_at(t).intersecting;
        CHECK(PCCD::do_intersect(a, b).intersects == truth);
        CHECK(PCCD::do_intersect(a, rebuild(scene.obstacle_points)).intersects == truth);
        CHECK(PCCD::intersection_points(a, b).points.empty() == !truth);
    }
}

TEST_CASE("The stretch rule: within the bound a frame is accepted, beyond it fails or rebuilds", "[kinetic][deforming]")
{
    const auto scene = small_scene(1000);
    Object object(scene.rest_points); // bound 0.25: lengths within [0.8, 1.25] of rest
    SECTION("uniform scaling")
    {
        const auto& ok = object.set_positions(Eigen::Matrix3Xd(1.2 * scene.rest_points));
        CHECK(ok.min_stretch == Approx(1.2));
        CHECK(ok.max_stretch == Approx(1.2));
        CHECK(object.sampling_radius() == Approx(1.2 * object.rest().sampling_radius()));
        CHECK(object.domain_radii()(0) == Approx(1.2 * object.rest().domain_radii()(0)));
        object.set_positions(Eigen::Matrix3Xd(0.81 * scene.rest_points));
        CHECK(object.deformation().frame == 2);
        for (const double s : {1.3, 1.0 / 1.3}) {
            try {
                object.set_positions(Eigen::Matrix3Xd(s * scene.rest_points));
                FAIL("no Deformation_error at scale " << s);
            } catch (const PCCD::Deformation_error& e) {
                CHECK(e.stretch() == Approx(s));
                CHECK_THAT(e.what(), Contains("stretch bound"));
            }
            // The object keeps its previous frame.
            CHECK(object.deformation().frame == 2);
            CHECK(object.cloud().position(0).isApprox(0.81 * scene.rest_points.col(0)));
        }
    }
    SECTION("one point pulled away")
    {
        Eigen::Matrix3Xd points = scene.rest_points;
        points.col(17) += 10.0 * object.rest().sampling_radius() * Eigen::Vector3d::UnitX();
        try {
            object.set_positions(points);
            FAIL("no Deformation_error");
        } catch (const PCCD::Deformation_error& e) {
            CHECK((e.source() == 17 || e.target() == 17));
            CHECK(e.stretch() > 1.25);
        }
        CHECK(object.deformation().frame == 0);
    }
    SECTION("a wider bound accepts it")
    {
        Object loose(scene.rest_points, {}, {.stretch_bound = 0.5});
        CHECK_NOTHROW(loose.set_positions(Eigen::Matrix3Xd(1.3 * scene.rest_points)));
    }
    SECTION("rebuild")
    {
        Object rebuilding(scene.rest_points, {}, {.on_stretch = PCCD::Stretch_action::rebuild});
        const Eigen::Matrix3Xd big = 1.3 * scene.rest_points;
        const auto& report = rebuilding.set_positions(big);
        CHECK(report.rebuilt);
        CHECK(report.rebuilds == 1);
        CHECK(report.points_beyond > 0);
        CHECK(rebuilding.rest().cloud().position(5) == big.col(5));
        CHECK(rebuilding.sampling_radius() == Approx(1.3 * object.rest().sampling_radius()).epsilon(0.02));
        // The new rest pose: the same positions again are no stretch at all.
        const auto& again = rebuilding.set_positions(big);
        CHECK_FALSE(again.rebuilt);
        CHECK(again.rebuilds == 1);
        CHECK(again.max_stretch == 1.0);
    }
}

TEST_CASE("Flightplans give the frame of their positions", "[kinetic][deforming]")
{
    const auto scene = small_scene(1000);
    std::vector<PCCD::Linear_flightplan> plans;
    for (Eigen::Index i = 0; i < scene.rest_points.cols(); ++i)
        plans.emplace_back(scene.rest_points.col(i), Eigen::Vector3d(0.1 * scene.rest_points(2, i), 0.0, 0.05));
    Object by_plans(scene.rest_points), by_positions(scene.rest_points);
    by_plans.advance_to(0.7, std::span<const PCCD::Linear_flightplan>(plans));
    Eigen::Matrix3Xd at(3, scene.rest_points.cols());
    for (std::size_t i = 0; i < plans.size(); ++i) at.col(Eigen::Index(i)) = plans[i].position(0.7);
    by_positions.set_positions(at);
    CHECK(by_plans.cloud().coordinates() == by_positions.cloud().coordinates());
    CHECK(by_plans.normals() == by_positions.normals());
    CHECK_THROWS_AS(by_plans.advance_to(std::numeric_limits<double>::quiet_NaN(),
                                        std::span<const PCCD::Linear_flightplan>(plans)),
                    PCCD::Invalid_input);
    plans.pop_back();
    CHECK_THROWS_WITH(by_plans.advance_to(0.5, std::span<const PCCD::Linear_flightplan>(plans)),
                      Contains("999 flightplans for 1000 points"));
}

TEST_CASE("Copies keep their frame", "[kinetic][deforming]")
{
    const auto scene = small_scene(1000);
    Object object(scene.rest_points);
    object.set_positions(scene.points_at(0.5));
    const Object copy = object;
    object.set_positions(scene.points_at(1.0));
    CHECK(copy.cloud().coordinates() == scene.points_at(0.5));
    CHECK(object.cloud().coordinates() == scene.points_at(1.0));
    CHECK(copy.deformation().frame == 1);
}

TEST_CASE("Bad positions and options are rejected and leave the frame as it was", "[kinetic][deforming]")
{
    const auto scene = small_scene(1000);
    Object object(scene.rest_points);
    object.set_positions(scene.points_at(0.3));
    CHECK_THROWS_WITH(object.set_positions(Eigen::Matrix3Xd(scene.rest_points.leftCols(999))),
                      Contains("999 positions given for 1000 points"));
    Eigen::Matrix3Xd bad = scene.rest_points;
    bad(2, 123) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(object.set_positions(bad), Contains("position of point 123 is not finite"));
    bad(2, 123) = std::numeric_limits<double>::infinity();
    CHECK_THROWS_AS(object.set_positions(bad), PCCD::Invalid_input);
    const std::vector<Eigen::Vector3d> few(10, Eigen::Vector3d::Zero());
    CHECK_THROWS_AS(object.set_positions(std::span<const Eigen::Vector3d>(few)), PCCD::Invalid_input);
    CHECK(object.deformation().frame == 1);
    CHECK(object.cloud().coordinates() == scene.points_at(0.3));
    for (const double b : {0.0, -0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
        CHECK_THROWS_WITH(Object(scene.rest_points, {}, {.stretch_bound = b}), Contains("stretch_bound"));
    CHECK_THROWS_AS(Object(scene.rest_points, {}, {.on_stretch = PCCD::Stretch_action(7)}), PCCD::Invalid_input);
    CHECK_THROWS_AS(Object(scene.rest_points, {}, {.normals = PCCD::Normal_update(9)}), PCCD::Invalid_input);
    CHECK_THROWS_AS(Object(Eigen::Matrix3Xd::Zero(3, 1)), PCCD::Invalid_input);
}
