// PCCD/Exact/Exact_mesh.h -- a triangle mesh prepared once for the exact reference queries of
// PCCD/Exact/ (doc/design.md, "Exact checks"; the truth behind the validation of doc/algorithms.md,
// "Randomized sampling" and "Interpolation search", and of the grazing rule of its "Benchmark
// procedure"): a CGAL Surface_mesh over the kernel with exact predicates (Epick), its AABB tree, an
// inside/outside oracle and a few facts about its topology.
//
// Every query of a pose pair works in the local frame of one mesh and maps only the other mesh's
// vertices into it, so the trees built here are reused for every pose: nothing is rebuilt per pose
// but one array of transformed vertices.
//
// This header includes CGAL's Polygon_mesh_processing: include it only where the exact reference is
// needed (tests, validation, benchmarks), never from the core headers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <optional>
#include <vector>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/IO/Triangle_mesh_data.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/internal/finite.h>

namespace PCCD {

/// A triangle mesh ready for exact intersection, containment and distance queries under rigid
/// motions (see exact_do_intersect, exact_containment, exact_intersection_polylines,
/// exact_separation).
///
/// Geometry and exactness: the vertices are stored as given (doubles) in a CGAL::Surface_mesh over
/// CGAL::Exact_predicates_inexact_constructions_kernel, whose predicates (orientation, triangle
/// intersection, ray parity) are exact for these doubles. A query on a pose pair maps the vertices
/// of one mesh into the local frame of the other with the relative motion T_fixed^-1 T_moved,
/// rounding each coordinate to the nearest double: the mapped mesh differs from the ideal one by a
/// few units in the last place of its coordinates (about 1e-15 for the normalized objects of the
/// benchmark, which fit [-1, 1]^3), while the sampling radius of a cloud of even 10^8 points on
/// such an object is above 1e-4: the rounding can only change the answer for poses that are
/// grazing by ten orders of magnitude. The decisions are then exact for the rounded coordinates.
///
/// Preprocessing (once): the soup is turned into a halfedge mesh (non-manifold vertices are
/// duplicated and inconsistently oriented triangles flipped when needed, as by
/// CGAL::Polygon_mesh_processing::orient_polygon_soup, which leaves the surface as a point set
/// unchanged), an AABB tree of the triangles is built with accelerated distance queries, the mesh
/// is tested for self-intersections, vertices used by no triangle are dropped, one vertex of each
/// connected component is kept for the containment tests, and the vertices are grouped into small
/// ball tree for the distance queries.
///
/// Move-only (the tree refers to the mesh, which therefore lives at a fixed address on the heap); a
/// moved-from Exact_mesh may only be destroyed or assigned to.
/// All member functions are const and safe to call concurrently once constructed.
class Exact_mesh {
public:
    /// \name Types
    /// @{
    /// The CGAL kernel: exact predicates, constructions in double.
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Point_3 = Kernel::Point_3;
    using Segment_3 = Kernel::Segment_3;
    using Triangle_3 = Kernel::Triangle_3;
    /// The halfedge mesh; its vertex and face indices are 0 .. n - 1 without gaps.
    using Triangle_mesh = CGAL::Surface_mesh<Point_3>;
    using Vertex_index = Triangle_mesh::Vertex_index;
    using Face_index = Triangle_mesh::Face_index;
    /// CGAL's ray-parity inside test, sharing this mesh's AABB tree.
    using Side_of_triangle_mesh = CGAL::Side_of_triangle_mesh<Triangle_mesh, Kernel>;
    /// The AABB tree of the triangles (the tree type Side_of_triangle_mesh expects).
    using AABB_tree = Side_of_triangle_mesh::AABB_tree;
    /// A node of the vertex ball tree: the vertices ball_tree_vertices()[begin, end) all lie in the
    /// ball of centre `centre` and radius `radius` (local frame; the radius is enlarged by a relative
    /// 1e-9 so that the rounding of a rigid motion or of a distance cannot move a vertex out of it).
    /// An inner node has the two children `children` (indices into vertex_ball_tree()) splitting its
    /// range; a leaf (at most max_leaf_size vertices) has `children` {0, 0}.
    struct Vertex_ball {
        Point_3 centre;
        double radius;
        /// The longest edge incident to a vertex of the node.
        double longest_incident_edge;
        std::size_t begin;
        std::size_t end;
        std::array<std::size_t, 2> children;
        bool is_leaf() const { return children[0] == 0; }
    };
    /// @}

