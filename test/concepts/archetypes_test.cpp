// Archetypes, in the manner of the Boost Concept Check Library: minimal types that model exactly what
// a concept states, with which the public algorithms are instantiated (so an algorithm that uses
// more than its concept says does not compile here), and near-miss types, each lacking one
// requirement, that the concept rejects. The archetypes wrap real models, so the algorithms also run
// on them and must give the same answers as on the models.
//
// Concepts covered: RigidMotion (time_of_contact), CollisionObject, ProximityObject (distance, within_distance, contacts, Collision_world) and LeafIntersector (do_intersect, intersection_points, both
// policies, both path choices, the batch queries, Collision_world), PathSource (the interpolation search's role),
// SurfaceDistance and SurfaceWeight (WLS_surface, estimate_normals), PointCloudKernel (Point_cloud,
// both distances, the graphs, the sampling radius, outliers, the domain, Point_cloud_object) and
// ReadablePointMap (Point_cloud_object, then the queries),
// PointGraph, ProximityGraph, EdgeFlagMap and WritableEdgeFlagMap (orient_normals, Paths_on_the_fly,
// graph_components, mark_long_edges, the CPSP map with both bounded Dijkstras). The kinetic concepts have their own file, concepts/kinetic_archetypes_test.cpp.
// Also covers Intersection/Posed_object.h, Intersection/Query_state.h: the test cases below exercise what they declare.
#include "surface_test_helpers.h"

#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/Paths_on_the_fly.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Intersection/Posed_object.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Intersection/ray_intersection.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/contacts.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/World/Collision_world.h>
#include <PCCD/concepts/RigidMotion.h>

#include <memory>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/prune_long_edges.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/Surface/orient_normals.h>
#include <PCCD/Surface/outliers.h>
#include <PCCD/Surface/surface_domain.h>
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/concepts/LeafIntersector.h>
#include <PCCD/concepts/PairObserver.h>
#include <PCCD/concepts/PathSource.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/concepts/ProximityGraph.h>
#include <PCCD/concepts/SurfaceDistance.h>
#include <PCCD/concepts/SurfaceWeight.h>
#include <PCCD/sampling_radius.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/transform_iterator.hpp>


namespace archetype {

/// Exactly what PointGraph / ProximityGraph require: a compressed adjacency with integral vertices,
/// vertex and out-edge ranges, source and target, and a length map (graph_traits below).
struct Graph {
    std::vector<std::uint64_t> offsets; // n + 1
    std::vector<std::uint32_t> targets;
    std::vector<float> lengths;
    std::vector<bool> flags; // per edge, read by Flag_map only
};
struct Edge {
    std::uint32_t source;
    std::uint64_t index;
    bool operator==(const Edge&) const = default;
};
struct Make_edge {
    std::uint32_t source;
    Edge operator()(std::uint64_t index) const { return {source, index}; }
};
using Vertex_iterator = boost::counting_iterator<std::uint32_t>;
using Out_edge_iterator = boost::transform_iterator<Make_edge, boost::counting_iterator<std::uint64_t>, Edge, Edge>;

inline std::size_t num_vertices(const Graph& g) { return g.offsets.size() - 1; }
inline std::pair<Vertex_iterator, Vertex_iterator> vertices(const Graph& g)
{
    return {Vertex_iterator(0), Vertex_iterator(std::uint32_t(num_vertices(g)))};
}
inline std::pair<Out_edge_iterator, Out_edge_iterator> out_edges(std::uint32_t v, const Graph& g)
{
    return {Out_edge_iterator(boost::counting_iterator<std::uint64_t>(g.offsets[v]), Make_edge{v}),
            Out_edge_iterator(boost::counting_iterator<std::uint64_t>(g.offsets[v + 1]), Make_edge{v})};
}
inline std::size_t out_degree(std::uint32_t v, const Graph& g) { return std::size_t(g.offsets[v + 1] - g.offsets[v]); }
inline std::uint32_t source(const Edge& e, const Graph&) { return e.source; }
inline std::uint32_t target(const Edge& e, const Graph& g) { return g.targets[e.index]; }

struct Length_map {
    const Graph* graph;
    friend double get(const Length_map& m, const Edge& e) { return m.graph->lengths[e.index]; }
};

/// Exactly what EdgeFlagMap requires: get() of an edge, convertible to bool. No property_traits.
struct Flag_map {
    const Graph* graph;
    friend bool get(const Flag_map& m, const Edge& e) { return m.graph->flags[e.index]; }
};

/// Exactly what WritableEdgeFlagMap requires: get() and put() of an edge's flag.
struct Writable_flag_map {
    Graph* graph;
    friend bool get(const Writable_flag_map& m, const Edge& e) { return m.graph->flags[e.index]; }
    friend void put(const Writable_flag_map& m, const Edge& e, bool b) { m.graph->flags[e.index] = b; }
};

/// Near-miss of EdgeFlagMap: get() gives a name, not a flag.
struct Name_map {
    friend std::string get(const Name_map&, const Edge&);
};

/// Near-miss: a graph whose vertices are not indices (a string-keyed graph).
struct Named_graph {};

/// Near-misses of PointGraph: the archetype's storage with one operation left out.
enum Left_out { no_num_vertices, no_out_edges, no_target };
template <int Missing>
struct Partial_graph {
    Graph g;
};
template <int M>
    requires(M != no_num_vertices)
std::size_t num_vertices(const Partial_graph<M>& p)
{
    return num_vertices(p.g);
}
template <int M>
std::pair<Vertex_iterator, Vertex_iterator> vertices(const Partial_graph<M>& p)
{
    return vertices(p.g);
}
template <int M>
    requires(M != no_out_edges)
std::pair<Out_edge_iterator, Out_edge_iterator> out_edges(std::uint32_t v, const Partial_graph<M>& p)
{
    return out_edges(v, p.g);
}
template <int M>
std::size_t out_degree(std::uint32_t v, const Partial_graph<M>& p)
{
    return out_degree(v, p.g);
}
template <int M>
std::uint32_t source(const Edge& e, const Partial_graph<M>& p)
{
    return source(e, p.g);
}
template <int M>
    requires(M != no_target)
std::uint32_t target(const Edge& e, const Partial_graph<M>& p)
{
    return target(e, p.g);
}

} // namespace archetype

