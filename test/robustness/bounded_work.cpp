// Bounded work (doc/reliability.md, "Bounded work"): every loop whose length
// depends on the data has a stated bound, and adversarial inputs stay within it. The interpolation
// search on paths along which f is not monotone (a wavy surface crossing a flat one several times
// per path), the sample counts of both leaf intersectors, the evaluation budget, the hierarchy
// traversal on degenerate boxes (flat, collinear, coincident points), the kinetic tree's events
// when all flightplans cross at the same instant, and the CPSP map's bounded Dijkstra.
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Hierarchy/overlapping_leaves.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Random.h>
#include <PCCD/testing/pose_generator.h>

#include <catch2/catch.hpp>

#include "kinetic_test_helpers.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <vector>

#include "graph_test_helpers.h"
#include "surface_test_helpers.h"

namespace {

using PCCD::Rigid_transform_3;
using Object = PCCD::Point_cloud_object<>;

/// A flat cloud A (z = 0, spacing 0.04 over [-0.5, 0.5]^2) and a wavy cloud B (z = 0.015 sin(2 pi x /
/// 0.1), spacing 0.0125 over [-0.3, 0.3]^2): B crosses A every 0.05 along x, and A's CPSP paths
/// (bound about 3 of A's spacings) span several crossings, so f_B along a path of A changes sign
/// several times, and so does f_A along B's paths.
struct Wavy_pair {
    Object flat;
    Object wavy;
};

std::vector<Eigen::Vector3d> jittered_grid(double half, double step, std::uint64_t seed, double amplitude, double wavelength)
{
    PCCD::Random_engine engine(seed);
    std::vector<Eigen::Vector3d> points;
    const int n = int(std::lround(2.0 * half / step)) + 1;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = -half + step * (i + PCCD::uniform_real(engine, -0.2, 0.2));
            const double y = -half + step * (j + PCCD::uniform_real(engine, -0.2, 0.2));
            const double z = amplitude == 0.0 ? 0.0 : amplitude * std::sin(2.0 * std::numbers::pi * x / wavelength);
            points.emplace_back(x, y, z);
        }
    return points;
}

const Wavy_pair& wavy_pair()
{
    static const Wavy_pair pair{Object(jittered_grid(0.5, 0.04, 1, 0.0, 1.0)),
                                Object(jittered_grid(0.3, 0.0125, 2, 0.015, 0.1))};
    return pair;
}

/// Two unit spheres of 1200 points each.
struct Sphere_pair {
    Object a;
    Object b;
};
const Sphere_pair& sphere_pair()
{
    static const Sphere_pair pair{
        Object(pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), 1200, 0.0, 5).points)),
        Object(pccd_test::columns(pccd_test::sample_shape(pccd_test::unit_sphere(), 1200, 0.0, 6).points))};
    return pair;
}

Rigid_transform_3<double> shifted(double x, double y = 0.0, double z = 0.0)
{
    return Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(x, y, z));
}
Rigid_transform_3<double> turned(double angle, const Eigen::Vector3d& shift)
{
    return Rigid_transform_3<double>(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix(), shift);
}

/// The largest number of edges of a stored CPSP path of `o`.
std::size_t longest_path(const Object& o)
{
    std::size_t longest = 1;
    std::vector<std::uint32_t> path;
    for (std::uint32_t p = 0; p < o.size(); ++p)
        for (std::size_t e = 0; e < o.cpsp().targets(p).size(); ++e) {
            o.cpsp().path(p, e, path);
            longest = std::max(longest, path.size() - 1);
        }
    return longest;
}

/// Interpolation_search's bound on the steps of one bracket along a path of m edges.
std::size_t steps_bound(std::size_t m) { return 2 * std::size_t(std::ceil(std::log2(double(std::max<std::size_t>(m, 1))))) + 2; }

