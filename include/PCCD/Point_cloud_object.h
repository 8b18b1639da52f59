// PCCD/Point_cloud_object.h -- the whole preprocessed state of one point cloud: points and kd-tree,
// proximity graph, sampling radius, CPSP map, oriented normals and the kernel bandwidth of the
// implicit surface, built in one call, saved to and loaded from one binary file (little-endian,
// through PCCD/internal/binary_stream.h), with the time each preprocessing stage took; the point
// cloud hierarchy of the intersection queries attaches to it. Implements doc/manual/surface.md,
// "One call: Point_cloud_object" (and its save and load).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <memory>
#include <optional>
#include <ranges>
#include <sstream>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/geodesic_io.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/IO/Point_data.h>
#include <PCCD/Identity_point_map.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_traits.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Surface/Euclidean_distance.h>
#include <PCCD/Surface/Gaussian_weight.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/Surface/orient_normals.h>
#include <PCCD/Surface/outliers.h>
#include <PCCD/Surface/surface_domain.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/concepts/ReadablePointMap.h>
#include <PCCD/internal/binary_stream.h>
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
    /// surface (Outlier_options); cloud() holds the other points, in their order.
    std::vector<std::uint32_t> outliers;
    /// The estimated noise level sigma of the points (noise_estimate(): median leave-one-out
    /// residual / 0.6745), length unit of the cloud. On clean samples it is the curvature the
    /// kernel's plane cannot follow: 0.1-0.15 mean spacings on 30k-point scans, more on coarse
    /// samples of curved shapes (0.27 on 2000 points of a sphere, 0.43 on a torus).
    double noise = 0.0;
};

/// The preprocessed state of one point cloud: everything a collision query needs, built once.
///
/// Construction runs, in order: the kd-tree (Point_cloud), the removal of isolated outliers
/// (Outlier_options), the proximity graph, the sampling radius r(P), the kernel bandwidth
/// h = eta r(P) / sqrt(-ln theta_eps) (or the user's h), the CPSP map bounded at the kernel's
/// support radius R = h sqrt(-ln theta_eps), the unoriented normals n(p_i) of the geodesic surface
/// with the noise estimate (and, when the noise asks for a wider kernel, CPSP map and normals once
/// more with it: Bandwidth_options::noise_factor), their orientation (over the graph, with the
/// normals the user gives as hints that decide the sign where they exist), and the surface's
/// domain radii (Surface_domain_options).
///
/// \tparam K a model of PointCloudKernel.
///
/// Immutable after construction; copies share the data. Thread safety: every member function is
/// const and safe to call concurrently. save() and load() touch only the file they are given (no
/// scratch files).
template <PointCloudKernel K = Eigen_kernel<double>>
class Point_cloud_object {
public:
    using Kernel = K;
    using FT = typename K::FT;
    using Geodesic_surface = WLS_surface<Geodesic_distance<K>, Gaussian_weight>;
    using Euclidean_surface = WLS_surface<Euclidean_distance<K>, Gaussian_weight>;

    /// Version of the file format written by save().
    static constexpr std::uint32_t file_version = 3;

    /// \name Construction
    /// @{

    /// Builds the object from the points of `items` (through `point_map`); normals are oriented by
    /// propagation over the graph.
    /// \tparam Range an input range of items.
    /// \tparam PointMap a model of ReadablePointMap for the range's items.
    /// \throws Invalid_input for an empty cloud, a non-finite point, fewer than two points, or
    ///         invalid options (messages of the stage that rejects them).
    /// Complexity: O(N log N) expected for bounded support (graph, CPSP and normals are O(N k)).
    template <std::ranges::input_range Range,
              class PointMap = Identity_point_map<std::ranges::range_value_t<Range>>>
        requires ReadablePointMap<PointMap, std::ranges::range_value_t<Range>>
    explicit Point_cloud_object(const Range& items, const PointMap& point_map = PointMap(),
                                const Point_cloud_object_options& options = {})
        : Point_cloud_object(timed_cloud(items, point_map), std::nullopt, options)
    {
    }