namespace boost {
template <>
struct graph_traits<archetype::Graph> {
    using vertex_descriptor = std::uint32_t;
    using edge_descriptor = archetype::Edge;
    struct traversal_category : vertex_list_graph_tag, incidence_graph_tag {};
    using directed_category = directed_tag;
    using edge_parallel_category = allow_parallel_edge_tag;
    using vertex_iterator = archetype::Vertex_iterator;
    using out_edge_iterator = archetype::Out_edge_iterator;
    using vertices_size_type = std::size_t;
    using edges_size_type = std::size_t;
    using degree_size_type = std::size_t;
    static vertex_descriptor null_vertex() { return std::numeric_limits<std::uint32_t>::max(); }
};
template <int M>
struct graph_traits<archetype::Partial_graph<M>> : graph_traits<archetype::Graph> {};
template <>
struct graph_traits<archetype::Named_graph> {
    using vertex_descriptor = std::string;
    using edge_descriptor = std::pair<std::string, std::string>;
    struct traversal_category : vertex_list_graph_tag, incidence_graph_tag {};
};
} // namespace boost

static_assert(PCCD::PointGraph<archetype::Graph>);
static_assert(PCCD::ProximityGraph<archetype::Graph, archetype::Length_map>);
static_assert(!PCCD::ProximityGraph<archetype::Graph, int>);
static_assert(!PCCD::PointGraph<archetype::Named_graph>);
static_assert(PCCD::PointGraph<archetype::Partial_graph<-1>>); // nothing left out
static_assert(!PCCD::PointGraph<archetype::Partial_graph<archetype::no_num_vertices>>);
static_assert(!PCCD::PointGraph<archetype::Partial_graph<archetype::no_out_edges>>);
static_assert(!PCCD::PointGraph<archetype::Partial_graph<archetype::no_target>>);
static_assert(PCCD::EdgeFlagMap<archetype::Flag_map, archetype::Graph>);
static_assert(PCCD::EdgeFlagMap<PCCD::No_virtual_edges, archetype::Graph>);
static_assert(!PCCD::EdgeFlagMap<archetype::Name_map, archetype::Graph>);
static_assert(PCCD::WritableEdgeFlagMap<archetype::Writable_flag_map, archetype::Graph>);
static_assert(PCCD::WritableEdgeFlagMap<PCCD::Proximity_graph::Virtual_map, PCCD::Proximity_graph::Graph>);
static_assert(!PCCD::WritableEdgeFlagMap<archetype::Flag_map, archetype::Graph>, "read-only");

using namespace pccd_test;

