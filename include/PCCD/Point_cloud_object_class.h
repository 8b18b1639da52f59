// PCCD/Point_cloud_object_class.h -- the class Point_cloud_object, the whole preprocessed state of one point cloud: points and kd-tree,
// proximity graph, sampling radius, CPSP map, oriented normals and the kernel bandwidth of the
// implicit surface, built in one call, saved to and loaded from one binary file (little-endian,
// through PCCD/internal/binary_stream.h), with the time each preprocessing stage took; the point
// cloud hierarchy of the intersection queries attaches to it. Implements doc/manual/surface.md,
// "One call: Point_cloud_object" (and its save and load).
#pragma once

// The class alone: PCCD/Point_cloud_object.h adds its preprocessing pipeline and its file format
// (Point_cloud_object_preprocessing.h, Point_cloud_object_file.h), the parts beside it.

#include <algorithm>
#include <chrono>
#include <concepts>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <memory>
#include <numeric>
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
#include <PCCD/Point_cloud_object_options.h>
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
#include <PCCD/internal/timing.h>
#include <PCCD/internal/spatial_order.h>
#include <PCCD/sampling_radius.h>

namespace PCCD {

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
    static constexpr std::uint32_t file_version = 5;

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
        : Point_cloud_object(timed_cloud(items, point_map, options), std::nullopt, options)
    {
    }

    /// From a range of points (any Point3 type: Eigen vectors, CGAL points, ...) and options: the
    /// constructor above with the identity point map, which need not be spelled.
    template <std::ranges::input_range Range>
        requires Point3<std::ranges::range_value_t<Range>>
    Point_cloud_object(const Range& points, const Point_cloud_object_options& options)
        : Point_cloud_object(points, Identity_point_map<std::ranges::range_value_t<Range>>(), options)
    {
    }

    /// From the points in the columns of a 3 x N matrix (Triangle_mesh_sample::points,
    /// an Eigen expression, ...), as the constructors above.
    /// \throws Invalid_input as above.
    explicit Point_cloud_object(const Eigen::Matrix3Xd& points, const Point_cloud_object_options& options = {})
        : Point_cloud_object(timed_cloud(points, options), std::nullopt, options)
    {
    }

    /// As above, with one normal per point (column i of `normals` for column i of `points`), used as
    /// hints as in the constructor with a normal map (zero or non-finite columns count as missing).
    /// \throws Invalid_input when `normals` does not have one column per point, and as above.
    /// (A template only so that `{...}` options in the second place never pick it.)
    template <class Normals>
        requires std::same_as<Normals, Eigen::Matrix3Xd>
    Point_cloud_object(const Eigen::Matrix3Xd& points, const Normals& normals,
                       const Point_cloud_object_options& options = {})
        : Point_cloud_object(timed_cloud(points, options), normals, options)
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
        : Point_cloud_object(timed_cloud(items, point_map, options), read_normals(items, normal_map), options)
    {
    }

