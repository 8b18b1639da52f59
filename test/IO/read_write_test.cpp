// Reading and writing point clouds and triangle meshes: PLY (ascii, binary), OFF, XYZ/PWN
// (doc/manual/io.md). Exact round trips, the real bunny, and every kind of broken file, each of
// which must throw PCCD::File_error naming the file and the problem -- never crash or hang.
#include <PCCD/Error.h>
#include <PCCD/IO/Format.h>
#include <PCCD/IO/Point_data.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/IO/read_points.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/IO/write_points.h>
#include <PCCD/IO/write_triangle_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>
#include "data_helpers.h"
#include "error_test_helpers.h"
#include "file_helpers.h"

namespace {

namespace fs = std::filesystem;
using PCCD::Point_data;
using PCCD::Triangle_mesh_data;
using PCCD::IO::Format;
using PCCD::IO::read_points;
using PCCD::IO::read_triangle_mesh;
using PCCD::IO::write_points;
using PCCD::IO::write_triangle_mesh;

// The data types are PCCD::Point_data and PCCD::Triangle_mesh_data, also named in PCCD::IO
// (doc/manual/io.md, "Namespaces").
static_assert(std::is_same_v<PCCD::IO::Point_data, PCCD::Point_data>);
static_assert(std::is_same_v<PCCD::IO::Triangle_mesh_data, PCCD::Triangle_mesh_data>);

template <class... Args>
std::string str(const Args&... args)
{
    std::ostringstream out;
    (out << ... << args);
    return out.str();
}

/// A path in this test's own directory under PCCD_TEST_TMP_DIR.
std::string tmp_path(const std::string& name) { return pccd_test::scratch_path("io", name); }

/// Writes `content` byte for byte to tmp_path(name) and returns that path.
std::string make_file(const std::string& name, const std::string& content)
{
    const std::string path = tmp_path(name);
    pccd_test::write_bytes(path, content);
    return path;
}

using pccd_test::read_bytes;

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

bool same_bits(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Eigen::Vector3d)) == 0);
}

using pccd_test::require_file_error;
using pccd_test::require_invalid_input;

void require_points_error(const std::string& path, const std::vector<std::string>& keywords)
{
    require_file_error(path, [&] { read_points(path); }, keywords);
}

void require_mesh_error(const std::string& path, const std::vector<std::string>& keywords)
{
    require_file_error(path, [&] { read_triangle_mesh(path); }, keywords);
}

/// A broken file: both readers must reject it (the mesh reader only for .off and .ply).
struct Broken {
    std::string name;
    std::string content;
    std::vector<std::string> keywords;
};

void require_broken(const Broken& b)
{
    const std::string path = make_file(b.name, b.content);
    require_points_error(path, b.keywords);
    if (PCCD::IO::format_from_extension(path) != Format::xyz) require_mesh_error(path, b.keywords);
}

/// Points whose decimal and binary forms are hard to keep exact: thirds, tenths, signed zero, the
/// extremes, subnormals, and random finite bit patterns.
Point_data tricky_points(bool with_normals)
{
    std::vector<double> values = {0.1,
                                  1.0 / 3.0,
                                  -0.0,
                                  0.0,
                                  -2.0 / 3.0,
                                  3.141592653589793,
                                  123456789.12345679,
                                  1e-310,
                                  std::numeric_limits<double>::denorm_min(),
                                  -std::numeric_limits<double>::denorm_min(),
                                  std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::max(),
                                  -std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::epsilon(),
                                  1.0 + std::numeric_limits<double>::epsilon(),
                                  1e22,
                                  9007199254740993.0,
                                  -1e-5};
    std::mt19937_64 random(20240607);
    while (values.size() < 3 * 200) {
        const std::uint64_t bits = random();
        if ((bits & 0x7FF0000000000000u) != 0x7FF0000000000000u) values.push_back(std::bit_cast<double>(bits));
    }
    Point_data data;
    for (std::size_t i = 0; i + 2 < values.size(); i += 3) data.points.emplace_back(values[i], values[i + 1], values[i + 2]);
    if (with_normals)
        for (std::size_t i = 0; i < data.points.size(); ++i)
            data.normals.emplace_back(values[(i * 7 + 1) % values.size()], values[(i * 5 + 2) % values.size()],
                                      values[(i * 3 + 4) % values.size()]);
    return data;
}

// Sample files. Lines of the ascii PLY mesh: 1 ply, 2 format, 3 comment, 4 element vertex, 5-7
// properties, 8 element face, 9 list property, 10 end_header, 11-14 vertices 0-3, 15-18 faces 0-3.
const std::string tet_vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string tet_faces = "3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n";

std::string off_tet(const std::string& counts = "4 4 0", const std::string& vertices = tet_vertices,
                    const std::string& faces = tet_faces)
{
    return "OFF\n" + counts + "\n" + vertices + faces;
}

std::string ply_ascii(const std::string& nv, const std::string& nf, const std::string& body,
                      const std::string& vertex_properties = "property float x\nproperty float y\nproperty float z\n")
{
    return "ply\nformat ascii 1.0\ncomment a tetrahedron\nelement vertex " + nv + "\n" + vertex_properties +
           "element face " + nf + "\nproperty list uchar int vertex_indices\nend_header\n" + body;
}

std::string ply_ascii_tet() { return ply_ascii("4", "4", tet_vertices + tet_faces); }

/// A binary PLY tetrahedron-like mesh: double x y z, faces as uchar-counted int lists.
std::string ply_binary(const std::string& nv, const std::string& nf, const std::vector<double>& coordinates,
                       const std::vector<std::vector<std::int32_t>>& faces, bool big_endian = false)
{
    std::string s = str("ply\nformat ", big_endian ? "binary_big_endian" : "binary_little_endian",
                        " 1.0\nelement vertex ", nv, "\nproperty double x\nproperty double y\nproperty double z\n",
                        "element face ", nf, "\nproperty list uchar int vertex_indices\nend_header\n");
    const bool swap = big_endian != (std::endian::native == std::endian::big);
    const auto put = [&](auto value) {
        char bytes[sizeof value];
        std::memcpy(bytes, &value, sizeof value);
        if (swap) std::reverse(bytes, bytes + sizeof value);
        s.append(bytes, sizeof value);
    };
    for (const double c : coordinates) put(c);
    for (const auto& face : faces) {
        put(static_cast<std::uint8_t>(face.size()));
        for (const std::int32_t index : face) put(index);
    }
    return s;
}

