// Tests of the lean object with the Euclidean kernel (PCCD/Euclidean_point_cloud_object.h) and of
// the interpolation search on objects without a CPSP map (Intersection/internal/isearch_partners.h),
// against analytic spheres: verdicts beyond the grazing band, contacts on the exact circle, the
// distance of two spheres, the surface and its normals, what the object keeps, bad input, and its
// files (PCCD/Euclidean_point_cloud_object_file.h: save and load, bit for bit).
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Euclidean_point_cloud_object_class.h>
#include <PCCD/Euclidean_point_cloud_object_file.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Random.h>
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/testing/statistics.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "Hierarchy/hierarchy_compare.h"
#include "surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using Lean = PCCD::Euclidean_point_cloud_object<>;

static_assert(PCCD::EuclideanCollisionObject<Lean>);
static_assert(PCCD::ProximityObject<Lean>);
static_assert(!PCCD::GeodesicCollisionObject<Lean>);
static_assert(PCCD::GeodesicCollisionObject<PCCD::Point_cloud_object<>>);
static_assert(PCCD::EuclideanCollisionObject<PCCD::Point_cloud_object<>>);

struct Lean_spheres {
    Lean a, b;
    double spacing, r;
};

/// Two unit spheres of 6,000 area-sampled points each, with noise `noise` (in units of the radius).
const Lean_spheres& lean_spheres()
{
    static const Lean_spheres s = [] {
        Lean a(pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 21).points));
        Lean b(pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 22).points));
        const double spacing = std::max(a.cloud().mean_spacing(), b.cloud().mean_spacing());
        const double r = std::max(a.sampling_radius(), b.sampling_radius());
        return Lean_spheres{std::move(a), std::move(b), spacing, r};
    }();
    return s;
}

Rigid_transform_3<double> shifted(double d)
{
    return Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(d, 0, 0));
}

} // namespace

TEST_CASE("Lean object: the surface and normals of a sampled sphere", "[lean]")
{
    const Lean_spheres& s = lean_spheres();
    const Lean& a = s.a;
    REQUIRE(a.size() == 6000);
    CHECK(a.hierarchy().has_reach());
    // The WLS evaluations' radius queries (at the support radius) come from the cloud's cell grid,
    // at most 8 cells each: cells at least twice the support radius wide.
    REQUIRE(a.cloud().kd_tree().cell_grid_side());
    CHECK(*a.cloud().kd_tree().cell_grid_side() >= 2.0 * a.weight().support_radius());
    // Normals point outward (the analytic normal of a unit sphere at p is p).
    std::size_t outward = 0;
    for (std::uint32_t i = 0; i < a.size(); ++i)
        outward += a.normals().col(i).dot(a.cloud().position(i).template cast<double>().normalized()) > 0.9;
    CHECK(outward == a.size());
    // f is a signed distance near the surface: at points half a mean spacing off the sphere (inside
    // the domain), inside negative and outside positive, with |f - exact| well below the spacing.
    PCCD::Random_engine engine(5);
    std::vector<double> errors;
    std::size_t undefined = 0;
    for (int k = 0; k < 500; ++k) {
        const Eigen::Vector3d u = PCCD::testing::uniform_random_rotation(engine).col(0);
        for (double offset : {-0.5, 0.5}) {
            const Eigen::Vector3d x = (1.0 + offset * s.spacing) * u;
            const auto e = a.surface().evaluate(x);
            if (!e.defined()) {
                ++undefined; // beyond the domain of the sparsest points
                continue;
            }
            CHECK((e.value < 0) == (offset < 0));
            errors.push_back(std::abs(e.value - offset * s.spacing));
        }
    }
    CHECK(undefined <= 10);
    std::sort(errors.begin(), errors.end());
    INFO("undefined " << undefined << " of 1000, median " << PCCD::testing::sorted_quantile(errors, 50) / s.spacing << " p99 "
                   << PCCD::testing::sorted_quantile(errors, 99) / s.spacing << " spacings");
    CHECK(PCCD::testing::sorted_quantile(errors, 50) < 0.05 * s.spacing);
    CHECK(PCCD::testing::sorted_quantile(errors, 99) < 0.2 * s.spacing);
    // Far from the points the surface is undefined (the domain).
    CHECK(!a.surface().evaluate(Eigen::Vector3d(0, 0, 0)).defined());
}

