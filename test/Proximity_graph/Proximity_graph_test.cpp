// Tests of PCCD/Proximity_graph: k-NN, SIG and r-SIG against a brute-force evaluation of their
// definitions, determinism across thread counts, other Boost.Graph models, coincident points and the
// long-edge test.
// Also covers Proximity_graph/graph_options.h: the test cases below exercise what it declares.
#include "build_helpers.h"
#include "graph_test_helpers.h"

#include <PCCD/Error.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/graph_options.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/prune_long_edges.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/concepts/ProximityGraph.h>

#include <boost/graph/adjacency_list.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace pccd_test;

namespace {

struct List_edge {
    double length = 0;
    bool is_virtual = false;
};
using List_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, List_edge>;

List_graph to_adjacency_list(const PCCD::Proximity_graph& g)
{
    List_graph list(g.num_vertices());
    for (const auto& [uv, length] : edge_set(g)) boost::add_edge(uv.first, uv.second, List_edge{length, false}, list);
    return list;
}

Coordinates two_clusters_and_a_bridge()
{
    // Two flat disks of 400 points (spacing ~0.05) 5 apart, joined by 3 sparse points 0.7 apart.
    PCCD::Random_engine rng(11);
    Coordinates c(3, 803);
    for (Eigen::Index i = 0; i < 800; ++i) {
        double x, y;
        do {
            x = PCCD::uniform_real(rng, -1, 1);
            y = PCCD::uniform_real(rng, -1, 1);
        } while (x * x + y * y > 1);
        c.col(i) = Eigen::Vector3d(x + (i < 400 ? 0.0 : 5.0), y, 0.0);
    }
    c.col(800) = Eigen::Vector3d(1.8, 0, 0);
    c.col(801) = Eigen::Vector3d(2.5, 0, 0);
    c.col(802) = Eigen::Vector3d(3.2, 0, 0);
    return c;
}

} // namespace

static_assert(PCCD::ProximityGraph<PCCD::Proximity_graph::Graph, PCCD::Proximity_graph::Length_map>);
static_assert(PCCD::EdgeFlagMap<PCCD::Proximity_graph::Virtual_map, PCCD::Proximity_graph::Graph>);
static_assert(PCCD::EdgeFlagMap<PCCD::No_virtual_edges, List_graph>);

TEST_CASE("r-SIG and k-NN graph equal the brute-force definition", "[graph]")
{
    struct Case {
        std::string name;
        Coordinates points;
    };
    // Debug builds: smaller clouds of the same kinds (the brute force is slow there).
    const auto size = [](int optimized) { return pccd_test::by_build(optimized, optimized * 2 / 5); };
    const std::vector<Case> cases = {{"uniform cube", uniform_cube(size(700), 1)},
                                     {"clusters, grid ties and duplicates", clustered_with_duplicates(size(2000), 2)},
                                     {"sphere sample", sphere_sample(size(1500), 3)},
                                     {"three points", uniform_cube(3, 4)}};
    for (const auto& [name, points] : cases) {
        const Cloud cloud(points);
        for (unsigned r : {1u, 2u, 3u, 4u}) {
            INFO(name << ", r = " << r);
            const auto g = PCCD::sphere_of_influence_graph(cloud, {.r = r});
            CHECK(g.kind() == PCCD::Graph_kind::sphere_of_influence);
            CHECK(g.parameter() == r);
            const auto expected = brute_force_graph(points, PCCD::Graph_kind::sphere_of_influence, r);
            CHECK(edge_set(g) == expected);
            CHECK(g.num_edges() == expected.size());
        }
        for (unsigned k : {1u, 6u}) {
            INFO(name << ", k = " << k);
            const auto g = PCCD::knn_graph(cloud, {.k = k});
            CHECK(edge_set(g) == brute_force_graph(points, PCCD::Graph_kind::knn, k));
        }
    }
}

TEST_CASE("graphs do not depend on the thread count", "[graph]")
{
    const Cloud cloud(clustered_with_duplicates(20000, 5));
    const auto one = PCCD::sphere_of_influence_graph(cloud, {.r = 3, .threads = 1});
    const auto two = PCCD::sphere_of_influence_graph(cloud, {.r = 3, .threads = 2});
    CHECK(one == two);
    CHECK(PCCD::knn_graph(cloud, {.k = 5, .threads = 1}) == PCCD::knn_graph(cloud, {.k = 5, .threads = 2}));
}

TEST_CASE("coincident points hang off their representative by one zero-length edge", "[graph]")
{
    // Point 0 and its two copies 3, 5; point 1 and its copy 4; point 2 alone.
    Coordinates c(3, 6);
    c << 0, 1, 0, 0, 1, 0, //
        0, 0, 1, 0, 0, 0,  //
        0, 0, 0, 0, 0, 0;
    const Cloud cloud(c);
    const auto g = PCCD::sphere_of_influence_graph(cloud, {.r = 1});
    const Edge_set expected = {{{0, 1}, 1.f}, {{0, 2}, 1.f}, {{1, 2}, float(std::sqrt(2.0))},
                               {{0, 3}, 0.f}, {{0, 5}, 0.f}, {{1, 4}, 0.f}};
    CHECK(edge_set(g) == expected);
    CHECK(g.num_virtual_edges() == 0);
    CHECK(PCCD::graph_components(g).count == 1);

    // All points at one position: a star of zero-length edges around point 0.
    const Cloud same(Coordinates::Zero(3, 4));
    CHECK(edge_set(PCCD::sphere_of_influence_graph(same)) == Edge_set{{{0, 1}, 0.f}, {{0, 2}, 0.f}, {{0, 3}, 0.f}});
    CHECK(PCCD::sphere_of_influence_graph(Cloud(Coordinates::Zero(3, 1))).num_edges() == 0);
}

