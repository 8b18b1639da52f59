// Bad-input catalogue, clouds (doc/reliability.md): degenerate, non-finite, extreme and
// disconnected point clouds given to Point_cloud, the proximity graphs and Point_cloud_object. Each
// case asserts the exact outcome: Invalid_input naming the problem, or a documented finite answer.
#include "robustness_helpers.h"

#include <PCCD/Point_cloud.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace pccd_robustness;

namespace {

using Object = PCCD::Point_cloud_object<>;
using Cloud = PCCD::Point_cloud<>;

/// Both graph builders accept the cloud: one vertex per point, finite non-negative edge lengths.
void require_graphs_build(const Cloud& cloud)
{
    for (const auto& graph : {PCCD::sphere_of_influence_graph(cloud), PCCD::knn_graph(cloud)}) {
        CHECK(graph.num_vertices() == cloud.size());
        for (std::uint64_t e = 0; e < graph.targets().size(); ++e) {
            const float length = graph.edge_property(e).length;
            CHECK((std::isfinite(length) && length >= 0.f));
        }
    }
}

/// The scalar state of a built object is finite and positive; every stored normal is a unit
/// vector or zero (undetermined), never NaN.
/// For each point given, its index in the object (which stores its points in spatial order);
/// object.size() for an outlier left out.
std::vector<std::size_t> object_index_of(const Object& object)
{
    std::vector<std::size_t> index(object.scan().input_points, object.size());
    for (std::size_t i = 0; i < object.size(); ++i) index[object.input_index(i)] = i;
    return index;
}

void require_finite_state(const Object& object)
{
    CHECK(std::isfinite(object.sampling_radius()));
    CHECK(object.sampling_radius() > 0.0);
    CHECK(std::isfinite(object.bandwidth()));
    CHECK(object.bandwidth() > 0.0);
    CHECK(std::isfinite(object.weight().support_radius()));
    std::size_t zero = 0;
    for (Eigen::Index i = 0; i < object.normals().cols(); ++i) {
        const Eigen::Vector3d n = object.normals().col(i);
        REQUIRE(std::isfinite(n.x()));
        REQUIRE(std::isfinite(n.y()));
        REQUIRE(std::isfinite(n.z()));
        if (n.isZero(0.0))
            ++zero;
        else
            CHECK(n.norm() == Approx(1.0).epsilon(1e-12));
    }
    CHECK(object.orientation().unoriented == zero);
}

/// An evaluation says what it found: defined with finite fields, or undefined with NaN fields
/// (Surface_evaluation's documented convention), never a NaN behind a "defined" status.
void require_consistent(const PCCD::Surface_evaluation& e)
{
    if (e.defined()) {
        CHECK(std::isfinite(e.value));
        CHECK(e.normal.allFinite());
        CHECK(e.centroid.allFinite());
    } else {
        CHECK(std::isnan(e.value));
    }
}

} // namespace

TEST_CASE("clouds: empty, one, two and three points", "[robustness]")
{
    SECTION("empty")
    {
        require_invalid_input([] { Cloud cloud(Points{}); }, {"point cloud is empty"});
        require_invalid_input([] { Cloud cloud(Cloud::Coordinates(3, 0)); }, {"point cloud is empty"});
        require_invalid_input([] { Object object(Points{}); }, {"point cloud is empty"});
    }
    SECTION("one point: a valid cloud, but no spacing and no surface")
    {
        const Cloud cloud(Points{{1, 2, 3}});
        CHECK(cloud.size() == 1);
        CHECK(cloud.nearest(Eigen::Vector3d(5, 5, 5)).index == 0);
        require_invalid_input([&] { (void)cloud.mean_spacing(); }, {"at least two points"});
        require_graphs_build(cloud);
        CHECK(PCCD::sphere_of_influence_graph(cloud).num_edges() == 0);
        require_invalid_input([] { Object object(Points{{1, 2, 3}}); }, {"at least two points", "has one"});
    }
    SECTION("two points: the object builds, no normal is determined, evaluations say degenerate")
    {
        const Points points = {{0, 0, 0}, {1, 0, 0}};
        require_graphs_build(Cloud(points));
        const Object object(points);
        require_finite_state(object);
        CHECK(object.graph().num_edges() == 1);
        CHECK(object.orientation().unoriented == 2);
        CHECK(object.orientation().components == 0);
        const auto e = object.surface().evaluate(points[0]);
        CHECK(e.status == PCCD::Surface_status::degenerate);
        require_consistent(e);
    }
    SECTION("three points: the object builds and its surface is their plane")
    {
        const Points points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        const Object object(points);
        require_finite_state(object);
        CHECK(object.orientation().unoriented == 0);
        CHECK(object.orientation().components == 1);
        for (const Eigen::Vector3d& p : points) {
            const auto e = object.surface().evaluate(p);
            REQUIRE(e.defined());
            CHECK(std::abs(e.value) < 1e-12);
            CHECK(std::abs(e.normal.z()) == Approx(1.0));
        }
        const auto above = object.euclidean_surface().evaluate(Eigen::Vector3d(0.3, 0.3, 0.1));
        REQUIRE(above.defined());
        CHECK(std::abs(above.value) == Approx(0.1));
    }
}

