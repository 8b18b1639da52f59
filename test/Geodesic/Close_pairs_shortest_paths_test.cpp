// Tests of PCCD/Geodesic: the CPSP map against BGL's full Dijkstra, its paths, its annulus search,
// the two bounded Dijkstra implementations, other graph models, thread counts, and the on-the-fly
// path policy.
#include "graph_test_helpers.h"

#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/Stored_paths.h>
#include <PCCD/Geodesic/Paths_on_the_fly.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/concepts/PathSource.h>
#include <PCCD/internal/spatial_order.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

using namespace pccd_test;

namespace {

using List_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                         boost::property<boost::edge_weight_t, double>>;

/// The non-virtual edges of `g` as an adjacency_list (double weights holding the float lengths).
List_graph surface_edges(const PCCD::Proximity_graph& g)
{
    List_graph list(g.num_vertices());
    const auto& rows = g.row_offsets();
    for (std::uint32_t u = 0; u + 1 < rows.size(); ++u)
        for (auto e = rows[u]; e < rows[u + 1]; ++e) {
            const auto v = g.targets()[e];
            if (u < v && !g.edge_property(e).is_virtual) boost::add_edge(u, v, double(g.edge_property(e).length), list);
        }
    return list;
}

/// target -> distance of one CPSP list.
std::map<std::uint32_t, float> as_map(const PCCD::Close_pairs_shortest_paths& map, std::uint32_t p)
{
    std::map<std::uint32_t, float> m;
    for (std::size_t i = 0; i < map.targets(p).size(); ++i) m[map.targets(p)[i]] = map.distances(p)[i];
    return m;
}

/// Sum, in double from the source, of the lengths of the non-virtual edges along `path`; NaN if a
/// step is not such an edge.
double path_length(const PCCD::Proximity_graph& g, const std::vector<std::uint32_t>& path, bool allow_virtual = false)
{
    double sum = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        const auto [e, found] = boost::edge(path[i - 1], path[i], g.graph());
        if (!found || (!allow_virtual && g.graph()[e].is_virtual)) return std::nan("");
        sum += double(g.graph()[e].length);
    }
    return sum;
}

struct Fixture {
    Cloud cloud;
    PCCD::Proximity_graph graph;
    double radius;
};

Fixture make_fixture(Coordinates points)
{
    Cloud cloud(std::move(points));
    auto graph = PCCD::sphere_of_influence_graph(cloud, {.r = 3});
    const double radius = 1.5 * cloud.mean_spacing();
    return {std::move(cloud), std::move(graph), radius};
}

} // namespace

static_assert(PCCD::PathSource<PCCD::Stored_paths>);
static_assert(PCCD::PathSource<PCCD::Paths_on_the_fly<PCCD::Proximity_graph::Graph, PCCD::Proximity_graph::Length_map,
                                                      PCCD::Proximity_graph::Virtual_map>>);

TEST_CASE("CPSP lists equal BGL's full Dijkstra within the bound", "[graph][geodesic]")
{
    for (auto* make : {+[] { return sphere_sample(1500, 21); }, +[] { return clustered_with_duplicates(1200, 22); }}) {
        const Fixture f = make_fixture(make());
        const PCCD::Close_pairs_shortest_paths map(f.graph, f.radius);
        REQUIRE(map.size() == f.cloud.size());
        CHECK(map.bound() == Approx(PCCD::Cpsp_options{}.support * f.radius));
        const List_graph list = surface_edges(f.graph);
        std::vector<double> full(f.cloud.size());
        std::size_t entries = 0;
        for (std::uint32_t p = 0; p < f.cloud.size(); ++p) {
            boost::dijkstra_shortest_paths(
                list, p, boost::distance_map(boost::make_iterator_property_map(full.data(), get(boost::vertex_index, list))));
            std::map<std::uint32_t, float> expected;
            for (std::uint32_t q = 0; q < f.cloud.size(); ++q)
                if (full[q] <= map.bound()) expected[q] = float(full[q]);
            INFO("source " << p);
            REQUIRE(as_map(map, p) == expected);
            CHECK(map.targets(p)[0] == p);
            CHECK(map.distances(p)[0] == 0.f);
            const auto d = map.distances(p);
            CHECK(std::is_sorted(d.begin(), d.end()));
            entries += expected.size();
        }
        CHECK(map.num_entries() == entries);
        CHECK(map.memory_bytes() == 8 * (f.cloud.size() + 1) + 12 * entries);
    }
}