TEST_CASE("long edges joining two clusters come out virtual", "[graph]")
{
    const Coordinates points = two_clusters_and_a_bridge();
    const Cloud cloud(points);
    const auto g = PCCD::sphere_of_influence_graph(cloud, {.r = 3});
    const auto edges = edge_set(g);
    std::size_t bridge_edges = 0, virtual_count = 0;
    const auto virtual_map = g.virtual_map();
    for (auto [v, v_end] = vertices(g.graph()); v != v_end; ++v)
        for (auto [e, e_end] = out_edges(*v, g.graph()); e != e_end; ++e) {
            const auto a = source(*e, g.graph()), b = target(*e, g.graph());
            const bool touches_bridge = a >= 800 || b >= 800;
            const bool crosses_cluster = a >= 800 && b >= 800;
            if (a < b) bridge_edges += touches_bridge;
            if (a < b) virtual_count += get(virtual_map, *e);
            INFO("edge " << a << " - " << b << " length " << get(g.length_map(), *e));
            // Every edge between a cluster point and a bridge point is virtual; cluster edges are not.
            if (touches_bridge && !crosses_cluster) CHECK(get(virtual_map, *e));
            if (!touches_bridge) CHECK_FALSE(get(virtual_map, *e));
        }
    CHECK(bridge_edges > 0);
    CHECK(g.num_virtual_edges() == virtual_count);
    const auto surface = PCCD::graph_components(g);
    const auto walkable = PCCD::graph_components(g, true);
    CHECK(surface.label[0] != surface.label[400]);
    CHECK(walkable.count == 1);

    // The same test on an adjacency_list copy gives the same flags and components.
    List_graph list = to_adjacency_list(g);
    const std::size_t marked =
        PCCD::mark_long_edges(list, get(&List_edge::length, std::as_const(list)), get(&List_edge::is_virtual, list));
    CHECK(marked == g.num_virtual_edges());
    for (auto [e, e_end] = boost::edges(list); e != e_end; ++e) {
        const auto a = source(*e, list), b = target(*e, list);
        const auto [csr_edge, found] = boost::edge(std::uint32_t(a), std::uint32_t(b), g.graph());
        REQUIRE(found);
        CHECK(list[*e].is_virtual == get(virtual_map, csr_edge));
    }
    const auto list_components = PCCD::graph_components(list, get(&List_edge::is_virtual, std::as_const(list)));
    CHECK(list_components.label == surface.label);
    CHECK(PCCD::graph_components(list).count == 1);
}

TEST_CASE("mark_long_edges on a hand-made graph", "[graph]")
{
    // A path of unit edges 0-1-2-3-4 plus a chord 0-4 of length 10 and a short chord 1-3 of length 2.
    List_graph g(5);
    for (int i = 0; i < 4; ++i) boost::add_edge(i, i + 1, List_edge{1.0, false}, g);
    boost::add_edge(0, 4, List_edge{10.0, false}, g);
    boost::add_edge(1, 3, List_edge{2.0, false}, g);
    const auto length = get(&List_edge::length, std::as_const(g));
    // Own medians m = (5.5, 1, 1, 1, 5.5); scales S = median of m over the closed neighbourhood =
    // (5.5, 1, 1, 1, 5.5). Chord 0-4: 10 > 3 * 5.5? no.
    CHECK(PCCD::mark_long_edges(g, length, get(&List_edge::is_virtual, g)) == 0);
    // With factor 1.5: 0-4 (10 > 8.25) and 1-3 (2 > 1.5) are long.
    CHECK(PCCD::mark_long_edges(g, length, get(&List_edge::is_virtual, g), {.factor = 1.5}) == 2);
    CHECK(g[boost::edge(0, 4, g).first].is_virtual);
    CHECK(g[boost::edge(1, 3, g).first].is_virtual);
    CHECK_FALSE(g[boost::edge(0, 1, g).first].is_virtual);
    CHECK(PCCD::mark_long_edges(g, length, get(&List_edge::is_virtual, g),
                                {.factor = std::numeric_limits<double>::infinity()}) == 0);
}

TEST_CASE("invalid graph options throw Invalid_input", "[graph]")
{
    const Cloud cloud(uniform_cube(10, 6));
    CHECK_THROWS_AS(PCCD::sphere_of_influence_graph(cloud, {.r = 0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::knn_graph(cloud, {.k = 0}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sphere_of_influence_graph(cloud, {.long_edges = {.factor = 0}}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::sphere_of_influence_graph(cloud, {.long_edges = {.factor = std::nan("")}}),
                    PCCD::Invalid_input);
    CHECK_THROWS_WITH(PCCD::sphere_of_influence_graph(cloud, {.r = 0}), Catch::Contains("r must be >= 1"));
}