/// Every evaluation of f belongs to a sample, a partner, a search step or a refinement sample (two
/// evaluations each); every bracket comes from a tried sample.
void check_accounting(const PCCD::Intersection_result& r, bool isearch)
{
    const PCCD::Intersection_counters& c = r.counters;
    if (isearch) {
        CHECK(c.f_evaluations <= c.samples + c.partner_candidates + c.search_steps + 2 * c.refinement_samples);
        CHECK(c.brackets_tried <= c.samples);
        CHECK(c.brackets_found <= c.partner_candidates);
        CHECK(c.bisection_steps <= c.search_steps);
    } else {
        CHECK(c.f_evaluations <= 2 * c.samples + 2 * c.refinement_samples);
    }
    for (const auto& p : r.points) CHECK(p.position.allFinite());
}

/// The node boxes of a kinetic tree against brute force at its current time; the tree's extremes
/// are candidates of their node (inner child's extreme or a leaf child's vertex).
template <class Tree>
void check_kinetic_tree(const Tree& tree)
{
    using Node = typename Tree::Node_index;
    const std::vector<Node> order = pccd_test::nodes_in_preorder(tree);
    std::vector<Eigen::AlignedBox3d> truth(tree.node_count());
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const Node n = *it;
        REQUIRE(n < truth.size());
        if (tree.is_leaf(n)) {
            truth[n] = Eigen::AlignedBox3d(tree.vertex_position(tree.primitive(tree.leaf_primitive(n)).vertex(0)));
        } else {
            truth[n] = truth[tree.left(n)].merged(truth[tree.right(n)]);
        }
        const Eigen::AlignedBox3d box = tree.box(n);
        INFO("node " << n << " at t = " << tree.now());
        REQUIRE(box.min() == truth[n].min());
        REQUIRE(box.max() == truth[n].max());
    }
}

using pccd_test::envelope_bound;

} // namespace

TEST_CASE("Interpolation search: f not monotone along the paths, steps within 2 ceil(log2 m) + 2 per bracket",
          "[robustness][intersection]")
{
    const Wavy_pair& w = wavy_pair();
    // The input is adversarial: some of A's paths see f_B change sign at least twice.
    std::size_t wavy_paths = 0;
    std::vector<std::uint32_t> path;
    for (std::uint32_t p = 0; p < w.flat.size() && wavy_paths == 0; ++p)
        for (std::size_t e = 0; e < w.flat.cpsp().targets(p).size(); ++e) {
            w.flat.cpsp().path(p, e, path);
            int changes = 0;
            double previous = 0.0;
            for (const std::uint32_t q : path) {
                const auto f = w.wavy.surface().evaluate(w.flat.cloud().position(q).cast<double>());
                if (!f.defined()) continue;
                if (previous != 0.0 && (f.value < 0.0) != (previous < 0.0)) ++changes;
                previous = f.value;
            }
            wavy_paths += changes >= 2;
        }
    REQUIRE(wavy_paths > 0);

    const std::size_t per_bracket = steps_bound(std::max(longest_path(w.flat), longest_path(w.wavy)));
    std::size_t brackets = 0;
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
        const Rigid_transform_3<double> pose = turned(0.6 * double(seed), Eigen::Vector3d(0.01 * double(seed % 5), 0.0, 0.0));
        for (const PCCD::Partner_choice choice : {PCCD::Partner_choice::predicted, PCCD::Partner_choice::random}) {
            const PCCD::Interpolation_search policy{.partner_choice = choice};
            for (const bool first_hit : {true, false}) {
                const PCCD::Intersection_options options{.seed = seed, .refinement = PCCD::Refinement::none};
                const auto r = first_hit ? PCCD::do_intersect(w.flat, {}, w.wavy, pose, options, policy)
                                         : PCCD::intersection_points(w.flat, {}, w.wavy, pose, options, policy);
                INFO("seed " << seed << ", first hit " << first_hit << ", steps " << r.counters.search_steps
                             << ", brackets " << r.counters.brackets_found << ", per bracket " << per_bracket);
                CHECK(r.intersects);
                CHECK(r.counters.search_steps <= r.counters.brackets_found * per_bracket);
                check_accounting(r, true);
                brackets += r.counters.brackets_found;
            }
        }
    }
    CHECK(brackets > 50);
    // The sphere pair, where every path across the circle meets it once but f is curved.
    const Sphere_pair& s = sphere_pair();
    const std::size_t sphere_bound = steps_bound(std::max(longest_path(s.a), longest_path(s.b)));
    for (double d : {0.2, 1.0, 1.9, 1.98}) {
        const auto r = PCCD::intersection_points(s.a, {}, s.b, shifted(d), {.seed = 3, .refinement = PCCD::Refinement::none});
        INFO("d = " << d);
        CHECK(r.counters.search_steps <= r.counters.brackets_found * sphere_bound);
        check_accounting(r, true);
    }
}

