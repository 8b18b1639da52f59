// PCCD/Point_cloud_object_options.h -- what Point_cloud_object's preprocessing can be told and
// what it reports besides the object: Point_cloud_object_options (every stage's options, with
// their defaults), Preprocessing_times and Scan_estimate. Implements doc/manual/surface.md, "One
// call: Point_cloud_object" and "Scans: where the surface is defined, noise and outliers".
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Surface/Surface_fit.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/Surface/outliers.h>
#include <PCCD/Surface/surface_domain.h>
#include <PCCD/sampling_radius.h>

namespace PCCD {

/// Options of Point_cloud_object. Every field has a documented default; use designated
/// initializers: `{.graph = Graph_kind::knn, .bandwidth = {.eta = 2.5}}`.
struct Point_cloud_object_options {
    /// Which proximity graph to build. Default: the r-SIG (Graph_kind::sphere_of_influence).
    Graph_kind graph = Graph_kind::sphere_of_influence;
    /// Options of the r-SIG (default r = 3), used when graph == sphere_of_influence.
    Sphere_of_influence_graph_options sphere_of_influence = {};
    /// Options of the k-NN graph (default k = 8), used when graph == knn.
    Knn_graph_options knn = {};
    /// Options of the Monte-Carlo sampling radius r(P) (default: 0.99 quantile, 10^4 samples).
    Sampling_radius_options sampling_radius = {};
    /// The kernel: eta (default 3), theta_eps (default 1e-2), or a bandwidth h given by the user.
    Bandwidth_options bandwidth = {};
    /// The local shape the surface fits at each point (Surface_fit). Default: the sphere, whose zero
    /// set follows curvature (measured in doc/benchmarks.md "Accuracy on scans": about half the
    /// curve error of the plane on clean scans); Surface_fit::plane gives the published surface.
    Surface_fit surface_fit = Surface_fit::sphere;
    /// The surface's domain: f is defined only within D_i of the nearest cloud point (default: D_i =
    /// the distance to the 6th nearest other point).
    Surface_domain_options domain = {};
    /// Isolated points (stray returns of a scanner) left out of the surface before anything else is
    /// built (default: removed, see Outlier_options).
    Outlier_options outliers = {};
    /// The point cloud hierarchy the intersection queries traverse (default: leaves of 16 points).
    Point_cloud_hierarchy_options hierarchy = {};
    /// Store the points in a spatial (Morton, Z-order) order rather than in the order given, so that
    /// points near in space are near in memory: every stage that visits neighbourhoods (graph, CPSP
    /// map, normals, the queries' evaluations) then reads memory it has just read. Default: on;
    /// preprocessing a 10^6-point random-order sample took half the time (doc/benchmarks.md, "Scale:
    /// 10^6 points"). Point_cloud_object::input_index() maps each point back to its index among the
    /// points given.
    bool spatial_order = true;
    /// Worker threads of every stage; 0 (default) uses all available. Ignored without TBB. The
    /// result does not depend on it.
    unsigned threads = 0;
};

/// Wall-clock time of each preprocessing stage, in milliseconds (0 for a loaded object, except
/// kd_tree, which is rebuilt on load).
struct Preprocessing_times {
    double kd_tree = 0.0;
    double graph = 0.0;
    double sampling_radius = 0.0;
    double cpsp = 0.0;
    /// Normal estimation and orientation.
    double normals = 0.0;
    /// The point cloud hierarchy (rebuilt on load, like the kd-tree).
    double hierarchy = 0.0;
    /// The local spacing: outlier test and domain radii (0 for a loaded object, which reads them).
    double outliers = 0.0;
};

/// What preprocessing found out about the cloud as a scan (doc/manual/surface.md, "Scans").
struct Scan_estimate {
    /// The number of points given.
    std::size_t input_points = 0;
    /// The indices (into the points given, ascending) of the isolated outliers left out of the
    /// surface (Outlier_options); cloud() holds the other points (Point_cloud_object::input_index()
    /// maps them back).
    std::vector<std::uint32_t> outliers;
    /// The estimated noise level sigma of the points (noise_estimate(): median leave-one-out
    /// residual / 0.6745), length unit of the cloud. On clean samples it is the curvature the
    /// kernel's plane cannot follow: 0.1-0.15 mean spacings on 30k-point scans, more on coarse
    /// samples of curved shapes (0.27 on 2000 points of a sphere, 0.43 on a torus).
    double noise = 0.0;
};

} // namespace PCCD
