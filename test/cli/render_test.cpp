// Tests of the pccd tool's renderer (tools/render/render.h, tools/render_objects.h) by pixel checks
// on a known scene: two unit spheres 1.2 apart, sampled, preprocessed and intersected with
// intersection_points(); their surfaces meet in the circle x = 0.6, y^2 + z^2 = 0.8^2. The picture
// must show each sphere's colour where that sphere is visible, the curve's colour along the visible
// part of the circle and nowhere far from it, and the background outside both spheres' outlines.
// Then the PNG round trip (read back with stb_image.h), the renderer's errors, and the profile plot
// of `pccd clearance --png` (tools/render/plot.h) by pixel checks at the places its mapping gives.
#include <render/plot.h>
#include <render/render.h>
#include <render_objects.h>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Sphere_shape.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace {

using pccd_render::Rgb;

constexpr double separation = 1.2;                           // centre of B: (1.2, 0, 0); both radius 1
constexpr double circle_x = separation / 2.0;                // the plane of the intersection circle
const double circle_radius = std::sqrt(1.0 - circle_x * circle_x);  // 0.8

PCCD::Point_cloud_object<> sphere_object(std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    const PCCD::testing::Surface_sample sample = PCCD::testing::Sphere_shape(Eigen::Vector3d::Zero(), 1.0).sample(6000, engine);
    std::vector<Eigen::Vector3d> points;
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points.push_back(sample.points.col(i));
    return PCCD::Point_cloud_object<>(points);
}

/// `p` is a shade (a multiple in [0.25, 1]) of `c`, allowing for rounding.
bool is_shade_of(Rgb p, Rgb c)
{
    const Eigen::Vector3d pv(p.r, p.g, p.b), cv(c.r, c.g, c.b);
    const double s = pv.dot(cv) / cv.squaredNorm();
    return s >= 0.25 && s <= 1.001 && (pv - s * cv).cwiseAbs().maxCoeff() <= 1.5;
}

/// Does the ray from `p` towards the eye enter the sphere (centre, radius 1) at t > tolerance?
bool ray_enters_sphere(const Eigen::Vector3d& p, const Eigen::Vector3d& dir, const Eigen::Vector3d& centre)
{
    const Eigen::Vector3d m = p - centre;
    const double b = m.dot(dir), c = m.squaredNorm() - 1.0;
    const double disc = b * b - c;
    if (disc <= 0.0) return false;
    const double t_far = -b + std::sqrt(disc);
    return t_far > 1e-3;
}

/// Is any pixel within `reach` of (x, y) of colour `c`?
bool colour_near(const pccd_render::Image& image, const Eigen::Vector2d& q, int reach, Rgb c)
{
    const int x0 = int(std::floor(q.x())), y0 = int(std::floor(q.y()));
    for (int y = y0 - reach; y <= y0 + reach; ++y)
        for (int x = x0 - reach; x <= x0 + reach; ++x)
            if (x >= 0 && y >= 0 && x < image.width && y < image.height && image.at(x, y) == c) return true;
    return false;
}

struct Known_scene {
    PCCD::Point_cloud_object<> a = sphere_object(1);
    PCCD::Point_cloud_object<> b = sphere_object(2);
    PCCD::Rigid_transform_3<double> pose_a;
    PCCD::Rigid_transform_3<double> pose_b{Eigen::Matrix3d::Identity(), Eigen::Vector3d(separation, 0.0, 0.0)};
    PCCD::Intersection_result curve;
    pccd_render::Scene scene;

    Known_scene()
    {
        PCCD::Intersection_options options;
        options.point_spacing = 0.02;
        curve = PCCD::intersection_points(a, pose_a, b, pose_b, options);
        scene.clouds.push_back(pccd_tool::cloud_layer(a, pose_a, pccd_render::colour_a));
        scene.clouds.push_back(pccd_tool::cloud_layer(b, pose_b, pccd_render::colour_b));
        scene.markers.push_back(pccd_tool::curve_layer(curve.points, 0.5 * scene.clouds.front().splat_radius));
    }
};

const Known_scene& known_scene()
{
    static const Known_scene scene;
    return scene;
}

} // namespace