TEST_CASE("Sample counts: at most max_samples per role (first-hit interpolation search) and per query (RST)",
          "[robustness][intersection]")
{
    const Sphere_pair& s = sphere_pair();
    const Wavy_pair& w = wavy_pair();
    struct Case {
        const Object* a;
        const Object* b;
        Rigid_transform_3<double> pose;
    };
    const std::vector<Case> cases{
        {&s.a, &s.b, shifted(0.0)}, {&s.a, &s.b, shifted(1.97)}, {&s.a, &s.b, shifted(2.1)}, {&w.flat, &w.wavy, {}}};
    for (std::size_t c = 0; c < cases.size(); ++c) {
        for (const bool first_hit : {true, false}) {
            for (const PCCD::Overlap_region region : {PCCD::Overlap_region::leaf_boxes, PCCD::Overlap_region::object_boxes}) {
                // The caps of the policies' own searches; the certification pass of a "separate"
                // (certify_separation) is intersection_points()' search, bounded below.
                const PCCD::Intersection_options options{.seed = c, .region = region, .refinement = PCCD::Refinement::none,
                                                         .certify_separation = false};
                const auto query = [&](const auto& policy) {
                    return first_hit ? PCCD::do_intersect(*cases[c].a, {}, *cases[c].b, cases[c].pose, options, policy)
                                     : PCCD::intersection_points(*cases[c].a, {}, *cases[c].b, cases[c].pose, options, policy);
                };
                for (const auto& [min, max] : std::vector<std::pair<std::size_t, std::size_t>>{
                         {1, 1}, {10, 10}, {30, 63}, {200, 400}}) {
                    const auto r = query(PCCD::Interpolation_search{.min_samples = min, .max_samples = max});
                    INFO("case " << c << ", first hit " << first_hit << ", region " << int(region) << ", min "
                                 << min << ", max " << max << ", samples " << r.counters.samples);
                    // max_samples caps the first-hit query; intersection_points() takes the whole
                    // covering count, at most the region.
                    if (first_hit) CHECK(r.counters.samples <= 2 * max);
                    CHECK(r.counters.samples <= r.counters.candidate_points);
                    check_accounting(r, true);
                }
                for (const std::size_t n : {1u, 50u}) {
                    const auto r = query(PCCD::Interpolation_search{.samples = n});
                    INFO("case " << c << ", samples = " << n << ", drawn " << r.counters.samples);
                    CHECK(r.counters.samples <= 2 * n);
                }
                for (const std::size_t max : {1u, 100u, 2000u}) {
                    const auto r = query(PCCD::Randomized_sampling{.max_samples = max});
                    INFO("case " << c << ", RST max " << max << ", samples " << r.counters.samples);
                    CHECK(r.counters.samples <= max);
                    check_accounting(r, false);
                }
            }
        }
    }
}

