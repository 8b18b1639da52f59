// The scanned-tunnel clearance scene (PCCD/testing/scenes/Tunnel_scene.h) against independent
// truths: the clouds lie on their meshes within the stated noise (CGAL's AABB tree through
// Exact_mesh), the outliers lie off the vault circle by their stated offsets (the analytic
// cross-section), the occlusion holes hold no wall sample (the points' tunnel coordinates computed
// here from the arc), the path's poses are rigid and tangent-aligned (the analytic centre line),
// the deliberate offsets bring the wagon below the 5 cm margin and the others leave it well above
// (exact mesh distance, PCCD/Exact/mesh_distance.h), and the files written read back.
#include <PCCD/Error.h>
#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_distance.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/testing/scenes/Tunnel_scene.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using PCCD::testing::Tunnel_scene;
using PCCD::testing::Tunnel_scene_options;

/// A small scene: 10^5 tunnel points with half the default noise (so that 4 sigma stays below
/// the 3 cm between the cables and the wall), 2 * 10^4 wagon points, 24 poses (4 deliberate).
const Tunnel_scene& small_scene()
{
    static const Tunnel_scene scene = [] {
        Tunnel_scene_options o;
        o.scene_points = 100'000;
        o.wagon_points = 20'000;
        o.poses = 24;
        o.noise = 0.05;
        o.seed = 11;
        return PCCD::testing::make_tunnel_scene(o);
    }();
    return scene;
}

/// The analytic centre line of the defaults' geometry: an arc of radius Rc curving left from the
/// origin along +x; arc length, point, tangent and left normal, from the test's own formulas.
struct Arc {
    double rc;
    Eigen::Vector3d point(double s) const { return {rc * std::sin(s / rc), rc - rc * std::cos(s / rc), 0.0}; }
    Eigen::Vector3d tangent(double s) const { return {std::cos(s / rc), std::sin(s / rc), 0.0}; }
    Eigen::Vector3d normal(double s) const { return {-std::sin(s / rc), std::cos(s / rc), 0.0}; }
    /// s, u (along the normal) and z of a world point.
    Eigen::Vector3d coordinates(const Eigen::Vector3d& p) const
    {
        const double s = rc * std::atan2(p.x(), rc - p.y());
        return {s, (p - point(s)).dot(normal(s)), p.z()};
    }
};

/// Signed distance of a cross-section point (u, z) to the vault circle (positive outside).
double off_vault(const Tunnel_scene_options& o, double u, double z)
{
    return std::hypot(u, z - o.vault_centre_height) - o.tunnel_radius;
}

double distance_to_mesh(const PCCD::Exact_mesh& mesh, const Eigen::Vector3d& p)
{
    return std::sqrt(mesh.tree().squared_distance(PCCD::Exact_mesh::Point_3(p.x(), p.y(), p.z())));
}

} // namespace

TEST_CASE("tunnel scene: the clouds lie on their meshes within the noise", "[sampling][tunnel]")
{
    const Tunnel_scene& scene = small_scene();
    const Tunnel_scene_options& o = scene.options;
    REQUIRE(scene.tunnel_points.cols() == Eigen::Index(o.scene_points));
    REQUIRE(scene.wagon_points.cols() == Eigen::Index(o.wagon_points));
    REQUIRE(scene.first_outlier == o.scene_points - o.outliers);
    // sigma = noise * sqrt(area / points), the area summed here.
    CHECK(scene.tunnel_sigma == Approx(o.noise * std::sqrt(scene.tunnel_area / double(o.scene_points))));
    // Surface of the defaults: the vault (240 degrees of a 3 m circle) and the 5.2 m bed over 50 m,
    // plus rails, cables and boxes: between 888 and 1000 m^2.
    CHECK(scene.tunnel_area > 888.0);
    CHECK(scene.tunnel_area < 1000.0);

    const PCCD::Exact_mesh tunnel(scene.tunnel_mesh), wagon(scene.wagon_mesh);
    // Isotropic Gaussian noise: the distance to a plane is |N(0, sigma^2)|, so the RMS distance is
    // sigma (a little less near edges, where the closest point is not along the normal), and no
    // sample of 10^5 lies beyond 6 sigma (probability 2e-9 each).
    const auto check_cloud = [](const PCCD::Exact_mesh& mesh, const Eigen::Matrix3Xd& points, Eigen::Index count, double sigma) {
        double sum = 0.0, worst = 0.0;
        for (Eigen::Index i = 0; i < count; ++i) {
            const double d = distance_to_mesh(mesh, points.col(i));
            sum += d * d;
            worst = std::max(worst, d);
        }
        const double rms = std::sqrt(sum / double(count));
        CHECK(worst < 6.0 * sigma);
        CHECK(rms > 0.85 * sigma);
        CHECK(rms < 1.05 * sigma);
    };
    check_cloud(tunnel, scene.tunnel_points, Eigen::Index(scene.first_outlier), scene.tunnel_sigma);
    check_cloud(wagon, scene.wagon_points, scene.wagon_points.cols(), scene.wagon_sigma);

    // Outliers: a wall point below 2.5 m moved 0.1 - 0.5 m along the wall's normal, so off the vault
    // circle by that much (2 mm for the polygon and the chords' normals).
    const Arc arc{o.curve_radius};
    for (Eigen::Index i = Eigen::Index(scene.first_outlier); i < scene.tunnel_points.cols(); ++i) {
        const Eigen::Vector3d c = arc.coordinates(scene.tunnel_points.col(i));
        const double off = std::abs(off_vault(o, c.y(), c.z()));
        CHECK(off > o.outlier_min_offset - 0.002);
        CHECK(off < o.outlier_max_offset + 0.002);
        CHECK(c.z() < 2.5 + o.outlier_max_offset);
    }
}

