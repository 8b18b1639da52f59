// Tests of the serialized files PCCD wrote before: two files committed under test/data/serialized/,
// a geodesic file and an object file written once by PCCD on a little-endian host, must still load
// with the values they were written with (and the geodesic one write back byte for byte), whatever
// the host: both formats are little-endian on disk.
//
// The committed files hold the object of the 25 points (x, y, x^2 + y^2), x and y in
// {-1/2, -1/4, 0, 1/4, 1/2} (x major), plus the outlier (0, 0, 8) that preprocessing removed, built
// with the default Point_cloud_object_options; paraboloid.pccdgeo holds its graph and CPSP map.
#include <PCCD/Error.h>
#include <PCCD/Geodesic/geodesic_io.h>
#include <PCCD/Point_cloud_object.h>

#include <catch2/catch.hpp>

#include "byte_helpers.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using pccd_test::bytes_of;

namespace {

std::string data_path(const std::string& name) { return std::string(PCCD_TEST_DATA_DIR) + "/serialized/" + name; }
std::string temp_path(const std::string& name) { return std::string(PCCD_TEST_TMP_DIR) + "/" + name; }

std::string file_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TEST_CASE("a committed geodesic file loads with its values and writes back byte for byte", "[io][graph]")
{
    const std::string path = data_path("paraboloid.pccdgeo");
    const std::string bytes = file_bytes(path);
    REQUIRE(bytes.size() == 10613);
    // Magic, version 1, the byte-order mark 0x01020304, the r-SIG (kind 1) with r = 3, N = 25.
    CHECK(bytes_of(bytes, 0, 29) ==
          std::vector<unsigned>{'P', 'C', 'C', 'D', 'G', 'E', 'O', 0, 1, 0, 0, 0, 4, 3, 2, 1, 1, 3, 0, 0, 0,
                                25, 0, 0, 0, 0, 0, 0, 0});

    const PCCD::Geodesic_data data = PCCD::read_geodesic_data(path);
    const PCCD::Proximity_graph& graph = data.graph;
    CHECK(graph.kind() == PCCD::Graph_kind::sphere_of_influence);
    CHECK(graph.parameter() == 3);
    CHECK(graph.num_vertices() == 25);
    CHECK(graph.targets().size() == 292);
    CHECK(graph.num_virtual_edges() == 0);
    REQUIRE(graph.row_offsets()[12] == 140);
    REQUIRE(graph.row_offsets()[13] == 152);
    const std::vector<std::uint32_t> row(graph.targets().begin() + 140, graph.targets().begin() + 152);
    CHECK(row == std::vector<std::uint32_t>{2, 6, 7, 8, 10, 11, 13, 14, 16, 17, 18, 22});
    CHECK(graph.edge_property(140).length == 0x1.1e377ap-1f);
    CHECK(graph.edge_property(141).length == 0x1.8p-2f);
    CHECK(graph.edge_property(142).length == 0x1.07e0f6p-2f);

    const PCCD::Close_pairs_shortest_paths& cpsp = data.cpsp;
    CHECK(cpsp.sampling_radius() == 0x1.883e143ad44c6p-1);
    CHECK(cpsp.support() == 0x1.7ffffffffffffp+1);
    CHECK(cpsp.num_entries() == 625);
    REQUIRE(cpsp.offsets()[12] == 300);
    REQUIRE(cpsp.offsets()[13] == 325);
    CHECK(cpsp.all_targets()[300] == 12);
    CHECK(cpsp.all_distances()[300] == 0.0f);
    CHECK(cpsp.all_targets()[313] == 1);
    CHECK(cpsp.all_distances()[313] == 0x1.6p-1f);
    CHECK(cpsp.all_predecessors()[313] == 5);
    CHECK(cpsp.all_targets()[324] == 24);
    CHECK(cpsp.all_distances()[324] == 0x1.c7e0f6p-1f);
    CHECK(cpsp.all_predecessors()[324] == 8);

    const std::string again = temp_path("paraboloid_again.pccdgeo");
    PCCD::write_geodesic_data(again, data.graph, data.cpsp);
    CHECK(file_bytes(again) == bytes);
}

TEST_CASE("a committed object file loads with the values it was written with", "[io][surface]")
{
    const std::string path = data_path("paraboloid.pccdobj");
    const std::string bytes = file_bytes(path);
    REQUIRE(bytes.size() == 12178);
    // Magic, version 2, the byte-order mark 0x01020304, N = 25.
    CHECK(bytes_of(bytes, 0, 24) == std::vector<unsigned>{'P', 'C', 'C', 'D', 'O', 'B', 'J', 0, 2, 0, 0, 0, 4, 3, 2, 1,
                                                           25, 0, 0, 0, 0, 0, 0, 0});

    const auto object = PCCD::Point_cloud_object<>::load(path);
    REQUIRE(object.size() == 25);
    for (std::size_t k = 0; k < 25; ++k) {
        const double x = (double(k / 5) - 2.0) / 4.0, y = (double(k % 5) - 2.0) / 4.0;
        CHECK(object.cloud().coordinates().col(Eigen::Index(k)) == Eigen::Vector3d(x, y, x * x + y * y));
    }
    CHECK(object.sampling_radius() == 0x1.883e143ad44c6p-1);
    CHECK(object.bandwidth() == 0x1.122c06921f0fcp+0);
    CHECK(object.theta_eps() == 0x1.47ae147ae147bp-7);
    CHECK_FALSE(object.normals_given());
    CHECK(object.orientation().flipped == 13);
    CHECK(object.orientation().components == 1);
    CHECK(object.orientation().unoriented == 0);
    CHECK(object.timings().graph == 0x1.690ca1cef241p+0);
    CHECK(object.timings().sampling_radius == 0x1.d0db8561d4307p+4);
    CHECK(object.timings().cpsp == 0x1.ac42e9899bf59p-4);
    CHECK(object.timings().normals == 0x1.634fc610f0e9p-5);
    CHECK(object.normals().col(0) == Eigen::Vector3d(-0x1.0a6fb12f32acbp-3, -0x1.0a6fb12f32ad5p-3, -0x1.f742849b06bf7p-1));
    CHECK(object.normals().col(12) == Eigen::Vector3d(0.0, 0.0, -1.0));
    CHECK(object.normals().col(24) == Eigen::Vector3d(0x1.0a6fb12f32ad5p-3, 0x1.0a6fb12f32acbp-3, -0x1.f742849b06bf7p-1));
    CHECK(object.scan().input_points == 26);
    CHECK(object.scan().outliers == std::vector<std::uint32_t>{25});
    CHECK(object.noise_estimate() == 0x1.a4c11dedb6aa6p-3);
    REQUIRE(object.domain_radii().size() == 25);
    CHECK(object.domain_radii()(0) == 0x1.6b733bfd8c648p-1);
    CHECK(object.domain_radii()(12) == 0x1.8p-2);

    // Its geodesic section is the committed geodesic file.
    const PCCD::Geodesic_data geodesic = PCCD::read_geodesic_data(data_path("paraboloid.pccdgeo"));
    CHECK(object.graph() == geodesic.graph);
    CHECK(object.cpsp() == geodesic.cpsp);
}