namespace archetype {

using Object = PCCD::Point_cloud_object<>;

/// The cloud as CollisionObject sees it: position(i) and coordinates(), nothing else.
class Cloud {
public:
    explicit Cloud(const Object& o) : m_object(&o) {}
    Eigen::Vector3d position(std::uint32_t i) const { return m_object->cloud().position(i); }
    const Eigen::Matrix3Xd& coordinates() const { return m_object->cloud().coordinates(); }

private:
    const Object* m_object;
};

/// The surface as CollisionObject sees it: evaluate(x) and support_radius().
class Surface {
public:
    explicit Surface(const Object& o) : m_object(&o) {}
    PCCD::Surface_evaluation evaluate(const Eigen::Vector3d& x) const { return m_object->surface().evaluate(x); }
    double support_radius() const { return m_object->surface().support_radius(); }

private:
    const Object* m_object;
};

/// Exactly the members CollisionObject requires.
class Collision_object {
public:
    explicit Collision_object(const Object& o) : m_object(&o), m_cloud(o), m_surface(o) {}
    std::size_t size() const { return m_object->size(); }
    const Cloud& cloud() const { return m_cloud; }
    const Surface& surface() const { return m_surface; }
    const PCCD::Point_cloud_hierarchy& hierarchy() const { return m_object->hierarchy(); }
    double sampling_radius() const { return m_object->sampling_radius(); }
    double noise_estimate() const { return m_object->noise_estimate(); }

protected:
    const Object* m_object;

private:
    Cloud m_cloud;
    Surface m_surface;
};

/// Exactly the members GeodesicCollisionObject requires: a collision object, its graph and CPSP map.
class Geodesic_collision_object : public Collision_object {
public:
    explicit Geodesic_collision_object(const Object& o) : Collision_object(o) {}
    const PCCD::Proximity_graph& graph() const { return m_object->graph(); }
    const PCCD::Close_pairs_shortest_paths& cpsp() const { return m_object->cpsp(); }
};

/// The cloud as EuclideanCollisionObject sees it: CollisionObject's members, its types, nearest()
/// and within_radius().
class Searchable_cloud : public Cloud {
public:
    using FT = double;
    using Vector_3 = Eigen::Vector3d;
    using Neighbor = PCCD::Neighbor<double>;
    explicit Searchable_cloud(const Object& o) : Cloud(o), m_object(&o) {}
    Neighbor nearest(const Vector_3& v) const { return m_object->cloud().nearest(v); }
    void within_radius(const Vector_3& v, FT r, std::vector<Neighbor>& out) const
    {
        m_object->cloud().within_radius(v, r, out);
    }

private:
    const Object* m_object;
};

/// Exactly the members EuclideanCollisionObject requires: no graph and no CPSP map.
class Euclidean_collision_object {
public:
    explicit Euclidean_collision_object(const Object& o) : m_object(&o), m_cloud(o), m_surface(o) {}
    std::size_t size() const { return m_object->size(); }
    const Searchable_cloud& cloud() const { return m_cloud; }
    const Surface& surface() const { return m_surface; }
    const PCCD::Point_cloud_hierarchy& hierarchy() const { return m_object->hierarchy(); }
    double sampling_radius() const { return m_object->sampling_radius(); }
    double noise_estimate() const { return m_object->noise_estimate(); }

private:
    const Object* m_object;
    Searchable_cloud m_cloud;
    Surface m_surface;
};

/// Exactly the members ProximityObject requires: a collision object and its normals (a geodesic
/// one, so that the default leaf intersector takes it).
class Proximity_object : public Geodesic_collision_object {
public:
    explicit Proximity_object(const Object& o) : Geodesic_collision_object(o), m_normals(&o.normals()) {}
    const Eigen::Matrix3Xd& normals() const { return *m_normals; }

private:
    const Eigen::Matrix3Xd* m_normals;
};

// Near-misses: each lacks one requirement of CollisionObject (Without_graph and With_foreign_paths
// one of GeodesicCollisionObject).
struct Without_noise_estimate {
    std::size_t size() const;
    const Cloud& cloud() const;
    const Surface& surface() const;
    const PCCD::Proximity_graph& graph() const;
    const PCCD::Close_pairs_shortest_paths& cpsp() const;
    const PCCD::Point_cloud_hierarchy& hierarchy() const;
    double sampling_radius() const;
};
struct Without_graph {
    std::size_t size() const;
    const Cloud& cloud() const;
    const Surface& surface() const;
    const PCCD::Close_pairs_shortest_paths& cpsp() const;
    const PCCD::Point_cloud_hierarchy& hierarchy() const;
    double sampling_radius() const;
    double noise_estimate() const;
};
struct With_foreign_paths { // cpsp() is not a CPSP map
    std::size_t size() const;
    const Cloud& cloud() const;
    const Surface& surface() const;
    const PCCD::Proximity_graph& graph() const;
    const std::vector<std::vector<std::uint32_t>>& cpsp() const;
    const PCCD::Point_cloud_hierarchy& hierarchy() const;
    double sampling_radius() const;
    double noise_estimate() const;
};
struct Value_surface { // evaluate() returns f only, not a Surface_evaluation
    double evaluate(const Eigen::Vector3d&) const;
    double support_radius() const;
};
struct With_value_surface {
    std::size_t size() const;
    const Cloud& cloud() const;
    const Value_surface& surface() const;
    const PCCD::Proximity_graph& graph() const;
    const PCCD::Close_pairs_shortest_paths& cpsp() const;
    const PCCD::Point_cloud_hierarchy& hierarchy() const;
    double sampling_radius() const;
    double noise_estimate() const;
};
struct Temporary_cloud { // coordinates() by value: a path search would keep a dangling reference
    Eigen::Vector3d position(std::uint32_t) const;
    Eigen::Matrix3Xd coordinates() const;
};
struct With_temporary_coordinates {
    std::size_t size() const;
    const Temporary_cloud& cloud() const;
    const Surface& surface() const;
    const PCCD::Proximity_graph& graph() const;
    const PCCD::Close_pairs_shortest_paths& cpsp() const;
    const PCCD::Point_cloud_hierarchy& hierarchy() const;
    double sampling_radius() const;
    double noise_estimate() const;
};
struct Without_hierarchy {
    std::size_t size() const;
    const Cloud& cloud() const;
    const Surface& surface() const;
    const PCCD::Proximity_graph& graph() const;
    const PCCD::Close_pairs_shortest_paths& cpsp() const;
    double sampling_radius() const;
    double noise_estimate() const;
};

/// Exactly what LeafIntersector requires; run() offers the sampled objects' first points that
/// lie within epsilon of the other surface (a real, if weak, intersector).
struct Leaf_intersector {
    static const char* name() { return "archetype"; }
    void check() const {}
    double default_epsilon(double r) const { return 0.05 * r; }
    template <class A, class B>
    void run(const PCCD::Posed_object<A>& a, const PCCD::Posed_object<B>& b,
             const PCCD::Intersection_options&, double epsilon, PCCD::Query_state& state, double& closest) const
    {
        closest = std::numeric_limits<double>::quiet_NaN();
        for (std::uint32_t i = 0; i < a.size() && !state.stop(); ++i) {
            const Eigen::Vector3d x = a.to_world.transform_point(a.position(i));
            const PCCD::Surface_evaluation e = state.evaluate_world(b, x);
            if (e.defined() && std::abs(e.value) <= epsilon)
                state.offer(PCCD::Intersection_point{x, 0.0, e.value, PCCD::Intersection_point_kind::approximate});
        }
    }
};
struct Without_run {
    static const char* name() { return "no run"; }
    void check() const {}
    double default_epsilon(double r) const { return r; }
};
struct With_numeric_name {
    static int name() { return 1; }
    void check() const {}
    double default_epsilon(double r) const { return r; }
    template <class A, class B>
    void run(const PCCD::Posed_object<A>&, const PCCD::Posed_object<B>&,
             const PCCD::Intersection_options&, double, PCCD::Query_state&, double&) const;
};

/// Exactly what PathSource requires.
struct Path_source {
    bool path(std::uint32_t from, std::uint32_t to, std::vector<std::uint32_t>& out) const
    {
        out = {from, to};
        return true;
    }
};
struct Silent_path_source { // does not say whether a path exists
    void path(std::uint32_t, std::uint32_t, std::vector<std::uint32_t>&) const;
};
struct Path_length_source { // gives a length, not a path
    bool path(std::uint32_t, std::uint32_t) const;
};
struct Caching_path_source { // path() is not const: not safe to call concurrently
    bool path(std::uint32_t, std::uint32_t, std::vector<std::uint32_t>&);
};

/// Exactly what PairObserver requires (non-const members, results ignored), counting the pairs.
struct Pair_observer {
    std::size_t nodes = 0, leaves = 0;
    void node_pair(std::uint32_t, std::uint32_t) { ++nodes; }
    void leaf_pair(std::uint32_t, std::uint32_t) { ++leaves; }
};
struct Node_only_observer { // no leaf_pair
    void node_pair(std::uint32_t, std::uint32_t);
};

/// Exactly what SurfaceDistance requires, over a Euclidean_distance.
class Distance {
public:
    explicit Distance(const PCCD::Euclidean_distance<>& d) : m_d(d) {}
    std::size_t size() const { return m_d.size(); }
    Eigen::Vector3d position(std::uint32_t i) const { return m_d.position(i); }
    double max_radius() const { return m_d.max_radius(); }
    template <class Visitor>
    void for_each_neighbor_of_point(std::uint32_t i, double radius, Visitor&& visitor) const
    {
        m_d.for_each_neighbor_of_point(i, radius, visitor);
    }
    template <class Visitor>
    std::optional<std::uint32_t> for_each_neighbor(const Eigen::Vector3d& x, double radius, Visitor&& visitor) const
    {
        return m_d.for_each_neighbor(x, radius, visitor);
    }

private:
    PCCD::Euclidean_distance<> m_d;
};
struct Distance_without_point_queries {
    std::size_t size() const;
    Eigen::Vector3d position(std::uint32_t) const;
    double max_radius() const;
    template <class Visitor>
    std::optional<std::uint32_t> for_each_neighbor(const Eigen::Vector3d&, double, Visitor&&) const;
};
struct Distance_without_nearest { // for_each_neighbor does not report the nearest point
    std::size_t size() const;
    Eigen::Vector3d position(std::uint32_t) const;
    double max_radius() const;
    template <class Visitor>
    void for_each_neighbor_of_point(std::uint32_t, double, Visitor&&) const;
    template <class Visitor>
    void for_each_neighbor(const Eigen::Vector3d&, double, Visitor&&) const;
};

/// Exactly what SurfaceWeight requires, over a Gaussian_weight.
class Weight {
public:
    explicit Weight(const PCCD::Gaussian_weight& w) : m_w(w) {}
    double operator()(double d) const { return double(m_w(d)); }
    double support_radius() const { return double(m_w.support_radius()); }

private:
    PCCD::Gaussian_weight m_w;
};
struct Weight_without_support {
    double operator()(double) const;
};

/// Exactly what PointCloudKernel requires: its own point and vector types, the four constructions.
struct Kernel {
    using FT = double;
    struct Point_3 {
        double x, y, z;
    };
    struct Vector_3 {
        double x, y, z;
    };
    struct Construct_point {
        Point_3 operator()(double x, double y, double z) const { return {x, y, z}; }
    };
    struct Coordinate {
        int axis;
        double operator()(const Point_3& p) const { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
    };
    struct Squared_distance {
        double operator()(const Point_3& p, const Point_3& q) const
        {
            return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z);
        }
    };
    Construct_point construct_point_3_object() const { return {}; }
    Coordinate compute_x_3_object() const { return {0}; }
    Coordinate compute_y_3_object() const { return {1}; }
    Coordinate compute_z_3_object() const { return {2}; }
    Squared_distance compute_squared_distance_3_object() const { return {}; }
};
struct Kernel_without_points { // cannot construct the points Point_cloud::point() returns
    using FT = double;
    using Point_3 = Kernel::Point_3;
    using Vector_3 = Kernel::Vector_3;
    Kernel::Coordinate compute_x_3_object() const;
    Kernel::Coordinate compute_y_3_object() const;
    Kernel::Coordinate compute_z_3_object() const;
    Kernel::Squared_distance compute_squared_distance_3_object() const;
};
struct Kernel_without_z { // a planar kernel
    using FT = double;
    using Point_3 = Kernel::Point_3;
    using Vector_3 = Kernel::Vector_3;
    Kernel::Construct_point construct_point_3_object() const;
    Kernel::Coordinate compute_x_3_object() const;
    Kernel::Coordinate compute_y_3_object() const;
    Kernel::Squared_distance compute_squared_distance_3_object() const;
};
struct Integer_kernel : Kernel { // FT is not a floating-point type
    using FT = long;
};
struct Kernel_without_distance {
    using FT = double;
    using Point_3 = Kernel::Point_3;
    using Vector_3 = Kernel::Vector_3;
    Kernel::Construct_point construct_point_3_object() const;
    Kernel::Coordinate compute_x_3_object() const;
    Kernel::Coordinate compute_y_3_object() const;
    Kernel::Coordinate compute_z_3_object() const;
};

/// A user's scan record and exactly what ReadablePointMap requires of a map over it: get() by ADL
/// returning a Point3 (here an Eigen vector by value).
struct Scan_record {
    float position[3];
    int intensity;
};
struct Point_map {
    friend Eigen::Vector3d get(const Point_map&, const Scan_record& r)
    {
        return Eigen::Vector3d(r.position[0], r.position[1], r.position[2]);
    }
};
struct Intensity_map { // get() gives no point
    friend int get(const Intensity_map&, const Scan_record& r) { return r.intensity; }
};
struct Map_without_get {};

} // namespace archetype

