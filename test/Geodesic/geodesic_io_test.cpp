// Tests of PCCD/Geodesic/geodesic_io.h: bit-exact round trips of a graph and its CPSP map, and
// rejection (File_error) of truncated, corrupted, foreign and other-version files.
#include "graph_test_helpers.h"

#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/geodesic_io.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace pccd_test;

namespace {

std::string temp_path(const std::string& name) { return std::string(PCCD_TEST_TMP_DIR) + "/" + name; }

std::vector<char> file_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<char>& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

} // namespace

TEST_CASE("geodesic data round-trips bit-exactly", "[graph][io]")
{
    const Cloud cloud(clustered_with_duplicates(1500, 41));
    const auto sig = PCCD::sphere_of_influence_graph(cloud, {.r = 4, .long_edges = {.factor = 2}});
    REQUIRE(sig.num_virtual_edges() > 0);
    const auto knn = PCCD::knn_graph(cloud, {.k = 5});
    const double radius = 2.0 * cloud.mean_spacing();
    for (const auto* graph : {&sig, &knn}) {
        const PCCD::Close_pairs_shortest_paths cpsp(*graph, radius, {.support = 3.0});
        const std::string path = temp_path("roundtrip.pccdgeo");
        PCCD::write_geodesic_data(path, *graph, cpsp);
        const PCCD::Geodesic_data data = PCCD::read_geodesic_data(path);
        CHECK(data.graph == *graph);
        CHECK(data.graph.num_virtual_edges() == graph->num_virtual_edges());
        CHECK(data.cpsp == cpsp);
        CHECK(data.cpsp.bound() == cpsp.bound());
        // Writing what was read gives the same bytes.
        const std::string again = temp_path("roundtrip2.pccdgeo");
        PCCD::write_geodesic_data(again, data.graph, data.cpsp);
        CHECK(file_bytes(again) == file_bytes(path));
    }
    // The empty cloud-less case: a one-point cloud.
    const Cloud single(Coordinates::Zero(3, 1));
    const auto g1 = PCCD::sphere_of_influence_graph(single);
    const PCCD::Close_pairs_shortest_paths c1(g1, 1.0);
    PCCD::write_geodesic_data(temp_path("single.pccdgeo"), g1, c1);
    const auto d1 = PCCD::read_geodesic_data(temp_path("single.pccdgeo"));
    CHECK(d1.graph == g1);
    CHECK(d1.cpsp == c1);
}

TEST_CASE("corrupt, truncated and foreign geodesic files are rejected", "[graph][io]")
{
    const Cloud cloud(sphere_sample(400, 42));
    const auto graph = PCCD::sphere_of_influence_graph(cloud);
    const PCCD::Close_pairs_shortest_paths cpsp(graph, 2.0 * cloud.mean_spacing());
    const std::string good = temp_path("good.pccdgeo");
    PCCD::write_geodesic_data(good, graph, cpsp);
    const std::vector<char> bytes = file_bytes(good);
    const std::string bad = temp_path("bad.pccdgeo");

    auto rejects = [&](const std::vector<char>& content, const std::string& message) {
        write_bytes(bad, content);
        INFO("expected: " << message);
        CHECK_THROWS_AS(PCCD::read_geodesic_data(bad), PCCD::File_error);
        CHECK_THROWS_WITH(PCCD::read_geodesic_data(bad), Catch::Contains(message) && Catch::Contains(bad));
    };
    for (std::size_t size : {std::size_t(0), std::size_t(5), std::size_t(30), bytes.size() / 2, bytes.size() - 1}) {
        INFO("truncated to " << size << " bytes");
        rejects(std::vector<char>(bytes.begin(), bytes.begin() + std::ptrdiff_t(size)), "truncated");
    }
    auto longer = bytes;
    longer.push_back(0);
    rejects(longer, "does not match its header");
    auto version = bytes;
    version[8] = 2; // version field follows the 8-byte magic
    rejects(version, "format version 2, this PCCD reads version 1");
    auto magic = bytes;
    magic[0] = 'X';
    rejects(magic, "not a PCCD geodesic file");
    for (std::size_t at : {std::size_t(100), bytes.size() / 3, bytes.size() * 2 / 3, bytes.size() - 9}) {
        auto flipped = bytes;
        flipped[at] = char(flipped[at] ^ 0x10);
        INFO("byte " << at << " flipped");
        rejects(flipped, "checksum mismatch");
    }
    CHECK_THROWS_AS(PCCD::read_geodesic_data(temp_path("does-not-exist.pccdgeo")), PCCD::File_error);
    CHECK_THROWS_AS(PCCD::write_geodesic_data(temp_path("no-such-dir/x.pccdgeo"), graph, cpsp), PCCD::File_error);
    const Cloud other(sphere_sample(10, 43));
    CHECK_THROWS_AS(PCCD::write_geodesic_data(bad, PCCD::sphere_of_influence_graph(other), cpsp), PCCD::Invalid_input);
}