const std::vector<double> tet_coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const std::vector<std::vector<std::int32_t>> tet_face_lists = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};

std::string ply_binary_tet(bool big_endian = false)
{
    return ply_binary("4", "4", tet_coordinates, tet_face_lists, big_endian);
}

const std::vector<std::array<std::uint32_t, 3>> tet_triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};

std::vector<Eigen::Vector3d> tet_points()
{
    return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}

} // namespace

// --- Formats and round trips ----------------------------------------------------------------------

TEST_CASE("formats are chosen from the extension, case-insensitively", "[io]")
{
    CHECK(PCCD::IO::format_from_extension("a/b.ply") == Format::ply);
    CHECK(PCCD::IO::format_from_extension("B.PLY") == Format::ply);
    CHECK(PCCD::IO::format_from_extension("c.Off") == Format::off);
    CHECK(PCCD::IO::format_from_extension("d.xyz") == Format::xyz);
    CHECK(PCCD::IO::format_from_extension("e.PWN") == Format::xyz);
    CHECK_FALSE(PCCD::IO::format_from_extension("f.stl").has_value());
    CHECK_FALSE(PCCD::IO::format_from_extension("ply").has_value());
    CHECK_FALSE(PCCD::IO::format_from_extension("dir.ply/file").has_value());
    CHECK(std::string(PCCD::IO::format_name(Format::off)) == "OFF");
}

TEST_CASE("points round-trip exactly through every format, with and without normals", "[io]")
{
    struct Target {
        std::string name;
        PCCD::IO::Write_options options;
    };
    const std::vector<Target> targets = {
        {"points_ascii.ply", {}},         {"points_binary.ply", {.binary = true}},
        {"points.off", {}},               {"points.xyz", {}},
        {"points.pwn", {}},               {"POINTS_UPPER.PLY", {.binary = true}},
        {"points_upper.XYZ", {}},
    };
    for (const bool with_normals : {false, true}) {
        const Point_data data = tricky_points(with_normals);
        for (const Target& target : targets) {
            const std::string path = tmp_path((with_normals ? "n_" : "") + target.name);
            INFO(path);
            write_points(path, data, target.options);
            const Point_data back = read_points(path);
            CHECK(back.points.size() == data.points.size());
            CHECK(same_bits(back.points, data.points));
            CHECK(back.has_normals() == with_normals);
            CHECK(same_bits(back.normals, data.normals));
        }
    }
}

TEST_CASE("written PLY headers say ascii or binary little endian with double coordinates", "[io]")
{
    Point_data data;
    data.points = tet_points();
    const std::string ascii = tmp_path("header_ascii.ply"), binary = tmp_path("header_binary.ply");
    write_points(ascii, data);
    write_points(binary, data, {.binary = true});
    CHECK_THAT(read_bytes(ascii), Catch::Contains("format ascii 1.0") && Catch::Contains("property double x"));
    CHECK_THAT(read_bytes(binary),
               Catch::Contains("format binary_little_endian 1.0") && Catch::Contains("property double z"));
    // 4 points of 3 doubles after the header.
    const std::string content = read_bytes(binary);
    CHECK(content.size() - (content.find("end_header\n") + 11) == 4 * 3 * sizeof(double));
}

TEST_CASE("a format can be forced whatever the extension", "[io]")
{
    const Point_data data = tricky_points(true);
    const std::string path = tmp_path("cloud.txt");
    write_points(path, data, Format::xyz);
    require_points_error(path, {"unknown extension", "'.txt'"});
    const Point_data back = read_points(path, Format::xyz);
    CHECK(same_bits(back.points, data.points));
    CHECK(same_bits(back.normals, data.normals));

    const std::string ply = tmp_path("cloud.dat");
    write_points(ply, data, Format::ply, {.binary = true});
    CHECK(same_bits(read_points(ply, Format::ply).points, data.points));
    Triangle_mesh_data mesh{tet_points(), tet_triangles};
    const std::string mesh_path = tmp_path("mesh.bin");
    write_triangle_mesh(mesh_path, mesh, Format::ply, {.binary = true});
    CHECK(read_triangle_mesh(mesh_path, Format::ply).triangles == tet_triangles);
}

TEST_CASE("triangle meshes round-trip exactly through OFF and PLY", "[io]")
{
    const Point_data tricky = tricky_points(false);
    Triangle_mesh_data mesh;
    mesh.vertices = tricky.points;
    for (std::uint32_t i = 0; i + 2 < mesh.vertices.size(); ++i) mesh.triangles.push_back({i, i + 2, i + 1});
    mesh.triangles.push_back({0, static_cast<std::uint32_t>(mesh.vertices.size() - 1), 7});
    const std::vector<std::pair<std::string, bool>> targets = {{"mesh.off", false}, {"mesh_ascii.ply", false}, {"mesh_binary.ply", true}};
    for (const auto& [name, binary] : targets) {
        const std::string path = tmp_path(name);
        INFO(path);
        write_triangle_mesh(path, mesh, {.binary = binary});
        const Triangle_mesh_data back = read_triangle_mesh(path);
        CHECK(same_bits(back.vertices, mesh.vertices));
        CHECK(back.triangles == mesh.triangles);
        // The vertices of a mesh file are its points.
        const Point_data points = read_points(path);
        CHECK(same_bits(points.points, mesh.vertices));
        CHECK_FALSE(points.has_normals());
    }
}

TEST_CASE("polygons are triangulated as fans", "[io]")
{
    const std::string square_and_pentagon =
        "OFF\n# a square and a pentagon sharing an edge\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 0.5 0\n-0.5 -1 0\n"
        "4 0 1 2 3\n5 0 3 4 5 1\n";
    const Triangle_mesh_data off = read_triangle_mesh(make_file("polygons.off", square_and_pentagon));
    const std::vector<std::array<std::uint32_t, 3>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1}};
    CHECK(off.vertices.size() == 6);
    CHECK(off.triangles == expected);

    const std::string ply = ply_ascii("6", "2", "0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 0.5 0\n-0.5 -1 0\n4 0 1 2 3\n5 0 3 4 5 1\n");
    CHECK(read_triangle_mesh(make_file("polygons.ply", ply)).triangles == expected);
}