static_assert(PCCD::PointCloudKernel<archetype::Kernel>);
static_assert(!PCCD::PointCloudKernel<archetype::Integer_kernel>);
static_assert(!PCCD::PointCloudKernel<archetype::Kernel_without_distance>);
static_assert(!PCCD::PointCloudKernel<archetype::Kernel_without_points>);
static_assert(!PCCD::PointCloudKernel<archetype::Kernel_without_z>);
// Every member function of the kernel-generic classes, instantiated with the kernel archetype.
template class PCCD::Point_cloud<archetype::Kernel>;
template class PCCD::Euclidean_distance<archetype::Kernel>;
template class PCCD::Geodesic_distance<archetype::Kernel>;
static_assert(PCCD::ReadablePointMap<archetype::Point_map, archetype::Scan_record>);
static_assert(!PCCD::ReadablePointMap<archetype::Intensity_map, archetype::Scan_record>);
static_assert(!PCCD::ReadablePointMap<archetype::Map_without_get, archetype::Scan_record>);

static_assert(PCCD::CollisionObject<archetype::Collision_object>);
static_assert(!PCCD::GeodesicCollisionObject<archetype::Collision_object>);
static_assert(!PCCD::EuclideanCollisionObject<archetype::Collision_object>); // a cloud without searches
static_assert(PCCD::GeodesicCollisionObject<archetype::Geodesic_collision_object>);
static_assert(PCCD::EuclideanCollisionObject<archetype::Euclidean_collision_object>);
static_assert(!PCCD::GeodesicCollisionObject<archetype::Euclidean_collision_object>);
static_assert(!PCCD::CollisionObject<archetype::Without_noise_estimate>);
static_assert(PCCD::CollisionObject<archetype::Without_graph>);
static_assert(!PCCD::GeodesicCollisionObject<archetype::Without_graph>);
static_assert(!PCCD::GeodesicCollisionObject<archetype::With_foreign_paths>);
static_assert(!PCCD::CollisionObject<archetype::With_value_surface>);
static_assert(!PCCD::CollisionObject<archetype::With_temporary_coordinates>);
static_assert(!PCCD::CollisionObject<archetype::Without_hierarchy>);
static_assert(PCCD::ProximityObject<archetype::Proximity_object>);
static_assert(!PCCD::ProximityObject<archetype::Collision_object>); // no normals