    /// As above, but the normals `get(normal_map, item)` the user gives (e.g. read from a PLY file)
    /// are hints (orient_normals_with_hints()): each normal n(p_i) takes the sign of its point's
    /// given normal, and the points whose given normal is zero or not finite (missing) get theirs
    /// by propagation over the graph from the others (or, in a component of the graph without any
    /// given normal, as without a normal map).
    /// \tparam NormalMap a readable property map from items to vectors (any Point3 type).
    /// \throws Invalid_input as above; a zero or non-finite given normal is not an error.
    template <std::ranges::input_range Range, class PointMap, class NormalMap>
        requires ReadablePointMap<PointMap, std::ranges::range_value_t<Range>> &&
                 ReadablePointMap<NormalMap, std::ranges::range_value_t<Range>>
    Point_cloud_object(const Range& items, const PointMap& point_map, const NormalMap& normal_map,
                       const Point_cloud_object_options& options = {})
        : Point_cloud_object(timed_cloud(items, point_map), read_normals(items, normal_map), options)
    {
    }

    /// From what a point file holds (PCCD::IO::read_points): its points, and its normals when it
    /// has them, which are then hints as in the constructor with a normal map (zero or non-finite
    /// normals, partly or wholly, count as missing for their points).
    /// \throws Invalid_input as the constructors above, and if there are normals but not exactly
    ///         one per point.
    explicit Point_cloud_object(const Point_data& data, const Point_cloud_object_options& options = {})
        : Point_cloud_object(from_point_data(data, options))
    {
    }

    /// Loads an object written by save(). The kd-tree is rebuilt; everything else is read back bit
    /// for bit.
    /// \throws File_error naming the file and the problem when it is missing, not a PCCD object
    ///         file, of another format version or byte order, truncated, corrupted (checksum) or
    ///         inconsistent.
    /// The hierarchy is not stored in the file: it is rebuilt with `hierarchy` (default options).
    static Point_cloud_object load(const std::string& path, const Point_cloud_hierarchy_options& hierarchy = {});
    /// @}

    /// Writes the object to the binary file `path` (replacing it): points, normals, parameters,
    /// timings and the graph and CPSP map (in the format of write_geodesic_data()), with a checksum.
    /// \throws File_error if the file cannot be written.
    void save(const std::string& path) const;

    /// \name The implicit surface
    /// @{
    /// The surface with the geodesic kernel (the default of PCCD).
    const Geodesic_surface& surface() const { return m_data->geodesic; }
    /// The same surface with the Euclidean kernel (same weight and normals); it bleeds across gaps
    /// thinner than twice the support radius.
    const Euclidean_surface& euclidean_surface() const { return m_data->euclidean; }
    /// @}

    /// \name Preprocessed state
    /// @{
    const Point_cloud<K>& cloud() const { return m_data->cloud; }
    std::size_t size() const { return m_data->cloud.size(); }
    const Proximity_graph& graph() const { return *m_data->graph; }
    /// The bounding-volume hierarchy over the points (doc/manual/intersection.md).
    const Point_cloud_hierarchy& hierarchy() const { return m_data->hierarchy; }
    const Close_pairs_shortest_paths& cpsp() const { return *m_data->cpsp; }
    /// r(P).
    double sampling_radius() const { return m_data->sampling_radius; }
    /// The kernel (bandwidth h, threshold theta_eps, support radius R).
    const Gaussian_weight& weight() const { return m_data->geodesic.weight(); }
    double bandwidth() const { return weight().bandwidth(); }
    double theta_eps() const { return weight().threshold(); }
    /// R / r(P): the eta of the options, or the one implied by a bandwidth the user gave.
    double eta() const { return weight().support_radius() / m_data->sampling_radius; }
    /// The oriented normals, 3 x N (zero columns: points whose normal is undetermined).
    const Eigen::Matrix3Xd& normals() const { return m_data->geodesic.normals(); }
    /// What the orientation did (components is 0 when the user gave a usable normal for every
    /// point). hints_used, hints_ignored and unhinted_components are not stored by save(): 0 for a
    /// loaded object.
    const Orientation_report& orientation() const { return m_data->orientation; }
    /// True when the user gave normals (hints, possibly missing for some points: see
    /// orientation().hints_used).
    bool normals_given() const { return m_data->normals_given; }
    /// Noise estimate and outliers (see Scan_estimate).
    const Scan_estimate& scan() const { return m_data->scan; }
    /// The estimated noise level sigma (scan().noise).
    double noise_estimate() const { return m_data->scan.noise; }
    /// The domain radii D_i of the surface (empty when the domain is disabled).
    const Eigen::VectorXd& domain_radii() const { return m_data->geodesic.domain_radii(); }
    const Preprocessing_times& timings() const { return m_data->timings; }
    /// @}

private:
    using Clock = std::chrono::steady_clock;