TEST_CASE("the variants of the formats that PCCD accepts read correctly", "[io]")
{
    SECTION("OFF: counts on the keyword line, comments, CRLF, colors, normals")
    {
        const Triangle_mesh_data one_line = read_triangle_mesh(make_file("one_line.off", "OFF 4 4 0\n" + tet_vertices + tet_faces));
        CHECK(one_line.vertices == tet_points());
        CHECK(one_line.triangles == tet_triangles);

        const std::string commented = "# header comment\nOFF # keyword\n# counts next\n4 4 0\n\n0 0 0 # first\n1 0 0\n# between\n"
                                      "0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3 # face comment\n3 0 2 3\n3 1 2 3";
        CHECK(read_triangle_mesh(make_file("commented.off", commented)).triangles == tet_triangles);

        std::string crlf = off_tet();
        for (std::size_t p = crlf.find('\n'); p != std::string::npos; p = crlf.find('\n', p + 2)) crlf.insert(p, "\r");
        CHECK(read_triangle_mesh(make_file("crlf.off", crlf)).vertices == tet_points());

        const std::string coff = "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0 0 255 0 255\n0 1 0 0.5 0.5 0.5\n0 0 1 7\n"
                                 "3 0 1 2 255 0 0\n3 0 1 3 4\n3 0 2 3 1\n3 1 2 3 0 0 255 255\n";
        const Triangle_mesh_data colored = read_triangle_mesh(make_file("colored.off", coff));
        CHECK(colored.vertices == tet_points());
        CHECK(colored.triangles == tet_triangles);

        const std::string noff = "NOFF\n3 0 0\n0 0 0 0 0 1\n1 0 0 0 0 -1\n0 1 0 1 0 0\n";
        const Point_data with_normals = read_points(make_file("normals.off", noff));
        CHECK(with_normals.points.size() == 3);
        REQUIRE(with_normals.normals.size() == 3);
        CHECK(with_normals.normals[1] == Eigen::Vector3d(0, 0, -1));

        const std::string cnoff = "CNOFF\n2 0 0\n0 0 0 0 0 1 255 0 0\n1 0 0 0 1 0 0 255 0\n";
        const Point_data cn = read_points(make_file("cnoff.off", cnoff));
        REQUIRE(cn.normals.size() == 2);
        CHECK(cn.normals[1] == Eigen::Vector3d(0, 1, 0));
    }
    SECTION("XYZ: count line, comments, tabs, CRLF, no final newline")
    {
        const Point_data counted = read_points(make_file("counted.xyz", "3\n0 0 0\n1 0 0\n0 1 0\n"));
        CHECK(counted.points.size() == 3);
        const Point_data messy = read_points(make_file("messy.xyz", "# comment\n\n0\t0\t0\r\n  1 2 3  # trailing\r\n\t\n4 5 6"));
        REQUIRE(messy.points.size() == 3);
        CHECK(messy.points[1] == Eigen::Vector3d(1, 2, 3));
        CHECK(messy.points[2] == Eigen::Vector3d(4, 5, 6));
        CHECK_FALSE(messy.has_normals());
        const Point_data signs = read_points(make_file("signs.xyz", "+1 -2 +3e0 +0.5 -.5 5.\n1e-400 0 0 0 0 1\n"));
        CHECK(signs.points[0] == Eigen::Vector3d(1, -2, 3));
        CHECK(signs.normals[0] == Eigen::Vector3d(0.5, -0.5, 5));
        CHECK(signs.points[1] == Eigen::Vector3d(0, 0, 0));
    }
    SECTION("PLY: big endian, float coordinates, extra properties and elements, CRLF header")
    {
        const Triangle_mesh_data big = read_triangle_mesh(make_file("big_endian.ply", ply_binary_tet(true)));
        CHECK(big.vertices == tet_points());
        CHECK(big.triangles == tet_triangles);
        CHECK(read_points(make_file("little_endian.ply", ply_binary_tet(false))).points == tet_points());

        const std::string extra =
            "ply\r\nformat ascii 1.0\r\nobj_info scanned\r\nelement vertex 3\r\nproperty float x\r\nproperty uchar red\r\n"
            "property float y\r\nproperty double z\r\nproperty float nx\r\nproperty float ny\r\nproperty float nz\r\n"
            "property list uchar float tags\r\nelement material 2\r\nproperty int id\r\nend_header\r\n"
            "0.5 255 1 2 0 0 1 2 0.5 0.25\r\n3 0 4 5 0 1 0 0\r\n6 7 7 8 1 0 0 1 1\r\n-1\r\n2\r\n";
        const Point_data points = read_points(make_file("extra.ply", extra));
        REQUIRE(points.points.size() == 3);
        CHECK(points.points[0] == Eigen::Vector3d(0.5, 1, 2));
        CHECK(points.points[2] == Eigen::Vector3d(6, 7, 8));
        REQUIRE(points.normals.size() == 3);
        CHECK(points.normals[1] == Eigen::Vector3d(0, 1, 0));

        const std::string plural = replaced(replaced(ply_ascii_tet(), "element vertex", "element vertices"), "element face",
                                            "element faces");
        const Triangle_mesh_data named = read_triangle_mesh(make_file("plural_names.ply", plural));
        CHECK(named.vertices == tet_points());
        CHECK(named.triangles == tet_triangles);
    }
}

