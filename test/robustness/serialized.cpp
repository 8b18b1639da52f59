// Bad-input catalogue, serialized objects (doc/reliability.md): files written by
// Point_cloud_object::save() and write_geodesic_data(), truncated at many offsets, with single
// bytes corrupted at many offsets, of another version, with a wrong magic, empty, and -- with the
// checksum recomputed, as a buggy or malicious writer would -- with inconsistent content. Every
// case must throw File_error naming the file and the problem; none may crash.
#include "robustness_helpers.h"

#include <PCCD/Geodesic/geodesic_io.h>
#include <PCCD/Point_cloud_object.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>
#include <string>
#include <vector>

using namespace pccd_robustness;

namespace {

using Object = PCCD::Point_cloud_object<>;

std::string path_of(const std::string& name) { return scratch_path("serialized", name); }

/// The offsets to damage in a file of `size` bytes: every byte of the first `head` ones, then about
/// `strided` more spread evenly, and the last 16.
std::set<std::size_t> offsets(std::size_t size, std::size_t head = 160, std::size_t strided = 160)
{
    std::set<std::size_t> result;
    for (std::size_t i = 0; i < std::min(size, head); ++i) result.insert(i);
    for (std::size_t k = 0; k < strided; ++k) result.insert(head + k * (size - head) / strided);
    for (std::size_t i = size > 16 ? size - 16 : 0; i < size; ++i) result.insert(i);
    return result;
}

/// Recomputes the trailing checksum of a PCCD binary file (FNV-1a over 64-bit words of everything
/// before it), so that a crafted file gets past the checksum to the structural checks.
void reseal(std::string& bytes)
{
    PCCD::internal::Word_checksum checksum;
    checksum.update(bytes.data(), bytes.size() - 8);
    const std::uint64_t value = checksum.value();
    std::memcpy(bytes.data() + bytes.size() - 8, &value, 8);
}

template <class T>
void put(std::string& bytes, std::size_t at, T value)
{
    REQUIRE(at + sizeof value <= bytes.size());
    std::memcpy(bytes.data() + at, &value, sizeof value);
}

template <class T>
T get(const std::string& bytes, std::size_t at)
{
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    return value;
}

const Object& small_object()
{
    static const Object object(fibonacci_sphere(120));
    return object;
}

const std::string& object_bytes()
{
    static const std::string bytes = [] {
        const std::string path = path_of("good.pccdobj");
        small_object().save(path);
        return read_bytes(path);
    }();
    return bytes;
}

/// Field offsets of an object file (format version 1, see Point_cloud_object.h), found from its end
/// so that they do not depend on the number of timing fields.
struct Object_layout {
    std::size_t n, sampling_radius = 24, bandwidth = 32, theta_eps = 40, points, normals, fit, input_indices,
        hierarchy, nodes, geodesic_size, geodesic;
};

Object_layout object_layout(const std::string& bytes, std::size_t n)
{
    // Version 5 (Point_cloud_object.h): a 113-byte header, points 24N, normals 24N, then the scan
    // section (f64 noise, u64 input points, u64 M, u32 outliers[M], u64 D, f64 radii[D]), u8 fit,
    // u64 I (= N), u32 input indices[I], the hierarchy (u8 volume, u64 leaf size, u64 K, u32
    // counts[K], u32 rights[K], u32 order[N]), u64 G, G bytes, u64 checksum.
    REQUIRE(get<std::uint64_t>(bytes, 16) == n);
    const std::size_t points = 113, normals = points + 24 * n, scan = normals + 24 * n;
    const auto m = get<std::uint64_t>(bytes, scan + 16);
    const std::size_t radii_count = scan + 24 + 4 * std::size_t(m);
    const auto d = get<std::uint64_t>(bytes, radii_count);
    const std::size_t fit = radii_count + 8 + 8 * std::size_t(d);
    REQUIRE(get<std::uint64_t>(bytes, fit + 1) == n);
    const std::size_t hierarchy = fit + 1 + 8 + 4 * n;
    const auto nodes = std::size_t(get<std::uint64_t>(bytes, hierarchy + 9));
    const std::size_t geodesic_size = hierarchy + 17 + 8 * nodes + 4 * n;
    REQUIRE(geodesic_size + 8 + get<std::uint64_t>(bytes, geodesic_size) + 8 == bytes.size());
    return {n, 24, 32, 40, points, normals, fit, fit + 1, hierarchy, nodes, geodesic_size, geodesic_size + 8};
}

void require_load_error(const std::string& name, const std::string& bytes, const std::vector<std::string>& keywords)
{
    const std::string path = path_of(name);
    write_bytes(path, bytes);
    require_file_error(path, [&] { (void)Object::load(path); }, keywords);
}

void require_geodesic_error(const std::string& name, const std::string& bytes, const std::vector<std::string>& keywords)
{
    const std::string path = path_of(name);
    write_bytes(path, bytes);
    require_file_error(path, [&] { (void)PCCD::read_geodesic_data(path); }, keywords);
}

} // namespace

