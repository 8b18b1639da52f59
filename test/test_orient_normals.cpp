// Tests of the normal orientation (ALGORITHMS.md section 1): Hoppe's MST propagation over any
// ProximityGraph model (here a boost::adjacency_list k-NN graph built by brute force), the outward
// choice per component, orientation like given normals, and the bunny scan against its mesh normals.
#include "surface_test_helpers.h"

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Surface/orient_normals.h>

#include <boost/graph/adjacency_list.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

using namespace pccd_test;

namespace {

using Adjacency_graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                          boost::property<boost::edge_weight_t, double>>;
static_assert(PCCD::ProximityGraph<Adjacency_graph,
                                   boost::property_map<Adjacency_graph, boost::edge_weight_t>::const_type>);

/// Symmetric k-NN graph by brute force (independent of the kd-tree and of PCCD's builders).
Adjacency_graph brute_force_knn_graph(const Eigen::Matrix3Xd& points, std::size_t k)
{
    const auto n = std::size_t(points.cols());
    Adjacency_graph g(n);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::VectorXd d2 = (points.colwise() - points.col(Eigen::Index(i))).colwise().squaredNorm();
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(k + 1), order.end(),
                          [&](std::size_t a, std::size_t b) { return d2(Eigen::Index(a)) < d2(Eigen::Index(b)); });
        for (std::size_t m = 1; m <= k; ++m)
            if (!boost::edge(i, order[m], g).second)
                boost::add_edge(i, order[m], std::sqrt(d2(Eigen::Index(order[m]))), g);
    }
    return g;
}

/// A readable property map from an index to a vector of a table (for points and normals).
struct Index_map {
    const std::vector<Eigen::Vector3d>* values;
    friend const Eigen::Vector3d& get(const Index_map& m, std::size_t i) { return (*m.values)[i]; }
};

/// Flips every third normal.
Eigen::Matrix3Xd scrambled(const Eigen::Matrix3Xd& normals)
{
    Eigen::Matrix3Xd out = normals;
    for (Eigen::Index i = 0; i < out.cols(); i += 3) out.col(i) = -out.col(i);
    return out;
}

} // namespace

TEST_CASE("orientation over an adjacency_list k-NN graph makes closed surfaces face outward", "[surface]")
{
    for (double noise : {0.0, 0.3}) {
        // Normals perturbed by noise too, so the MST weights are not all zero.
        const auto sphere = sample_shape(unit_sphere(), 2000, noise, 51);
        const auto torus = sample_shape(test_torus(), 2000, noise, 52);
        for (const auto* sample : {&sphere, &torus}) {
            Eigen::Matrix3Xd normals = scrambled(sample->normals);
            PCCD::Random_engine engine(5);
            for (Eigen::Index i = 0; i < normals.cols(); ++i)
                for (int d = 0; d < 3; ++d) normals(d, i) += 0.1 * noise * PCCD::standard_normal(engine);
            const Adjacency_graph g = brute_force_knn_graph(sample->points, 10);
            const PCCD::Orientation_report report = PCCD::orient_normals(g, sample->points, normals);
            std::size_t inward = 0;
            for (Eigen::Index i = 0; i < normals.cols(); ++i)
                if (normals.col(i).dot(sample->normals.col(i)) <= 0.0) ++inward;
            CHECK(inward == 0);
            CHECK(report.components == 1);
            CHECK(report.flipped == std::size_t((normals.cols() + 2) / 3));
            CHECK(report.unoriented == 0);
        }
    }
}