using Arch = archetype::Geodesic_collision_object;
using Euclidean_arch = archetype::Euclidean_collision_object;
static_assert(PCCD::LeafIntersector<archetype::Leaf_intersector, Arch, Arch>);
static_assert(PCCD::LeafIntersector<PCCD::Interpolation_search, Euclidean_arch, Arch>);
static_assert(PCCD::LeafIntersector<PCCD::Randomized_sampling, archetype::Collision_object, archetype::Collision_object>);
static_assert(PCCD::LeafIntersector<PCCD::Interpolation_search, Arch, Arch>);
static_assert(PCCD::LeafIntersector<PCCD::Randomized_sampling, Arch, Arch>);
static_assert(!PCCD::LeafIntersector<archetype::Without_run, Arch, Arch>);
static_assert(!PCCD::LeafIntersector<archetype::With_numeric_name, Arch, Arch>);

static_assert(PCCD::PathSource<archetype::Path_source>);
static_assert(PCCD::PathSource<PCCD::Stored_paths>);
static_assert(!PCCD::PathSource<archetype::Silent_path_source>);
static_assert(PCCD::PairObserver<archetype::Pair_observer>);
static_assert(PCCD::PairObserver<PCCD::Ignore_pairs>);
static_assert(!PCCD::PairObserver<archetype::Node_only_observer>);
static_assert(!PCCD::PairObserver<int>);
static_assert(!PCCD::PathSource<archetype::Path_length_source>);
static_assert(!PCCD::PathSource<archetype::Caching_path_source>);
// The interpolation search's role reads its paths through the PathSource archetype.
template struct PCCD::internal::Isearch_role<PCCD::Interpolation_search, Arch, Arch, archetype::Path_source>;
template struct PCCD::internal::Isearch_role<PCCD::Interpolation_search, Euclidean_arch, Arch, archetype::Path_source>;

static_assert(PCCD::SurfaceDistance<archetype::Distance>);
static_assert(!PCCD::SurfaceDistance<archetype::Distance_without_point_queries>);
static_assert(!PCCD::SurfaceDistance<archetype::Distance_without_nearest>);
static_assert(PCCD::SurfaceWeight<archetype::Weight>);
static_assert(!PCCD::SurfaceWeight<archetype::Weight_without_support>);

TEST_CASE("the intersection queries run on collision-object archetypes as on the model", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 3000, 0.0, 91);
    const archetype::Object object(columns(sample.points));
    const Arch arch(object);
    const PCCD::Rigid_transform_3<double> apart(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.5, 0.0, 0.0));
    const PCCD::Rigid_transform_3<double> overlapping(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0));
    const PCCD::Rigid_transform_3<double> identity;
    const PCCD::Interpolation_search on_the_fly{.paths = PCCD::Path_choice::on_the_fly};
    for (const bool expected : {false, true}) {
        const PCCD::Rigid_transform_3<double>& pose = expected ? overlapping : apart;
        const auto model = PCCD::do_intersect(object, identity, object, pose);
        const auto with_archetype = PCCD::do_intersect(arch, identity, arch, pose);
        CHECK(model.intersects == expected);
        CHECK(with_archetype.intersects == model.intersects);
        CHECK(with_archetype.counters.f_evaluations == model.counters.f_evaluations);
        CHECK(PCCD::do_intersect(arch, identity, object, pose, {}, PCCD::Randomized_sampling{}).intersects == expected);
        CHECK(PCCD::do_intersect(arch, identity, arch, pose, {}, on_the_fly).intersects == expected);
        CHECK(PCCD::do_intersect(arch, identity, arch, pose, {}, archetype::Leaf_intersector{}).intersects == expected);
        // Without a CPSP map: the Euclidean partners and chord paths, with both policies (the
        // certification of "separate" runs the interpolation search whatever the policy).
        const Euclidean_arch euclidean(object);
        CHECK(PCCD::do_intersect(euclidean, identity, euclidean, pose).intersects == expected);
        CHECK(PCCD::do_intersect(euclidean, identity, arch, pose).intersects == expected);
        CHECK(PCCD::do_intersect(euclidean, identity, euclidean, pose, {}, PCCD::Randomized_sampling{}).intersects == expected);
        const auto curve = PCCD::intersection_points(arch, identity, arch, pose);
        CHECK(curve.points.size() == PCCD::intersection_points(object, identity, object, pose).points.size());
    }
}

// CollisionObject is also all ray_intersection() may use.
TEST_CASE("the ray query runs on the collision-object archetype as on the model", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 3000, 0.0, 93);
    const archetype::Object object(columns(sample.points));
    const Arch arch(object);
    const PCCD::Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0.0, 0.0));
    for (const double y : {0.3, 1.5}) {
        const Eigen::Vector3d origin(0.5, y, -3.0), direction(0.0, 0.0, 1.0);
        const PCCD::Ray_hit model = PCCD::ray_intersection(object, pose, origin, direction);
        const PCCD::Ray_hit with_archetype = PCCD::ray_intersection(arch, pose, origin, direction);
        CHECK(model.hit == (y < 1.0));
        CHECK(with_archetype.hit == model.hit);
        CHECK(with_archetype.counters.f_evaluations == model.counters.f_evaluations);
        if (model.hit) CHECK(with_archetype.t == model.t);
    }
}

TEST_CASE("the proximity queries run on proximity-object archetypes as on the model", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 3000, 0.0, 92);
    const archetype::Object object(columns(sample.points));
    const archetype::Proximity_object arch(object);
    const PCCD::Rigid_transform_3<double> identity;
    for (const double shift : {1.8, 2.3}) {
        const PCCD::Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(shift, 0.0, 0.0));
        const PCCD::Distance_options options{.penetration = true};
        const PCCD::Distance_result model = PCCD::distance(object, identity, object, pose, options);
        const PCCD::Distance_result with_archetype = PCCD::distance(arch, identity, arch, pose, options);
        CHECK(with_archetype.status == model.status);
        CHECK(with_archetype.counters == model.counters);
        CHECK((std::isnan(model.distance) ? std::isnan(with_archetype.distance) : with_archetype.distance == model.distance));
        CHECK(PCCD::within_distance(arch, identity, arch, pose, 0.5).within);
        CHECK(PCCD::contacts(arch, identity, arch, pose).contacts.size() == PCCD::contacts(object, identity, object, pose).contacts.size());
    }
}