TEST_CASE("clouds: identical, collinear and coplanar points", "[robustness]")
{
    SECTION("all points identical: graphs build, the object is rejected (sampling radius 0)")
    {
        const Points points(50, Eigen::Vector3d(1, 1, 1));
        const Cloud cloud(points);
        CHECK(cloud.mean_spacing() == 0.0);
        require_graphs_build(cloud);
        // Every copy hangs on its representative by one zero-length edge.
        CHECK(PCCD::sphere_of_influence_graph(cloud).num_edges() == 49);
        require_invalid_input([&] { Object object(points); }, {"sampling radius is 0", "must be finite and > 0"});
    }
    SECTION("collinear points: the object builds, every normal is undetermined")
    {
        for (const Eigen::Vector3d& direction : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 2, -1)}) {
            Points points;
            for (int i = 0; i < 50; ++i) points.push_back(0.1 * i * direction);
            require_graphs_build(Cloud(points));
            const Object object(points);
            require_finite_state(object);
            CHECK(object.orientation().unoriented == 50);
            CHECK(object.orientation().components == 0);
            for (const auto* surface_point : {&points[0], &points[25]}) {
                const auto e = object.surface().evaluate(*surface_point);
                CHECK(e.status == PCCD::Surface_status::degenerate);
                require_consistent(e);
            }
        }
    }
    SECTION("a flat grid (coplanar points): the object builds, one consistently oriented plane")
    {
        const Points points = flat_grid(20, 0.05);
        const Object object(points);
        require_finite_state(object);
        CHECK(object.orientation().unoriented == 0);
        CHECK(object.orientation().components == 1);
        const double sign = object.normals()(2, 0) > 0 ? 1.0 : -1.0;
        for (Eigen::Index i = 0; i < object.normals().cols(); ++i) CHECK(sign * object.normals()(2, i) == Approx(1.0));
        const Eigen::Vector3d inside(0.5, 0.5, 0.0);
        for (double height : {-0.02, 0.0, 0.02}) {
            const auto e = object.surface().evaluate(inside + Eigen::Vector3d(0, 0, height));
            REQUIRE(e.defined());
            CHECK(e.value == Approx(sign * height).margin(1e-12));
        }
    }
}

TEST_CASE("clouds: NaN and infinite coordinates are named by point index", "[robustness]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const double bad : {nan, inf, -inf})
        for (int coordinate = 0; coordinate < 3; ++coordinate)
            for (const std::size_t index : {std::size_t(0), std::size_t(17), std::size_t(199)}) {
                Points points = fibonacci_sphere(200);
                points[index][coordinate] = bad;
                INFO("point " << index << ", coordinate " << coordinate << " = " << bad);
                const std::string named = "point " + std::to_string(index) + " has a non-finite coordinate";
                require_invalid_input([&] { Cloud cloud(points); }, {named});
                require_invalid_input([&] { PCCD::Point_cloud<PCCD::Eigen_kernel<float>> cloud(points); }, {named});
                require_invalid_input([&] { Object object(points); }, {named});
            }
    // The first bad point is the one named.
    Points points = fibonacci_sphere(20);
    points[12].x() = inf;
    points[5].z() = nan;
    require_invalid_input([&] { Cloud cloud(points); }, {"point 5 "});
}

