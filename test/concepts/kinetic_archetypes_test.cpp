// Archetypes of the kinetic concepts (concepts/Flightplan.h, concepts/KineticPrimitive.h): a
// flightplan and a primitive that model exactly what the concepts state, with which both kinetic
// trees are instantiated (every member function by explicit instantiation, the query templates by
// calls), and near-miss types, each lacking one requirement, that the concepts reject. The
// archetype flightplan wraps a Linear_flightplan and the archetype primitive is a segment (two
// vertices, a primitive PCCD does not ship), so the trees also run on them: their overlap queries
// are checked against a brute-force test of every pair of segment boxes.
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Kinetic_primitives.h>
#include <PCCD/Kinetic/Linear_flightplan.h>
#include <PCCD/Kinetic/Refit_AABB_tree.h>
#include <PCCD/Random.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/KineticPrimitive.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace archetype {

/// Exactly what Flightplan requires: copyable (not default constructible), position(),
/// coordinate() and next_crossing() against its own type.
class Flightplan {
public:
    explicit Flightplan(const PCCD::Linear_flightplan& f) : m_f(f) {}
    Eigen::Vector3d position(double t) const { return m_f.position(t); }
    double coordinate(int axis, double t) const { return m_f.coordinate(axis, t); }
    double next_crossing(const Flightplan& b, int axis, double t) const { return m_f.next_crossing(b.m_f, axis, t); }

private:
    PCCD::Linear_flightplan m_f;
};

// Near-misses of Flightplan, each lacking one requirement.
struct Plan_without_coordinate {
    Eigen::Vector3d position(double) const;
    double next_crossing(const Plan_without_coordinate&, int, double) const;
};
struct Plan_with_float_crossing { // next_crossing() in float: crossing times would be rounded
    Eigen::Vector3d position(double) const;
    double coordinate(int, double) const;
    float next_crossing(const Plan_with_float_crossing&, int, double) const;
};
struct Plan_with_proxy_position { // position() gives a type merely convertible to a vector
    struct Position {
        operator Eigen::Vector3d() const;
    };
    Position position(double) const;
    double coordinate(int, double) const;
    double next_crossing(const Plan_with_proxy_position&, int, double) const;
};
struct Unassignable_plan { // set_flightplan() replaces a flightplan in place
    Unassignable_plan(const Unassignable_plan&) = default;
    Unassignable_plan& operator=(const Unassignable_plan&) = delete;
    Eigen::Vector3d position(double) const;
    double coordinate(int, double) const;
    double next_crossing(const Unassignable_plan&, int, double) const;
};
struct Move_only_plan { // the trees copy flightplans
    std::unique_ptr<int> state;
    Eigen::Vector3d position(double) const;
    double coordinate(int, double) const;
    double next_crossing(const Move_only_plan&, int, double) const;
};

/// A vertex index that is not an integer, only convertible to one.
struct Vertex_id {
    std::uint32_t value;
    operator std::uint32_t() const { return value; }
};

/// Exactly what KineticPrimitive requires: a segment of two vertices (copyable, default
/// constructible, vertex_count, vertex(i)); no comparison operators.
struct Segment {
    static constexpr std::size_t vertex_count = 2;
    std::uint32_t ends[2] = {0, 0};
    Vertex_id vertex(std::size_t i) const { return {ends[i]}; }
};

// Near-misses of KineticPrimitive, each lacking one requirement.
struct Primitive_without_vertices { // vertex_count 0
    static constexpr std::size_t vertex_count = 0;
    std::uint32_t vertex(std::size_t) const;
};
struct Primitive_without_count {
    std::uint32_t vertex(std::size_t) const;
};
struct Primitive_with_named_vertices { // vertex() gives no index
    static constexpr std::size_t vertex_count = 1;
    std::string vertex(std::size_t) const;
};
struct Primitive_without_default { // the trees keep free slots of primitives
    explicit Primitive_without_default(std::uint32_t);
    static constexpr std::size_t vertex_count = 1;
    std::uint32_t vertex(std::size_t) const;
};

} // namespace archetype

static_assert(PCCD::Flightplan<archetype::Flightplan>);
static_assert(PCCD::Flightplan<PCCD::Linear_flightplan>);
static_assert(!PCCD::Flightplan<archetype::Plan_without_coordinate>);
static_assert(!PCCD::Flightplan<archetype::Plan_with_float_crossing>);
static_assert(!PCCD::Flightplan<archetype::Plan_with_proxy_position>);
static_assert(!PCCD::Flightplan<archetype::Unassignable_plan>);
static_assert(!PCCD::Flightplan<archetype::Move_only_plan>);
static_assert(PCCD::KineticPrimitive<archetype::Segment>);
static_assert(PCCD::KineticPrimitive<PCCD::Kinetic_point>);
static_assert(PCCD::KineticPrimitive<PCCD::Kinetic_triangle>);
static_assert(!PCCD::KineticPrimitive<archetype::Primitive_without_vertices>);
static_assert(!PCCD::KineticPrimitive<archetype::Primitive_without_count>);
static_assert(!PCCD::KineticPrimitive<archetype::Primitive_with_named_vertices>);
static_assert(!PCCD::KineticPrimitive<archetype::Primitive_without_default>);

// Every member function of both trees, instantiated with the archetypes (the ray queries are
// constrained to triangles and drop out).
template class PCCD::Kinetic_AABB_tree<archetype::Flightplan, archetype::Segment>;
template class PCCD::Refit_AABB_tree<archetype::Flightplan, archetype::Segment>;