TEST_CASE("the real bunny reads as a mesh and as points", "[io][data]")
{
    if (std::string(PCCD_DATA_DIR).empty()) {
        PCCD_SKIP_TEST("bunny00.off of libcgal-demo not found (PCCD_DATA_DIR is empty)");
    }
    const std::string path = std::string(PCCD_DATA_DIR) + "/bunny00.off";
    const Triangle_mesh_data bunny = read_triangle_mesh(path);
    REQUIRE(bunny.vertices.size() == 37706);
    REQUIRE(bunny.triangles.size() == 75408);
    CHECK(bunny.vertices[0] == Eigen::Vector3d(-0.167662, -0.411917, -0.0732205));
    CHECK(std::all_of(bunny.triangles.begin(), bunny.triangles.end(), [&](const auto& t) {
        return t[0] < bunny.vertices.size() && t[1] < bunny.vertices.size() && t[2] < bunny.vertices.size();
    }));
    const Point_data points = read_points(path);
    CHECK(same_bits(points.points, bunny.vertices));
    CHECK_FALSE(points.has_normals());

    const std::string copy = tmp_path("bunny_copy.ply");
    write_triangle_mesh(copy, bunny, {.binary = true});
    const Triangle_mesh_data back = read_triangle_mesh(copy);
    CHECK(same_bits(back.vertices, bunny.vertices));
    CHECK(back.triangles == bunny.triangles);
}

// --- Broken files ---------------------------------------------------------------------------------

TEST_CASE("missing, unreadable, empty and unnamed files throw File_error", "[io][robustness]")
{
    for (const char* name : {"missing.ply", "missing.off", "missing.xyz", "missing.pwn"}) {
        const std::string path = tmp_path(name);
        fs::remove(path);
        require_points_error(path, {"does not exist"});
        if (std::string(name) != "missing.xyz" && std::string(name) != "missing.pwn")
            require_mesh_error(path, {"does not exist"});
    }
    const std::string dir = tmp_path("a_directory.ply");
    fs::create_directories(dir);
    require_points_error(dir, {"directory"});
    require_mesh_error(dir, {"directory"});

    for (const char* name : {"empty.ply", "empty.off", "empty.xyz"}) require_broken({name, "", {"empty"}});
    for (const char* name : {"blank.ply", "blank.off", "blank.xyz"}) require_broken({name, " \n\t\r\n\n", {"empty"}});

    for (const char* name : {"cloud.stl", "cloud", "cloud.ply.bak", "cloud."}) {
        const std::string path = make_file(name, "0 0 0\n");
        require_points_error(path, {"unknown extension"});
        require_mesh_error(path, {"unknown extension"});
    }
    const std::string xyz = make_file("cloud_for_mesh.xyz", "0 0 0\n1 0 0\n0 1 0\n");
    require_mesh_error(xyz, {"unknown extension", "'.xyz'"});
    require_file_error(xyz, [&] { read_triangle_mesh(xyz, Format::xyz); }, {"unsupported", "XYZ"});
}

