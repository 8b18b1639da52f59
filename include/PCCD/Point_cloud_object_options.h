// PCCD/Point_cloud_object_options.h -- what Point_cloud_object's preprocessing can be told and
// what it reports besides the object: Point_cloud_object_options (every stage's options, with
// their defaults, and a progress callback), resolve_threads() (which thread count each stage
// uses), Preprocessing_stage, Preprocessing_progress, Preprocessing_times and Scan_estimate. Implements doc/manual/surface.md, "One
// call: Point_cloud_object" and "Scans: where the surface is defined, noise and outliers".
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <vector>

#include <PCCD/Hierarchy/Point_cloud_hierarchy_options.h>
#include <PCCD/Proximity_graph/graph_options.h>
#include <PCCD/Surface/surface_options.h>
#include <PCCD/internal/timing.h>
#include <PCCD/sampling_radius_options.h>

namespace PCCD {

/// A stage of Point_cloud_object's preprocessing. They run in this order; cpsp_map and normals run
/// a second time when the noise estimate asks for a wider kernel (Bandwidth_options::noise_factor).
enum class Preprocessing_stage : std::uint8_t {
    kd_tree,         ///< the points are read and their kd-tree built
    outliers,        ///< isolated outliers found and left out (Outlier_options)
    graph,           ///< the proximity graph
    sampling_radius, ///< r(P) and the kernel bandwidth
    cpsp_map,        ///< the close pairs shortest paths within the kernel's support
    normals,         ///< the unoriented normals and the noise estimate
    orientation,     ///< the normals' orientation
    domain,          ///< the domain radii of the surface (Surface_domain_options)
    hierarchy,       ///< the point cloud hierarchy
};

/// The stage's name in words ("kd-tree", "CPSP map", ...).
constexpr const char* to_string(Preprocessing_stage stage)
{
    switch (stage) {
    case Preprocessing_stage::kd_tree: return "kd-tree";
    case Preprocessing_stage::outliers: return "outliers";
    case Preprocessing_stage::graph: return "proximity graph";
    case Preprocessing_stage::sampling_radius: return "sampling radius";
    case Preprocessing_stage::cpsp_map: return "CPSP map";
    case Preprocessing_stage::normals: return "normals";
    case Preprocessing_stage::orientation: return "orientation";
    case Preprocessing_stage::domain: return "domain";
    case Preprocessing_stage::hierarchy: return "hierarchy";
    }
    return "unknown stage";
}

/// What Point_cloud_object_options::progress is told: a stage starts (finished == false,
/// milliseconds == 0) or has ended (finished == true, milliseconds: its wall-clock time).
struct Preprocessing_progress {
    Preprocessing_stage stage = Preprocessing_stage::kd_tree;
    bool finished = false;
    double milliseconds = 0.0;
    /// The number of points the stage works on (before outlier removal for kd_tree and outliers).
    std::size_t points = 0;
};

/// Options of Point_cloud_object. Every field has a documented default; use designated
/// initializers: `{.graph = Graph_kind::knn, .bandwidth = {.eta = 2.5}}`.
struct Point_cloud_object_options {
    /// Which proximity graph to build. Default: the r-SIG (Graph_kind::sphere_of_influence).
    Graph_kind graph = Graph_kind::sphere_of_influence;
    /// Options of the r-SIG (default r = 3), used when graph == sphere_of_influence.
    Sphere_of_influence_graph_options sphere_of_influence = {};
    /// Options of the k-NN graph (default k = 8), used when graph == knn.
    Knn_graph_options knn = {};
    /// The lean object (Euclidean_point_cloud_object) only: the k of the bare symmetric k-NN graph its
    /// normals are oriented over (>= 1; default 6: against k = 8, at 10^6 points 27 % less
    /// orientation time and 32 B less peak memory per point, and no contact missed on the scan
    /// validation with either; doc/benchmarks.md "The lean object"). Point_cloud_object orients over
    /// its proximity graph.
    unsigned orientation_neighbors = 6;
    /// Options of the Monte-Carlo sampling radius r(P) (default: 0.99 quantile, 10^4 samples).
    Sampling_radius_options sampling_radius = {};
    /// The kernel: eta (default 3), theta_eps (default 1e-2), or a bandwidth h given by the user.
    Bandwidth_options bandwidth = {};
    /// The local shape the surface fits at each point (Surface_fit). Default: the sphere, whose zero
    /// set follows curvature (measured in doc/benchmarks.md "Accuracy on scans": about half the
    /// curve error of the plane on clean scans); Surface_fit::plane gives the published surface.
    Surface_fit surface_fit = Surface_fit::sphere;
    /// The stored normals are estimated with the kernel above, oriented, and then, when this is
    /// below 1, fitted again (refit_normals(), keeping their orientation) with a Gaussian of
    /// normal_bandwidth times the kernel's bandwidth and support: sharper across edges, noisier on
    /// noisy scans. Default 1 (no refit). Meant for Surface_fit::imls on parts with sharp edges: with
    /// bandwidth.theta_eps = 3e-5 (a Gaussian of 2/3 the default bandwidth within the same support),
    /// 0.75 (normals from half the default bandwidth) is the measured choice (doc/manual/surface.md,
    /// "Sharp features"). Must lie in (0, 1].
    double normal_bandwidth = 1.0;
    /// When set, the stored normals are also fitted again robustly (refit_normals() with
    /// residual_scale = normal_residual_scale times the kernel's bandwidth h): neighbours off the
    /// plane of the face a point lies on lose their weight, so normals near sharp edges turn to
    /// their face's instead of bending across the edge. Unset by default (no refit). Meant for
    /// Surface_fit::imls on parts with sharp edges; 0.25 (with theta_eps 3e-5 and normal_bandwidth
    /// 1) is the measured choice of doc/manual/surface.md, "Sharp features". Must be finite and > 0.
    std::optional<double> normal_residual_scale = std::nullopt;
    /// The surface's domain: f is defined only within D_i of the nearest cloud point (default: D_i =
    /// the distance to the 6th nearest other point).
    Surface_domain_options domain = {};
    /// Isolated points (stray returns of a scanner) left out of the surface before anything else is
    /// built (default: removed, see Outlier_options).
    Outlier_options outliers = {};
    /// The point cloud hierarchy the intersection queries traverse (default: leaves of 8 points, boxes
    /// and slabs). Its `threads`, when unset, takes `threads` below.
    Point_cloud_hierarchy_options hierarchy = {};
    /// Store the points in a spatial (Morton, Z-order) order rather than in the order given, so that
    /// points near in space are near in memory: every stage that visits neighbourhoods (graph, CPSP
    /// map, normals, the queries' evaluations) then reads memory it has just read. Default: on;
    /// preprocessing a 10^6-point random-order sample took half the time (doc/benchmarks.md, "Scale:
    /// 10^6 points"). Point_cloud_object::input_index() maps each point back to its index among the
    /// points given.
    bool spatial_order = true;
    /// Worker threads of the stages, >= 1 (at most 4096). Unset (default): all available. A
    /// stage whose own options set `threads` (knn.threads, sphere_of_influence.threads,
    /// sampling_radius.threads, domain.threads, outliers.threads) keeps its own count; a stage
    /// whose `threads` is unset uses this one; the CPSP map and the normals, which have no options
    /// here, use this one. Ignored without TBB. The result does not depend on it.
    std::optional<unsigned> threads = std::nullopt;
    /// Called at the start and at the end of every preprocessing stage, in order (see
    /// Preprocessing_progress), on the thread that builds the object. Empty (default): nothing is
    /// called. An exception it throws leaves the constructor. The pccd tool prints these on a
    /// terminal.
    std::function<void(const Preprocessing_progress&)> progress = {};
};

/// The options as the preprocessing stages use them: every stage's `threads` that is unset takes
/// options.threads (unset too when that is unset: all available threads); a stage's own count
/// stands. Point_cloud_object applies this rule; it is a function so that the rule can be seen.
inline Point_cloud_object_options resolve_threads(Point_cloud_object_options options)
{
    for (std::optional<unsigned>* stage : {&options.sphere_of_influence.threads, &options.knn.threads,
                                           &options.sampling_radius.threads, &options.domain.threads,
                                           &options.outliers.threads, &options.hierarchy.threads})
        if (!*stage) *stage = options.threads;
    return options;
}

/// Wall-clock time of each preprocessing stage, in milliseconds (0 for a loaded object, except
/// kd_tree, which is rebuilt on load).
struct Preprocessing_times {
    double kd_tree = 0.0;
    double graph = 0.0;
    double sampling_radius = 0.0;
    double cpsp = 0.0;
    /// Normal estimation and orientation.
    double normals = 0.0;
    /// The point cloud hierarchy (rebuilt on load from the layout the file stores, or built).
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

namespace internal {

/// Tells options.progress (if any) that `stage` starts, and, through finish(), that it ended (the
/// stages of Point_cloud_object's preprocessing).
class Stage_timer {
public:
    Stage_timer(const Point_cloud_object_options& options, Preprocessing_stage stage, std::size_t points)
        : m_options(options), m_stage(stage), m_points(points)
    {
        if (m_options.progress) m_options.progress(Preprocessing_progress{m_stage, false, 0.0, m_points});
        m_start = Steady_clock::now();
    }
    /// The stage's wall-clock time in milliseconds.
    double finish()
    {
        const double ms = ms_since(m_start);
        if (m_options.progress) m_options.progress(Preprocessing_progress{m_stage, true, ms, m_points});
        return ms;
    }

private:
    const Point_cloud_object_options& m_options;
    Preprocessing_stage m_stage;
    std::size_t m_points;
    Steady_clock::time_point m_start;
};

} // namespace internal

} // namespace PCCD