TEST_CASE("The known scene: the query finds points on the circle of the two spheres", "[render]")
{
    const Known_scene& s = known_scene();
    REQUIRE(s.curve.intersects);
    REQUIRE(s.curve.points.size() >= 100);
    for (const PCCD::Intersection_point& p : s.curve.points) {
        CHECK(std::abs(p.position.x() - circle_x) < 0.02);
        CHECK(std::abs(p.position.tail<2>().norm() - circle_radius) < 0.02);
    }
}

TEST_CASE("Pixels of the known scene: object colours, the curve along the circle, background elsewhere", "[render]")
{
    const Known_scene& s = known_scene();
    for (const pccd_render::View view : {pccd_render::View{15.0, 30.0}, pccd_render::View{180.0, 30.0},
                                         pccd_render::View{0.0, 90.0}}) {
        INFO("view " << view.azimuth << "," << view.elevation);
        const pccd_render::Camera camera = pccd_render::fit_camera(s.scene, view, 640, 480);
        const pccd_render::Image image = pccd_render::render(s.scene, camera);
        REQUIRE(image.width == 640);
        REQUIRE(image.height == 480);
        const Eigen::Vector3d eye = camera.toward_eye;
        const Eigen::Vector3d centre_a = Eigen::Vector3d::Zero(), centre_b(separation, 0.0, 0.0);
        const double splat_px = s.scene.clouds.front().splat_radius * camera.pixels_per_unit;
        const double marker_px = std::max(s.scene.markers.front().radius * camera.pixels_per_unit,
                                          s.scene.markers.front().min_pixels);

        // The curve's colour along the visible part of the circle (both surfaces face the eye at
        // less than 60 degrees, so nothing hides it and the markers stand in front of the splats): 720 points of the circle; those within half a marker radius of a point
        // the query returned (the query covers most of the circle, not all of it) must have the
        // curve's colour within 1 pixel.
        const double marker_world = s.scene.markers.front().radius;
        std::vector<Eigen::Vector2d> circle;
        std::size_t visible = 0, covered = 0, coloured = 0;
        for (int k = 0; k < 720; ++k) {
            const double phi = 2.0 * std::numbers::pi * k / 720.0;
            const Eigen::Vector3d q(circle_x, circle_radius * std::cos(phi), circle_radius * std::sin(phi));
            circle.push_back(camera.project(q));
            if ((q - centre_a).normalized().dot(eye) <= 0.5 || (q - centre_b).normalized().dot(eye) <= 0.5) continue;
            ++visible;
            const bool near_point = std::any_of(s.curve.points.begin(), s.curve.points.end(), [&](const auto& p) {
                return (p.position - q).norm() <= 0.5 * marker_world;
            });
            if (!near_point) continue;
            ++covered;
            coloured += colour_near(image, circle.back(), 1, pccd_render::colour_curve);
        }
        REQUIRE(visible >= 60);
        REQUIRE(covered >= visible / 3);
        CHECK(coloured == covered);

        // Each object's colour where its sphere is visible and away from the other sphere: the
        // points of a 40 x 80 grid in angles that face the eye and whose ray to the eye meets no
        // sphere.
        for (const auto& [centre, other, colour] :
             {std::tuple{centre_a, centre_b, pccd_render::colour_a}, std::tuple{centre_b, centre_a, pccd_render::colour_b}}) {
            std::size_t tested = 0, right = 0;
            for (int i = 1; i < 40; ++i)
                for (int j = 0; j < 80; ++j) {
                    const double theta = std::numbers::pi * i / 40.0, phi = 2.0 * std::numbers::pi * j / 80.0;
                    const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                            std::cos(theta));
                    const Eigen::Vector3d p = centre + n;
                    if (n.dot(eye) < 0.4 || (p - other).norm() < 1.15 || ray_enters_sphere(p, eye, other)) continue;
                    const Eigen::Vector2d q = camera.project(p);
                    ++tested;
                    right += is_shade_of(image.at(int(q.x()), int(q.y())), colour);
                }
            REQUIRE(tested >= 200);
            CHECK(double(right) >= 0.97 * double(tested));
        }

        // Nothing but background outside both outlines (projected unit discs grown by a splat), and
        // no curve colour farther than a marker from the circle.
        const Eigen::Vector2d outline_a = camera.project(centre_a), outline_b = camera.project(centre_b);
        const double outline = camera.pixels_per_unit + splat_px + 1.5;
        std::size_t background = 0, stray_background = 0, stray_curve = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const Eigen::Vector2d c(x + 0.5, y + 0.5);
                const Rgb pixel = image.at(x, y);
                if ((c - outline_a).norm() > outline && (c - outline_b).norm() > outline) {
                    ++background;
                    stray_background += !(pixel == pccd_render::colour_background);
                }
                if (pixel == pccd_render::colour_curve) {
                    double nearest = std::numeric_limits<double>::infinity();
                    for (const Eigen::Vector2d& q : circle) nearest = std::min(nearest, (c - q).norm());
                    stray_curve += nearest > marker_px + 0.02 * camera.pixels_per_unit + 2.0;
                }
            }
        CHECK(background > 20000);
        CHECK(stray_background == 0);
        CHECK(stray_curve == 0);
        // The corners are background (the camera leaves a margin).
        CHECK(image.at(0, 0) == pccd_render::colour_background);
        CHECK(image.at(639, 479) == pccd_render::colour_background);
    }
}