TEST_CASE("Budget: max_f_evaluations = k is never exceeded", "[robustness][intersection]")
{
    const Sphere_pair& s = sphere_pair();
    const Wavy_pair& w = wavy_pair();
    const auto check = [](const PCCD::Intersection_result& r, std::size_t k) {
        INFO("budget " << k << ", evaluations " << r.counters.f_evaluations << ", status " << PCCD::to_string(r.status));
        CHECK(r.counters.f_evaluations <= k);
        if (r.status == PCCD::Intersection_status::undecided) CHECK_FALSE(r.intersects);
    };
    for (const std::size_t k : {1u, 2u, 3u, 7u, 25u, 160u, 1000u}) {
        for (const PCCD::Refinement refinement :
             {PCCD::Refinement::projection, PCCD::Refinement::sampling, PCCD::Refinement::none}) {
            const PCCD::Intersection_options options{.seed = k, .refinement = refinement, .max_f_evaluations = k};
            for (const double d : {0.5, 1.95, 2.05}) {
                INFO("spheres at " << d << ", refinement " << int(refinement));
                check(PCCD::do_intersect(s.a, {}, s.b, shifted(d), options), k);
                check(PCCD::intersection_points(s.a, {}, s.b, shifted(d), options), k);
                check(PCCD::do_intersect(s.a, {}, s.b, shifted(d), options, PCCD::Randomized_sampling{}), k);
                check(PCCD::intersection_points(s.a, {}, s.b, shifted(d), options, PCCD::Randomized_sampling{}), k);
            }
            INFO("wavy pair, refinement " << int(refinement));
            check(PCCD::do_intersect(w.flat, {}, w.wavy, {}, options), k);
            check(PCCD::intersection_points(w.flat, {}, w.wavy, {}, options), k);
            check(PCCD::intersection_points(w.flat, {}, w.wavy, {}, options, PCCD::Randomized_sampling{}), k);
        }
    }
    // Budgets that run out during the refinement, whose steps evaluate both surfaces: every budget
    // between the search's evaluations and the whole query's.
    for (const PCCD::Refinement refinement : {PCCD::Refinement::projection, PCCD::Refinement::sampling}) {
        const PCCD::Intersection_options options{.seed = 8, .refinement = refinement};
        const auto full = PCCD::intersection_points(s.a, {}, s.b, shifted(1.2), options);
        const std::size_t total = full.counters.f_evaluations;
        REQUIRE(full.counters.refinement_samples > 0);
        const std::size_t search = total - std::min(total, 2 * full.counters.refinement_samples);
        for (std::size_t k = search + 1; k <= std::min(total, search + 16); ++k) {
            PCCD::Intersection_options limited = options;
            limited.max_f_evaluations = k;
            check(PCCD::intersection_points(s.a, {}, s.b, shifted(1.2), limited), k);
        }
    }
}