    struct Data {
        Point_cloud<K> cloud;
        std::shared_ptr<const Proximity_graph> graph;
        std::shared_ptr<const Close_pairs_shortest_paths> cpsp;
        double sampling_radius;
        Orientation_report orientation;
        bool normals_given;
        Scan_estimate scan;
        Preprocessing_times timings;
        Geodesic_surface geodesic;
        Euclidean_surface euclidean;
        Point_cloud_hierarchy hierarchy;
    };

    struct Timed_cloud {
        Point_cloud<K> cloud;
        double milliseconds;
    };

    explicit Point_cloud_object(std::shared_ptr<const Data> data) : m_data(std::move(data)) {}

    Point_cloud_object(Timed_cloud built, std::optional<Eigen::Matrix3Xd> given_normals,
                       const Point_cloud_object_options& options)
        : m_data(preprocess(std::move(built), std::move(given_normals), options))
    {
    }

    static double ms_since(Clock::time_point start)
    {
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }

    /// Readable property map from an index to a row of a vector (points or normals of Point_data).
    struct Row_map {
        const std::vector<Eigen::Vector3d>* rows;
        friend const Eigen::Vector3d& get(const Row_map& m, std::size_t i) { return (*m.rows)[i]; }
    };
    static Point_cloud_object from_point_data(const Point_data& data, const Point_cloud_object_options& options)
    {
        if (!data.has_normals()) return Point_cloud_object(data.points, Identity_point_map<Eigen::Vector3d>(), options);
        if (data.normals.size() != data.points.size())
            throw Invalid_input(internal::concat("point data: ", data.normals.size(), " normals for ",
                                                 data.points.size(), " points (need one per point, or none)"));
        std::vector<std::size_t> items(data.points.size());
        for (std::size_t i = 0; i < items.size(); ++i) items[i] = i;
        return Point_cloud_object(items, Row_map{&data.points}, Row_map{&data.normals}, options);
    }

    template <class Range, class PointMap>
    static Timed_cloud timed_cloud(const Range& items, const PointMap& point_map)
    {
        const auto start = Clock::now();
        Point_cloud<K> cloud(items, point_map);
        return {std::move(cloud), ms_since(start)};
    }

    template <class Range, class NormalMap>
    static Eigen::Matrix3Xd read_normals(const Range& items, const NormalMap& normal_map)
    {
        std::vector<Eigen::Vector3d> normals;
        for (const auto& item : items) {
            const auto& v = get(normal_map, item);
            using V = std::remove_cvref_t<decltype(v)>;
            normals.emplace_back(double(Point_traits<V>::x(v)), double(Point_traits<V>::y(v)),
                                 double(Point_traits<V>::z(v)));
        }
        Eigen::Matrix3Xd result(3, Eigen::Index(normals.size()));
        for (std::size_t i = 0; i < normals.size(); ++i) result.col(Eigen::Index(i)) = normals[i];
        return result;
    }