    /// Builds the mesh, its tree and its topological facts from a triangle soup.
    /// \throws Invalid_input if there is no vertex or no triangle, a vertex coordinate is NaN or
    ///         infinite, a triangle refers to a vertex that does not exist or twice to the same
    ///         vertex, three vertices of a triangle are collinear (exact test: the triangle has no
    ///         area), or the triangles cannot be made into a manifold surface (e.g. an edge shared
    ///         by more than two triangles). Each message names the vertex or triangle.
    /// Complexity: O(n log n) for n triangles (tree, self-intersection test by box intersection).
    explicit Exact_mesh(const Triangle_mesh_data& data) : m_data(std::make_unique<Data>())
    {
        check_input(data);
        build_mesh(data);
        Data& d = *m_data;
        d.tree.insert(faces(d.mesh).first, faces(d.mesh).second, d.mesh);
        d.tree.build();
        d.tree.accelerate_distance_queries();
        d.closed = CGAL::is_closed(d.mesh);
        d.self_intersecting = CGAL::Polygon_mesh_processing::does_self_intersect(d.mesh);
        if (d.closed && !d.self_intersecting) d.side.emplace(d.tree);
        find_component_representatives();
        std::vector<double> longest_incident(d.mesh.number_of_vertices(), 0.0);
        for (const auto e : edges(d.mesh)) {
            const Triangle_mesh::Halfedge_index h = d.mesh.halfedge(e);
            const Vertex_index u = d.mesh.source(h), w = d.mesh.target(h);
            const double length = std::sqrt(CGAL::squared_distance(d.mesh.point(u), d.mesh.point(w)));
            longest_incident[u] = std::max(longest_incident[u], length);
            longest_incident[w] = std::max(longest_incident[w], length);
            d.longest_edge = std::max(d.longest_edge, length);
        }
        d.ball_vertices.assign(vertices(d.mesh).begin(), vertices(d.mesh).end());
        build_ball(0, d.ball_vertices.size(), longest_incident);
    }

    Exact_mesh(Exact_mesh&&) noexcept = default;
    Exact_mesh& operator=(Exact_mesh&&) noexcept = default;
    Exact_mesh(const Exact_mesh&) = delete;
    Exact_mesh& operator=(const Exact_mesh&) = delete;

    /// \name Access (O(1))
    /// @{
    /// The halfedge mesh, in the local frame of the input coordinates.
    const Triangle_mesh& mesh() const { return m_data->mesh; }
    /// The AABB tree of the triangles of mesh(), in the local frame.
    const AABB_tree& tree() const { return m_data->tree; }
    /// Number of vertices of mesh(): the input's, minus those used by no triangle, plus the copies
    /// made when non-manifold vertices were split.
    std::size_t number_of_vertices() const { return m_data->mesh.number_of_vertices(); }
    /// Number of triangles.
    std::size_t number_of_triangles() const { return m_data->mesh.number_of_faces(); }
    /// Whether every edge has two incident triangles.
    bool is_closed() const { return m_data->closed; }
    /// Whether two triangles intersect other than at a shared vertex or edge (exact test).
    bool is_self_intersecting() const { return m_data->self_intersecting; }
    /// Whether the mesh is closed and free of self-intersections, so that it bounds a volume and
    /// the inside test bounded_side() is defined (by ray parity; the orientation does not matter).
    bool encloses_volume() const { return m_data->side.has_value(); }
    /// One vertex of each connected component of mesh().
    const std::vector<Vertex_index>& component_representatives() const { return m_data->representatives; }
    /// A binary ball tree over the vertices (median splits along the longest box side), root first:
    /// exact_separation bounds the distances of all the vertices of a node with one closest-point
    /// query at its centre and descends only into the nodes that can matter.
    const std::vector<Vertex_ball>& vertex_ball_tree() const { return m_data->balls; }
    /// The vertices in ball-tree order: each node of vertex_ball_tree() holds a contiguous range.
    const std::vector<Vertex_index>& ball_tree_vertices() const { return m_data->ball_vertices; }
    /// The largest number of vertices in a leaf of the ball tree.
    static constexpr std::size_t max_leaf_size = 16;
    /// The length of the longest edge (the mesh resolution that bounds the error of vertex-based
    /// estimates such as the penetration depth of exact_separation).
    double longest_edge_length() const { return m_data->longest_edge; }
    /// @}

