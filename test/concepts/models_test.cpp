// Compile-time checks that every shipped model satisfies its concept and that unrelated types are
// rejected; plus a user-defined point type going through a point map.
// Also covers Point_traits.h: the test cases below exercise what it declares.
#include <PCCD/Eigen_kernel.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Identity_point_map.h>
#include <PCCD/Intersection/Intersection_visitor.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Point_traits.h>
#include <PCCD/concepts/PairObserver.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/concepts/ProximityGraph.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/concepts/ReadablePointMap.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Sc_double = CGAL::Simple_cartesian<double>;

// --- PointCloudKernel ------------------------------------------------------------------------
static_assert(PCCD::PointCloudKernel<PCCD::Eigen_kernel<double>>);
static_assert(PCCD::PointCloudKernel<PCCD::Eigen_kernel<float>>);
static_assert(PCCD::PointCloudKernel<Sc_double>);
static_assert(PCCD::PointCloudKernel<CGAL::Simple_cartesian<float>>);
static_assert(PCCD::PointCloudKernel<Epick>);

// Intersection (doc/reference/intersection-reference.md).
static_assert(PCCD::CollisionObject<PCCD::Point_cloud_object<PCCD::Eigen_kernel<double>>>);
static_assert(PCCD::CollisionObject<PCCD::Point_cloud_object<PCCD::Eigen_kernel<float>>>);
static_assert(PCCD::CollisionObject<PCCD::Point_cloud_object<Epick>>);
static_assert(PCCD::CollisionObject<PCCD::Point_cloud_object<Sc_double>>);
static_assert(!PCCD::CollisionObject<PCCD::Point_cloud<>>);
static_assert(PCCD::ProximityObject<PCCD::Point_cloud_object<PCCD::Eigen_kernel<double>>>);
static_assert(PCCD::ProximityObject<PCCD::Point_cloud_object<PCCD::Eigen_kernel<float>>>);
static_assert(PCCD::ProximityObject<PCCD::Point_cloud_object<Epick>>);
static_assert(PCCD::ProximityObject<PCCD::Point_cloud_object<Sc_double>>);
static_assert(PCCD::GeodesicCollisionObject<PCCD::Point_cloud_object<PCCD::Eigen_kernel<float>>>);
static_assert(PCCD::GeodesicCollisionObject<PCCD::Point_cloud_object<Epick>>);
static_assert(PCCD::EuclideanCollisionObject<PCCD::Euclidean_point_cloud_object<PCCD::Eigen_kernel<double>>>);
static_assert(PCCD::EuclideanCollisionObject<PCCD::Euclidean_point_cloud_object<PCCD::Eigen_kernel<float>>>);
static_assert(PCCD::EuclideanCollisionObject<PCCD::Euclidean_point_cloud_object<Epick>>);
static_assert(PCCD::ProximityObject<PCCD::Euclidean_point_cloud_object<Sc_double>>);
static_assert(!PCCD::GeodesicCollisionObject<PCCD::Euclidean_point_cloud_object<>>);
static_assert(!PCCD::ProximityObject<PCCD::Point_cloud<>>);
static_assert(PCCD::LeafIntersector<PCCD::Interpolation_search, PCCD::Point_cloud_object<>, PCCD::Point_cloud_object<>>);
static_assert(PCCD::LeafIntersector<PCCD::Randomized_sampling, PCCD::Point_cloud_object<>, PCCD::Point_cloud_object<Epick>>);
static_assert(!PCCD::LeafIntersector<PCCD::Intersection_options, PCCD::Point_cloud_object<>, PCCD::Point_cloud_object<>>);
static_assert(!PCCD::PointCloudKernel<Epeck>, "exact number types are not floating point");
static_assert(!PCCD::PointCloudKernel<int>);
static_assert(!PCCD::PointCloudKernel<std::vector<double>>);
static_assert(!PCCD::PointCloudKernel<Eigen::Vector3d>);

// --- Point3 and ReadablePointMap ----------------------------------------------------------------
static_assert(PCCD::Point3<Eigen::Vector3d>);
static_assert(PCCD::Point3<Eigen::Vector3f>);
static_assert(PCCD::Point3<Epick::Point_3>);
static_assert(PCCD::Point3<Sc_double::Vector_3>);
static_assert(PCCD::Point3<std::array<float, 3>>);
static_assert(!PCCD::Point3<std::array<float, 2>>);
static_assert(!PCCD::Point3<double>);
static_assert(!PCCD::Point3<std::string>);