TEST_CASE("Lean object: do_intersect agrees with the analytic answer for both policies", "[lean][intersection]")
{
    const Lean_spheres& s = lean_spheres();
    for (double d : {0.0, 0.4, 1.0, 1.6, 1.9, 2.0 - 1.5 * s.r, 2.0 + 1.5 * s.r, 2.3, 2.9, 4.0}) {
        const bool truth = d < 2.0;
        for (std::uint64_t seed = 0; seed < 5; ++seed) {
            INFO("d = " << d << ", seed " << seed);
            const PCCD::Intersection_options options{.seed = seed};
            const auto isearch = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(d), options);
            CHECK(isearch.intersects == truth);
            const auto rst = PCCD::do_intersect(s.a, Rigid_transform_3<double>(), s.b, shifted(d), options,
                                                PCCD::Randomized_sampling{});
            CHECK(rst.intersects == truth);
            if (truth && isearch.intersects) {
                const Eigen::Vector3d x = isearch.points.at(0).position;
                CHECK(std::abs(x.norm() - 1.0) < 0.5 * s.r);
                CHECK(std::abs((x - Eigen::Vector3d(d, 0, 0)).norm() - 1.0) < 0.5 * s.r);
            }
        }
    }
}

TEST_CASE("Lean object: the interpolation search brackets along chords and finds the circle", "[lean][intersection]")
{
    const Lean_spheres& s = lean_spheres();
    for (double d : {0.5, 1.2, 1.8}) {
        INFO("d = " << d);
        const auto result = PCCD::intersection_points(s.a, Rigid_transform_3<double>(), s.b, shifted(d), {.seed = 3});
        REQUIRE(result.intersects);
        CHECK(result.counters.brackets_found > 0);
        std::vector<double> errors;
        const double radius = std::sqrt(1.0 - d * d / 4.0);
        for (const auto& p : result.points)
            errors.push_back(std::hypot(p.position.x() - d / 2.0, std::hypot(p.position.y(), p.position.z()) - radius));
        std::sort(errors.begin(), errors.end());
        CHECK(PCCD::testing::sorted_quantile(errors, 50) <= 0.5 * s.spacing);
        CHECK(PCCD::testing::sorted_quantile(errors, 95) <= 2.0 * s.spacing);
        CHECK(result.points.size() >= 20);
    }
}

TEST_CASE("Lean object: mixed with a geodesic object, and the distance of two spheres", "[lean][proximity]")
{
    const Lean_spheres& s = lean_spheres();
    const PCCD::Point_cloud_object<> g(pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), 6000, 0.0, 23).points));
    for (double d : {1.0, 1.9, 2.3, 3.0}) {
        INFO("d = " << d);
        const bool truth = d < 2.0;
        CHECK(PCCD::do_intersect(s.a, Rigid_transform_3<double>(), g, shifted(d), {.seed = 1}).intersects == truth);
        CHECK(PCCD::do_intersect(g, Rigid_transform_3<double>(), s.a, shifted(d), {.seed = 1}).intersects == truth);
    }
    // Two unit spheres whose centres are d apart are d - 2 apart.
    for (double d : {2.2, 2.5, 3.0}) {
        INFO("d = " << d);
        const auto result = PCCD::distance(s.a, Rigid_transform_3<double>(), s.b, shifted(d), {.intersection = {.seed = 1}});
        REQUIRE(result.status == PCCD::Intersection_status::separate);
        CHECK(std::abs(result.distance - (d - 2.0)) < 0.25 * s.spacing);
        CHECK(result.lower_bound <= d - 2.0 + 0.25 * s.spacing);
        CHECK(result.upper_bound >= d - 2.0 - 0.25 * s.spacing);
    }
}

TEST_CASE("Lean object: keeps a fifth of the geodesic object's memory and the same points", "[lean]")
{
    const auto points = pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), 4000, 0.0, 31).points);
    const Lean lean(points);
    const PCCD::Point_cloud_object<> full(points);
    REQUIRE(lean.size() == full.size());
    CHECK(lean.input_indices() == full.input_indices());
    CHECK(lean.sampling_radius() == full.sampling_radius());
    const std::size_t full_bytes = full.cloud().kd_tree().memory_bytes() + full.graph().memory_bytes() +
                                   full.cpsp().memory_bytes() + full.hierarchy().memory_bytes();
    INFO("lean " << lean.memory_bytes() / double(lean.size()) << " B/point, geodesic object at least "
                 << full_bytes / double(full.size()));
    CHECK(lean.memory_bytes() < full_bytes / 3);
    CHECK(lean.memory_bytes() / double(lean.size()) < 200.0);
    // The two objects differ only in the distance of their kernel: their normals agree in sign.
    std::size_t agree = 0;
    for (Eigen::Index i = 0; i < lean.normals().cols(); ++i) agree += lean.normals().col(i).dot(full.normals().col(i)) > 0.0;
    CHECK(agree == lean.size());
}