TEST_CASE("the batch queries run on collision-object archetypes as on the model", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 2000, 0.0, 98);
    const archetype::Object object(columns(sample.points));
    const Arch arch(object);
    std::vector<PCCD::Posed_pair<Arch, Arch>> on_archetype;
    std::vector<PCCD::Posed_pair<archetype::Object, archetype::Object>> on_model;
    const PCCD::Rigid_transform_3<double> identity;
    for (const double shift : {0.5, 1.5, 2.5, 3.0}) {
        const PCCD::Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(shift, 0.0, 0.0));
        on_archetype.push_back({&arch, identity, &arch, pose});
        on_model.push_back({&object, identity, &object, pose});
    }
    const auto expected = PCCD::do_intersect_many(on_model);
    const auto found = PCCD::do_intersect_many(on_archetype, {.threads = 2});
    const auto points = PCCD::intersection_points_many(on_archetype, {}, {}, PCCD::Randomized_sampling{});
    REQUIRE(found.size() == 4);
    for (std::size_t k = 0; k < found.size(); ++k) {
        CHECK(expected[k].intersects == (k < 2)); // unit spheres overlap below a shift of 2
        CHECK(found[k].intersects == expected[k].intersects);
        CHECK(found[k].counters.f_evaluations == expected[k].counters.f_evaluations);
        CHECK(points[k].intersects == expected[k].intersects);
    }
}

namespace archetype {
/// Exactly what RigidMotion requires, over a Linear_motion.
class Motion {
public:
    explicit Motion(const PCCD::Linear_motion& m) : m_motion(m) {}
    PCCD::Rigid_transform_3<double> pose(double t) const { return m_motion.pose(t); }
    double max_point_speed(const Eigen::Vector3d& c, double r) const { return m_motion.max_point_speed(c, r); }

private:
    PCCD::Linear_motion m_motion;
};
struct Motion_without_speed {
    PCCD::Rigid_transform_3<double> pose(double t) const;
};
struct Motion_with_matrix_pose {
    Eigen::Matrix4d pose(double t) const;
    double max_point_speed(const Eigen::Vector3d& c, double r) const;
};
} // namespace archetype

static_assert(PCCD::RigidMotion<archetype::Motion>);
static_assert(!PCCD::RigidMotion<archetype::Motion_without_speed>);
static_assert(!PCCD::RigidMotion<archetype::Motion_with_matrix_pose>);

TEST_CASE("continuous collision runs on motion and proximity-object archetypes as on the models", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 2000, 0.0, 96);
    const archetype::Object object(columns(sample.points));
    const archetype::Proximity_object arch(object);
    const PCCD::Rigid_transform_3<double> origin;
    const PCCD::Linear_motion still(origin, origin);
    const PCCD::Linear_motion through(PCCD::Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(4, 0, 0)),
                                      PCCD::Rigid_transform_3<double>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-4, 0, 0)));
    const auto model = PCCD::time_of_contact(object, still, object, through);
    const auto with_archetypes = PCCD::time_of_contact(arch, archetype::Motion(still), arch, archetype::Motion(through));
    CHECK(model.status == PCCD::Contact_time_status::contact);
    CHECK(with_archetypes.status == model.status);
    CHECK(with_archetypes.t == model.t);
    CHECK(with_archetypes.counters == model.counters);
}

TEST_CASE("a collision world runs on proximity-object archetypes as on the model", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 2000, 0.0, 97);
    const auto object = std::make_shared<const archetype::Object>(columns(sample.points));
    const auto arch = std::make_shared<const archetype::Proximity_object>(*object);
    PCCD::Collision_world<archetype::Object> on_model;
    PCCD::Collision_world<archetype::Proximity_object> on_archetype;
    for (const double shift : {0.0, 1.5, 3.0, 6.5, 7.0}) {
        const PCCD::Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(shift, 0.0, 0.0));
        on_model.insert(object, pose);
        on_archetype.insert(arch, pose);
    }
    const auto expected = on_model.intersecting_pairs();
    const auto found = on_archetype.intersecting_pairs();
    REQUIRE(expected.size() == 3); // 0-1.5, 1.5-3, 6.5-7
    REQUIRE(found.size() == expected.size());
    for (std::size_t k = 0; k < found.size(); ++k) CHECK(found[k] == expected[k]);
    const PCCD::World_handle first = on_archetype.handles().front();
    CHECK(on_archetype.within_distance(first, 0.2).size() == on_model.within_distance(on_model.handles().front(), 0.2).size());
    CHECK(on_archetype.intersecting(*arch, PCCD::Rigid_transform_3<double>()).size() == 2);
    CHECK(on_archetype.overlapping(Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.1), Eigen::Vector3d::Constant(0.1))).empty());
}

TEST_CASE("the preprocessing runs on the kernel archetype as on the default kernel", "[concepts]")
{
    // The same points in the archetype kernel and in Eigen_kernel<double>: the same graphs, sampling
    // radius, outliers, domain radii and distances (the archetype adds no rounding: FT is double).
    const auto sample = sample_shape(test_torus(), 1500, 0.01, 99);
    const PCCD::Point_cloud<> model(sample.points);
    const PCCD::Point_cloud<archetype::Kernel> cloud(sample.points);
    CHECK(PCCD::knn_graph(cloud) == PCCD::knn_graph(model));
    const PCCD::Proximity_graph graph = PCCD::sphere_of_influence_graph(cloud);
    CHECK(graph == PCCD::sphere_of_influence_graph(model));
    const double r = PCCD::sampling_radius(cloud);
    CHECK(r == PCCD::sampling_radius(model));
    const std::vector<std::uint32_t> half = {0, 2, 4, 6, 8, 10, 12, 14, 16, 18};
    CHECK(PCCD::sampling_radius(cloud, half) == PCCD::sampling_radius(model, half));
    CHECK(PCCD::find_outliers(cloud) == PCCD::find_outliers(model));
    CHECK(PCCD::surface_domain_radii(cloud) == PCCD::surface_domain_radii(model));
    const auto map = std::make_shared<const PCCD::Close_pairs_shortest_paths>(graph, r);
    const PCCD::Geodesic_distance<archetype::Kernel> geodesic(cloud, map);
    const PCCD::Geodesic_distance<> geodesic_model(model, map);
    const PCCD::Euclidean_distance<archetype::Kernel> euclidean(cloud);
    const PCCD::Euclidean_distance<> euclidean_model(model);
    for (std::uint32_t i = 0; i < 1500; i += 101) {
        const Eigen::Vector3d x = model.position(i) + Eigen::Vector3d(0.01, -0.02, 0.015);
        std::vector<std::pair<std::uint32_t, double>> a, b, c, d;
        const auto na = geodesic.for_each_neighbor(x, 3 * r, [&](std::uint32_t j, double g) { a.emplace_back(j, g); });
        const auto nb = geodesic_model.for_each_neighbor(x, 3 * r, [&](std::uint32_t j, double g) { b.emplace_back(j, g); });
        const auto nc = euclidean.for_each_neighbor(x, 3 * r, [&](std::uint32_t j, double g) { c.emplace_back(j, g); });
        const auto nd = euclidean_model.for_each_neighbor(x, 3 * r, [&](std::uint32_t j, double g) { d.emplace_back(j, g); });
        CHECK(na == nb);
        CHECK(a == b);
        CHECK(nc == nd);
        CHECK(c == d);
        CHECK(!a.empty());
    }
}

