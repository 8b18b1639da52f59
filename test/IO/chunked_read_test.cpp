// Reading files larger than the readers' chunks (doc/manual/io.md, "How it works"): binary PLY (both
// byte orders, float and double, skipped properties and lists, elements before and after the
// vertices) and XYZ files of several MiB, written here byte by byte from known values, must read
// back exactly; truncations, trailing bytes, NaN and infinite values and malformed lines far past
// the first chunk must throw File_error with the index or line computed here independently.
#include <PCCD/Error.h>
#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/read_points.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>
#include "error_test_helpers.h"
#include "file_helpers.h"

namespace {

namespace fs = std::filesystem;
using PCCD::Point_data;
using PCCD::IO::read_points;
using pccd_test::require_file_error;

std::string tmp_path(const std::string& name) { return pccd_test::scratch_path("io_chunked", name); }

std::string make_file(const std::string& name, const std::string& content)
{
    const std::string path = tmp_path(name);
    pccd_test::write_bytes(path, content);
    return path;
}

/// Appends the bytes of `value` in the given byte order.
template <class T>
void put(std::string& s, T value, bool big_endian)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (big_endian != (std::endian::native == std::endian::big)) std::reverse(bytes, bytes + sizeof(T));
    s.append(bytes, sizeof(T));
}

/// A cloud of `n` points with normals, fixed seed; coordinates that a float holds exactly where the
/// file stores floats are made so by the writer below, which also returns what must be read.
struct Cloud {
    std::vector<Eigen::Vector3d> points, normals;
};

Cloud random_cloud(std::size_t n, unsigned seed)
{
    std::mt19937_64 engine(seed);
    std::uniform_real_distribution<double> u(-1e3, 1e3);
    Cloud c;
    for (std::size_t i = 0; i < n; ++i) {
        c.points.emplace_back(u(engine), u(engine), u(engine));
        c.normals.emplace_back(u(engine), u(engine), u(engine));
    }
    return c;
}

/// The vertex layout of the big PLY files: uchar flags, float x, double y, short s, float z,
/// float nx, double ny, float nz, uint id (39 bytes: items straddle the chunk boundaries).
const char* const mixed_vertex_properties =
    "property uchar flags\nproperty float x\nproperty double y\nproperty short s\nproperty float z\n"
    "property float nx\nproperty double ny\nproperty float nz\nproperty uint id\n";

/// A binary PLY with a 'camera' element (2 fixed items) and a 'scan' element with a list (3 items)
/// before the vertices, and a face element after them. `expected` receives the points and normals
/// as the file stores them (floats rounded).
std::string mixed_ply(const Cloud& c, bool big_endian, Cloud& expected, std::size_t declared)
{
    const std::size_t n = c.points.size();
    std::string s = "ply\nformat ";
    s += big_endian ? "binary_big_endian" : "binary_little_endian";
    s += " 1.0\ncomment written byte by byte\nelement camera 2\nproperty double fx\nproperty int w\n"
         "element scan 3\nproperty list uchar ushort lines\nproperty float t\n"
         "element vertex " + std::to_string(declared) + "\n" + mixed_vertex_properties +
         "element face 2\nproperty list uchar uint vertex_indices\nend_header\n";
    for (int i = 0; i < 2; ++i) {
        put(s, 500.0 + i, big_endian);
        put(s, std::int32_t(640), big_endian);
    }
    for (int i = 0; i < 3; ++i) {
        put(s, std::uint8_t(i), big_endian);
        for (int k = 0; k < i; ++k) put(s, std::uint16_t(k + 7), big_endian);
        put(s, float(i) * 0.5f, big_endian);
    }
    expected = {};
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d& p = c.points[i];
        const Eigen::Vector3d& q = c.normals[i];
        put(s, std::uint8_t(i * 13), big_endian);
        put(s, float(p.x()), big_endian);
        put(s, p.y(), big_endian);
        put(s, std::int16_t(-int(i % 1000)), big_endian);
        put(s, float(p.z()), big_endian);
        put(s, float(q.x()), big_endian);
        put(s, q.y(), big_endian);
        put(s, float(q.z()), big_endian);
        put(s, std::uint32_t(i), big_endian);
        expected.points.emplace_back(double(float(p.x())), p.y(), double(float(p.z())));
        expected.normals.emplace_back(double(float(q.x())), q.y(), double(float(q.z())));
    }
    for (std::uint32_t f = 0; f < 2; ++f) {
        put(s, std::uint8_t(3), big_endian);
        for (std::uint32_t k = 0; k < 3; ++k) put(s, f + k, big_endian);
    }
    return s;
}

constexpr std::size_t mixed_item = 39;

bool same_bits(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Eigen::Vector3d)) == 0;
}

} // namespace