TEST_CASE("tunnel scene: the occlusion holes hold no wall sample", "[sampling][tunnel]")
{
    const Tunnel_scene& scene = small_scene();
    const Tunnel_scene_options& o = scene.options;
    REQUIRE(scene.holes.size() == o.holes);
    const Arc arc{o.curve_radius};
    const double guard = 6.0 * scene.tunnel_sigma;
    const double on_wall = 4.0 * scene.tunnel_sigma; // cables are 3 cm off the wall: 4 sigma < 3 cm here
    REQUIRE(on_wall < 0.03);
    std::vector<Eigen::Vector3d> wall; // (s, u, z) of the wall samples
    for (Eigen::Index i = 0; i < Eigen::Index(scene.first_outlier); ++i) {
        const Eigen::Vector3d c = arc.coordinates(scene.tunnel_points.col(i));
        if (c.z() > 0.1 && std::abs(off_vault(o, c.y(), c.z())) < on_wall) wall.push_back(c);
    }
    const auto count_in = [&](double s0, double s1, double z0, double z1, int side) {
        std::size_t n = 0;
        for (const Eigen::Vector3d& c : wall)
            if ((c.y() > 0.0) == (side > 0) && c.x() > s0 && c.x() < s1 && c.z() > z0 && c.z() < z1) ++n;
        return n;
    };
    std::size_t compared = 0;
    for (const auto& hole : scene.holes) {
        CHECK(hole.s_end - hole.s_begin == Approx(o.hole_length));
        CHECK(count_in(hole.s_begin + guard, hole.s_end - guard, hole.z_begin + guard, hole.z_end - guard, hole.side) == 0);
        // The same patch on the other wall, where it is no hole, is sampled: about area * density
        // = 1.2 m^2 * 10^5 / 968 m^2 = 120 points expected.
        bool free = true;
        for (const auto& other : scene.holes)
            if (other.side == -hole.side && other.s_begin < hole.s_end && hole.s_begin < other.s_end &&
                other.z_begin < hole.z_end && hole.z_begin < other.z_end)
                free = false;
        if (!free) continue;
        ++compared;
        CHECK(count_in(hole.s_begin, hole.s_end, hole.z_begin, hole.z_end, -hole.side) > 60);
    }
    CHECK(compared > 0);
}