namespace {

using Kinetic_tree = PCCD::Kinetic_AABB_tree<archetype::Flightplan, archetype::Segment>;
using Refit_tree = PCCD::Refit_AABB_tree<archetype::Flightplan, archetype::Segment>;
using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

struct Scene {
    std::vector<PCCD::Linear_flightplan> motions;
    std::vector<archetype::Segment> segments;
};

/// n vertices in the unit cube moving at random velocities, joined into n / 2 disjoint segments
/// plus n / 2 - 1 segments bridging consecutive ones (so some segments share a vertex).
Scene random_scene(std::size_t n, std::uint64_t seed)
{
    PCCD::Random_engine rng(seed);
    Scene scene;
    for (std::size_t v = 0; v < n; ++v) {
        Eigen::Vector3d p, w;
        for (int k = 0; k < 3; ++k) p[k] = PCCD::uniform_real(rng, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) w[k] = PCCD::uniform_real(rng, -0.5, 0.5);
        scene.motions.emplace_back(p, w);
    }
    for (std::uint32_t v = 0; v + 1 < n; ++v) scene.segments.push_back({{v, v + 1}});
    return scene;
}

std::vector<archetype::Flightplan> archetype_plans(const Scene& scene)
{
    std::vector<archetype::Flightplan> plans;
    for (const auto& m : scene.motions) plans.emplace_back(m);
    return plans;
}

Eigen::AlignedBox3d segment_box(const Scene& scene, const archetype::Segment& s, double t)
{
    Eigen::AlignedBox3d box(scene.motions[s.ends[0]].position(t));
    box.extend(scene.motions[s.ends[1]].position(t));
    return box;
}

bool adjacent(const archetype::Segment& a, const archetype::Segment& b)
{
    for (const std::uint32_t x : a.ends)
        for (const std::uint32_t y : b.ends)
            if (x == y) return true;
    return false;
}

/// The oracle: every pair of non-adjacent segments whose boxes at time t overlap, by brute force.
Pairs brute_force_pairs(const Scene& scene, double t)
{
    Pairs pairs;
    for (std::uint32_t i = 0; i < scene.segments.size(); ++i)
        for (std::uint32_t j = i + 1; j < scene.segments.size(); ++j)
            if (!adjacent(scene.segments[i], scene.segments[j]) &&
                segment_box(scene, scene.segments[i], t).intersects(segment_box(scene, scene.segments[j], t)))
                pairs.emplace_back(i, j);
    return pairs;
}

Pairs normalized(Pairs pairs)
{
    for (auto& [a, b] : pairs)
        if (a > b) std::swap(a, b);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

} // namespace

TEST_CASE("both kinetic trees run on flightplan and primitive archetypes", "[concepts][kinetic]")
{
    const Scene scene = random_scene(120, 31);
    Kinetic_tree kinetic(archetype_plans(scene), scene.segments);
    Refit_tree refit(archetype_plans(scene), scene.segments);
    std::size_t total = 0;
    for (const double t : {0.0, 0.25, 0.5, 1.0, 2.0}) {
        INFO("t = " << t);
        kinetic.advance_to(t);
        refit.advance_to(t);
        const Pairs expected = brute_force_pairs(scene, t);
        total += expected.size();
        Pairs found;
        kinetic.self_overlapping_pairs(found);
        CHECK(normalized(found) == expected);
        found.clear();
        refit.self_overlapping_pairs(found);
        CHECK(normalized(found) == expected);
        // The kinetic tree against the refitted one: every overlapping pair, adjacent or not, and
        // each segment with itself.
        found.clear();
        kinetic.overlapping_pairs(refit, found);
        std::size_t self_pairs = 0, adjacent_pairs = 0;
        for (const auto& [a, b] : found) {
            self_pairs += a == b;
            adjacent_pairs += a != b && adjacent(scene.segments[a], scene.segments[b]);
        }
        CHECK(self_pairs == scene.segments.size());
        CHECK(found.size() == self_pairs + adjacent_pairs + 2 * expected.size());
    }
    CHECK(total > 50); // the scene does overlap
    CHECK(kinetic.statistics().events > 0);
}

TEST_CASE("the kinetic trees' edits work on the archetypes", "[concepts][kinetic]")
{
    Scene scene = random_scene(40, 32);
    Kinetic_tree kinetic(archetype_plans(scene), scene.segments);
    Refit_tree refit(archetype_plans(scene), scene.segments);
    // Replace a motion, add a vertex and a segment to it, remove a segment: the trees answer as the
    // brute force does on the edited scene.
    const PCCD::Linear_flightplan still(Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d::Zero());
    scene.motions[7] = still;
    kinetic.set_flightplan(7, archetype::Flightplan(still));
    refit.set_flightplan(7, archetype::Flightplan(still));
    const PCCD::Linear_flightplan added(Eigen::Vector3d(0.1, 0.9, 0.5), Eigen::Vector3d(0.2, -0.2, 0.0));
    scene.motions.push_back(added);
    const std::uint32_t v = kinetic.add_vertex(archetype::Flightplan(added));
    CHECK(refit.add_vertex(archetype::Flightplan(added)) == v);
    const archetype::Segment bridge{{3, v}};
    scene.segments.push_back(bridge);
    const std::uint32_t s = kinetic.insert(bridge);
    CHECK(refit.insert(bridge) == s);
    kinetic.remove(20);
    refit.remove(20);
    for (const double t : {0.3, 1.5}) {
        kinetic.advance_to(t);
        refit.advance_to(t);
        Pairs expected;
        for (const auto& [a, b] : brute_force_pairs(scene, t))
            if (a != 20 && b != 20) expected.emplace_back(a, b);
        Pairs found;
        kinetic.self_overlapping_pairs(found);
        CHECK(normalized(found) == expected);
        found.clear();
        refit.self_overlapping_pairs(found);
        CHECK(normalized(found) == expected);
    }
}