TEST_CASE("orientation works per component and leaves points without a normal alone", "[surface]")
{
    // Two spheres far apart, both with scrambled normals, and one point without a normal.
    const auto a = sample_shape(unit_sphere(), 1000, 0.0, 61);
    Eigen::Matrix3Xd points(3, 2000), truth(3, 2000);
    points << a.points, (a.points.colwise() + Eigen::Vector3d(5, 0, 0));
    truth << a.normals, a.normals;
    Eigen::Matrix3Xd normals = scrambled(truth);
    normals.col(10).setZero();
    const Adjacency_graph g = brute_force_knn_graph(points, 8);
    const PCCD::Orientation_report report = PCCD::orient_normals(g, points, normals);
    CHECK(report.components == 2);
    CHECK(report.unoriented == 1);
    CHECK(normals.col(10).isZero(0.0));
    for (Eigen::Index i = 0; i < 2000; ++i)
        if (i != 10) CHECK(normals.col(i).dot(truth.col(i)) > 0.0);
    // Sizes must match.
    Eigen::Matrix3Xd short_normals = Eigen::Matrix3Xd::Ones(3, 5);
    CHECK_THROWS_AS(PCCD::orient_normals(g, points, short_normals), PCCD::Invalid_input);
}

TEST_CASE("orientation like given normals follows them and fills undetermined normals", "[surface]")
{
    const auto sample = sample_shape(test_torus(), 3000, 0.0, 71);
    const auto points = columns(sample.points);
    // Given normals of the "wrong" (inward) side: the object follows them, not the outward rule.
    const auto given = columns(-sample.normals);
    std::vector<std::size_t> items(points.size());
    std::iota(items.begin(), items.end(), std::size_t(0));
    const PCCD::Point_cloud_object<> object(items, Index_map{&points}, Index_map{&given});
    CHECK(object.normals_given());
    CHECK(object.orientation().components == 0);
    for (Eigen::Index i = 0; i < sample.normals.cols(); ++i) CHECK(object.normals().col(i).dot(sample.normals.col(i)) < 0.0);
    const double s = object.cloud().mean_spacing();
    const Eigen::Vector3d outside(1.4 + s, 0.0, 0.0); // s outside the outer equator
    REQUIRE(object.surface().value(outside).has_value());
    CHECK(*object.surface().value(outside) < 0.0);
}

TEST_CASE("oriented normals of the bunny scan agree with its mesh normals", "[surface]")
{
    const std::string data_dir = PCCD_DATA_DIR;
    if (data_dir.empty()) {
        WARN("PCCD_DATA_DIR is empty (libcgal-demo not installed): bunny orientation test skipped");
        return;
    }
    const PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(data_dir + "/bunny00.off", PCCD::IO::Format::off);
    // Mesh vertex normals: area-weighted sums of the incident faces' normals.
    std::vector<Eigen::Vector3d> mesh_normals(mesh.vertices.size(), Eigen::Vector3d::Zero());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d n =
            (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (const auto v : t) mesh_normals[v] += n;
    }
    const PCCD::Point_cloud_object<> object(mesh.vertices);
    const PCCD::Graph_components components =
        PCCD::graph_components(object.graph().graph(), object.graph().virtual_map());
    // Per component, the global sign that agrees best; count the normals that disagree with it
    // (or have none). Vertices used by no face have no mesh normal and are not counted.
    std::vector<double> vote(components.count, 0.0);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!mesh_normals[i].isZero(0.0))
            vote[components.label[i]] += object.normals().col(Eigen::Index(i)).dot(mesh_normals[i].normalized()) > 0.0 ? 1 : -1;
    std::size_t counted = 0, agree = 0;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (mesh_normals[i].isZero(0.0)) continue;
        ++counted;
        const double sign = vote[components.label[i]] >= 0.0 ? 1.0 : -1.0;
        if (sign * object.normals().col(Eigen::Index(i)).dot(mesh_normals[i]) > 0.0) ++agree;
    }
    const double fraction = double(agree) / double(counted);
    INFO("bunny: " << agree << " of " << counted << " normals agree (" << 100.0 * fraction << " %), "
                   << components.count << " components, " << object.orientation().flipped << " flipped, "
                   << object.orientation().unoriented << " without a normal");
    CHECK(fraction >= 0.999);
    // The bunny is a closed-looking scan: its largest component faces outward as a whole.
    CHECK(vote[components.label[0]] > 0.0);
}