TEST_CASE("every stored path is made of graph edges summing to the stored distance", "[graph][geodesic]")
{
    const Fixture f = make_fixture(clustered_with_duplicates(1500, 23));
    const PCCD::Close_pairs_shortest_paths map(f.graph, f.radius);
    const PCCD::Stored_paths stored(map);
    std::vector<std::uint32_t> path, again;
    for (std::uint32_t p = 0; p < map.size(); ++p)
        for (std::size_t i = 0; i < map.targets(p).size(); ++i) {
            map.path(p, i, path);
            INFO("path from " << p << " to entry " << i);
            REQUIRE(path.front() == p);
            REQUIRE(path.back() == map.targets(p)[i]);
            CHECK(float(path_length(f.graph, path)) == map.distances(p)[i]);
            REQUIRE(stored.path(p, map.targets(p)[i], again));
            CHECK(again == path);
        }
    // A point beyond the bound: no stored path.
    const auto far = PCCD::Close_pairs_shortest_paths(f.graph, f.radius, {.support = 0.5});
    std::uint32_t p = 0;
    while (far.targets(p).size() == map.targets(p).size()) ++p;
    const std::uint32_t beyond = map.targets(p).back();
    CHECK(far.find(p, beyond) == PCCD::Close_pairs_shortest_paths::npos);
    CHECK_FALSE(PCCD::Stored_paths(far).path(p, beyond, path));
    CHECK(path.empty());
}

TEST_CASE("both bounded Dijkstras, both graph models and both thread counts agree", "[graph][geodesic]")
{
    const Fixture f = make_fixture(clustered_with_duplicates(2000, 24));
    const PCCD::Close_pairs_shortest_paths hand(f.graph, f.radius, {.threads = 1});
    const PCCD::Close_pairs_shortest_paths hand2(f.graph, f.radius, {.threads = 2});
    CHECK(hand == hand2);
    const PCCD::Close_pairs_shortest_paths bgl(f.graph, f.radius, {.algorithm = PCCD::Bounded_dijkstra::boost});
    CHECK(bgl == PCCD::Close_pairs_shortest_paths(f.graph, f.radius,
                                                  {.algorithm = PCCD::Bounded_dijkstra::boost, .threads = 1}));
    const List_graph list = surface_edges(f.graph);
    const PCCD::Close_pairs_shortest_paths from_list(list, get(boost::edge_weight, list), f.radius);
    CHECK(from_list.num_entries() == hand.num_entries());
    for (std::uint32_t p = 0; p < hand.size(); ++p) {
        INFO("source " << p);
        CHECK(as_map(bgl, p) == as_map(hand, p));
        CHECK(as_map(from_list, p) == as_map(hand, p));
    }
    // With virtual edges walked, lists can only grow.
    const PCCD::Close_pairs_shortest_paths walk(f.graph, f.radius, {.use_virtual_edges = true});
    CHECK(walk.num_entries() >= hand.num_entries());
}

TEST_CASE("a cloud in random order and in spatial order has the same lists (both build orders)", "[graph][geodesic]")
{
    // The map takes its sources in point order, appending as it goes, when consecutive points are
    // close in the graph (spatial order), and breadth-first, scattering at the end, otherwise.
    const Coordinates random = sphere_sample(4000, 31);
    const std::vector<std::uint32_t> perm = PCCD::internal::spatial_order(random);
    Coordinates sorted(3, random.cols());
    for (Eigen::Index i = 0; i < random.cols(); ++i) sorted.col(i) = random.col(perm[std::size_t(i)]);
    const Fixture a = make_fixture(random), b = make_fixture(sorted);
    const auto local = [](const PCCD::Proximity_graph& g) {
        const std::vector<std::uint32_t> order = PCCD::internal::breadth_first_order(g.graph());
        std::vector<std::uint32_t> rank(order.size());
        for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = std::uint32_t(k);
        return PCCD::internal::point_order_is_local(rank);
    };
    REQUIRE_FALSE(local(a.graph));
    REQUIRE(local(b.graph));
    for (const unsigned threads : {1u, 2u}) {
        const PCCD::Close_pairs_shortest_paths ma(a.graph, a.radius, {.threads = threads});
        const PCCD::Close_pairs_shortest_paths mb(b.graph, a.radius, {.threads = threads});
        REQUIRE(ma.num_entries() == mb.num_entries());
        for (std::uint32_t i = 0; i < mb.size(); ++i) {
            // Point i of the sorted cloud is point perm[i] of the random one.
            std::map<std::uint32_t, float> mapped;
            for (const auto& [target, d] : as_map(mb, i)) mapped[perm[target]] = d;
            const std::map<std::uint32_t, float> expected = as_map(ma, perm[i]);
            REQUIRE(mapped.size() == expected.size());
            auto y = expected.begin();
            for (auto x = mapped.begin(); x != mapped.end(); ++x, ++y) {
                CHECK(x->first == y->first);
                CHECK(x->second == Approx(y->second).epsilon(1e-6));
            }
            CHECK(mb.distances(i).size() == mb.targets(i).size());
        }
    }
}