TEST_CASE("clouds: coordinates near 1e30, near 1e-30 and far from the origin", "[robustness]")
{
    // The whole pipeline is scale-invariant in this range: r(P), h, the orientation and f scale
    // with the cloud, and everything stays finite.
    const Points unit = fibonacci_sphere(400);
    const Object reference(unit);
    const Eigen::Vector3d probe = 1.05 * unit[7];
    const double f_reference = *reference.surface().value(probe);
    for (const double scale : {1e30, 1e-30, 1e35, 1e-35}) {
        INFO("scale " << scale);
        Points scaled;
        for (const auto& p : unit) scaled.push_back(scale * p);
        const Object object(scaled);
        require_finite_state(object);
        CHECK(object.sampling_radius() / scale == Approx(reference.sampling_radius()).epsilon(1e-6));
        CHECK(object.bandwidth() / scale == Approx(reference.bandwidth()).epsilon(1e-6));
        CHECK(object.orientation().components == reference.orientation().components);
        CHECK(object.orientation().unoriented == 0);
        const auto e = object.surface().evaluate(scale * probe);
        REQUIRE(e.defined());
        CHECK(e.value / scale == Approx(f_reference).epsilon(1e-6));
        require_consistent(object.euclidean_surface().evaluate(scale * probe));
    }
    // A unit sphere 1e8 away from the origin: same radius, same surface (offsets are taken about
    // the query, so no digits are lost to the translation).
    const Eigen::Vector3d far(1e8, -1e8, 1e8);
    Points moved;
    for (const auto& p : unit) moved.push_back(p + far);
    const Object object(moved);
    require_finite_state(object);
    CHECK(object.sampling_radius() == Approx(reference.sampling_radius()).epsilon(1e-6));
    const auto e = object.surface().evaluate(probe + far);
    REQUIRE(e.defined());
    CHECK(e.value == Approx(f_reference).epsilon(1e-5));
}

TEST_CASE("clouds: far-apart pieces, isolated points and duplicated points", "[robustness]")
{
    SECTION("three spheres far apart: one component and one orientation tree each, all outward")
    {
        const std::vector<Eigen::Vector3d> centres = {{0, 0, 0}, {100, 0, 0}, {0, 1000, 0}};
        Points points;
        for (const auto& c : centres) {
            const Points piece = fibonacci_sphere(300, 1.0, c);
            points.insert(points.end(), piece.begin(), piece.end());
        }
        const Object object(points);
        require_finite_state(object);
        CHECK(PCCD::graph_components(object.graph()).count == 3);
        CHECK(object.orientation().components == 3);
        CHECK(object.orientation().unoriented == 0);
        for (std::size_t i = 0; i < object.size(); ++i) {
            const std::size_t given = object.input_index(i);
            CHECK(object.normals().col(Eigen::Index(i)).dot(points[given] - centres[given / 300]) > 0.0);
        }
        // Between the pieces the surface is undefined, and says so.
        const auto gap = object.surface().evaluate(Eigen::Vector3d(50, 0, 0));
        CHECK(gap.status == PCCD::Surface_status::outside_support);
        require_consistent(gap);
    }
    SECTION("an isolated outlier: removed by default; kept, it alone is unoriented")
    {
        Points points = fibonacci_sphere(300);
        points.push_back({50, 50, 50});
        const Object object(points);
        require_finite_state(object);
        CHECK(object.scan().outliers == std::vector<std::uint32_t>{300});
        CHECK(object.scan().input_points == 301);
        CHECK(object.size() == 300);
        CHECK(object.orientation().unoriented == 0);
        const Object kept(points, PCCD::Identity_point_map<Eigen::Vector3d>(), {.outliers = {.remove = false}});
        require_finite_state(kept);
        CHECK(kept.scan().outliers.empty());
        CHECK(kept.orientation().unoriented == 1);
        CHECK(kept.normals().col(Eigen::Index(object_index_of(kept)[300])).isZero(0.0));
        CHECK(kept.orientation().components == 1);
    }
    SECTION("every point duplicated: copies share their normal and their surface value")
    {
        Points points = fibonacci_sphere(300);
        const Points copy = points;
        points.insert(points.end(), copy.begin(), copy.end());
        require_graphs_build(Cloud(points));
        const Object object(points);
        require_finite_state(object);
        CHECK(object.orientation().components == 1);
        CHECK(object.orientation().unoriented == 0);
        const std::vector<std::size_t> at = object_index_of(object);
        for (std::size_t i = 0; i < 300; ++i) {
            const auto a = Eigen::Index(at[i]), b = Eigen::Index(at[i + 300]);
            CHECK(object.normals().col(a).isApprox(object.normals().col(b)));
            CHECK(object.normals().col(a).dot(copy[i]) > 0.0);
        }
        const auto e = object.surface().evaluate_at(std::uint32_t(at[0])), f = object.surface().evaluate_at(std::uint32_t(at[300]));
        REQUIRE(e.defined());
        REQUIRE(f.defined());
        CHECK(e.value == Approx(f.value).margin(1e-12));
    }
    SECTION("one point repeated many times inside a cloud")
    {
        Points points = flat_grid(12, 0.1);
        for (int k = 0; k < 40; ++k) points.push_back(points[30]);
        const Object object(points);
        require_finite_state(object);
        CHECK(object.orientation().components == 1);
        const std::vector<std::size_t> at = object_index_of(object);
        for (std::size_t i = 144; i < points.size(); ++i)
            CHECK(object.normals().col(Eigen::Index(at[i])).isApprox(object.normals().col(Eigen::Index(at[30]))));
    }
}