TEST_CASE("a point cloud object builds and collides with kernel and point-map archetypes", "[concepts]")
{
    // The same points through a user record and map, and in a kernel with nothing but the required
    // constructions: the same object (points, normals) and the same answers as the default model.
    const auto sample = sample_shape(unit_sphere(), 2000, 0.0, 95);
    std::vector<archetype::Scan_record> records;
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i)
        records.push_back({{float(sample.points(0, i)), float(sample.points(1, i)), float(sample.points(2, i))}, 7});
    std::vector<Eigen::Vector3d> points;
    for (const auto& r : records) points.push_back(get(archetype::Point_map{}, r));
    const archetype::Object model(points);
    const archetype::Object mapped(records, archetype::Point_map{});
    const PCCD::Point_cloud_object<archetype::Kernel> kernel(records, archetype::Point_map{});
    CHECK(mapped.normals() == model.normals());
    CHECK(kernel.normals() == model.normals());
    const auto p = kernel.cloud().point(3);
    CHECK(p.x == model.cloud().position(3).x());
    const PCCD::Rigid_transform_3<double> identity;
    for (const double shift : {1.0, 2.5}) {
        const PCCD::Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(shift, 0.0, 0.0));
        const auto expected = PCCD::do_intersect(model, identity, model, pose);
        CHECK(expected.intersects == (shift < 2.0));
        CHECK(PCCD::do_intersect(kernel, identity, mapped, pose).intersects == expected.intersects);
        CHECK(PCCD::do_intersect(kernel, identity, kernel, pose).counters.f_evaluations ==
              expected.counters.f_evaluations);
    }
}

TEST_CASE("the reach traversals tell a pair-observer archetype of every pair they count", "[concepts]")
{
    const auto sample = sample_shape(unit_sphere(), 2000, 0.0, 93);
    const PCCD::Point_cloud_object<> a(columns(sample.points)); // a cloud with reaches
    const PCCD::Point_cloud_hierarchy& h = a.hierarchy();
    const PCCD::Rigid_transform_3<double> shift(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.5, 0.2, 0.0));
    const PCCD::Reach_rule rule{};
    archetype::Pair_observer walk, meet;
    const PCCD::Reach_counters c = PCCD::for_each_leaf_pair_within_reach(
        h, h, shift, rule, rule, [](std::uint32_t, std::uint32_t) { return true; }, true, false, walk);
    CHECK(walk.nodes == c.node_pairs);
    CHECK(walk.leaves == c.leaf_pairs);
    CHECK(c.leaf_pairs > 0);
    PCCD::Reach_counters counters;
    CHECK(PCCD::reaches_meet(h, h, shift, rule, rule, counters, std::numeric_limits<std::size_t>::max(), meet));
    CHECK(meet.nodes == counters.node_pairs);
    CHECK(meet.leaves == counters.leaf_pairs);
}

TEST_CASE("stored and on-the-fly paths give the interpolation search the same curves", "[concepts]")
{
    // Paths on the fly are shortest paths of the same length as the stored ones (ties aside), so
    // the curves of two overlapping unit spheres (the circle x = 0.5, radius sqrt(3) / 2) agree.
    const auto sample = sample_shape(unit_sphere(), 4000, 0.0, 92);
    const archetype::Object object(columns(sample.points));
    const PCCD::Rigid_transform_3<double> pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, 0.0));
    const PCCD::Rigid_transform_3<double> identity;
    for (const auto paths : {PCCD::Path_choice::stored, PCCD::Path_choice::on_the_fly}) {
        const auto curve = PCCD::intersection_points(object, identity, object, pose, {},
                                                     PCCD::Interpolation_search{.paths = paths});
        INFO("paths " << int(paths));
        REQUIRE(curve.points.size() > 30); // about 5.4 / the point spacing (r)
        for (const auto& p : curve.points) {
            CHECK(std::abs(p.position.x() - 0.5) < 0.02);
            CHECK(std::abs(Eigen::Vector2d(p.position.y(), p.position.z()).norm() - std::sqrt(0.75)) < 0.02);
        }
    }
    CHECK_THROWS_AS(PCCD::do_intersect(object, identity, object, pose, {},
                                       PCCD::Interpolation_search{.paths = PCCD::Path_choice(9)}),
                    PCCD::Invalid_input);
}

TEST_CASE("the implicit surface runs on distance and weight archetypes as on the models", "[concepts]")
{
    const auto sample = sample_shape(test_torus(), 2000, 0.1, 93);
    const PCCD::Point_cloud<> cloud(sample.points);
    const PCCD::Euclidean_distance<> distance(cloud);
    const PCCD::Gaussian_weight weight(0.08, 0.01);
    const archetype::Distance arch_distance(distance);
    const archetype::Weight arch_weight(weight);
    const auto normals = PCCD::estimate_normals(distance, weight);
    const auto arch_normals = PCCD::estimate_normals(arch_distance, arch_weight);
    CHECK(arch_normals.normals == normals.normals);
    for (const PCCD::Surface_fit fit : {PCCD::Surface_fit::plane, PCCD::Surface_fit::sphere}) {
        const PCCD::WLS_surface<PCCD::Euclidean_distance<>> model(distance, weight, sample.normals, {}, fit);
        const PCCD::WLS_surface<archetype::Distance, archetype::Weight> arch(arch_distance, arch_weight,
                                                                             sample.normals, {}, fit);
        for (const Query& q : queries_near(test_torus(), 50, 0.05, 94)) {
            const auto a = arch.evaluate(q.x), m = model.evaluate(q.x);
            CHECK(a.status == m.status);
            if (m.defined()) CHECK(a.value == m.value);
        }
        CHECK(arch.evaluate_at(7).value == model.evaluate_at(7).value);
    }
}