    /// Where `p` (local coordinates) lies: CGAL::ON_BOUNDED_SIDE inside, ON_BOUNDARY on the surface,
    /// ON_UNBOUNDED_SIDE outside. Exact (ray parity with exact predicates).
    /// \pre encloses_volume() (else throws Invalid_input).
    /// Complexity: O(log n) expected. Thread-safe.
    CGAL::Bounded_side bounded_side(const Point_3& p) const
    {
        if (!encloses_volume())
            throw Invalid_input(is_closed() ? "exact mesh: inside test on a self-intersecting mesh"
                                            : "exact mesh: inside test on a mesh that is not closed");
        return (*m_data->side)(p);
    }

    /// The vertices of mesh() mapped by `transformation` and rounded to double, indexed by vertex
    /// index. Complexity: O(n). Thread-safe.
    std::vector<Point_3> transformed_points(const Rigid_transform_3<double>& transformation) const
    {
        std::vector<Point_3> points;
        points.reserve(number_of_vertices());
        for (const Vertex_index v : vertices(m_data->mesh)) {
            const Point_3& p = m_data->mesh.point(v);
            const Eigen::Vector3d q = transformation.transform_point(Eigen::Vector3d(p.x(), p.y(), p.z()));
            points.emplace_back(q.x(), q.y(), q.z());
        }
        return points;
    }

    /// The triangle of face `f` with its vertices taken from `points` (as returned by
    /// transformed_points). O(1).
    Triangle_3 triangle(Face_index f, const std::vector<Point_3>& points) const
    {
        const Triangle_mesh& m = m_data->mesh;
        const auto h = m.halfedge(f);
        return Triangle_3(points[m.source(h)], points[m.target(h)], points[m.target(m.next(h))]);
    }

private:
    struct Data {
        Triangle_mesh mesh;
        AABB_tree tree;
        std::optional<Side_of_triangle_mesh> side;
        std::vector<Vertex_index> representatives;
        std::vector<Vertex_ball> balls;
        std::vector<Vertex_index> ball_vertices;
        bool closed = false;
        bool self_intersecting = false;
        double longest_edge = 0.0;
    };

    static void check_input(const Triangle_mesh_data& data)
    {
        if (data.vertices.empty()) throw Invalid_input("exact mesh: the mesh has no vertex");
        if (data.triangles.empty()) throw Invalid_input("exact mesh: the mesh has no triangle");
        for (std::size_t i = 0; i < data.vertices.size(); ++i)
            if (!internal::all_finite(data.vertices[i]))
                throw Invalid_input(internal::concat("exact mesh: vertex ", i, " (", data.vertices[i].transpose(),
                                                     ") is not finite"));
        const Kernel::Collinear_3 collinear = Kernel().collinear_3_object();
        for (std::size_t t = 0; t < data.triangles.size(); ++t) {
            const auto& tri = data.triangles[t];
            for (const std::uint32_t index : tri)
                if (index >= data.vertices.size())
                    throw Invalid_input(internal::concat("exact mesh: triangle ", t, " refers to vertex ", index,
                                                         " but there are ", data.vertices.size(), " vertices"));
            if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
                throw Invalid_input(internal::concat("exact mesh: triangle ", t, " repeats a vertex (", tri[0],
                                                     ", ", tri[1], ", ", tri[2], ")"));
            const auto point = [&](std::uint32_t i) {
                return Point_3(data.vertices[i].x(), data.vertices[i].y(), data.vertices[i].z());
            };
            if (collinear(point(tri[0]), point(tri[1]), point(tri[2])))
                throw Invalid_input(internal::concat("exact mesh: triangle ", t, " (vertices ", tri[0], ", ", tri[1],
                                                     ", ", tri[2], ") has collinear vertices (no area)"));
        }
    }