TEST_CASE("The automatic camera frames the scene and turns to show the curve", "[render]")
{
    const Known_scene& s = known_scene();
    const pccd_render::View view = pccd_render::choose_view(s.scene, 640, 480);
    const pccd_render::Camera camera = pccd_render::fit_camera(s.scene, view, 640, 480);
    std::size_t total = 0;
    for (const auto& m : s.scene.markers) total += std::size_t(m.points.cols());
    // From the side of A (looking along +x) the circle hides behind A's front; the chosen view shows
    // most of the points (about half of a circle is visible from any direction).
    const pccd_render::View hidden{-90.0, 0.0};
    CHECK(pccd_render::visible_markers(s.scene, pccd_render::fit_camera(s.scene, hidden, 640, 480)) < total / 20);
    CHECK(pccd_render::visible_markers(s.scene, camera) > total / 4);
    // Every point of the scene projects inside the image.
    for (const auto& cloud : s.scene.clouds)
        for (Eigen::Index i = 0; i < cloud.points.cols(); ++i) {
            const Eigen::Vector2d q = camera.project(cloud.points.col(i));
            CHECK((q.x() >= 0 && q.y() >= 0 && q.x() < 640 && q.y() < 480));
            if (!(q.x() >= 0 && q.y() >= 0 && q.x() < 640 && q.y() < 480)) break;
        }
}

TEST_CASE("The PNG file holds the rendered pixels", "[render]")
{
    const Known_scene& s = known_scene();
    const pccd_render::Image image =
        pccd_render::render(s.scene, pccd_render::fit_camera(s.scene, pccd_render::View{}, 200, 150));
    const std::string path = std::string(PCCD_TEST_TMP_DIR) + "/render_round_trip.png";
    pccd_render::write_png(path, image);
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
    REQUIRE(pixels != nullptr);
    CHECK(width == 200);
    CHECK(height == 150);
    CHECK(std::equal(image.rgb.begin(), image.rgb.end(), pixels));
    stbi_image_free(pixels);
}

TEST_CASE("The renderer rejects bad input with clear errors", "[render]")
{
    CHECK_THROWS_WITH(pccd_render::parse_view("sideways"), Catch::Contains("AZIMUTH,ELEVATION"));
    CHECK_THROWS_WITH(pccd_render::parse_view("30,91"), Catch::Contains("[-90, 90]"));
    CHECK_THROWS_WITH(pccd_render::parse_view("x,20"), Catch::Contains("not a finite number"));
    CHECK(pccd_render::parse_view("top").elevation == 90.0);
    CHECK(pccd_render::parse_view("12.5,-30").azimuth == 12.5);
    CHECK_THROWS_WITH(pccd_render::parse_size("800"), Catch::Contains("WIDTHxHEIGHT"));
    CHECK_THROWS_WITH(pccd_render::parse_size("8x600"), Catch::Contains("[16, 8192]"));
    CHECK(pccd_render::parse_size("320x200") == std::pair{320, 200});

    pccd_render::Scene empty;
    CHECK_THROWS_WITH(pccd_render::fit_camera(empty, {}, 100, 100), Catch::Contains("no point"));

    pccd_render::Scene scene;
    pccd_render::Cloud_layer cloud;
    cloud.points = Eigen::Matrix3Xd::Random(3, 10);
    cloud.normals = Eigen::Matrix3Xd::Random(3, 9);
    cloud.splat_radius = 0.1;
    scene.clouds.push_back(cloud);
    const pccd_render::Camera camera = pccd_render::fit_camera(scene, {}, 100, 100);
    CHECK_THROWS_WITH(pccd_render::render(scene, camera), Catch::Contains("9 normals for 10 points"));
    scene.clouds.front().normals.resize(3, 0);
    scene.clouds.front().splat_radius = 0.0;
    CHECK_THROWS_WITH(pccd_render::render(scene, camera), Catch::Contains("splat radius"));
    scene.clouds.front().points(0, 3) = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(pccd_render::fit_camera(scene, {}, 100, 100), Catch::Contains("not finite"));

    pccd_render::Image image;
    image.width = image.height = 16;
    image.rgb.assign(3 * 16 * 16, 0);
    CHECK_THROWS_AS(pccd_render::write_png(std::string(PCCD_TEST_TMP_DIR) + "/no/such/dir/x.png", image),
                    PCCD::File_error);
}