    static Data make_data(Point_cloud<K> cloud, std::shared_ptr<const Proximity_graph> graph,
                          std::shared_ptr<const Close_pairs_shortest_paths> cpsp, double sampling_radius,
                          const Gaussian_weight& weight, Eigen::Matrix3Xd normals, Eigen::VectorXd domain,
                          Orientation_report orientation, bool normals_given, Scan_estimate scan,
                          Preprocessing_times timings, const Point_cloud_hierarchy_options& hierarchy_options,
                          Surface_fit fit)
    {
        Geodesic_surface geodesic(Geodesic_distance<K>(cloud, cpsp), weight, normals, domain, fit);
        Euclidean_surface euclidean(Euclidean_distance<K>(cloud), weight, std::move(normals), std::move(domain), fit);
        const auto start = Clock::now();
        Point_cloud_hierarchy hierarchy(cloud.coordinates(), hierarchy_options);
        timings.hierarchy = ms_since(start);
        return Data{std::move(cloud),       std::move(graph),     std::move(cpsp),
                    sampling_radius,        orientation,          normals_given,
                    std::move(scan),        timings,              std::move(geodesic),
                    std::move(euclidean),   std::move(hierarchy)};
    }

    /// Removes the points `outliers` (ascending indices) of `cloud`, and their given normals, in place.
    static void remove_outliers(Point_cloud<K>& cloud, std::optional<Eigen::Matrix3Xd>& given_normals,
                                const std::vector<std::uint32_t>& outliers)
    {
        if (outliers.empty()) return;
        if (cloud.size() - outliers.size() < 2)
            throw Invalid_input(internal::concat("point cloud object: ", outliers.size(), " of the ", cloud.size(),
                                                 " points are isolated outliers; fewer than two points are left"));
        const Eigen::Index kept = Eigen::Index(cloud.size() - outliers.size());
        typename Point_cloud<K>::Coordinates inliers(3, kept);
        Eigen::Matrix3Xd normals(3, given_normals ? kept : 0);
        Eigen::Index next = 0;
        std::size_t skip = 0;
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            if (skip < outliers.size() && outliers[skip] == i) {
                ++skip;
                continue;
            }
            inliers.col(next) = cloud.position(std::uint32_t(i));
            if (given_normals) normals.col(next) = given_normals->col(Eigen::Index(i));
            ++next;
        }
        cloud = Point_cloud<K>(std::move(inliers));
        if (given_normals) given_normals = std::move(normals);
    }

    static std::shared_ptr<const Data> preprocess(Timed_cloud built, std::optional<Eigen::Matrix3Xd> given_normals,
                                                  Point_cloud_object_options options)
    {
        Point_cloud<K>& cloud = built.cloud;
        Preprocessing_times timings;
        timings.kd_tree = built.milliseconds;
        if (cloud.size() < 2)
            throw Invalid_input("point cloud object: a surface needs at least two points, the cloud has one");
        if (options.hierarchy.leaf_size == 0)
            throw Invalid_input("point cloud object: the hierarchy's leaf_size must be >= 1");
        if (given_normals && std::size_t(given_normals->cols()) != cloud.size())
            throw Invalid_input(internal::concat("point cloud object: ", given_normals->cols(), " normals for ",
                                                 cloud.size(), " points"));
        internal::check_domain_options(options.domain);
        internal::check_outlier_options(options.outliers);
        internal::check_noise_factor(options.bandwidth);

        auto start = Clock::now();
        options.sphere_of_influence.threads = options.knn.threads = options.sampling_radius.threads =
            options.domain.threads = options.outliers.threads = options.threads;
        Scan_estimate scan;
        scan.input_points = cloud.size();
        // One local-spacing pass serves the outlier test and, when no point was removed and both
        // use the same k, the domain radii below.
        std::optional<Local_spacing> spacing;
        if (options.outliers.remove) {
            spacing = local_spacing(cloud, options.outliers.neighbors, true, options.threads);
            scan.outliers = find_outliers(*spacing, options.outliers);
            remove_outliers(cloud, given_normals, scan.outliers);
            if (!scan.outliers.empty()) spacing.reset(); // the cloud changed
        }
        timings.outliers = ms_since(start);

        start = Clock::now();
        auto graph = std::make_shared<const Proximity_graph>(options.graph == Graph_kind::knn
                                                                 ? knn_graph(cloud, options.knn)
                                                                 : sphere_of_influence_graph(cloud, options.sphere_of_influence));
        timings.graph = ms_since(start);

        start = Clock::now();
        const double r = PCCD::sampling_radius(cloud, options.sampling_radius);
        timings.sampling_radius = ms_since(start);
        Gaussian_weight weight = gaussian_weight(r, options.bandwidth);

        std::shared_ptr<const Close_pairs_shortest_paths> cpsp;
        Normal_estimate estimate;
        // At most twice: a second time when the noise estimate asks for a wider kernel than the
        // sampling radius alone (automatic bandwidth only).
        for (int pass = 0; pass < 2; ++pass) {
            start = Clock::now();
            // The map must hold every point within the kernel's support radius R; its bound is
            // support * r, so support = R / r (eta itself for the automatic bandwidth).
            cpsp = std::make_shared<const Close_pairs_shortest_paths>(
                *graph, r, Cpsp_options{.support = weight.support_radius() / r, .threads = options.threads});
            timings.cpsp += ms_since(start);
            start = Clock::now();
            estimate = estimate_normals(Geodesic_distance<K>(cloud, cpsp), weight, options.threads);
            timings.normals += ms_since(start);
            scan.noise = PCCD::noise_estimate(estimate);
            const std::optional<Gaussian_weight> wider = noise_aware_weight(weight, scan.noise, options.bandwidth);
            if (!wider || pass == 1) break;
            weight = *wider;
        }

        start = Clock::now();
        const Orientation_report orientation =
            given_normals ? orient_normals_with_hints(*graph, cloud.coordinates(), estimate.normals, *given_normals)
                          : orient_normals(*graph, cloud.coordinates(), estimate.normals);
        timings.normals += ms_since(start);
        start = Clock::now();
        const bool reuse = spacing && spacing->k == std::min<std::size_t>(options.domain.neighbors, cloud.size() - 1);
        Eigen::VectorXd domain = reuse ? surface_domain_radii(*spacing, options.domain)
                                       : surface_domain_radii(cloud, options.domain);
        timings.outliers += ms_since(start);

        return std::make_shared<const Data>(make_data(std::move(cloud), std::move(graph), std::move(cpsp), r, weight,
                                                      std::move(estimate.normals), std::move(domain), orientation,
                                                      given_normals.has_value(), std::move(scan), timings,
                                                      options.hierarchy, options.surface_fit));
    }

    std::shared_ptr<const Data> m_data;
};