// --- Former known bugs -----------------------------------------------------------------------------
// Found by this catalogue (doc/reliability.md); each died of SIGFPE in the Debug test build and gave
// a wrong or misleading answer in Release. Fixed in Point_cloud (magnitude and narrowing checks),
// the graph construction (extent check) and Kd_tree (query check).

TEST_CASE("coordinates near 1e150: graph edge lengths would overflow float", "[robustness]")
{
    // Was: float(length) overflowed (a trap in Debug); in Release every length was +inf and no
    // normal was determined.
    Points points;
    for (const auto& p : fibonacci_sphere(300)) points.push_back(1e150 * p);
    require_invalid_input([&] { Object object(points); }, {"extent", "float", "rescale"});
    // The cloud itself (kd-tree, squared distances in double) is still fine at this scale.
    CHECK(Cloud(points).size() == 300);
}

TEST_CASE("coordinates near 1e300: squared distances would overflow double", "[robustness]")
{
    // Was: the kd-tree's squared distances overflowed (a trap in Debug); in Release the object was
    // rejected with the misleading message "the sampling radius is 0".
    Points points;
    for (const auto& p : fibonacci_sphere(300)) points.push_back(1e300 * p);
    require_invalid_input([&] { Object object(points); }, {"coordinate", "magnitude"});
    require_invalid_input([&] { Cloud cloud(points); }, {"coordinate", "magnitude"});
    // Just inside the limit is accepted.
    const double limit = Cloud::max_coordinate_magnitude();
    CHECK(Cloud(Points{{0, 0, 0}, {limit, -limit, limit}}).size() == 2);
    require_invalid_input([&] { Cloud cloud(Points{{0, 0, 0}, {std::nextafter(limit, 2 * limit), 0, 0}}); },
                          {"point 1", "magnitude"});
}

TEST_CASE("a float cloud from doubles beyond FLT_MAX is rejected by point", "[robustness]")
{
    // Was: static_cast<float>(1e39) trapped in Debug; in Release the message called the point non-finite.
    require_invalid_input([] { PCCD::Point_cloud<PCCD::Eigen_kernel<float>> cloud(Points{{0, 0, 0}, {1e39, 0, 0}}); },
                          {"point 1", "float"});
}

TEST_CASE("a float object near 1e30 is rejected with the reason", "[robustness]")
{
    // Was: squared distances overflowed float in the kd-tree (a trap in Debug); in Release: "the
    // sampling radius is 0".
    Points points;
    for (const auto& p : fibonacci_sphere(300)) points.push_back(1e30 * p);
    require_invalid_input([&] { const PCCD::Point_cloud_object<PCCD::Eigen_kernel<float>> object(points); },
                          {"coordinate", "magnitude"});
}

TEST_CASE("queries at a NaN or infinite point are rejected", "[robustness]")
{
    // Was a known bug: nanoflann compared with the NaN (a trap in Debug), k_nearest returned
    // nothing and nearest() read front() of an empty vector. The kd-tree now checks the query.
    const Cloud cloud(fibonacci_sphere(100));
    const Object object(fibonacci_sphere(300));
    for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        const Eigen::Vector3d point(bad, 0, 0);
        require_invalid_input([&] { (void)cloud.nearest(point); }, {"non-finite"});
        require_invalid_input([&] { (void)cloud.k_nearest(point, 3); }, {"non-finite"});
        require_invalid_input([&] { (void)cloud.within_radius(point, 0.1); }, {"non-finite"});
        CHECK_THROWS_AS(object.surface().evaluate(point), PCCD::Error);
    }
}