TEST_CASE("Lean object: bad input is rejected with a message", "[lean]")
{
    Eigen::Matrix3Xd one(3, 1);
    one.setZero();
    CHECK_THROWS_AS(Lean(one), PCCD::Invalid_input);
    Eigen::Matrix3Xd nan = Eigen::Matrix3Xd::Random(3, 50);
    nan(1, 7) = std::nan("");
    CHECK_THROWS_AS(Lean(nan), PCCD::Invalid_input);
    PCCD::Point_data data;
    data.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
    data.normals = {Eigen::Vector3d(0, 0, 1)};
    CHECK_THROWS_AS(Lean(data), PCCD::Invalid_input);
    const Eigen::Matrix3Xd cloud = pccd_test::sample_shape(pccd_test::unit_sphere(), 500, 0.0, 41).points;
    CHECK_THROWS_WITH(Lean(cloud, PCCD::Point_cloud_object_options{.orientation_neighbors = 0}),
                      Catch::Matchers::Contains("orientation_neighbors"));
}

TEST_CASE("Lean object: given normals decide the orientation, from a file's point data", "[lean]")
{
    const Eigen::Matrix3Xd p = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 51).points;
    PCCD::Point_data data;
    for (Eigen::Index i = 0; i < p.cols(); ++i) {
        data.points.push_back(p.col(i));
        data.normals.push_back(-p.col(i)); // inward: the hints win over the outward rule
    }
    const Lean lean(data);
    CHECK(lean.normals_given());
    REQUIRE(lean.size() == 3000);
    std::size_t inward = 0;
    for (std::uint32_t i = 0; i < lean.size(); ++i)
        inward += lean.normals().col(i).dot(lean.cloud().position(i).template cast<double>()) < 0.0;
    CHECK(inward == lean.size());
    // The input index finds each point of the file again.
    for (std::uint32_t i = 0; i < lean.size(); i += 97)
        CHECK((lean.cloud().position(i).template cast<double>() - data.points[lean.input_index(i)]).norm() == 0.0);
}

TEST_CASE("Lean object: point data given up is freed and makes the same object", "[lean]")
{
    // The rvalue constructor frees the caller's arrays once the object holds its own copy; the object
    // is the one the const& constructor makes from the same data.
    const Eigen::Matrix3Xd p = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.0, 52).points;
    PCCD::Point_data data;
    for (Eigen::Index i = 0; i < p.cols(); ++i) {
        data.points.push_back(p.col(i));
        data.normals.push_back(p.col(i));
    }
    const Lean kept(data);
    PCCD::Point_data given = data;
    const Lean taken(std::move(given));
    CHECK(given.points.empty());
    CHECK(given.points.capacity() == 0);
    CHECK(given.normals.capacity() == 0);
    REQUIRE(taken.size() == kept.size());
    CHECK(taken.cloud().coordinates() == kept.cloud().coordinates());
    CHECK(taken.normals() == kept.normals());
    CHECK(taken.normals_given());
    for (const double d : {1.8, 2.2}) { // unit spheres: touching below 2
        const bool answer = PCCD::do_intersect(taken, shifted(0), kept, shifted(d), {.seed = 3}).intersects;
        CHECK(answer == (d < 2.0));
        CHECK(answer == PCCD::do_intersect(kept, shifted(0), kept, shifted(d), {.seed = 3}).intersects);
    }
    // Bad data given up is rejected as before.
    PCCD::Point_data bad;
    bad.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
    bad.normals = {Eigen::Vector3d(0, 0, 1)};
    CHECK_THROWS_AS(Lean(std::move(bad)), PCCD::Invalid_input);
}