namespace internal {

inline constexpr char object_magic[8] = {'P', 'C', 'C', 'D', 'O', 'B', 'J', '\0'};

/// A read-only stream buffer over bytes held elsewhere, without copying them (the geodesic section
/// of a loaded object file, read in place).
class Span_streambuf : public std::streambuf {
public:
    Span_streambuf(const char* data, std::size_t size)
    {
        char* begin = const_cast<char*>(data); // a get area only: never written through
        setg(begin, begin, begin + size);
    }
};

inline std::string read_binary_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw File_error(path, "cannot open the file: it does not exist or is not readable");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace internal

// File format (version 3, little-endian whatever the host, with a byte-order mark, no padding):
//   magic "PCCDOBJ\0" | u32 version | u32 byte-order mark | u64 N | f64 sampling radius
//   f64 bandwidth h | f64 theta_eps | u8 normals given | u64 flipped, components, unoriented
//   f64 timings[5] | f64 points[3N] | f64 normals[3N]
//   | f64 noise | u64 input points | u64 M | u32 outliers[M] | u64 D (0 or N) | f64 domain radii[D]
//   | u8 surface fit (Surface_fit)
//   | u64 G | G bytes: a geodesic file
//   | u64 checksum (FNV-1a over 64-bit words of everything before it)
// Version 1 files (without the scan section) still load: no outliers, noise 0, and the domain of
// the default Surface_domain_options; versions 1 and 2 (without the fit) get the plane fit they
// were made with.
template <PointCloudKernel K>
void Point_cloud_object<K>::save(const std::string& path) const
{
    const Data& d = *m_data;
    std::ostringstream geodesic_stream(std::ios::binary);
    internal::write_geodesic_stream(geodesic_stream, path, *d.graph, *d.cpsp);
    const std::string geodesic = std::move(geodesic_stream).str();

    internal::Binary_writer out;
    out.write(internal::object_magic, sizeof internal::object_magic);
    out.put(file_version);
    out.put(internal::byte_order_mark);
    out.put(std::uint64_t(size()));
    out.put(d.sampling_radius);
    out.put(bandwidth());
    out.put(theta_eps());
    out.put(std::uint8_t(d.normals_given ? 1 : 0));
    out.put(std::uint64_t(d.orientation.flipped));
    out.put(std::uint64_t(d.orientation.components));
    out.put(std::uint64_t(d.orientation.unoriented));
    for (double t : {d.timings.kd_tree, d.timings.graph, d.timings.sampling_radius, d.timings.cpsp, d.timings.normals})
        out.put(t);
    const Eigen::Matrix3Xd points = d.cloud.coordinates().template cast<double>();
    out.write(points.data(), sizeof(double) * std::size_t(points.size()));
    out.write(normals().data(), sizeof(double) * std::size_t(normals().size()));
    out.put(d.scan.noise);
    out.put(std::uint64_t(d.scan.input_points));
    out.put(std::uint64_t(d.scan.outliers.size()));
    out.write(d.scan.outliers.data(), sizeof(std::uint32_t) * d.scan.outliers.size());
    out.put(std::uint64_t(domain_radii().size()));
    out.write(domain_radii().data(), sizeof(double) * std::size_t(domain_radii().size()));
    out.put(std::uint8_t(surface().fit()));
    out.put(std::uint64_t(geodesic.size()));
    out.write(geodesic.data(), geodesic.size());
    out.finish();

    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw File_error(path, "cannot open the file for writing");
    file.write(out.bytes().data(), std::streamsize(out.bytes().size()));
    file.close();
    if (!file) throw File_error(path, "write failed (disk full?)");
}

template <PointCloudKernel K>
Point_cloud_object<K> Point_cloud_object<K>::load(const std::string& path,
                                                 const Point_cloud_hierarchy_options& hierarchy)
{
    const std::string bytes = internal::read_binary_file(path);
    internal::Binary_reader in(bytes, path);
    char magic[8];
    in.read(magic, sizeof magic);
    if (std::memcmp(magic, internal::object_magic, sizeof magic) != 0) in.fail("not a PCCD object file");
    const auto version = in.get<std::uint32_t>();
    if (version == 0 || version > file_version)
        in.fail(internal::concat("object file format version ", version, ", this PCCD reads versions 1 to ",
                                 file_version));
    if (in.get<std::uint32_t>() != internal::byte_order_mark) in.fail("written on a machine of another byte order");
    if (bytes.size() < sizeof(std::uint64_t)) in.fail("truncated file");
    {
        internal::Word_checksum checksum;
        checksum.update(bytes.data(), bytes.size() - sizeof(std::uint64_t));
        const auto stored =
            internal::decode_little_endian<std::uint64_t>(bytes.data() + bytes.size() - sizeof(std::uint64_t));
        if (stored != checksum.value()) in.fail("checksum mismatch: the file is truncated or corrupted");
    }
    const auto n = in.get<std::uint64_t>();
    if (n < 2 || n >= std::uint64_t(std::numeric_limits<std::uint32_t>::max()) ||
        in.remaining() < 6 * sizeof(double) * n)
        in.fail(internal::concat("inconsistent point count ", n));
    const auto r = in.get<double>();
    const auto h = in.get<double>();
    const auto theta = in.get<double>();
    const bool given = in.get<std::uint8_t>() != 0;
    Orientation_report orientation;
    orientation.flipped = std::size_t(in.get<std::uint64_t>());
    orientation.components = std::size_t(in.get<std::uint64_t>());
    orientation.unoriented = std::size_t(in.get<std::uint64_t>());
    Preprocessing_times timings;
    for (double* t : {&timings.kd_tree, &timings.graph, &timings.sampling_radius, &timings.cpsp, &timings.normals})
        *t = in.get<double>();
    Eigen::Matrix3Xd points(3, Eigen::Index(n)), normals(3, Eigen::Index(n));
    in.read(points.data(), sizeof(double) * 3 * n);
    in.read(normals.data(), sizeof(double) * 3 * n);
    Scan_estimate scan;
    scan.input_points = std::size_t(n);
    std::optional<Eigen::VectorXd> domain;
    if (version >= 2) {
        scan.noise = in.get<double>();
        const auto input = in.get<std::uint64_t>();
        const auto m = in.get<std::uint64_t>();
        if (!(std::isfinite(scan.noise) && scan.noise >= 0.0)) in.fail(internal::concat("invalid noise estimate ", scan.noise));
        if (input < n || input - n != m || in.remaining() / sizeof(std::uint32_t) < m)
            in.fail(internal::concat("inconsistent outlier count ", m, " for ", input, " input points"));
        scan.input_points = std::size_t(input);
        scan.outliers.resize(std::size_t(m));
        in.read(scan.outliers.data(), sizeof(std::uint32_t) * std::size_t(m));
        for (std::size_t k = 0; k < scan.outliers.size(); ++k)
            if (scan.outliers[k] >= input || (k > 0 && scan.outliers[k] <= scan.outliers[k - 1]))
                in.fail("outlier indices out of range or not ascending");
        const auto radii = in.get<std::uint64_t>();
        if ((radii != 0 && radii != n) || in.remaining() / sizeof(double) < radii)
            in.fail(internal::concat("inconsistent number of domain radii ", radii));
        domain.emplace(Eigen::Index(radii));
        in.read(domain->data(), sizeof(double) * std::size_t(radii));
    }
    Surface_fit fit = Surface_fit::plane;
    if (version >= 3) {
        const auto stored = in.get<std::uint8_t>();
        if (stored > std::uint8_t(Surface_fit::sphere)) in.fail(internal::concat("unknown surface fit ", int(stored)));
        fit = Surface_fit(stored);
    }
    const auto geodesic_size = in.get<std::uint64_t>();
    if (in.remaining() < sizeof(std::uint64_t) || in.remaining() - sizeof(std::uint64_t) != geodesic_size)
        in.fail("inconsistent size of the geodesic section");
    if (!(std::isfinite(r) && r > 0.0)) in.fail(internal::concat("invalid sampling radius ", r));

    internal::Span_streambuf geodesic_section(bytes.data() + in.position(), geodesic_size);
    std::istream geodesic_stream(&geodesic_section);
    Geodesic_data geodesic = internal::read_geodesic_stream(geodesic_stream, geodesic_size, path, "geodesic section: ");
    if (geodesic.graph.num_vertices() != n || geodesic.cpsp.size() != n)
        in.fail("the geodesic section does not have one vertex per point");

    try {
        const auto start = Clock::now();
        Point_cloud<K> cloud(typename Point_cloud<K>::Coordinates(points.template cast<FT>()));
        timings.kd_tree = ms_since(start);
        const Gaussian_weight weight(h, theta);
        auto cpsp = std::make_shared<const Close_pairs_shortest_paths>(std::move(geodesic.cpsp));
        auto graph = std::make_shared<const Proximity_graph>(std::move(geodesic.graph));
        if (!domain) domain = surface_domain_radii(cloud);
        return Point_cloud_object(std::make_shared<const Data>(
            make_data(std::move(cloud), std::move(graph), std::move(cpsp), r, weight, std::move(normals),
                      std::move(*domain), orientation, given, std::move(scan), timings, hierarchy, fit)));
    } catch (const File_error&) {
        throw;
    } catch (const Invalid_input& e) {
        in.fail(internal::concat("inconsistent content: ", e.what()));
    }
}

} // namespace PCCD