    void build_mesh(const Triangle_mesh_data& data)
    {
        namespace PMP = CGAL::Polygon_mesh_processing;
        std::vector<Point_3> points;
        points.reserve(data.vertices.size());
        for (const Eigen::Vector3d& v : data.vertices) points.emplace_back(v.x(), v.y(), v.z());
        std::vector<std::array<std::size_t, 3>> polygons;
        polygons.reserve(data.triangles.size());
        for (const auto& t : data.triangles) polygons.push_back({t[0], t[1], t[2]});
        if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
            PMP::orient_polygon_soup(points, polygons);
            if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
                throw Invalid_input("exact mesh: the triangles do not form a manifold surface even after splitting "
                                    "non-manifold vertices (duplicate triangles or an edge shared by more than two "
                                    "triangles)");
        }
        PMP::polygon_soup_to_polygon_mesh(points, polygons, m_data->mesh);
    }

    void find_component_representatives()
    {
        Data& d = *m_data;
        std::vector<std::size_t> component_of(d.mesh.number_of_faces());
        const auto face_component = boost::make_iterator_property_map(component_of.begin(),
                                                                      get(boost::face_index, d.mesh));
        const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(d.mesh, face_component);
        std::vector<bool> seen(count, false);
        for (const Face_index f : faces(d.mesh)) {
            const std::size_t c = component_of[f];
            if (seen[c]) continue;
            seen[c] = true;
            d.representatives.push_back(d.mesh.target(d.mesh.halfedge(f)));
        }
    }

    /// Appends the node of ball_vertices[begin, end) and its subtree; returns its index.
    std::size_t build_ball(std::size_t begin, std::size_t end, const std::vector<double>& longest_incident)
    {
        Data& d = *m_data;
        const auto first = d.ball_vertices.begin() + std::ptrdiff_t(begin);
        const auto last = d.ball_vertices.begin() + std::ptrdiff_t(end);
        CGAL::Bbox_3 box;
        double band = 0.0;
        for (auto it = first; it != last; ++it) {
            box += d.mesh.point(*it).bbox();
            band = std::max(band, longest_incident[*it]);
        }
        const Point_3 centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
        double radius = 0.0;
        for (auto it = first; it != last; ++it)
            radius = std::max(radius, std::sqrt(CGAL::squared_distance(centre, d.mesh.point(*it))));
        const double magnitude = std::sqrt(CGAL::squared_distance(centre, Point_3(CGAL::ORIGIN)));
        const std::size_t index = d.balls.size();
        d.balls.push_back({centre, radius + 1e-9 * (radius + magnitude), band, begin, end, {0, 0}});
        if (end - begin <= max_leaf_size) return index;
        int axis = 0;
        for (int i = 1; i < 3; ++i)
            if (box.max(i) - box.min(i) > box.max(axis) - box.min(axis)) axis = i;
        const std::size_t middle = begin + (end - begin) / 2;
        std::nth_element(first, d.ball_vertices.begin() + std::ptrdiff_t(middle), last,
                         [&](Vertex_index u, Vertex_index v) { return d.mesh.point(u)[axis] < d.mesh.point(v)[axis]; });
        const std::size_t left = build_ball(begin, middle, longest_incident);
        const std::size_t right = build_ball(middle, end, longest_incident);
        d.balls[index].children = {left, right};
        return index;
    }

    std::unique_ptr<Data> m_data;
};

} // namespace PCCD
