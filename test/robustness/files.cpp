// Bad-input catalogue, files (doc/reliability.md). test/IO/read_write_test.cpp already holds about 110 broken
// PLY, OFF and XYZ files and a prefix/corruption fuzz loop; this file adds only what it lacks:
// mislabelled encodings (binary bodies under ascii headers and the reverse, the wrong byte order),
// valid files forced through the wrong reader, header oddities, and files that read correctly but
// hold a cloud the later stages reject.
#include "robustness_helpers.h"

#include <PCCD/IO/read_points.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/IO/write_points.h>
#include <PCCD/Point_cloud_object.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace pccd_robustness;
using PCCD::IO::Format;

namespace {

std::string path_of(const std::string& name) { return scratch_path("files", name); }

std::string make_file(const std::string& name, const std::string& content)
{
    const std::string path = path_of(name);
    write_bytes(path, content);
    return path;
}

const std::string xyz_properties = "property double x\nproperty double y\nproperty double z\n";

std::string binary_doubles(const std::vector<double>& values, bool big_endian)
{
    std::string s;
    for (const double v : values) {
        char bytes[8];
        std::memcpy(bytes, &v, 8);
        if (big_endian != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + 8);
        s.append(bytes, 8);
    }
    return s;
}

double byte_reversed(double value)
{
    char bytes[8];
    std::memcpy(bytes, &value, 8);
    std::reverse(bytes, bytes + 8);
    std::memcpy(&value, bytes, 8);
    return value;
}

std::string ply_header(const std::string& format, int vertices)
{
    return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) + "\n" + xyz_properties +
           "end_header\n";
}

const std::vector<double> square = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};

} // namespace

TEST_CASE("files: mislabelled encodings", "[robustness]")
{
    SECTION("binary body under an ascii header")
    {
        const std::string path = make_file("binary_as_ascii.ply", ply_header("ascii", 4) + binary_doubles(square, false));
        require_file_error(path, [&] { PCCD::IO::read_points(path); }, {"malformed"});
    }
    SECTION("ascii body under a binary header")
    {
        const std::string body = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n";
        for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
            const std::string path = make_file(std::string("ascii_as_") + format + ".ply", ply_header(format, 4) + body);
            INFO(format);
            require_file_error(path, [&] { PCCD::IO::read_points(path); }, {"truncated binary body"});
        }
    }
    SECTION("big-endian body under a little-endian header, and the reverse")
    {
        // 1.0 with its bytes reversed is the subnormal 3.0e-319; 0 stays 0. The file is well formed
        // in the wrong order, so it reads, and the values are finite: a documented, defined answer.
        for (const bool big : {false, true}) {
            const std::string path = make_file(big ? "big_as_little.ply" : "little_as_big.ply",
                                               ply_header(big ? "binary_little_endian" : "binary_big_endian", 4) +
                                                   binary_doubles(square, big));
            const auto data = PCCD::IO::read_points(path);
            REQUIRE(data.points.size() == 4);
            for (const auto& p : data.points) CHECK(p.allFinite());
            CHECK(data.points[1].x() == byte_reversed(1.0));
        }
        // Byte-swapped values that are NaN are caught and named.
        const std::vector<double> swapped_nan = {0, 0, 0, std::bit_cast<double>(std::uint64_t(0x000000000000f87f)), 0, 0};
        const std::string path = make_file("swapped_nan.ply", ply_header("binary_big_endian", 2) + binary_doubles(swapped_nan, false));
        require_file_error(path, [&] { PCCD::IO::read_points(path); }, {"vertex 1", "NaN coordinate"});
    }
}