TEST_CASE("serialized objects: empty, foreign, other version and byte order", "[robustness]")
{
    const std::string& good = object_bytes();
    require_load_error("empty.pccdobj", "", {"truncated file"});
    require_load_error("seven.pccdobj", good.substr(0, 7), {"truncated file"});
    require_load_error("text.pccdobj", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n", {"not a PCCD object file"});
    std::string magic = good;
    magic[3] = 'X';
    require_load_error("magic.pccdobj", magic, {"not a PCCD object file"});
    // A geodesic file is not an object file, and the other way round.
    const std::string geodesic_path = path_of("good.pccdgeo");
    PCCD::write_geodesic_data(geodesic_path, small_object().graph(), small_object().cpsp());
    require_load_error("geodesic_as_object.pccdobj", read_bytes(geodesic_path), {"not a PCCD object file"});
    require_geodesic_error("object_as_geodesic.pccdgeo", good, {"not a PCCD geodesic file"});
    for (const std::uint32_t version : {0u, 6u, 0xffffffffu}) {
        std::string other = good;
        put(other, 8, version);
        require_load_error("version.pccdobj", other,
                           {"object file format version " + std::to_string(version), "reads versions 1 to 5"});
        reseal(other);
        require_load_error("version.pccdobj", other, {"object file format version " + std::to_string(version)});
    }
    std::string swapped = good;
    put(swapped, 12, std::uint32_t(0x04030201));
    require_load_error("byte_order.pccdobj", swapped, {"another byte order"});
    const std::string missing = path_of("missing.pccdobj");
    std::filesystem::remove(missing);
    require_file_error(missing, [&] { (void)Object::load(missing); }, {"cannot open the file"});
}

TEST_CASE("serialized objects: truncated at many offsets", "[robustness]")
{
    const std::string& good = object_bytes();
    const std::string path = path_of("truncated.pccdobj");
    std::size_t cases = 0;
    for (const std::size_t size : offsets(good.size())) {
        INFO("truncated to " << size << " of " << good.size() << " bytes");
        write_bytes(path, good.substr(0, size));
        // Before the byte-order mark the reader cannot tell more than "truncated"; after it the
        // checksum (the last 8 bytes are no longer the checksum) catches it.
        require_file_error(path, [&] { (void)Object::load(path); }, {size < 16 ? "truncated file" : ""});
        ++cases;
    }
    CHECK(cases > 300);
}

TEST_CASE("serialized objects: single bytes corrupted at many offsets", "[robustness]")
{
    const std::string& good = object_bytes();
    const std::string path = path_of("corrupted.pccdobj");
    for (const std::size_t at : offsets(good.size()))
        for (const unsigned char mask : {0x01, 0x80, 0xff}) {
            INFO("byte " << at << " xor " << int(mask));
            std::string bad = good;
            bad[at] = char(bad[at] ^ mask);
            write_bytes(path, bad);
            // The magic, version and byte-order mark are read first; everything else is caught by
            // the checksum, as is a version changed into another readable one (3 xor 1 = 2).
            const std::uint32_t version = get<std::uint32_t>(bad, 8);
            const bool readable = version >= 1 && version <= Object::file_version;
            const char* keyword = at < 8 ? "not a PCCD object file"
                                  : at < 12 && !readable ? "format version"
                                  : at >= 12 && at < 16  ? "byte order"
                                                         : "checksum mismatch";
            require_file_error(path, [&] { (void)Object::load(path); }, {keyword});
        }
}

TEST_CASE("serialized objects: inconsistent content behind a valid checksum", "[robustness]")
{
    const std::string& good = object_bytes();
    const std::size_t n = small_object().size();
    const Object_layout at = object_layout(good, n);
    const auto crafted = [&](const std::string& name, auto&& edit, const std::vector<std::string>& keywords) {
        std::string bytes = good;
        edit(bytes);
        reseal(bytes);
        INFO("crafted file " << name);
        require_load_error(name + ".pccdobj", bytes, keywords);
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const std::uint64_t count : {std::uint64_t(0), std::uint64_t(1), std::uint64_t(1) << 40, ~std::uint64_t(0)})
        crafted("count", [&](std::string& b) { put(b, 16, count); }, {"inconsistent point count " + std::to_string(count)});
    // A count off by one moves every later field: the scan section no longer fits.
    for (const std::uint64_t count : {n - 1, n + 1})
        crafted("count_off_by_one", [&](std::string& b) { put(b, 16, count); }, {"inconsistent"});
    crafted("fit", [&](std::string& b) { b[at.fit] = char(7); }, {"unknown surface fit 7"});
    // Input indices: one repeated, one beyond the points given, a count that is not N.
    crafted("repeated input index", [&](std::string& b) { put(b, at.input_indices + 8 + 4, get<std::uint32_t>(b, at.input_indices + 8)); },
            {"repeated or beyond"});
    crafted("input index beyond", [&](std::string& b) { put(b, at.input_indices + 8, std::uint32_t(1u << 30)); },
            {"repeated or beyond"});
    crafted("input index count", [&](std::string& b) { put(b, at.input_indices, std::uint64_t(at.n - 1)); },
            {"input indices are not one per point"});
    for (const double r : {0.0, -1.0, nan, inf})
        crafted("radius", [&](std::string& b) { put(b, at.sampling_radius, r); }, {"invalid sampling radius"});
    for (const double h : {0.0, -1.0, nan, inf, 1e300})
        crafted("bandwidth", [&](std::string& b) { put(b, at.bandwidth, h); }, {"inconsistent content", "Gaussian weight"});
    // A bandwidth larger than the stored CPSP map supports.
    crafted("bandwidth_too_wide", [&](std::string& b) { put(b, at.bandwidth, 10.0 * small_object().bandwidth()); },
            {"inconsistent content", "exceeds the largest radius"});
    for (const double theta : {0.0, 1.0, nan})
        crafted("theta", [&](std::string& b) { put(b, at.theta_eps, theta); }, {"inconsistent content", "theta_eps"});
    for (const double bad : {nan, inf}) {
        crafted("point", [&](std::string& b) { put(b, at.points + 8 * (3 * 17 + 1), bad); },
                {"inconsistent content", "point 17 has a non-finite coordinate"});
        crafted("normal", [&](std::string& b) { put(b, at.normals + 8 * (3 * 5 + 2), bad); },
                {"inconsistent content", "normal of point 5 is not finite"});
    }
    // The scan section (noise, outliers, domain radii).
    const std::size_t scan = at.normals + 24 * n;
    for (const double noise : {-1.0, nan, inf})
        crafted("noise", [&](std::string& b) { put(b, scan, noise); }, {"invalid noise estimate"});
    crafted("input_points", [&](std::string& b) { put(b, scan + 8, std::uint64_t(n - 1)); }, {"inconsistent outlier count"});
    crafted("outliers", [&](std::string& b) { put(b, scan + 16, std::uint64_t(3)); }, {"inconsistent outlier count"});
    for (const double radius : {0.0, -1.0, nan})
        crafted("domain_radius", [&](std::string& b) { put(b, scan + 32 + 8 * 4, radius); },
                {"inconsistent content", "domain radius of point 4"});
    crafted("domain_count", [&](std::string& b) { put(b, scan + 24, std::uint64_t(n - 1)); },
            {"inconsistent number of domain radii"});
    // The hierarchy section: volume, leaf size, node count, and a layout that is not a median-split
    // tree of the points (an order that is not a permutation, a count off the median, a right child
    // out of place), each caught before any query could trust it.
    crafted("volume", [&](std::string& b) { b[at.hierarchy] = char(9); }, {"unknown bounding volume 9"});
    for (const std::uint64_t leaf : {std::uint64_t(0), std::uint64_t(1) << 40})
        crafted("leaf_size", [&](std::string& b) { put(b, at.hierarchy + 1, leaf); }, {"invalid hierarchy leaf size"});
    for (const std::uint64_t nodes : {std::uint64_t(0), std::uint64_t(2 * n), ~std::uint64_t(0)})
        crafted("nodes", [&](std::string& b) { put(b, at.hierarchy + 9, nodes); }, {"inconsistent number of hierarchy nodes"});
    const std::size_t counts = at.hierarchy + 17, rights = counts + 4 * at.nodes, order = rights + 4 * at.nodes;
    // A leaf size above N is legitimate (one leaf): such a file loads.
    {
        const Object few(fibonacci_sphere(7));
        REQUIRE(few.hierarchy().nodes().size() == 1);
        const std::string few_path = path_of("few.pccdobj");
        few.save(few_path);
        const Object loaded = Object::load(few_path);
        CHECK(loaded.hierarchy().nodes().size() == 1);
        CHECK(loaded.hierarchy().order() == few.hierarchy().order());
    }
    crafted("hierarchy_order", [&](std::string& b) { put(b, order + 4, get<std::uint32_t>(b, order)); },
            {"inconsistent content", "not a permutation"});
    crafted("hierarchy_count", [&](std::string& b) { put(b, counts + 4, get<std::uint32_t>(b, counts + 4) + 1); },
            {"inconsistent content", "not split at its median"});
    crafted("hierarchy_right", [&](std::string& b) { put(b, rights, get<std::uint32_t>(b, rights) + 1); },
            {"inconsistent content", "not where its left subtree ends"});
    crafted("hierarchy_leaf", [&](std::string& b) { put(b, rights, std::uint32_t(0)); },
            {"inconsistent content", "nodes outside the tree"});
    crafted("geodesic_size", [&](std::string& b) { put(b, at.geodesic_size, get<std::uint64_t>(b, at.geodesic_size) + 1); },
            {"inconsistent size of the geodesic section"});
    crafted("geodesic_size_huge", [&](std::string& b) { put(b, at.geodesic_size, ~std::uint64_t(0) - 7); },
            {"inconsistent size of the geodesic section"});
    crafted("geodesic_magic", [&](std::string& b) { b[at.geodesic] = 'X'; }, {"geodesic section", "not a PCCD geodesic file"});
    crafted("geodesic_body", [&](std::string& b) { b[at.geodesic + 200] = char(b[at.geodesic + 200] ^ 1); },
            {"geodesic section", "checksum mismatch"});
    // The geodesic section of another object, sealed: one vertex per point is checked.
    {
        const Object other(fibonacci_sphere(90));
        const std::string other_path = path_of("other.pccdobj");
        other.save(other_path);
        const std::string other_bytes = read_bytes(other_path);
        const Object_layout o = object_layout(other_bytes, 90);
        std::string spliced = good.substr(0, at.geodesic_size);
        spliced += other_bytes.substr(o.geodesic_size, other_bytes.size() - o.geodesic_size);
        reseal(spliced);
        require_load_error("spliced.pccdobj", spliced, {"geodesic section does not have one vertex per point"});
    }
}

TEST_CASE("serialized geodesic data: truncated, corrupted and crafted files", "[robustness]")
{
    const std::string good_path = path_of("geodesic_good.pccdgeo");
    PCCD::write_geodesic_data(good_path, small_object().graph(), small_object().cpsp());
    const std::string good = read_bytes(good_path);
    const std::string path = path_of("geodesic_bad.pccdgeo");
    require_geodesic_error("geodesic_empty.pccdgeo", "", {"truncated file"});
    for (const std::size_t size : offsets(good.size())) {
        INFO("truncated to " << size);
        write_bytes(path, good.substr(0, size));
        require_file_error(path, [&] { (void)PCCD::read_geodesic_data(path); }, {size < 8 ? "truncated file" : ""});
    }
    for (const std::size_t at : offsets(good.size())) {
        INFO("byte " << at << " flipped");
        std::string bad = good;
        bad[at] = char(bad[at] ^ 0x40);
        write_bytes(path, bad);
        require_file_error(path, [&] { (void)PCCD::read_geodesic_data(path); }, {});
    }
    // Header fields (format in geodesic_io.h): kind at 16, parameter 17, N 21, E 29, radius 37,
    // support 45, M 53, then the arrays from 61.
    const std::uint64_t n = get<std::uint64_t>(good, 21);
    REQUIRE(n == small_object().size());
    const auto crafted = [&](const std::string& name, auto&& edit, const std::vector<std::string>& keywords) {
        std::string bytes = good;
        edit(bytes);
        reseal(bytes);
        INFO("crafted file " << name);
        require_geodesic_error(name + ".pccdgeo", bytes, keywords);
    };
    crafted("version", [&](std::string& b) { put(b, 8, std::uint32_t(7)); }, {"format version 7"});
    crafted("kind", [&](std::string& b) { b[16] = char(9); }, {"unknown graph kind 9"});
    crafted("count", [&](std::string& b) { put(b, 21, n + 1); }, {"does not match its header"});
    crafted("edges_huge", [&](std::string& b) { put(b, 29, ~std::uint64_t(0)); }, {"does not match its header"});
    for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
        crafted("radius", [&](std::string& b) { put(b, 37, bad); }, {"invalid sampling radius or support"});
        crafted("support", [&](std::string& b) { put(b, 45, bad); }, {"invalid sampling radius or support"});
    }
    const std::size_t rows = 61, targets = rows + 8 * (n + 1);
    crafted("first_row", [&](std::string& b) { put(b, rows, std::uint64_t(1)); }, {"inconsistent graph offsets"});
    crafted("target_out_of_range", [&](std::string& b) { put(b, targets, std::uint32_t(n + 5)); },
            {"graph edge 0 points to vertex " + std::to_string(n + 5)});
    crafted("target_changed", [&](std::string& b) { put(b, targets, get<std::uint32_t>(b, targets + 4)); },
            {"graph"});
}

TEST_CASE("serialized objects: a save that cannot be written", "[robustness]")
{
    // save() streams the file as it goes: a full disk (/dev/full accepts the open and fails every
    // write) is a File_error naming the file, from the parts and from the geodesic section, which is
    // written through the enclosing writer; a directory that does not exist fails at the open.
    REQUIRE(std::filesystem::exists("/dev/full"));
    require_file_error("/dev/full", [&] { small_object().save("/dev/full"); }, {"write failed (disk full?)"});
    const std::string no_dir = path_of("no_such_directory/object.pccdobj");
    require_file_error(no_dir, [&] { small_object().save(no_dir); }, {"cannot open the file for writing"});
    // The small object fits in the writer's 1 MiB buffer: its failure comes at the last flush. At
    // 5,000 points the parts (about 65 B per point) still fit and the geodesic section (about 450 B
    // per point) does not: the failure comes from inside that section's writer.
    const Object larger(fibonacci_sphere(5000));
    require_file_error("/dev/full", [&] { larger.save("/dev/full"); }, {"write failed (disk full?)"});
    // A save after a failed one writes a file that loads back.
    const std::string path = path_of("after_failure.pccdobj");
    small_object().save(path);
    CHECK(Object::load(path).size() == small_object().size());
}