static_assert(PCCD::ReadablePointMap<PCCD::Identity_point_map<Eigen::Vector3d>, Eigen::Vector3d>);
static_assert(PCCD::ReadablePointMap<PCCD::Identity_point_map<Epick::Point_3>, Epick::Point_3>);
static_assert(PCCD::ReadablePointMap<CGAL::Identity_property_map<Epick::Point_3>, Epick::Point_3>);
static_assert(PCCD::ReadablePointMap<boost::typed_identity_property_map<Eigen::Vector3d>, Eigen::Vector3d>);
static_assert(PCCD::ReadablePointMap<CGAL::First_of_pair_property_map<std::pair<Epick::Point_3, Epick::Vector_3>>,
                                     std::pair<Epick::Point_3, Epick::Vector_3>>);
static_assert(!PCCD::ReadablePointMap<PCCD::Identity_point_map<double>, double>, "a double is not a point");
static_assert(!PCCD::ReadablePointMap<int, Eigen::Vector3d>, "an int is not a map");

// A user type from a photogrammetry pipeline (coordinates in an array, a track id), read through a
// Boost-style point map that narrows them to float.
struct Tie_point {
    double coordinates[3];
    std::uint32_t track;
};
struct Tie_point_map {
    using key_type = Tie_point;
    using value_type = Eigen::Vector3f;
    using reference = Eigen::Vector3f;
    using category = boost::readable_property_map_tag;
    friend Eigen::Vector3f get(const Tie_point_map&, const Tie_point& p)
    {
        return Eigen::Vector3d(p.coordinates[0], p.coordinates[1], p.coordinates[2]).cast<float>();
    }
};
static_assert(PCCD::ReadablePointMap<Tie_point_map, Tie_point>);
static_assert(!PCCD::ReadablePointMap<Tie_point_map, Eigen::Vector3d>, "wrong item type");
static_assert(!PCCD::Point3<Tie_point>, "no Point_traits for the raw tie point type");

// --- ProximityGraph ------------------------------------------------------------------------------
struct Edge_length {
    float length;
};
using Csr_graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Edge_length,
                                                     boost::no_property, std::uint32_t, std::uint32_t>;
using Csr_weight_map = boost::property_map<Csr_graph, float Edge_length::*>::const_type;
using List_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                         boost::property<boost::edge_weight_t, double>>;
using List_weight_map = boost::property_map<List_graph, boost::edge_weight_t>::const_type;
using List_graph_set = boost::adjacency_list<boost::setS, boost::listS, boost::undirectedS, boost::no_property,
                                             boost::property<boost::edge_weight_t, double>>;
using List_set_weight_map = boost::property_map<List_graph_set, boost::edge_weight_t>::const_type;

static_assert(PCCD::ProximityGraph<Csr_graph, Csr_weight_map>);
static_assert(PCCD::ProximityGraph<List_graph, List_weight_map>);
static_assert(!PCCD::ProximityGraph<List_graph_set, List_set_weight_map>, "listS vertices are not point indices");
static_assert(!PCCD::ProximityGraph<List_graph, int>, "int is not a weight map");

// PairObserver: the traversals' default, the visitor's forwarder, and a visitor itself (its pair members).
static_assert(PCCD::PairObserver<PCCD::Ignore_pairs>);
static_assert(PCCD::PairObserver<PCCD::internal::Visitor_pairs>);
static_assert(PCCD::PairObserver<PCCD::Intersection_visitor>);
static_assert(!PCCD::PairObserver<std::vector<int>>);

TEST_CASE("a user point type works through a point map", "[concepts]")
{
    const std::vector<Tie_point> ties = {{{0, 0, 0}, 10}, {{1, 0, 0}, 20}, {{0, 2, 0}, 30}, {{0, 0, 3}, 40}};
    const PCCD::Point_cloud<PCCD::Eigen_kernel<float>> cloud(ties, Tie_point_map{});
    REQUIRE(cloud.size() == 4);
    CHECK(cloud.position(2) == Eigen::Vector3f(0, 2, 0));
    CHECK(cloud.nearest(Eigen::Vector3f(0.9f, 0.1f, 0)).index == 1);
    CHECK(cloud.bbox().max() == Eigen::Vector3f(1, 2, 3));
}

TEST_CASE("CGAL kernels and points are accepted", "[concepts]")
{
    const std::vector<Epick::Point_3> pts = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    const PCCD::Point_cloud<Epick> cloud(pts);
    CHECK(cloud.point(1) == Epick::Point_3(1, 1, 1));
    const std::vector<std::pair<Sc_double::Point_3, Sc_double::Vector_3>> with_normals = {
        {{0, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
    const PCCD::Point_cloud<Sc_double> cloud2(
        with_normals, CGAL::First_of_pair_property_map<std::pair<Sc_double::Point_3, Sc_double::Vector_3>>());
    CHECK(cloud2.size() == 2);
    CHECK(cloud2.mean_spacing() == Approx(1.0));
}