TEST_CASE("binary PLY files of several chunks read exactly, in both byte orders", "[io]")
{
    const std::size_t n = 100000; // 3.9 MB of vertices: several 1 MiB chunks
    const Cloud cloud = random_cloud(n, 11);
    for (const bool big_endian : {false, true}) {
        INFO("big endian: " << big_endian);
        Cloud expected;
        const std::string path = make_file(big_endian ? "mixed_big.ply" : "mixed_little.ply",
                                           mixed_ply(cloud, big_endian, expected, n));
        const Point_data data = read_points(path);
        CHECK(same_bits(data.points, expected.points));
        CHECK(same_bits(data.normals, expected.normals));
        // Reserved once from the header's count: no spare capacity.
        CHECK(data.points.capacity() == n);
        CHECK(data.normals.capacity() == n);
    }
}

TEST_CASE("a vertex element with a list property is read item by item across chunks", "[io]")
{
    const std::size_t n = 60000;
    const Cloud cloud = random_cloud(n, 12);
    for (const bool big_endian : {false, true}) {
        std::string s = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                        " 1.0\nelement vertex " + std::to_string(n) +
                        "\nproperty double x\nproperty list uchar int tags\nproperty double y\nproperty double z\n"
                        "end_header\n";
        for (std::size_t i = 0; i < n; ++i) {
            put(s, cloud.points[i].x(), big_endian);
            put(s, std::uint8_t(i % 7), big_endian);
            for (std::size_t k = 0; k < i % 7; ++k) put(s, std::int32_t(k), big_endian);
            put(s, cloud.points[i].y(), big_endian);
            put(s, cloud.points[i].z(), big_endian);
        }
        REQUIRE(s.size() > (std::size_t(2) << 20));
        const Point_data data = read_points(make_file("vertex_lists.ply", s));
        CHECK(same_bits(data.points, cloud.points));
        CHECK_FALSE(data.has_normals());
        // Truncated in the middle of vertex 50000's list.
        std::size_t cut = s.find("end_header\n") + 11;
        for (std::size_t i = 0; i < 50000; ++i) cut += 8 + 1 + 4 * (i % 7) + 16;
        const std::string path = make_file("vertex_lists_cut.ply", s.substr(0, cut + 8 + 1 + 2));
        require_file_error(path, [&] { read_points(path); }, {"truncated binary body", "vertex 50000 of the 60000"});
    }
}

TEST_CASE("truncated and overlong binary PLY files are refused with the item where the data ends", "[io][robustness]")
{
    const std::size_t n = 80000;
    const Cloud cloud = random_cloud(n, 13);
    Cloud expected;
    const std::string full = mixed_ply(cloud, false, expected, n);
    // The vertices start after the header, the 2 cameras (12 bytes each) and the 3 scans (1 + 2i + 4).
    const std::size_t vertices_at = full.find("end_header\n") + 11 + 2 * 12 + (5 + 7 + 9);
    const std::size_t faces_at = vertices_at + n * mixed_item;
    REQUIRE(full.size() == faces_at + 2 * 13);
    for (const std::size_t j : {std::size_t(0), std::size_t(1), std::size_t(31000), n - 1}) {
        // Every truncation inside the vertex element is found before any vertex is read: the
        // message names the first vertex that is not complete.
        const std::string path = make_file("cut_vertex.ply", full.substr(0, vertices_at + j * mixed_item + 17));
        require_file_error(path, [&] { read_points(path); },
                           {"truncated binary body", "vertex " + std::to_string(j) + " of the " + std::to_string(n)});
    }
    const std::string in_face = make_file("cut_face.ply", full.substr(0, faces_at + 13 + 5));
    require_file_error(in_face, [&] { read_points(in_face); }, {"truncated binary body", "face 1 of the 2"});
    // A header that declares more vertices than the file holds, by far: refused before reading.
    Cloud ignored;
    const std::string huge = make_file("huge_count.ply", mixed_ply(random_cloud(10, 1), false, ignored, 4000000000000));
    require_file_error(huge, [&] { read_points(huge); }, {"truncated binary body", "of the 4000000000000"});
    const std::string trailing = make_file("trailing.ply", full + std::string(1000, '\0'));
    require_file_error(trailing, [&] { read_points(trailing); }, {"unexpected data", "1000 bytes"});
    // Fewer vertices declared than written: the rest is read as faces, whose counts are then wrong.
    const std::string fewer = make_file("fewer.ply", mixed_ply(cloud, false, ignored, n - 1));
    require_file_error(fewer, [&] { read_points(fewer); }, {});
}

