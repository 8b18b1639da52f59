// Tests of PCCD/object_file_info.h: the kind, format version and number of points of the files
// Point_cloud_object::save and Euclidean_point_cloud_object::save write, read from their opening
// and checked against the objects that wrote them and the classes' stated format versions; point
// files and other files are "none"; broken openings and missing files get File_errors naming them.
#include <PCCD/Error.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/object_file_info.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "file_helpers.h"
#include "surface_test_helpers.h"

namespace {

std::vector<Eigen::Vector3d> sphere_points(std::size_t n, std::uint64_t seed)
{
    return pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), n, 0.0, seed).points);
}

std::string scratch(const std::string& name) { return pccd_test::scratch_path("object_file_info", name); }

} // namespace

TEST_CASE("object_file_info: the kind, version and size of both kinds of object file")
{
    const std::vector<Eigen::Vector3d> points = sphere_points(1500, 5);
    const PCCD::Point_cloud_object<> geodesic(points);
    const PCCD::Euclidean_point_cloud_object<> lean(sphere_points(2300, 6));
    const std::string geodesic_path = scratch("sphere.pccdobj");
    const std::string lean_path = scratch("sphere.pccdlean");
    geodesic.save(geodesic_path);
    lean.save(lean_path);

    const PCCD::Object_file_info g = PCCD::object_file_info(geodesic_path);
    CHECK(g.kind == PCCD::Object_file_kind::geodesic);
    CHECK(g.version == PCCD::Point_cloud_object<>::file_version);
    CHECK(g.points == geodesic.size());
    CHECK(g.points > 1400); // a clean sphere keeps nearly all its 1,500 points
    CHECK(std::string(PCCD::to_string(g.kind)) == "geodesic");

    const PCCD::Object_file_info l = PCCD::object_file_info(lean_path);
    CHECK(l.kind == PCCD::Object_file_kind::euclidean);
    CHECK(l.version == PCCD::Euclidean_point_cloud_object<>::file_version);
    CHECK(l.points == lean.size());
    CHECK(l.points > 2200);
    CHECK(std::string(PCCD::to_string(l.kind)) == "euclidean");

    // The kind it reports is the one whose loader reads the file.
    CHECK(PCCD::Point_cloud_object<>::load(geodesic_path).size() == g.points);
    CHECK(PCCD::Euclidean_point_cloud_object<>::load(lean_path).size() == l.points);
}

TEST_CASE("object_file_info: point files and other files are none")
{
    const std::string xyz = scratch("points.xyz");
    pccd_test::write_bytes(xyz, "0 0 0\n1 0 0\n0 1 0\n");
    const PCCD::Object_file_info info = PCCD::object_file_info(xyz);
    CHECK(info.kind == PCCD::Object_file_kind::none);
    CHECK(info.version == 0);
    CHECK(info.points == 0);
    CHECK(std::string(PCCD::to_string(info.kind)) == "none");

    const std::string empty = scratch("empty.bin");
    pccd_test::write_bytes(empty, "");
    CHECK(PCCD::object_file_info(empty).kind == PCCD::Object_file_kind::none);
    // A magic cut short is not a magic.
    const std::string short_magic = scratch("short.bin");
    pccd_test::write_bytes(short_magic, "PCCDLEA");
    CHECK(PCCD::object_file_info(short_magic).kind == PCCD::Object_file_kind::none);
    // The geodesic data file of write_geodesic_data has a magic of its own: not an object file.
    const std::string geo = scratch("graph.pccdgeo");
    std::string geo_bytes("PCCDGEO\0", 8);
    geo_bytes.append(40, '\1'); // (appended: GCC 12 warns falsely on operator+ of these two strings)
    pccd_test::write_bytes(geo, geo_bytes);
    CHECK(PCCD::object_file_info(geo).kind == PCCD::Object_file_kind::none);
}

TEST_CASE("object_file_info: broken openings and missing files are File_errors naming the file")
{
    const PCCD::Euclidean_point_cloud_object<> lean(sphere_points(800, 7));
    const std::string path = scratch("broken.pccdlean");
    lean.save(path);
    const std::string bytes = pccd_test::read_bytes(path);
    REQUIRE(bytes.size() > 24);

    const auto message_of = [](const std::string& file) {
        try {
            (void)PCCD::object_file_info(file);
        } catch (const PCCD::File_error& e) {
            CHECK(e.file() == file);
            return std::string(e.what());
        }
        return std::string("no error");
    };

    const std::string truncated = scratch("truncated.pccdlean");
    pccd_test::write_bytes(truncated, bytes.substr(0, 20));
    CHECK_THAT(message_of(truncated), Catch::Contains("truncated"));

    std::string swapped = bytes;
    std::swap(swapped[12], swapped[15]); // the byte-order mark 0x01020304 read backwards
    std::swap(swapped[13], swapped[14]);
    const std::string other_order = scratch("other_order.pccdlean");
    pccd_test::write_bytes(other_order, swapped);
    CHECK_THAT(message_of(other_order), Catch::Contains("another byte order"));

    CHECK_THAT(message_of(scratch("missing.pccdlean")), Catch::Contains("cannot open"));
}