TEST_CASE("broken OFF files throw File_error naming the problem", "[io][robustness]")
{
    const std::vector<Broken> cases = {
        {"off_comments_only.off", "# nothing here\n# at all\n", {"empty"}},
        {"off_header_only.off", "OFF\n", {"bad header", "vertex count is missing"}},
        {"off_header_partial.off", "OFF\n4 4\n", {"bad header", "edge count is missing"}},
        {"off_header_counts_only.off", "OFF\n4 4 0\n", {"truncated", "4 vertices and 4 faces", "only 0"}},
        {"off_bad_magic.off", "OFX\n4 4 0\n" + tet_vertices + tet_faces, {"bad header", "'OFX'"}},
        {"off_lowercase_magic.off", "off\n4 4 0\n" + tet_vertices + tet_faces, {"bad header", "'off'"}},
        {"off_negative_vertices.off", off_tet("-4 4 0"), {"bad header", "negative vertex count -4"}},
        {"off_negative_faces.off", off_tet("4 -4 0"), {"bad header", "negative face count"}},
        {"off_garbage_count.off", off_tet("four 4 0"), {"bad header", "malformed vertex count 'four'"}},
        {"off_float_count.off", off_tet("4.5 4 0"), {"bad header", "malformed vertex count"}},
        {"off_huge_count.off", off_tet("99999999999999999999 4 0"), {"bad header", "too large"}},
        {"off_int_overflow_count.off", off_tet("4 2147483648 0"), {"bad header", "face count", "too large"}},
        {"off_counts_junk.off", off_tet("4 4 0 7"), {"bad header", "unexpected '7'"}},
        {"off_truncated_vertices.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n", {"truncated", "4 vertices"}},
        {"off_truncated_vertices_and_faces.off", off_tet("6 4 0"), {"truncated", "6 vertices"}},
        {"off_truncated_faces.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n3 0 1 3\n"), {"truncated", "only 6"}},
        {"off_token.off", off_tet("4 4 0", "0 0 0\n1 abc 0\n0 1 0\n0 0 1\n"), {"malformed number 'abc'", "line 4", "vertex 1"}},
        {"off_half_number.off", off_tet("4 4 0", "0 0 0\n1 0 0\n0 1.5.2 0\n0 0 1\n"), {"malformed number", "line 5"}},
        {"off_nan.off", off_tet("4 4 0", "0 0 0\n1 0 0\n0 nan 0\n0 0 1\n"), {"vertex 2", "NaN coordinate", "line 5"}},
        {"off_inf.off", off_tet("4 4 0", "0 0 0\n-inf 0 0\n0 1 0\n0 0 1\n"), {"vertex 1", "infinite coordinate"}},
        {"off_overflow.off", off_tet("4 4 0", "0 0 0\n1e400 0 0\n0 1 0\n0 0 1\n"), {"'1e400'", "overflows"}},
        {"off_zero_points.off", "OFF\n0 0 0\n", {"no points"}},
        {"off_face_out_of_range.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n3 0 1 4\n3 0 2 3\n3 1 2 3\n"),
         {"face 1", "line 8", "vertex 4", "out of range"}},
        {"off_face_negative_index.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n3 0 -1 3\n3 0 2 3\n3 1 2 3\n"),
         {"face 1", "out of range"}},
        {"off_face_float_index.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n3 0 1.5 3\n3 0 2 3\n3 1 2 3\n"),
         {"malformed number '1.5'", "face 1"}},
        {"off_face_two_vertices.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n2 0 1\n3 0 2 3\n3 1 2 3\n"),
         {"face 1", "at least 3"}},
        {"off_face_short.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n3 0 1 3\n4 0 2 3\n3 1 2 3\n"),
         {"face 2", "declares 4 vertices but lists 3"}},
        {"off_face_huge_size.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\n3 0 1 3\n1000000000000 0 2 3\n3 1 2 3\n"),
         {"face 2", "declares 1000000000000 vertices"}},
        {"off_face_garbage_size.off", off_tet("4 4 0", tet_vertices, "3 0 1 2\nx 0 1 3\n3 0 2 3\n3 1 2 3\n"),
         {"malformed number 'x'", "face 1"}},
        {"off_trailing.off", off_tet() + "3 0 1 2\n", {"unexpected data on line 11"}},
        {"off_extra_numbers.off", off_tet("4 4 0", "0 0 0 1\n1 0 0\n0 1 0\n0 0 1\n"), {"malformed vertex", "vertex 0", "4 numbers"}},
        {"off_six_numbers.off", "OFF\n1 0 0\n0 0 0 0 0 1\n", {"malformed vertex", "NOFF"}},
        {"off_two_numbers.off", off_tet("4 4 0", "0 0 0\n1 0\n0 1 0\n0 0 1\n"), {"malformed vertex", "vertex 1", "2 numbers"}},
        {"off_noff_missing_normal.off", "NOFF\n2 0 0\n0 0 0 0 0 1\n1 0 0\n", {"inconsistent normals", "vertex 1"}},
        {"off_noff_nan_normal.off", "NOFF\n2 0 0\n0 0 0 0 0 1\n1 0 0 0 nan 1\n", {"vertex 1", "NaN normal"}},
        {"off_coff_mixed_vertex_colors.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0\n0 1 0 0 0 255\n3 0 1 2\n",
         {"inconsistent colors", "vertex 0 (line 3) has a color", "vertex 1 (line 4) has none"}},
        {"off_coff_mixed_face_colors.off", "COFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n3 0 1 2\n",
         {"inconsistent colors", "face 1"}},
        {"off_cnoff_mixed_colors.off", "CNOFF\n2 0 0\n0 0 0 0 0 1 255 0 0\n1 0 0 0 1 0\n", {"inconsistent colors"}},
        {"off_coff_color_too_large.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 300 0\n0 1 0 0 0 255\n3 0 1 2\n",
         {"malformed color on line 4", "vertex 1", "out of range"}},
        {"off_coff_fraction_too_large.off", "COFF\n3 1 0\n0 0 0 0.5 1.5 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2\n",
         {"malformed color on line 3", "vertex 0"}},
        {"off_coff_color_index.off", "COFF\n3 1 0\n0 0 0 7\n1 0 0 149\n0 1 0 0\n3 0 1 2\n",
         {"malformed color on line 4", "[0, 148]"}},
        {"off_coff_face_color.off", "COFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 -1 0 0\n",
         {"malformed color on line 6", "face 0"}},
        {"off_glued_comment.off", "OFF# glued\n4 4 0\n" + tet_vertices + tet_faces, {"bad header", "glued", "line 1"}},
        {"off_comment_in_counts.off", "OFF\n4 # vertices\n4 0\n" + tet_vertices + tet_faces,
         {"bad header", "comment between", "line 2"}},
        {"off_binary.off", "OFF BINARY\n\x00\x00\x00\x04", {"unsupported", "binary OFF"}},
        {"off_4off.off", "4OFF\n1 0 0\n0 0 0 1\n", {"unsupported", "'4OFF'"}},
        {"off_stoff.off", "STOFF\n1 0 0\n0 0 0 0 0\n", {"unsupported", "'STOFF'"}},
        {"off_ply_body.off", ply_ascii_tet(), {"bad header", "'ply'", "PLY file"}},
        {"off_binary_ply_body.off", ply_binary_tet(), {"bad header", "PLY file"}},
        {"off_xyz_body.off", "0 0 0\n1 0 0\n", {"bad header", "XYZ file"}},
        {"off_binary_garbage.off", std::string("\x7f\x45\x4c\x46\x02\x01\x01\x00\xff\xfe", 10), {"bad header"}},
    };
    for (const Broken& b : cases) require_broken(b);

    // A point cloud in OFF is fine as points, but not as a mesh.
    const std::string cloud = make_file("off_no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    CHECK(read_points(cloud).points.size() == 3);
    require_mesh_error(cloud, {"no faces"});
}

TEST_CASE("broken XYZ files throw File_error naming the problem", "[io][robustness]")
{
    const std::vector<Broken> cases = {
        {"xyz_comments_only.xyz", "# a\n# b\n", {"no points"}},
        {"xyz_count_only.xyz", "0\n", {"no points"}},
        {"xyz_token.xyz", "0 0 0\n1 x 0\n", {"malformed number 'x'", "line 2"}},
        {"xyz_comma.xyz", "0 0 0\n1,5 2 0\n", {"malformed number '1,5'", "line 2"}},
        {"xyz_nan.xyz", "0 0 0\n1 1 1\nnan 0 0\n", {"point 2", "NaN coordinate", "line 3"}},
        {"xyz_inf.xyz", "0 0 0\n1 -inf 1\n", {"point 1", "infinite coordinate"}},
        {"xyz_nan_normal.xyz", "0 0 0 0 nan 1\n", {"point 0", "NaN normal"}},
        {"xyz_overflow.xyz", "0 0 1e999\n", {"overflows"}},
        {"xyz_four_numbers.xyz", "0 0 0\n1 1 1 1\n", {"malformed line 2", "4 numbers"}},
        {"xyz_two_numbers.xyz", "0 0 0\n1 1\n", {"malformed line 2", "2 numbers"}},
        {"xyz_inconsistent_normals.xyz", "0 0 0 0 0 1\n1 1 1 0 0 1\n2 2 2\n", {"inconsistent normals", "line 3"}},
        {"xyz_inconsistent_normals2.xyz", "0 0 0\n1 1 1 0 0 1\n", {"inconsistent normals", "line 2"}},
        {"xyz_truncated.xyz", "5\n0 0 0\n1 1 1\n", {"truncated", "declares 5 points", "only 2"}},
        {"xyz_too_many.xyz", "1\n0 0 0\n1 1 1\n", {"unexpected data", "declares 1 points"}},
        {"xyz_negative_count.xyz", "-3\n0 0 0\n", {"bad header", "negative point count"}},
        {"xyz_off_body.xyz", off_tet(), {"malformed number 'OFF'", "line 1", "OFF file"}},
        {"xyz_ply_body.xyz", ply_ascii_tet(), {"malformed number 'ply'", "line 1", "PLY file"}},
        {"xyz_binary_ply_body.pwn", ply_binary_tet(), {"malformed number 'ply'", "PLY file"}},
        {"xyz_binary_garbage.xyz", std::string("\x01\x02\x03 \xff\x00\x10\n", 8), {"malformed number", "line 1"}},
    };
    for (const Broken& b : cases) require_broken(b);
}