TEST_CASE("Hierarchy traversal on degenerate boxes: flat, collinear and coincident points",
          "[robustness][hierarchy]")
{
    using Index = PCCD::Point_cloud_hierarchy::Index;
    std::vector<std::pair<std::string, Eigen::Matrix3Xd>> clouds;
    {
        Eigen::Matrix3Xd flat(3, 900), line(3, 500), oblique(3, 500), same(3, 200), mostly_same(3, 200);
        for (int i = 0; i < 900; ++i) flat.col(i) = Eigen::Vector3d(0.05 * (i % 30), 0.05 * (i / 30), 0.0);
        for (int i = 0; i < 500; ++i) {
            line.col(i) = Eigen::Vector3d(0.01 * i, 0.0, 0.0);
            oblique.col(i) = 0.01 * i * Eigen::Vector3d(1.0, 2.0, -0.5);
        }
        same.colwise() = Eigen::Vector3d(0.3, 0.3, 0.0);
        for (int i = 0; i < 200; ++i)
            mostly_same.col(i) = i % 4 ? Eigen::Vector3d(0.2, 0.2, 0.0) : Eigen::Vector3d(0.01 * i, 0.2, 0.0);
        clouds = {{"flat", flat}, {"line", line}, {"oblique line", oblique}, {"identical", same}, {"mostly identical", mostly_same}};
    }
    for (const auto& [name_a, pa] : clouds) {
        for (const auto& [name_b, pb] : clouds) {
            for (const std::size_t leaf : {1u, 16u}) {
                const PCCD::Point_cloud_hierarchy a(pa, {.leaf_size = leaf}), b(pb, {.leaf_size = leaf});
                std::size_t leaves_a = 0, leaves_b = 0;
                for (const auto& n : a.nodes()) leaves_a += n.is_leaf();
                for (const auto& n : b.nodes()) leaves_b += n.is_leaf();
                for (const auto& pose : {Rigid_transform_3<double>(), turned(0.5, Eigen::Vector3d(0.1, 0.0, 0.0))}) {
                    for (const double margin : {0.0, 0.02}) {
                        std::set<std::pair<Index, Index>> pairs;
                        const auto c = PCCD::for_each_overlapping_leaf_pair(a, b, pose, margin, [&](Index i, Index j) {
                            CHECK(pairs.emplace(i, j).second); // each pair once
                        });
                        INFO(name_a << " / " << name_b << ", leaf size " << leaf << ", margin " << margin);
                        CHECK(c.node_pairs <= a.nodes().size() * b.nodes().size());
                        CHECK(c.leaf_pairs <= leaves_a * leaves_b);
                        CHECK(c.leaf_pairs == pairs.size());
                    }
                }
            }
        }
    }

    // The queries over flat and collinear objects (the object rejects coincident points) terminate
    // within the same traversal bound: one per role, plus the root test of each role's sampler.
    const Sphere_pair& s = sphere_pair();
    std::vector<Eigen::Vector3d> flat_points, line_points;
    for (int i = 0; i < 900; ++i) flat_points.emplace_back(-0.75 + 0.05 * (i % 30), -0.75 + 0.05 * (i / 30), 0.0);
    for (int i = 0; i < 300; ++i) line_points.emplace_back(-1.5 + 0.01 * i, 0.0, 0.0);
    const Object flat(flat_points), line(line_points);
    for (const Object* o : {&flat, &line}) {
        for (const Object* other : {&s.a, &flat, &line}) {
            const std::size_t bound = 2 * (o->hierarchy().nodes().size() * other->hierarchy().nodes().size() + 1);
            for (const double z : {0.0, 3.0}) {
                const PCCD::Intersection_options options{.seed = 1};
                const auto isearch = PCCD::intersection_points(*o, {}, *other, shifted(0.0, 0.0, z), options);
                const auto rst = PCCD::intersection_points(*o, {}, *other, shifted(0.0, 0.0, z), options,
                                                           PCCD::Randomized_sampling{.max_samples = 500});
                INFO("objects of " << o->size() << " and " << other->size() << " points, shift " << z);
                CHECK(isearch.counters.node_pairs <= bound);
                CHECK(rst.counters.node_pairs <= bound);
                check_accounting(isearch, true);
                check_accounting(rst, false);
            }
        }
    }
}

TEST_CASE("Kinetic tree: flightplans crossing at the same instant", "[robustness][kinetic]")
{
    using Tree = PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan, PCCD::Kinetic_point>;
    // Every vertex passes through the origin at t = 1: p_i(t) = v_i (t - 1). Velocities from a set of
    // 5 values per axis (many identical trajectories, exact ties before and after t = 1) or random.
    for (const bool discrete : {true, false}) {
        PCCD::Random_engine engine(discrete ? 1 : 2);
        std::vector<PCCD::Linear_flightplan> plans;
        std::vector<PCCD::Kinetic_point> points;
        for (std::uint32_t i = 0; i < 600; ++i) {
            Eigen::Vector3d v;
            for (int a = 0; a < 3; ++a)
                v[a] = discrete ? double(PCCD::uniform_index(engine, 5)) - 2.0 : PCCD::uniform_real(engine, -1, 1);
            plans.emplace_back(Eigen::Vector3d::Zero(), v, 1.0);
            points.push_back({i});
        }
        Tree tree(plans, points, 0.0);
        const std::uint64_t bound = envelope_bound(tree);
        for (const double t : {0.5, 1.0, std::nextafter(1.0, 2.0), 1.0 + 1e-9, 2.0, 1e6}) {
            tree.advance_to(t);
            INFO((discrete ? "discrete" : "random") << " velocities, t = " << t << ", events "
                                                    << tree.statistics().events << ", bound " << bound);
            check_kinetic_tree(tree);
            CHECK(tree.statistics().events <= bound);
        }
        // Stepping through the instant in many small calls does the same work as one call.
        Tree stepped(plans, points, 0.0);
        for (int k = 0; k <= 400; ++k) stepped.advance_to(0.9 + 0.0005 * k);
        stepped.advance_to(1e6);
        check_kinetic_tree(stepped);
        CHECK(stepped.statistics().events == tree.statistics().events);
    }
    // All vertices on one trajectory: always tied, never an event.
    std::vector<PCCD::Linear_flightplan> same(300, PCCD::Linear_flightplan(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-1, 0, 2)));
    std::vector<PCCD::Kinetic_point> points;
    for (std::uint32_t i = 0; i < 300; ++i) points.push_back({i});
    Tree tied(same, points, 0.0);
    tied.advance_to(100.0);
    check_kinetic_tree(tied);
    CHECK(tied.statistics().events == 0);
    // Triangles whose three vertices cross each other and their neighbours at t = 1.
    using Triangle_tree = PCCD::Kinetic_AABB_tree<PCCD::Linear_flightplan, PCCD::Kinetic_triangle>;
    std::vector<PCCD::Linear_flightplan> plans;
    std::vector<PCCD::Kinetic_triangle> triangles;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const double k = double(i % 3) - 1.0;
        plans.emplace_back(Eigen::Vector3d(0.0, 0.0, double(i / 30)), Eigen::Vector3d(k, -k, 0.0), 1.0);
    }
    for (std::uint32_t i = 0; i + 2 < 300; i += 3) triangles.push_back({{i, i + 1, i + 2}});
    Triangle_tree soup(plans, triangles, 0.0);
    for (const double t : {1.0, std::nextafter(1.0, 2.0), 5.0}) {
        soup.advance_to(t);
        const Eigen::AlignedBox3d root = soup.box(soup.root());
        Eigen::AlignedBox3d truth;
        for (std::uint32_t v = 0; v < plans.size(); ++v) truth.extend(plans[v].position(t));
        CHECK(root.min() == truth.min());
        CHECK(root.max() == truth.max());
    }
}