TEST_CASE("tunnel scene: the path's poses are rigid and tangent-aligned", "[sampling][tunnel]")
{
    const Tunnel_scene& scene = small_scene();
    const Tunnel_scene_options& o = scene.options;
    REQUIRE(scene.path.size() == o.poses);
    const Arc arc{o.curve_radius};
    std::size_t deliberate = 0;
    for (std::size_t k = 0; k < scene.path.size(); ++k) {
        const auto& p = scene.path[k];
        const Eigen::Matrix3d& r = p.pose.rotation();
        CHECK((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-12);
        CHECK(std::abs(r.determinant() - 1.0) < 1e-12);
        CHECK((r.col(0) - arc.tangent(p.s)).norm() < 1e-12);
        CHECK((r.col(2) - Eigen::Vector3d::UnitZ()).norm() < 1e-12);
        const Eigen::Vector3d offset = p.pose.translation() - arc.point(p.s);
        CHECK((offset - p.lateral * arc.normal(p.s)).norm() < 1e-9);
        // The wagon's ends stay inside the tube.
        CHECK(p.s - 0.5 * o.wagon_length > 0.0);
        CHECK(p.s + 0.5 * o.wagon_length < o.tunnel_length);
        if (k > 0) CHECK(p.s > scene.path[k - 1].s);
        CHECK(p.deliberate == (k % o.offset_every == o.offset_every / 2));
        if (p.deliberate) ++deliberate;
        else CHECK(std::abs(p.lateral) <= o.sway_amplitude);
    }
    CHECK(deliberate == o.poses / o.offset_every);
}

TEST_CASE("tunnel scene: the deliberate offsets bring the wagon below the margin (exact)", "[sampling][tunnel][exact]")
{
    const Tunnel_scene& scene = small_scene();
    const PCCD::Exact_mesh tunnel(scene.tunnel_mesh), wagon(scene.wagon_mesh);
    const PCCD::Rigid_transform_3<double> identity;
    const double margin = 0.05;
    std::size_t below = 0;
    for (std::size_t k = 0; k < scene.path.size(); ++k) {
        const auto& p = scene.path[k];
        const PCCD::Exact_distance d = PCCD::exact_distance(wagon, p.pose, tunnel, identity);
        INFO("pose " << k << " lateral " << p.lateral << " target " << p.target_clearance << " exact " << d.distance);
        REQUIRE_FALSE(d.surfaces_intersect);
        if (p.deliberate) {
            // The pan head's outer top edge is at the target from the vault circle; the vault polygon
            // lies inside the circle by at most R (1 - cos(0.75 deg)) = 0.26 mm.
            CHECK(d.distance <= p.target_clearance + 1e-6);
            CHECK(d.distance > p.target_clearance - 0.001);
            CHECK((d.distance < margin) == (p.target_clearance < margin));
            if (d.distance < margin) ++below;
        } else {
            // Centred with the sway (|lateral| <= 4 cm): the pan head is >= 0.105 m from the circle.
            CHECK(d.distance > 0.1);
        }
    }
    CHECK(below == 3); // targets 1, 2.5 and 4 cm; the fourth deliberate pose (7 cm) stays above
}

TEST_CASE("tunnel scene: the written files read back", "[sampling][tunnel][io]")
{
    const Tunnel_scene& scene = small_scene();
    const std::string dir = std::string(PCCD_TEST_TMP_DIR) + "/tunnel_scene";
    std::filesystem::remove_all(dir);
    PCCD::testing::write_tunnel_scene(scene, dir);
    const PCCD::Point_data tunnel = PCCD::IO::read_points(dir + "/tunnel.ply");
    REQUIRE(tunnel.points.size() == scene.options.scene_points);
    CHECK(tunnel.points[123] == Eigen::Vector3d(scene.tunnel_points.col(123))); // binary PLY: bit exact
    CHECK(PCCD::IO::read_points(dir + "/wagon.ply").points.size() == scene.options.wagon_points);
    CHECK(PCCD::IO::read_triangle_mesh(dir + "/tunnel.off").triangles.size() == scene.tunnel_mesh.triangles.size());
    CHECK(PCCD::IO::read_triangle_mesh(dir + "/wagon.off").triangles.size() == scene.wagon_mesh.triangles.size());
    for (const char* name : {"poses.csv", "cases.csv"}) {
        std::ifstream in(dir + "/" + name);
        std::string line;
        if (std::string(name) == "poses.csv") std::getline(in, line); // header
        std::size_t rows = 0;
        while (std::getline(in, line)) {
            std::vector<double> v;
            std::stringstream fields(line);
            for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
            REQUIRE(v.size() == (std::string(name) == "poses.csv" ? 12u : 24u));
            const auto& pose = scene.path[rows].pose;
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) CHECK(v[std::size_t(4 * i + j)] == pose.rotation()(i, j));
                CHECK(v[std::size_t(4 * i + 3)] == pose.translation()(i));
            }
            ++rows;
        }
        CHECK(rows == scene.path.size());
    }
}

TEST_CASE("tunnel scene: options outside their ranges are refused", "[sampling][tunnel]")
{
    const auto refuses = [](auto change) {
        Tunnel_scene_options o;
        o.scene_points = 2000;
        o.wagon_points = 2000;
        change(o);
        CHECK_THROWS_AS(PCCD::testing::make_tunnel_scene(o), PCCD::Invalid_input);
    };
    refuses([](Tunnel_scene_options& o) { o.scene_points = 10; });
    refuses([](Tunnel_scene_options& o) { o.poses = 1; });
    refuses([](Tunnel_scene_options& o) { o.noise = -0.1; });
    refuses([](Tunnel_scene_options& o) { o.tunnel_radius = 1.5; });
    refuses([](Tunnel_scene_options& o) { o.offset_clearances = {0.5}; });
    refuses([](Tunnel_scene_options& o) { o.tunnel_length = 10.0; });
    refuses([](Tunnel_scene_options& o) { o.curve_radius = std::nan(""); });
}
