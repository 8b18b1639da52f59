// Tests of Point_cloud_object (DESIGN.md "Object"): one-call preprocessing, its reported state,
// and saving and loading (bit-for-bit round trip, corrupted and foreign files rejected).
#include "surface_test_helpers.h"

#include <PCCD/Point_cloud_object.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

using namespace pccd_test;

TEST_CASE("the CPSP map's default bound is the surface's default support", "[surface]")
{
    // A map built with Cpsp_options{} serves a surface with the default bandwidth options.
    CHECK(PCCD::Cpsp_options{}.support == PCCD::Bandwidth_options{}.eta);
}

TEST_CASE("a point cloud object reports its preprocessed state", "[surface]")
{
    const auto sample = sample_shape(test_torus(), 3000, 0.1, 91);
    const PCCD::Point_cloud_object<> object(columns(sample.points));
    CHECK(object.size() == 3000);
    CHECK(object.graph().num_vertices() == 3000);
    CHECK(object.cpsp().size() == 3000);
    CHECK(object.sampling_radius() > 0.0);
    CHECK(object.eta() == Approx(3.0));
    CHECK(object.theta_eps() == 1e-2);
    CHECK(object.bandwidth() == Approx(3.0 * object.sampling_radius() / std::sqrt(-std::log(1e-2))));
    CHECK(object.cpsp().bound() >= object.weight().support_radius() * (1 - 1e-12));
    CHECK_FALSE(object.normals_given());
    CHECK(object.orientation().components >= 1);
    const auto& t = object.timings();
    for (double ms : {t.kd_tree, t.graph, t.sampling_radius, t.cpsp, t.normals}) CHECK(ms >= 0.0);
    // A user bandwidth is used as given; eta follows from it.
    const PCCD::Point_cloud_object<> given(columns(sample.points), PCCD::Identity_point_map<Eigen::Vector3d>(),
                                           {.graph = PCCD::Graph_kind::knn, .bandwidth = {.bandwidth = 0.05}});
    CHECK(given.bandwidth() == 0.05);
    CHECK(given.graph().kind() == PCCD::Graph_kind::knn);
    CHECK(given.eta() == Approx(0.05 * std::sqrt(-std::log(1e-2)) / given.sampling_radius()));
}

TEST_CASE("a saved point cloud object loads back identical", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 2000, 0.1, 93);
    const PCCD::Point_cloud_object<> object(columns(sample.points));
    const std::string path = std::string(PCCD_TEST_TMP_DIR) + "/sphere.pccdobj";
    object.save(path);
    const auto loaded = PCCD::Point_cloud_object<>::load(path);
    CHECK(loaded.size() == object.size());
    CHECK(loaded.cloud().coordinates() == object.cloud().coordinates());
    CHECK(loaded.normals() == object.normals());
    CHECK(loaded.graph() == object.graph());
    CHECK(loaded.cpsp() == object.cpsp());
    CHECK(loaded.sampling_radius() == object.sampling_radius());
    CHECK(loaded.bandwidth() == object.bandwidth());
    CHECK(loaded.theta_eps() == object.theta_eps());
    CHECK(loaded.orientation().flipped == object.orientation().flipped);
    CHECK(loaded.timings().graph == object.timings().graph);
    for (const Query& q : queries_near(unit_sphere(), 100, 0.05, 3)) {
        CHECK(loaded.surface().evaluate(q.x).value == object.surface().evaluate(q.x).value);
        CHECK(loaded.euclidean_surface().evaluate(q.x).value == object.euclidean_surface().evaluate(q.x).value);
    }

    // Corruption anywhere is caught by the checksum; a foreign or missing file is named.
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string bad = std::string(PCCD_TEST_TMP_DIR) + "/corrupt.pccdobj";
    for (std::size_t position : {std::size_t(100), bytes.size() / 2, bytes.size() - 20}) {
        std::string copy = bytes;
        copy[position] = char(copy[position] ^ 0x5a);
        std::ofstream(bad, std::ios::binary).write(copy.data(), std::streamsize(copy.size()));
        CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(bad), PCCD::File_error);
    }
    std::ofstream(bad, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 3));
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(bad), PCCD::File_error);
    std::ofstream(bad, std::ios::binary) << "OFF\n3 1 0\n";
    CHECK_THROWS_WITH(PCCD::Point_cloud_object<>::load(bad), Catch::Contains("not a PCCD object file"));
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>::load(std::string(PCCD_TEST_TMP_DIR) + "/missing.pccdobj"),
                    PCCD::File_error);
}

TEST_CASE("a point cloud object from a point file's data uses its normals when it has them", "[surface]")
{
    const auto sample = sample_shape(unit_sphere(), 1500, 0.0, 97);
    PCCD::Point_data data;
    data.points = columns(sample.points);
    // Without normals: the same object as from the points alone (normals propagated).
    const PCCD::Point_cloud_object<> from_points(data.points);
    const PCCD::Point_cloud_object<> from_data(data);
    CHECK_FALSE(from_data.normals_given());
    CHECK(from_data.normals() == from_points.normals());
    // With normals pointing inwards (a file whose normals point into the sphere): every normal of the
    // object takes that sign, the opposite of the propagated (outward) orientation.
    for (const Eigen::Vector3d& p : data.points) data.normals.push_back(-2.0 * p);
    const PCCD::Point_cloud_object<> oriented(data);
    CHECK(oriented.normals_given());
    std::size_t inward = 0;
    for (Eigen::Index i = 0; i < oriented.normals().cols(); ++i)
        inward += oriented.normals().col(i).dot(data.points[std::size_t(i)]) < 0.0;
    CHECK(inward == data.points.size());
    // Normals, but not one per point.
    data.normals.pop_back();
    CHECK_THROWS_AS(PCCD::Point_cloud_object<>(data), PCCD::Invalid_input);
}