TEST_CASE("The profile plot: dots, levels, bars and the marker where the mapping puts them", "[render]")
{
    pccd_render::Profile_plot plot;
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    plot.values = {0.5, 1.0, inf, nan};
    const pccd_render::Rgb red{220, 20, 30}, grey{150, 150, 150}, green{20, 160, 60};
    plot.dot_colours = {pccd_render::colour_a, red, grey, pccd_render::colour_a};
    plot.lower = {0.2, 0.9, 1.5, nan};
    plot.upper = {0.8, 1.1, inf, nan};
    plot.levels = {{1.5, green, false}};
    plot.marker = 1;
    plot.y_max = 2.0;
    const int w = 400, h = 300;
    const pccd_render::Image image = pccd_render::plot_profile(plot, w, h);
    REQUIRE(image.width == w);
    REQUIRE(image.height == h);
    const auto px = [&](std::size_t i) { return int(std::lround(pccd_render::plot_x(i, 4, w, h))); };
    const auto py = [&](double y) { return int(std::lround(pccd_render::plot_y(y, plot.y_max, w, h))); };
    const int m = pccd_render::plot_margin(w, h);
    // the mapping: index 0 at the left edge of the plot area, the last at its right; 0 at the bottom, y_max at the top
    CHECK(px(0) == m);
    CHECK(px(3) == w - 1 - m);
    CHECK(py(0.0) == h - 1 - m);
    CHECK(py(2.0) == m);
    // each value's dot in its colour; +inf at the top edge; NaN not drawn
    CHECK(image.at(px(0), py(0.5)) == pccd_render::colour_a);
    CHECK(image.at(px(1), py(1.0)) == red);
    CHECK(image.at(px(2), py(2.0)) == grey);
    CHECK(image.at(px(3), py(0.5)) == pccd_render::colour_background);
    CHECK(image.at(px(3), py(1.0)) == pccd_render::colour_background);
    // index 2's interval bar below its dot, the level across the plot away from the polyline, the
    // dashed marker at index 1 from the top
    CHECK(image.at(px(2), py(1.75)) == plot.bar_colour);
    CHECK(image.at(px(0) + 2, py(1.5)) == green);
    CHECK(image.at(px(3) - 2, py(1.5)) == green);
    CHECK(image.at(px(1), m + 2) == red);
    // the axes
    CHECK(image.at(w / 2, h - 1 - m) == plot.axis_colour);
    CHECK(image.at(m, h / 2) == plot.axis_colour);
    // outside the plot area: background
    CHECK(image.at(2, 2) == pccd_render::colour_background);

    CHECK_THROWS_WITH(pccd_render::plot_profile(plot, 8, 300), Catch::Contains("[16, 8192]"));
    pccd_render::Profile_plot bad = plot;
    bad.y_max = 0.0;
    CHECK_THROWS_WITH(pccd_render::plot_profile(bad, w, h), Catch::Contains("y_max"));
    bad = plot;
    bad.dot_colours.pop_back();
    CHECK_THROWS_WITH(pccd_render::plot_profile(bad, w, h), Catch::Contains("dot colour"));
    bad = plot;
    bad.upper.pop_back();
    CHECK_THROWS_WITH(pccd_render::plot_profile(bad, w, h), Catch::Contains("interval bars"));
    // an empty plot is only the axes
    const pccd_render::Image empty = pccd_render::plot_profile(pccd_render::Profile_plot{}, 64, 64);
    CHECK(empty.at(32, 64 - 1 - pccd_render::plot_margin(64, 64)) == pccd_render::Profile_plot{}.axis_colour);
}