TEST_CASE("NaN and infinite values past the first chunk are refused with their vertex index", "[io][robustness]")
{
    const std::size_t n = 70000;
    Cloud cloud = random_cloud(n, 14);
    const double signaling_nan = std::bit_cast<double>(std::uint64_t(0x7FF0000000000001));
    for (const bool big_endian : {false, true}) {
        Cloud c = cloud, ignored;
        c.points[61234].y() = signaling_nan; // a double property
        const std::string nan = make_file("nan.ply", mixed_ply(c, big_endian, ignored, n));
        require_file_error(nan, [&] { read_points(nan); }, {"vertex 61234", "NaN coordinate"});
        c = cloud;
        c.points[45678].z() = -std::numeric_limits<double>::infinity(); // a float property
        const std::string inf = make_file("inf.ply", mixed_ply(c, big_endian, ignored, n));
        require_file_error(inf, [&] { read_points(inf); }, {"vertex 45678", "infinite coordinate"});
        c = cloud;
        c.normals[69999].x() = std::numeric_limits<double>::quiet_NaN();
        const std::string normal = make_file("nan_normal.ply", mixed_ply(c, big_endian, ignored, n));
        require_file_error(normal, [&] { read_points(normal); }, {"vertex 69999", "NaN normal"});
    }
}

TEST_CASE("a PLY header longer than the first read is read whole", "[io]")
{
    std::string header = "ply\nformat binary_little_endian 1.0\n";
    for (int i = 0; i < 20000; ++i) header += "comment padding line " + std::to_string(i) + "\n"; // ~500 kB
    header += "element vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    std::string s = header;
    for (const float v : {1.5f, -2.0f, 3.25f, 0.0f, 1e-3f, -7.0f}) put(s, v, false);
    const Point_data data = read_points(make_file("long_header.ply", s));
    REQUIRE(data.points.size() == 2);
    CHECK(data.points[0] == Eigen::Vector3d(1.5, -2.0, 3.25));
    CHECK(data.points[1] == Eigen::Vector3d(0.0, double(1e-3f), -7.0));
}

TEST_CASE("XYZ files of several chunks read exactly, with long lines and without a final newline", "[io]")
{
    const std::size_t n = 50000;
    const Cloud cloud = random_cloud(n, 15);
    std::string s = "# a comment longer than a chunk: " + std::string(std::size_t(3) << 20, 'c') + "\n";
    std::vector<std::size_t> lines_of_points;
    std::size_t line = 1;
    for (std::size_t i = 0; i < n; ++i) {
        char text[32];
        for (int k = 0; k < 6; ++k) { // shortest round-trip form: reads back exactly
            const double v = k < 3 ? cloud.points[i][k] : cloud.normals[i][k - 3];
            s.append(text, std::to_chars(text, text + sizeof text, v).ptr);
            s += k < 5 ? (i % 3 == 0 ? "\t" : " ") : "";
        }
        s += i % 5 == 0 ? "\r\n" : i + 1 < n ? "\n" : "";
        lines_of_points.push_back(++line);
        if (i % 1000 == 999 && i + 1 < n) {
            s += "\n# blank line above\n";
            line += 2;
        }
    }
    REQUIRE(s.size() > (std::size_t(5) << 20));
    const Point_data data = read_points(make_file("big.xyz", s));
    CHECK(same_bits(data.points, cloud.points));
    CHECK(same_bits(data.normals, cloud.normals));

    // A malformed number and a NaN far from the start, reported on their lines.
    const std::size_t j = 41234;
    std::string bad = s;
    std::size_t at = 0;
    for (std::size_t l = 1; l < lines_of_points[j]; ++l) at = bad.find('\n', at) + 1;
    bad.insert(at, "1.5x");
    const std::string malformed = make_file("malformed.xyz", bad);
    require_file_error(malformed, [&] { read_points(malformed); },
                       {"malformed number", "on line " + std::to_string(lines_of_points[j])});
    std::string with_nan = s;
    with_nan.insert(at, "nan ");
    with_nan.erase(at + 4, with_nan.find_first_of(" \t", at + 4) - (at + 4) + 1); // replaces x
    const std::string nan = make_file("nan.xyz", with_nan);
    require_file_error(nan, [&] { read_points(nan); },
                       {"point " + std::to_string(j), "line " + std::to_string(lines_of_points[j]), "NaN coordinate"});
}

TEST_CASE("an XYZ count line is checked against the points of a large file", "[io][robustness]")
{
    const std::size_t n = 200000;
    std::string body;
    for (std::size_t i = 0; i < n; ++i) body += std::to_string(i) + " " + std::to_string(i % 977) + " -1\n";
    const Point_data data = read_points(make_file("counted.xyz", std::to_string(n) + "\n" + body));
    REQUIRE(data.points.size() == n);
    CHECK(data.points[123456] == Eigen::Vector3d(123456, 123456 % 977, -1));
    CHECK(data.points.capacity() == n); // reserved from the count line
    const std::string more = make_file("count_more.xyz", std::to_string(n + 1) + "\n" + body);
    require_file_error(more, [&] { read_points(more); }, {"truncated", "declares " + std::to_string(n + 1)});
    const std::string fewer = make_file("count_fewer.xyz", std::to_string(n - 1) + "\n" + body);
    require_file_error(fewer, [&] { read_points(fewer); }, {"unexpected data", "declares " + std::to_string(n - 1)});
}