TEST_CASE("broken ascii PLY files throw File_error naming the problem", "[io][robustness]")
{
    const std::string xyz_props = "property float x\nproperty float y\nproperty float z\n";
    const std::vector<Broken> cases = {
        {"ply_bad_magic.ply", "plx\nformat ascii 1.0\nelement vertex 1\n" + xyz_props + "end_header\n0 0 0\n", {"bad header", "'plx'"}},
        {"ply_magic_only.ply", "ply\n", {"bad header", "format line is missing"}},
        {"ply_no_format.ply", "ply\nelement vertex 1\n" + xyz_props + "end_header\n0 0 0\n", {"bad header", "line 2"}},
        {"ply_unknown_format.ply", "ply\nformat binary 1.0\nelement vertex 1\n" + xyz_props + "end_header\n",
         {"bad header", "unknown PLY format 'binary'"}},
        {"ply_negative_count.ply", ply_ascii("-4", "4", tet_vertices + tet_faces), {"bad header", "negative count -4", "'vertex'"}},
        {"ply_negative_faces.ply", ply_ascii("4", "-1", tet_vertices + tet_faces), {"bad header", "negative count", "'face'"}},
        {"ply_garbage_count.ply", ply_ascii("four", "4", tet_vertices + tet_faces), {"bad header", "malformed count 'four'"}},
        {"ply_huge_count.ply", ply_ascii("99999999999999999999", "4", tet_vertices + tet_faces), {"bad header", "too large"}},
        {"ply_element_without_property.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props + "element nothing 1000000000000\nend_header\n0 0 0\n",
         {"bad header", "'nothing'", "no property"}},
        {"ply_unknown_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty int64 x\nend_header\n0\n",
         {"bad header", "unknown property type 'int64'"}},
        {"ply_float_list_count.ply", replaced(ply_ascii_tet(), "list uchar", "list float"), {"bad header", "integer type"}},
        {"ply_no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props, {"bad header", "end_header"}},
        {"ply_unknown_keyword.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props + "weird line\nend_header\n0 0 0\n",
         {"bad header", "unknown keyword 'weird'"}},
        {"ply_property_first.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n",
         {"bad header", "property before any element"}},
        {"ply_no_vertex_element.ply", "ply\nformat ascii 1.0\nelement point 1\n" + xyz_props + "end_header\n0 0 0\n",
         {"bad header", "no 'vertex' element"}},
        {"ply_no_y.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float z\nend_header\n0 0\n",
         {"bad header", "no 'y' property"}},
        {"ply_int_coordinates.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty int y\nproperty int z\nend_header\n0 0 0\n",
         {"unsupported", "'x' is int"}},
        {"ply_partial_normals.ply", ply_ascii("4", "4", tet_vertices + tet_faces, xyz_props + "property float nx\n"),
         {"inconsistent normals", "'nx'", "not 'ny' 'nz'"}},
        {"ply_header_only.ply", ply_ascii("4", "4", ""), {"truncated", "vertex 0 of the 4"}},
        {"ply_truncated_vertices.ply", ply_ascii("4", "0", "0 0 0\n1 0 0\n"), {"truncated", "vertex 2 of the 4"}},
        {"ply_truncated_faces.ply", ply_ascii("4", "4", tet_vertices + "3 0 1 2\n"), {"truncated", "face 1 of the 4"}},
        {"ply_token.ply", ply_ascii("4", "4", "0 0 0\n1 zz 0\n0 1 0\n0 0 1\n" + tet_faces),
         {"malformed number 'zz'", "line 12", "vertex 1", "property 'y'"}},
        {"ply_nan.ply", ply_ascii("4", "4", "0 0 0\nnan 0 0\n0 1 0\n0 0 1\n" + tet_faces), {"vertex 1", "NaN coordinate", "line 12"}},
        {"ply_inf.ply", ply_ascii("4", "4", "0 0 0\n1 0 0\n0 1 inf\n0 0 1\n" + tet_faces), {"vertex 2", "infinite coordinate"}},
        {"ply_float_overflow.ply", ply_ascii("4", "4", "0 0 0\n1e39 0 0\n0 1 0\n0 0 1\n" + tet_faces), {"'1e39'", "overflows float"}},
        {"ply_zero_vertices.ply", ply_ascii("0", "0", ""), {"no points"}},
        {"ply_face_out_of_range.ply", ply_ascii("4", "4", tet_vertices + "3 0 1 2\n3 0 1 9\n3 0 2 3\n3 1 2 3\n"),
         {"face 1", "line 16", "vertex 9", "out of range"}},
        {"ply_face_negative_index.ply", ply_ascii("4", "4", tet_vertices + "3 0 -1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n"),
         {"face 0", "out of range"}},
        {"ply_face_two_vertices.ply", ply_ascii("4", "4", tet_vertices + "3 0 1 2\n2 0 1\n3 0 2 3\n3 1 2 3\n"),
         {"face 1", "at least 3"}},
        {"ply_face_list_too_long.ply", ply_ascii("4", "4", tet_vertices + "3 0 1 2\n200 0 1 3\n3 0 2 3\n3 1 2 3\n"),
         {"malformed line 16", "declares 200 values"}},
        {"ply_face_count_out_of_range.ply", ply_ascii("4", "4", tet_vertices + "3 0 1 2\n300 0 1 3\n3 0 2 3\n3 1 2 3\n"),
         {"'300'", "out of range for uchar"}},
        {"ply_extra_values.ply", ply_ascii("4", "4", "0 0 0\n1 0 0 7\n0 1 0\n0 0 1\n" + tet_faces), {"malformed line 12", "vertex 1"}},
        {"ply_missing_value.ply", ply_ascii("4", "4", "0 0 0\n1 0\n0 1 0\n0 0 1\n" + tet_faces),
         {"malformed line 12", "vertex 1", "'z'"}},
        {"ply_trailing.ply", ply_ascii_tet() + "3 0 1 2\n", {"unexpected data on line 19"}},
        {"ply_nan_other_property.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props + "property float quality\nend_header\n0 0 0 nan\n",
         {"vertex 0", "NaN value in property 'quality'"}},
        {"ply_off_body.ply", off_tet(), {"bad header", "'OFF'", "OFF file"}},
        {"ply_xyz_body.ply", "0 0 0\n1 0 0\n", {"bad header", "XYZ file"}},
    };
    for (const Broken& b : cases) require_broken(b);

    // Point clouds and unusual face elements are fine as points, but not as meshes.
    const std::string cloud = make_file("ply_cloud.ply", "ply\nformat ascii 1.0\nelement vertex 2\n" + xyz_props + "end_header\n0 0 0\n1 1 1\n");
    CHECK(read_points(cloud).points.size() == 2);
    require_mesh_error(cloud, {"no faces", "no 'face' element"});
    const std::string no_faces = make_file("ply_zero_faces.ply", ply_ascii("4", "0", tet_vertices));
    CHECK(read_points(no_faces).points.size() == 4);
    require_mesh_error(no_faces, {"no faces", "declares 0 faces"});
    // Properties CGAL's mesh reader would read with the wrong type.
    const std::string float_green = make_file(
        "ply_float_green.ply", replaced(ply_ascii("3", "1", "0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n"),
                                        "property float z\n",
                                        "property float z\nproperty uchar red\nproperty uchar g\nproperty float green\n"
                                        "property uchar blue\n"));
    CHECK(read_points(float_green).points.size() == 3);
    require_mesh_error(float_green, {"unsupported vertex property", "'green' is float"});
    const std::string int_source = make_file(
        "ply_int_halfedge.ply",
        replaced(ply_ascii("4", "4", tet_vertices + tet_faces + "5\n"), "end_header", "element halfedge 1\nproperty int source\nend_header"));
    CHECK(read_points(int_source).points.size() == 4);
    require_mesh_error(int_source, {"unsupported halfedge property", "'source' is int"});
    const std::string ushort_path = make_file("ply_ushort_indices.ply", replaced(ply_ascii_tet(), "uchar int", "uchar ushort"));
    CHECK(read_points(ushort_path).points.size() == 4);
    require_mesh_error(ushort_path, {"unsupported face element", "vertex_indices"});
}

TEST_CASE("broken binary PLY files throw File_error naming the problem", "[io][robustness]")
{
    const std::string valid = ply_binary_tet();
    const std::vector<Broken> cases = {
        {"bin_truncated_faces.ply", valid.substr(0, valid.size() - 5), {"truncated binary body", "face 3 of the 4"}},
        {"bin_truncated_in_vertex.ply", valid.substr(0, valid.find("end_header\n") + 11 + 8 * 7),
         {"truncated binary body", "vertex 2 of the 4"}},
        {"bin_truncated_vertices.ply", ply_binary("5", "0", tet_coordinates, {}), {"truncated binary body", "vertex 4 of the 5"}},
        {"bin_header_only.ply", ply_binary("4", "4", {}, {}), {"truncated binary body", "vertex 0 of the 4"}},
        {"bin_huge_count.ply", ply_binary("1000000000000", "4", tet_coordinates, tet_face_lists), {"truncated binary body"}},
        {"bin_trailing.ply", valid + "xyz", {"unexpected data", "3 bytes"}},
        {"bin_nan.ply", ply_binary("4", "4", {0, 0, 0, 1, std::nan(""), 0, 0, 1, 0, 0, 0, 1}, tet_face_lists),
         {"vertex 1", "NaN coordinate"}},
        {"bin_inf.ply",
         ply_binary("4", "4", {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -std::numeric_limits<double>::infinity()}, tet_face_lists),
         {"vertex 3", "infinite coordinate"}},
        {"bin_face_out_of_range.ply", ply_binary("4", "4", tet_coordinates, {{0, 1, 2}, {0, 1, 3}, {0, 2, 4}, {1, 2, 3}}),
         {"face 2", "vertex 4", "out of range"}},
        {"bin_face_negative_index.ply", ply_binary("4", "4", tet_coordinates, {{0, 1, 2}, {0, -7, 3}, {0, 2, 3}, {1, 2, 3}}),
         {"face 1", "vertex -7", "out of range"}},
        {"bin_face_two_vertices.ply", ply_binary("4", "4", tet_coordinates, {{0, 1, 2}, {0, 1}, {0, 2, 3}, {1, 2, 3}}),
         {"face 1", "at least 3"}},
        {"bin_zero_vertices.ply", ply_binary("0", "0", {}, {}), {"no points"}},
        {"bin_negative_count.ply", ply_binary("-4", "4", tet_coordinates, tet_face_lists), {"bad header", "negative count"}},
        {"bin_bad_magic.ply", "PLY" + valid.substr(3), {"bad header", "'PLY'"}},
        {"bin_bad_format.ply", replaced(valid, "binary_little_endian", "binary_middle_endian"),
         {"bad header", "unknown PLY format 'binary_middle_endian'"}},
        {"bin_cut_header.ply", valid.substr(0, valid.find("end_header") + 4), {"bad header"}},
    };
    for (const Broken& b : cases) require_broken(b);
}

TEST_CASE("writing throws File_error for unwritable paths and Invalid_input for bad data", "[io][robustness]")
{
    Point_data data;
    data.points = tet_points();
    const Triangle_mesh_data mesh{tet_points(), tet_triangles};

    const std::string no_dir = tmp_path("no_such_directory/cloud.ply");
    fs::remove_all(tmp_path("no_such_directory"));
    require_file_error(no_dir, [&] { write_points(no_dir, data); }, {"cannot open the file for writing"});
    require_file_error(no_dir, [&] { write_triangle_mesh(no_dir, mesh); }, {"cannot open the file for writing"});
    const std::string dir = tmp_path("a_directory.off");
    fs::create_directories(dir);
    require_file_error(dir, [&] { write_points(dir, data); }, {"cannot open the file for writing"});
    for (const char* name : {"cloud.stl", "cloud"}) {
        const std::string path = tmp_path(name);
        require_file_error(path, [&] { write_points(path, data); }, {"unknown extension"});
        require_file_error(path, [&] { write_triangle_mesh(path, mesh); }, {"unknown extension"});
    }
    const std::string mesh_xyz = tmp_path("mesh_out.xyz");
    require_file_error(mesh_xyz, [&] { write_triangle_mesh(mesh_xyz, mesh); }, {"unknown extension"});

    const std::string path = tmp_path("bad_data.ply");
    // The writers name the file and the problem.
    const auto invalid = [&](auto&& write, const std::string& keyword) {
        require_invalid_input(write, {"bad_data.", keyword});
    };
    invalid([&] { write_points(path, Point_data{}); }, "no points");
    Point_data bad_normals = data;
    bad_normals.normals.resize(2);
    invalid([&] { write_points(path, bad_normals); }, "inconsistent normals");
    Point_data nan_point = data;
    nan_point.points[2].y() = std::nan("");
    invalid([&] { write_points(path, nan_point); }, "point 2");
    Point_data inf_normal = data;
    inf_normal.normals.assign(4, Eigen::Vector3d(0, 0, 1));
    inf_normal.normals[3].x() = std::numeric_limits<double>::infinity();
    invalid([&] { write_points(path, inf_normal); }, "point 3");
    invalid([&] { write_points(tmp_path("bad_data.off"), data, {.binary = true}); }, "");
    invalid([&] { write_points(path, data, {.precision = 0}); }, "precision");
    invalid([&] { write_points(path, data, {.precision = 18}); }, "precision");
    invalid([&] { write_triangle_mesh(path, Triangle_mesh_data{tet_points(), {}}); }, "no triangle");
    invalid([&] { write_triangle_mesh(path, Triangle_mesh_data{{}, tet_triangles}); }, "no vertex");
    invalid([&] { write_triangle_mesh(path, Triangle_mesh_data{tet_points(), {{0, 1, 4}}}); }, "out of range");
    invalid([&] { write_triangle_mesh(path, mesh, Format::xyz); }, "XYZ");
    Triangle_mesh_data nan_mesh = mesh;
    nan_mesh.vertices[1].z() = -std::numeric_limits<double>::infinity();
    invalid([&] { write_triangle_mesh(path, nan_mesh); }, "vertex 1");
}

TEST_CASE("a lower precision writes fewer digits", "[io]")
{
    Point_data data;
    data.points = {{1.0 / 3.0, 0.1, 2.0 / 3.0}};
    const std::string path = tmp_path("precision.xyz");
    write_points(path, data, {.precision = 6});
    CHECK_THAT(read_bytes(path), Catch::Contains("0.333333 0.1 0.666667"));
    CHECK(read_points(path).points[0] == Eigen::Vector3d(0.333333, 0.1, 0.666667));
}

TEST_CASE("no prefix or corruption of a valid file crashes, hangs or escapes File_error", "[io][robustness]")
{
    Point_data cloud = tricky_points(true);
    cloud.points.resize(6);
    cloud.normals.resize(6);
    std::vector<std::pair<std::string, std::string>> samples = {
        {"fuzz_tet.off", off_tet()},
        {"fuzz_coff.off", "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n0 0 1 9 9 9\n" + tet_faces},
        {"fuzz_tet_ascii.ply", ply_ascii_tet()},
        {"fuzz_tet_binary.ply", ply_binary_tet()},
        {"fuzz_tet_big.ply", ply_binary_tet(true)},
    };
    const std::vector<std::pair<std::string, PCCD::IO::Write_options>> written = {
        {"fuzz_cloud.xyz", {}}, {"fuzz_cloud.off", {}}, {"fuzz_cloud_ascii.ply", {}}, {"fuzz_cloud_binary.ply", {.binary = true}}};
    for (const auto& [name, options] : written) {
        write_points(tmp_path(name), cloud, options);
        samples.emplace_back("src_" + name, read_bytes(tmp_path(name)));
    }

    std::size_t reads = 0, rejected = 0;
    const auto try_read = [&](const std::string& path, bool mesh) {
        ++reads;
        try {
            if (mesh)
                read_triangle_mesh(path);
            else
                read_points(path);
        } catch (const PCCD::File_error& e) {
            ++rejected;
            const std::string message = e.what();
            // A file that passed PCCD's checks but that CGAL rejected would be a PCCD bug.
            if (message.find("PCCD bug") != std::string::npos) FAIL(message);
        }
    };
    std::mt19937 random(12345);
    const std::string replacements = std::string("0123456789-+.eE \n\t#xnaif,") + '\0' + '\xff' + '\x80';
    for (const auto& [name, content] : samples) {
        const std::string extension = fs::path(name).extension().string();
        const bool mesh_format = extension != ".xyz";
        const std::string path = tmp_path("fuzz_case" + extension);
        INFO("sample " << name);
        for (std::size_t length = 0; length < content.size(); ++length) {
            make_file("fuzz_case" + extension, content.substr(0, length));
            try_read(path, false);
            if (mesh_format) try_read(path, true);
        }
        for (int trial = 0; trial < 400; ++trial) {
            std::string corrupted = content;
            const int flips = 1 + static_cast<int>(random() % 3);
            for (int f = 0; f < flips; ++f) {
                const std::size_t at = random() % corrupted.size();
                if (random() % 4 == 0)
                    corrupted[at] = static_cast<char>(random() % 256);
                else
                    corrupted[at] = replacements[random() % replacements.size()];
            }
            make_file("fuzz_case" + extension, corrupted);
            try_read(path, false);
            if (mesh_format) try_read(path, true);
        }
    }
    CHECK(rejected > reads / 2); // most damaged files are rejected, none crashed
}