TEST_CASE("annulus search returns exactly the brute-force entries", "[graph][geodesic]")
{
    const Fixture f = make_fixture(sphere_sample(1000, 25));
    const PCCD::Close_pairs_shortest_paths map(f.graph, f.radius);
    PCCD::Random_engine rng(26);
    for (int trial = 0; trial < 20000; ++trial) {
        const auto p = std::uint32_t(PCCD::uniform_index(rng, map.size()));
        const auto d = map.distances(p);
        double d0, d1;
        if (trial % 3 == 0) { // bounds exactly on stored values
            d0 = d[PCCD::uniform_index(rng, d.size())];
            d1 = d[PCCD::uniform_index(rng, d.size())];
        } else {
            d0 = PCCD::uniform_real(rng, -0.1, 1.1) * map.bound();
            d1 = d0 + PCCD::uniform_real(rng, -0.1, 0.5) * map.bound();
        }
        std::size_t first = d.size(), last = 0, count = 0;
        for (std::size_t i = 0; i < d.size(); ++i)
            if (double(d[i]) >= d0 && double(d[i]) <= d1) {
                first = std::min(first, i);
                last = i + 1;
                ++count;
            }
        const auto [a, b] = map.annulus(p, d0, d1);
        INFO("p " << p << " annulus [" << d0 << ", " << d1 << "]");
        REQUIRE(b - a == count);
        if (count > 0) {
            CHECK(a == first);
            CHECK(b == last);
        }
    }
}

TEST_CASE("paths on the fly are shortest paths of the stored length", "[graph][geodesic]")
{
    const Fixture f = make_fixture(clustered_with_duplicates(1500, 27));
    const PCCD::Close_pairs_shortest_paths map(f.graph, f.radius);
    const auto on_the_fly = PCCD::paths_on_the_fly(f.graph, f.cloud);
    const auto bounded = PCCD::paths_on_the_fly(f.graph, f.cloud, {.bound = map.bound()});
    PCCD::Random_engine rng(28);
    std::vector<std::uint32_t> path;
    for (int trial = 0; trial < 3000; ++trial) {
        const auto p = std::uint32_t(PCCD::uniform_index(rng, map.size()));
        const auto i = PCCD::uniform_index(rng, map.targets(p).size());
        const auto q = map.targets(p)[i];
        INFO("from " << p << " to " << q);
        REQUIRE(on_the_fly.path(p, q, path));
        REQUIRE(path.front() == p);
        REQUIRE(path.back() == q);
        CHECK(path_length(f.graph, path) == Approx(map.distances(p)[i]).epsilon(1e-6).margin(1e-9));
        REQUIRE(bounded.path(p, q, path));
        CHECK(path_length(f.graph, path) == Approx(map.distances(p)[i]).epsilon(1e-6).margin(1e-9));
    }
    // Across components, with virtual edges only: no path unless they are walked.
    const auto components = PCCD::graph_components(f.graph);
    REQUIRE(components.count > 1);
    std::uint32_t other = 1;
    while (components.label[other] == components.label[0]) ++other;
    CHECK_FALSE(bounded.path(0, other, path));
    CHECK(path.empty());
    const auto walking = PCCD::paths_on_the_fly(f.graph, f.cloud, {.use_virtual_edges = true});
    if (PCCD::graph_components(f.graph, true).label[other] == PCCD::graph_components(f.graph, true).label[0]) {
        REQUIRE(walking.path(0, other, path));
        CHECK(std::isfinite(path_length(f.graph, path, true)));
    }
}

TEST_CASE("invalid CPSP parameters throw Invalid_input", "[graph][geodesic]")
{
    const Fixture f = make_fixture(uniform_cube(50, 29));
    CHECK_THROWS_AS(PCCD::Close_pairs_shortest_paths(f.graph, 0.0), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::Close_pairs_shortest_paths(f.graph, std::nan("")), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::Close_pairs_shortest_paths(f.graph, 1.0, {.support = -1}), PCCD::Invalid_input);
    CHECK_THROWS_AS(PCCD::paths_on_the_fly(f.graph, f.cloud, {.bound = 0}), PCCD::Invalid_input);
}