TEST_CASE("files: valid files forced through the wrong reader", "[robustness]")
{
    PCCD::Point_data data;
    data.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::string ply = path_of("valid.ply"), binary = path_of("valid_binary.ply"), off = path_of("valid.off"),
                      xyz = path_of("valid.xyz");
    PCCD::IO::write_points(ply, data);
    PCCD::IO::write_points(binary, data, {.binary = true});
    PCCD::IO::write_points(off, data);
    PCCD::IO::write_points(xyz, data);
    for (const std::string& path : {ply, binary}) {
        require_file_error(path, [&] { PCCD::IO::read_points(path, Format::off); }, {"bad header", "PLY file"});
        require_file_error(path, [&] { PCCD::IO::read_points(path, Format::xyz); }, {"malformed number 'ply'"});
    }
    require_file_error(off, [&] { PCCD::IO::read_points(off, Format::ply); }, {"bad header", "OFF file"});
    require_file_error(off, [&] { PCCD::IO::read_points(off, Format::xyz); }, {"malformed number 'OFF'"});
    require_file_error(xyz, [&] { PCCD::IO::read_points(xyz, Format::ply); }, {"bad header", "XYZ file"});
    require_file_error(xyz, [&] { PCCD::IO::read_points(xyz, Format::off); }, {"bad header", "XYZ file"});
}

TEST_CASE("files: header oddities", "[robustness]")
{
    const std::string body = "0 0 0\n1 0 0\n";
    const std::string bom = "\xEF\xBB\xBF";
    require_file_error(make_file("bom.ply", bom + ply_header("ascii", 2) + body), [] { PCCD::IO::read_points(path_of("bom.ply")); },
                       {"bad header"});
    require_file_error(make_file("bom.off", bom + "OFF\n2 0 0\n" + body), [] { PCCD::IO::read_points(path_of("bom.off")); },
                       {"bad header"});
    // Only format version 1.0 is known (was: not checked, a "2.0" file read as 1.0).
    require_file_error(make_file("version2.ply", "ply\nformat ascii 2.0\nelement vertex 2\n" + xyz_properties +
                                                     "end_header\n" + body),
                       [] { PCCD::IO::read_points(path_of("version2.ply")); }, {"bad header", "version", "2.0"});
    CHECK(PCCD::IO::read_points(make_file("version1.ply", "ply\nformat ascii 1\nelement vertex 2\n" + xyz_properties +
                                                              "end_header\n" + body))
              .points.size() == 2);
    require_file_error(make_file("two_vertex_elements.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_properties +
                                                                "element vertex 1\n" + xyz_properties + "end_header\n" + body),
                       [] { PCCD::IO::read_points(path_of("two_vertex_elements.ply")); }, {"bad header"});
    require_file_error(make_file("xyz_zero_count.xyz", "0\n" + body), [] { PCCD::IO::read_points(path_of("xyz_zero_count.xyz")); },
                       {"unexpected data"});
    // Properties in another order are read by name.
    const std::string zyx = make_file("zyx.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double z\nproperty double y\n"
                                                 "property double x\nend_header\n1 2 3\n");
    const auto data = PCCD::IO::read_points(zyx);
    REQUIRE(data.points.size() == 1);
    CHECK(data.points[0] == Eigen::Vector3d(3, 2, 1));
}

TEST_CASE("files: valid files holding clouds the later stages reject", "[robustness]")
{
    using Object = PCCD::Point_cloud_object<>;
    const auto object_from = [](const std::string& path) { return Object(PCCD::IO::read_points(path).points); };
    const std::string one = make_file("one_point.xyz", "1 2 3\n");
    require_invalid_input([&] { object_from(one); }, {"at least two points", "has one"});
    std::string same;
    for (int i = 0; i < 30; ++i) same += "1 1 1\n";
    const std::string identical = make_file("identical.xyz", same);
    require_invalid_input([&] { object_from(identical); }, {"sampling radius is 0"});
    // Extreme but representable coordinates read exactly and build.
    PCCD::Point_data big;
    for (const auto& p : fibonacci_sphere(200)) big.points.push_back(1e30 * p);
    const std::string path = path_of("big.ply");
    PCCD::IO::write_points(path, big, {.binary = true});
    CHECK(object_from(path).sampling_radius() > 1e28);
}