TEST_CASE("Lean object: a saved object loads back identical and answers as it did", "[lean][io]")
{
    const auto sample = pccd_test::sample_shape(pccd_test::unit_sphere(), 3000, 0.05, 61);
    const Lean object(pccd_test::columns(sample.points));
    const std::string path = std::string(PCCD_TEST_TMP_DIR) + "/sphere.pccdlean";
    object.save(path);
    const Lean loaded = Lean::load(path);
    REQUIRE(loaded.size() == object.size());
    CHECK(loaded.cloud().coordinates() == object.cloud().coordinates());
    CHECK(loaded.normals() == object.normals());
    CHECK(loaded.domain_radii() == object.domain_radii());
    CHECK(loaded.input_indices() == object.input_indices());
    CHECK(loaded.sampling_radius() == object.sampling_radius());
    CHECK(loaded.bandwidth() == object.bandwidth());
    CHECK(loaded.weight().threshold() == object.weight().threshold());
    CHECK(loaded.surface().fit() == object.surface().fit());
    CHECK(loaded.noise_estimate() == object.noise_estimate());
    CHECK(loaded.scan().input_points == object.scan().input_points);
    CHECK(loaded.orientation().flipped == object.orientation().flipped);
    CHECK(loaded.normals_given() == object.normals_given());
    pccd_test::require_same_hierarchy(loaded.hierarchy(), object.hierarchy());
    CHECK(loaded.memory_bytes() == object.memory_bytes());
    REQUIRE(object.cloud().kd_tree().cell_grid_side());
    CHECK(loaded.cloud().kd_tree().cell_grid_side() == object.cloud().kd_tree().cell_grid_side());
    for (const pccd_test::Query& q : pccd_test::queries_near(pccd_test::unit_sphere(), 100, 0.05, 3)) {
        const double x = loaded.surface().evaluate(q.x).value, y = object.surface().evaluate(q.x).value;
        CHECK((x == y || (std::isnan(x) && std::isnan(y)))); // NaN: undefined there, for both
    }
    // Every query answers as the saved object did (the same numbers): first hits, distances.
    const auto& spheres = lean_spheres();
    for (double d : {1.2, 1.9, 2.05, 2.4}) {
        INFO("d = " << d);
        const auto x = PCCD::do_intersect(object, Rigid_transform_3<double>(), spheres.b, shifted(d), {.seed = 2});
        const auto y = PCCD::do_intersect(loaded, Rigid_transform_3<double>(), spheres.b, shifted(d), {.seed = 2});
        CHECK(x.status == y.status);
        CHECK(x.counters.f_evaluations == y.counters.f_evaluations);
        const auto p = PCCD::distance(object, Rigid_transform_3<double>(), spheres.b, shifted(d), {.intersection = {.seed = 2}});
        const auto q = PCCD::distance(loaded, Rigid_transform_3<double>(), spheres.b, shifted(d), {.intersection = {.seed = 2}});
        CHECK(p.status == q.status);
        CHECK((p.distance == q.distance || (std::isnan(p.distance) && std::isnan(q.distance))));
    }
    // Other hierarchy options build that hierarchy; the stored one serves when they are the file's.
    const Lean spheres_loaded = Lean::load(path, {.leaf_size = 4, .volume = PCCD::Bounding_volume::sphere});
    CHECK(spheres_loaded.hierarchy().volume() == PCCD::Bounding_volume::sphere);
    CHECK(spheres_loaded.hierarchy().leaf_size() == 4);
    pccd_test::require_same_hierarchy(Lean::load(path, {}).hierarchy(), object.hierarchy());
    CHECK_THROWS_WITH(Lean::load(path, {.leaf_size = 0}), Catch::Matchers::Contains("leaf_size must be >= 1"));
    // An object without a domain keeps none.
    const Lean bare(pccd_test::columns(sample.points), PCCD::Point_cloud_object_options{.domain = {.enabled = false}});
    bare.save(path);
    CHECK(Lean::load(path).domain_radii().size() == 0);
    CHECK(!Lean::load(path).hierarchy().has_reach());

    // The other kind's file is named as such, both ways; corruption is caught by the checksum.
    const std::string geodesic_path = std::string(PCCD_TEST_TMP_DIR) + "/sphere_geodesic.pccdobj";
    PCCD::Point_cloud_object<>(pccd_test::columns(sample.points)).save(geodesic_path);
    CHECK_THROWS_WITH(Lean::load(geodesic_path), Catch::Matchers::Contains("load it with Point_cloud_object::load"));
    object.save(path);
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>::load(path),
                      Catch::Matchers::Contains("load it with Euclidean_point_cloud_object::load"));
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string bad = std::string(PCCD_TEST_TMP_DIR) + "/corrupt.pccdlean";
    for (std::size_t position : {std::size_t(40), bytes.size() / 2, bytes.size() - 20}) {
        std::string copy = bytes;
        copy[position] = char(copy[position] ^ 0x5a);
        std::ofstream(bad, std::ios::binary).write(copy.data(), std::streamsize(copy.size()));
        CHECK_THROWS_WITH(Lean::load(bad), Catch::Matchers::Contains("checksum"));
    }
    std::ofstream(bad, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 3));
    CHECK_THROWS_AS(Lean::load(bad), PCCD::File_error);
    std::ofstream(bad, std::ios::binary) << "OFF\n3 1 0\n";
    CHECK_THROWS_WITH(Lean::load(bad), Catch::Matchers::Contains("not a PCCD lean object file"));
    CHECK_THROWS_AS(Lean::load(std::string(PCCD_TEST_TMP_DIR) + "/missing.pccdlean"), PCCD::File_error);
}