TEST_CASE("normal orientation and paths on the fly run on a graph archetype as on the model", "[concepts]")
{
    // The object's proximity graph copied into the archetype (real edges only, same order): the
    // same orientation and the same path lengths as on PCCD's own graph type.
    const auto sample = sample_shape(test_torus(), 2000, 0.0, 96);
    const archetype::Object object(columns(sample.points));
    const PCCD::Proximity_graph& model = object.graph();
    archetype::Graph graph;
    graph.offsets.push_back(0);
    for (std::uint32_t v = 0; v < model.num_vertices(); ++v) {
        for (auto e = model.row_offsets()[v]; e < model.row_offsets()[v + 1]; ++e) {
            if (model.edge_property(e).is_virtual) continue;
            graph.targets.push_back(model.targets()[e]);
            graph.lengths.push_back(model.edge_property(e).length);
        }
        graph.offsets.push_back(graph.targets.size());
    }
    Eigen::Matrix3Xd on_model = object.normals(), on_archetype = object.normals();
    for (Eigen::Index i = 0; i < on_model.cols(); i += 3) { // scramble some signs
        on_model.col(i) *= -1.0;
        on_archetype.col(i) *= -1.0;
    }
    const auto report_model = PCCD::orient_normals(model, object.cloud().coordinates(), on_model);
    const auto report_archetype = PCCD::orient_normals(graph, object.cloud().coordinates(), on_archetype);
    CHECK(on_archetype == on_model);
    CHECK(report_archetype.flipped == report_model.flipped);
    CHECK(report_archetype.components == report_model.components);

    const PCCD::Paths_on_the_fly<archetype::Graph, archetype::Length_map> archetype_paths(
        graph, archetype::Length_map{&graph}, object.cloud().coordinates(), {.bound = object.cpsp().bound()});
    const auto model_paths = PCCD::paths_on_the_fly(model, object.cloud(), {.bound = object.cpsp().bound()});
    std::vector<std::uint32_t> a, m;
    std::size_t found = 0;
    for (std::uint32_t from = 0; from < 2000; from += 97)
        for (const std::uint32_t to : object.cpsp().targets(from)) {
            const bool on_archetype_graph = archetype_paths.path(from, to, a);
            REQUIRE(on_archetype_graph == model_paths.path(from, to, m));
            found += on_archetype_graph;
            const auto length = [&](const std::vector<std::uint32_t>& path) {
                double sum = 0.0;
                for (std::size_t k = 0; k + 1 < path.size(); ++k)
                    sum += (object.cloud().position(path[k]) - object.cloud().position(path[k + 1])).norm();
                return sum;
            };
            CHECK(length(a) == Catch::Detail::Approx(length(m)).epsilon(1e-6));
        }
    CHECK(found > 100);
}

TEST_CASE("the CPSP map builds over a graph archetype as over the model", "[concepts]")
{
    // Every edge of the object's graph, virtual ones included, copied into the archetype with its
    // flag: both bounded Dijkstras, over real edges only and over all edges, give the lists of the
    // CPSP map of PCCD's own graph type (same points, same distances up to float rounding).
    const auto sample = sample_shape(test_torus(), 1500, 0.0, 97);
    const archetype::Object object(columns(sample.points));
    const PCCD::Proximity_graph& model = object.graph();
    archetype::Graph graph;
    graph.offsets.push_back(0);
    std::size_t virtual_edges = 0;
    for (std::uint32_t v = 0; v < model.num_vertices(); ++v) {
        for (auto e = model.row_offsets()[v]; e < model.row_offsets()[v + 1]; ++e) {
            graph.targets.push_back(model.targets()[e]);
            graph.lengths.push_back(model.edge_property(e).length);
            graph.flags.push_back(model.edge_property(e).is_virtual);
            virtual_edges += model.edge_property(e).is_virtual;
        }
        graph.offsets.push_back(graph.targets.size());
    }
    INFO(virtual_edges << " virtual edges");
    // Components and the long-edge marking on the archetype: as on the model.
    const PCCD::Graph_components components = PCCD::graph_components(graph, archetype::Flag_map{&graph});
    CHECK(components.count == PCCD::graph_components(model).count);
    CHECK(components.label == PCCD::graph_components(model).label);
    const std::vector<bool> marked_by_model = graph.flags;
    graph.flags.assign(graph.flags.size(), false);
    CHECK(PCCD::mark_long_edges(graph, archetype::Length_map{&graph}, archetype::Writable_flag_map{&graph}) ==
          virtual_edges / 2);
    CHECK(graph.flags == marked_by_model);
    const double r = object.sampling_radius();
    for (const auto algorithm : {PCCD::Bounded_dijkstra::hand_written, PCCD::Bounded_dijkstra::boost})
        for (const bool use_virtual : {false, true}) {
            INFO("algorithm " << int(algorithm) << ", virtual edges " << use_virtual);
            const PCCD::Cpsp_options options{.use_virtual_edges = use_virtual, .algorithm = algorithm};
            const PCCD::Close_pairs_shortest_paths expected(model, r, options);
            const PCCD::Close_pairs_shortest_paths on_archetype(graph, archetype::Length_map{&graph}, r, options,
                                                                archetype::Flag_map{&graph});
            REQUIRE(on_archetype.size() == expected.size());
            CHECK(on_archetype.num_entries() == expected.num_entries());
            CHECK(expected.num_entries() > 10 * expected.size());
            for (std::uint32_t p = 0; p < expected.size(); p += 7) {
                const auto targets = on_archetype.targets(p);
                REQUIRE(targets.size() == expected.targets(p).size());
                for (std::size_t k = 0; k < targets.size(); ++k) {
                    const std::size_t at = expected.find(p, targets[k]);
                    REQUIRE(at != PCCD::Close_pairs_shortest_paths::npos);
                    CHECK(on_archetype.distances(p)[k] == Catch::Detail::Approx(expected.distances(p)[at]).epsilon(1e-6));
                }
            }
        }
}