TEST_CASE("CPSP bounded Dijkstra: each list holds at most the points within the bound", "[robustness][graph]")
{
    using pccd_test::Coordinates;
    std::vector<std::pair<std::string, Coordinates>> clouds;
    clouds.emplace_back("clustered with duplicates", pccd_test::clustered_with_duplicates(600, 7));
    clouds.emplace_back("sphere", pccd_test::sphere_sample(500, 8));
    Coordinates line(3, 300), grid(3, 400), pile(3, 200);
    for (int i = 0; i < 300; ++i) line.col(i) = Eigen::Vector3d(0.01 * i, 0.0, 0.0);
    for (int i = 0; i < 400; ++i) grid.col(i) = Eigen::Vector3d(0.01 * (i % 20), 0.01 * (i / 20), 0.0);
    for (int i = 0; i < 200; ++i) pile.col(i) = i % 2 ? Eigen::Vector3d(0.5, 0.5, 0.5) : Eigen::Vector3d(0.002 * i, 0.0, 0.0);
    clouds.emplace_back("line (equal edge lengths)", line);
    clouds.emplace_back("grid (exact ties)", grid);
    clouds.emplace_back("half the points identical", pile);
    for (const auto& [name, coordinates] : clouds) {
        const pccd_test::Cloud cloud(coordinates);
        const PCCD::Proximity_graph graph = PCCD::sphere_of_influence_graph(cloud, {.r = 3});
        for (const double radius : {0.01, 0.03, 0.1}) {
            const PCCD::Close_pairs_shortest_paths map(graph, radius);
            const double bound = map.bound();
            const std::size_t n = cloud.size();
            for (std::uint32_t p = 0; p < n; ++p) {
                std::size_t within = 0; // brute force: Euclidean <= geodesic, so the list is a subset
                for (std::size_t q = 0; q < n; ++q)
                    within += pccd_test::distance(coordinates, p, q) <= bound * (1.0 + 1e-6);
                const auto targets = map.targets(p);
                INFO(name << ", radius " << radius << ", point " << p);
                REQUIRE(targets.size() <= within);
                CHECK(std::set<std::uint32_t>(targets.begin(), targets.end()).size() == targets.size());
                CHECK(map.distances(p).back() <= float(bound) * (1.0f + 1e-6f));
            }
        }
    }
}