    /// From a range of points and a range of their normals (any Point3 types; normals[i] for
    /// points[i]), as hints as in the constructor above: no point map or normal map to spell.
    /// \throws Invalid_input when the ranges differ in length, and as above.
    template <std::ranges::input_range Points, std::ranges::input_range Normals>
        requires Point3<std::ranges::range_value_t<Points>> && Point3<std::ranges::range_value_t<Normals>>
    Point_cloud_object(const Points& points, const Normals& normals, const Point_cloud_object_options& options = {})
        : Point_cloud_object(timed_cloud(points, Identity_point_map<std::ranges::range_value_t<Points>>(), options),
                             read_normals(normals, Identity_point_map<std::ranges::range_value_t<Normals>>()), options)
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
    /// for bit. The hierarchy is rebuilt from the layout the file stores (the same tree, its boxes,
    /// slabs or spheres recomputed from the points: Point_cloud_hierarchy's Layout constructor);
    /// a file of format version 4 or older, which has none, gets one built with default options.
    /// \throws File_error naming the file and the problem when it is missing, not a PCCD object
    ///         file, of another format version or byte order, truncated, corrupted (checksum) or
    ///         inconsistent (a stored hierarchy layout that is not a median-split tree of its points
    ///         among them).
    static Point_cloud_object load(const std::string& path);
    /// load() with the hierarchy's options given: the stored hierarchy when it has this leaf size and
    /// volume, otherwise one built with `hierarchy`.
    /// \throws Invalid_input if hierarchy.leaf_size is 0 or hierarchy.threads is 0 or above 4096;
    ///         File_error as load() above.
    static Point_cloud_object load(const std::string& path, const Point_cloud_hierarchy_options& hierarchy);
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
    /// The points of the surface: those given, without the outliers (scan().outliers), in a spatial
    /// order (Point_cloud_object_options::spatial_order) unless that was switched off. Every
    /// per-point array of the object (normals(), domain_radii(), graph(), cpsp(), the indices of
    /// the hierarchy) is in this order; input_index() finds a given point again.
    const Point_cloud<K>& cloud() const { return m_data->cloud; }
    /// The index, among the points given to the constructor (or in the file it was read from), of
    /// point `i` of cloud(). \pre i < size()
    std::uint32_t input_index(std::size_t i) const
    {
        PCCD_precondition(i < size());
        return m_data->input_index[i];
    }
    /// input_index() of every point of cloud(), in order (ascending when the points kept their order).
    const std::vector<std::uint32_t>& input_indices() const { return m_data->input_index; }
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
    // The lean object shares the first stages (timed_cloud, checked_input, outlier_stage,
    // domain_stage).
    template <PointCloudKernel>
    friend class Euclidean_point_cloud_object;

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
        std::vector<std::uint32_t> input_index;
    };

    struct Timed_cloud {
        Point_cloud<K> cloud;
        double milliseconds;
        /// input_index of each point of `cloud` (empty: the identity).
        std::vector<std::uint32_t> input_index;
    };

    explicit Point_cloud_object(std::shared_ptr<const Data> data) : m_data(std::move(data)) {}

    Point_cloud_object(Timed_cloud built, std::optional<Eigen::Matrix3Xd> given_normals,
                       const Point_cloud_object_options& options)
        : m_data(preprocess(std::move(built), std::move(given_normals), options))
    {
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

    /// The cloud of the given points (and its kd-tree), in spatial order when the options ask for it.
    template <class Range, class PointMap>
    static Timed_cloud timed_cloud(const Range& items, const PointMap& point_map,
                                   const Point_cloud_object_options& options)
    {
        std::size_t n = 0;
        if constexpr (std::ranges::sized_range<Range>) n = std::size_t(std::ranges::size(items));
        internal::Stage_timer stage(options, Preprocessing_stage::kd_tree, n);
        return ordered_cloud(Point_cloud<K>::read_coordinates(items, point_map), options, stage);
    }

    static Timed_cloud timed_cloud(const Eigen::Matrix3Xd& points, const Point_cloud_object_options& options)
    {
        internal::Stage_timer stage(options, Preprocessing_stage::kd_tree, std::size_t(points.cols()));
        return ordered_cloud(Point_cloud<K>::checked_coordinates(points.template cast<FT>()), options, stage);
    }

    /// The cloud of the checked `coordinates` (and its kd-tree), in spatial order when the options
    /// ask for it.
    static Timed_cloud ordered_cloud(typename Point_cloud<K>::Coordinates coordinates,
                                     const Point_cloud_object_options& options, internal::Stage_timer& stage)
    {
        std::vector<std::uint32_t> input_index;
        if (options.spatial_order) {
            input_index = internal::spatial_order(coordinates);
            coordinates = internal::gather_columns(coordinates, input_index);
        }
        Point_cloud<K> cloud(std::move(coordinates));
        return {std::move(cloud), stage.finish(), std::move(input_index)};
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

    /// The object's data from its preprocessed parts; builds the surfaces and the hierarchy.
    static Data make_data(Point_cloud<K> cloud, std::shared_ptr<const Proximity_graph> graph,
                          std::shared_ptr<const Close_pairs_shortest_paths> cpsp, double sampling_radius,
                          const Gaussian_weight& weight, Eigen::Matrix3Xd normals, Eigen::VectorXd domain,
                          Orientation_report orientation, bool normals_given, Scan_estimate scan,
                          Preprocessing_times timings, const Point_cloud_object_options& options,
                          std::vector<std::uint32_t> input_index,
                          const Point_cloud_hierarchy::Layout* layout = nullptr);
    /// load() with the caller's hierarchy options, or none (the stored hierarchy as it is).
    static Point_cloud_object load_file(const std::string& path, const Point_cloud_hierarchy_options* hierarchy);
    /// Removes the points `outliers` (ascending positions in `cloud`) of `cloud`, their given normals
    /// and their entries of `input_index`, in place, and turns `outliers` into the input indices of
    /// those points, ascending.
    static void remove_outliers(Point_cloud<K>& cloud, std::optional<Eigen::Matrix3Xd>& given_normals,
                                std::vector<std::uint32_t>& input_index, std::vector<std::uint32_t>& outliers);
    /// The outlier stage (Outlier_options): finds and removes the isolated outliers (scan.outliers,
    /// timings.outliers); returns the local spacing of the cloud left, with its neighbour lists
    /// (local_spacing_without() after a removal), for the domain radii and the lean object's
    /// orientation graph; none when outlier removal is off.
    static std::optional<Local_spacing> outlier_stage(Point_cloud<K>& cloud, std::optional<Eigen::Matrix3Xd>& given_normals,
                                                      std::vector<std::uint32_t>& input_index,
                                                      const Point_cloud_object_options& options, Scan_estimate& scan,
                                                      Preprocessing_times& timings);
    /// The domain radii (Surface_domain_options), from `spacing` when it has the domain's k.
    static Eigen::VectorXd domain_stage(const Point_cloud<K>& cloud, const std::optional<Local_spacing>& spacing,
                                        const Point_cloud_object_options& options, Preprocessing_times& timings);
    /// Checks the cloud and the options; returns each point's input index (the identity when the
    /// points kept their order) and puts the given normals in the cloud's order.
    static std::vector<std::uint32_t> checked_input(Timed_cloud& built, std::optional<Eigen::Matrix3Xd>& given_normals,
                                                    const Point_cloud_object_options& options);
    /// When options.normal_bandwidth < 1 or options.normal_residual_scale is set: the oriented
    /// normals fitted again with the narrower kernel and/or robustly (refit_normals()), timed as part
    /// of the normals.
    template <class Distance>
    static void refit_stage(const Distance& distance, const Gaussian_weight& weight,
                            const Point_cloud_object_options& options, Eigen::Matrix3Xd& normals,
                            Preprocessing_times& timings);
    /// The kernel's weight, the CPSP map and the normal estimate (twice when the noise estimate asks
    /// for a wider automatic kernel); sets scan.noise and the timings of those stages.
    static Gaussian_weight fit_kernel(const Point_cloud<K>& cloud, const Proximity_graph& graph, double r,
                                      const Point_cloud_object_options& options,
                                      std::shared_ptr<const Close_pairs_shortest_paths>& cpsp,
                                      Normal_estimate& estimate, Scan_estimate& scan, Preprocessing_times& timings);
    /// The whole preprocessing pipeline (doc/design.md): outliers, graph, sampling radius, kernel,
    /// CPSP map, normals, orientation, domain, hierarchy.
    static std::shared_ptr<const Data> preprocess(Timed_cloud built, std::optional<Eigen::Matrix3Xd> given_normals,
                                                  Point_cloud_object_options options);

    std::shared_ptr<const Data> m_data;
};

} // namespace PCCD
