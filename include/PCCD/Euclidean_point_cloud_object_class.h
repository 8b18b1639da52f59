// PCCD/Euclidean_point_cloud_object_class.h -- the class of the lean preprocessed object for
// scene-scale scans: the implicit surface with the Euclidean kernel over the points, their kd-tree,
// oriented normals, domain radii and hierarchy, and nothing else (no proximity graph, no CPSP map),
// so that it holds about a fifth of a Point_cloud_object per point. Every query takes it (a
// EuclideanCollisionObject); the interpolation search takes the partners of its samples from
// kd-tree radius queries. Its file format is in Euclidean_point_cloud_object_file.h; include
// PCCD/Euclidean_point_cloud_object.h for both. Implements doc/manual/surface.md, "The lean object:
// the Euclidean kernel for large scans".
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <optional>
#include <ranges>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Point_cloud_object.h>
#include <PCCD/Surface/internal/knn_orientation_graph.h>

namespace PCCD {

/// A preprocessed point cloud whose implicit surface uses the Euclidean kernel: f(x) is the WLS fit
/// over the points within the support radius of x in space (Euclidean_distance), not along the
/// surface. It keeps the points (in spatial order) with their kd-tree, the input index of each
/// point, the oriented normals, the domain radii and the hierarchy; a bare k-NN graph is built only
/// to orient the normals and freed, and no CPSP map is built.
///
/// Preprocessing, in order: the kd-tree, the outliers (Outlier_options), the sampling radius r(P),
/// the kernel (Bandwidth_options, with the noise-aware widening of Point_cloud_object), the
/// unoriented normals and the noise estimate with the Euclidean kernel, the domain radii, the
/// orientation of the normals (the rule of orient_normals(), with the given normals as hints as in
/// Point_cloud_object) over the symmetric k-NN graph of `options.orientation_neighbors` neighbours,
/// built bare for it and freed, and the hierarchy. Each stage frees what only it needed before the
/// next starts, so that the peak stays near what the object keeps. The options are
/// Point_cloud_object_options; those of the proximity graph (`graph`, `sphere_of_influence`, the
/// long edges) do not apply.
///
/// What it gives up against Point_cloud_object: the Euclidean kernel bleeds across gaps thinner than
/// twice the support radius (two faces of a thin wall, fingers that nearly touch), where the
/// geodesic kernel keeps them apart; Path_choice does not apply (the paths of brackets are the
/// samples nearest to the chord); it has no Deforming_point_cloud_object, and its files (save(),
/// load()) are its own kind.
///
/// \tparam K a model of PointCloudKernel.
///
/// Immutable after construction; copies share the data. Every member function is const and safe
/// to call concurrently.
template <PointCloudKernel K = Eigen_kernel<double>>
class Euclidean_point_cloud_object {
    using Base = Point_cloud_object<K>;

public:
    using Kernel = K;
    using FT = typename K::FT;
    using Surface = WLS_surface<Euclidean_distance<K>, Gaussian_weight>;

    /// \name Construction
    /// @{
    /// From the points in the columns of a 3 x N matrix.
    /// \throws Invalid_input for fewer than two points, a non-finite point or invalid options.
    explicit Euclidean_point_cloud_object(const Eigen::Matrix3Xd& points, const Point_cloud_object_options& options = {})
        : m_data(preprocess(Base::timed_cloud(points, options), std::nullopt, options))
    {
    }

    /// From a range of points (any Point3 type).
    template <std::ranges::input_range Range>
        requires Point3<std::ranges::range_value_t<Range>>
    explicit Euclidean_point_cloud_object(const Range& points, const Point_cloud_object_options& options = {})
        : m_data(preprocess(Base::timed_cloud(points, Identity_point_map<std::ranges::range_value_t<Range>>(), options),
                            std::nullopt, options))
    {
    }

    /// From what a point file holds (PCCD::IO::read_points): its points, and its normals, when it
    /// has them, as hints of the orientation (as Point_cloud_object does).
    /// \throws Invalid_input as above, and if there are normals but not exactly one per point.
    explicit Euclidean_point_cloud_object(const Point_data& data, const Point_cloud_object_options& options = {})
        : m_data(from_point_data(data, options))
    {
    }
    /// The same, taking the data over: its points and normals are freed as soon as the object holds
    /// its own copies, before the rest of the preprocessing (at 10^7 points the peak is 240 MB
    /// lower). `data` is left empty.
    explicit Euclidean_point_cloud_object(Point_data&& data, const Point_cloud_object_options& options = {})
        : m_data(from_point_data(data, options, &data))
    {
    }
    /// @}

    /// \name Files (defined in PCCD/Euclidean_point_cloud_object_file.h)
    /// @{
    /// The file format version save() writes (the sections of Point_cloud_object's format 5 without
    /// its geodesic section, behind the magic "PCCDLEAN").
    static constexpr std::uint32_t file_version = 1;
    /// Writes the object to a binary file (replaced if it exists): points, normals, domain radii,
    /// kernel, scan estimate, fit, input indices and the hierarchy's layout, with a checksum.
    /// \throws File_error when the file cannot be written.
    void save(const std::string& path) const;
    /// Loads an object written by save(): the kd-tree is rebuilt, the hierarchy from its stored
    /// layout, everything else read back bit for bit, so every query answers as the saved object.
    /// \throws File_error naming the file and the problem when it is missing, not a lean object's
    ///         file (a Point_cloud_object's is named as such), of another format version or byte
    ///         order, truncated, corrupted (checksum) or inconsistent.
    static Euclidean_point_cloud_object load(const std::string& path);
    /// load() with the hierarchy's options given: the stored hierarchy when it has this leaf size and
    /// volume, otherwise one built with `hierarchy`.
    /// \throws Invalid_input if hierarchy.leaf_size is 0 or hierarchy.threads is 0 or above 4096;
    ///         File_error as load() above.
    static Euclidean_point_cloud_object load(const std::string& path, const Point_cloud_hierarchy_options& hierarchy);
    /// @}

    /// \name The implicit surface
    /// @{
    const Surface& surface() const { return m_data->surface; }
    /// @}

    /// \name Preprocessed state (as in Point_cloud_object)
    /// @{
    const Point_cloud<K>& cloud() const { return m_data->cloud; }
    std::size_t size() const { return m_data->cloud.size(); }
    /// The index, among the points given, of point `i` of cloud(). \pre i < size()
    std::uint32_t input_index(std::size_t i) const
    {
        PCCD_precondition(i < size());
        return m_data->input_index[i];
    }
    const std::vector<std::uint32_t>& input_indices() const { return m_data->input_index; }
    const Point_cloud_hierarchy& hierarchy() const { return m_data->hierarchy; }
    double sampling_radius() const { return m_data->sampling_radius; }
    const Gaussian_weight& weight() const { return m_data->surface.weight(); }
    double bandwidth() const { return weight().bandwidth(); }
    double eta() const { return weight().support_radius() / m_data->sampling_radius; }
    const Eigen::Matrix3Xd& normals() const { return m_data->surface.normals(); }
    const Orientation_report& orientation() const { return m_data->orientation; }
    bool normals_given() const { return m_data->normals_given; }
    const Scan_estimate& scan() const { return m_data->scan; }
    double noise_estimate() const { return m_data->scan.noise; }
    const Eigen::VectorXd& domain_radii() const { return m_data->surface.domain_radii(); }
    const Preprocessing_times& timings() const { return m_data->timings; }
    /// Bytes the object holds: points and kd-tree, input indices, normals, domain radii, hierarchy.
    std::size_t memory_bytes() const
    {
        const std::size_t n = size();
        return m_data->cloud.kd_tree().memory_bytes() + n * sizeof(std::uint32_t) +
               std::size_t(normals().size()) * sizeof(double) + std::size_t(domain_radii().size()) * sizeof(double) +
               m_data->hierarchy.memory_bytes();
    }
    /// @}

private:
    /// The side of the cloud's cell grid (Point_cloud::with_cell_grid), in sampling radii: twice
    /// the default support radius (3 r), so that the WLS evaluations' radius queries meet at most 8
    /// cells (27 up to a support of 6 r); cells of one support radius were slower (doc/benchmarks.md,
    /// "Radius queries from a cell grid").
    static constexpr double cell_grid_side = 6.0;

    struct Data {
        Point_cloud<K> cloud;
        double sampling_radius;
        Orientation_report orientation;
        bool normals_given;
        Scan_estimate scan;
        Preprocessing_times timings;
        Surface surface;
        Point_cloud_hierarchy hierarchy;
        std::vector<std::uint32_t> input_index;
    };

    explicit Euclidean_point_cloud_object(std::shared_ptr<const Data> data) : m_data(std::move(data)) {}
    static Euclidean_point_cloud_object load_file(const std::string& path, const Point_cloud_hierarchy_options* hierarchy);

    /// `taken`: `data` itself when the caller gave it up; its arrays are freed once copied.
    static std::shared_ptr<const Data> from_point_data(const Point_data& data, const Point_cloud_object_options& options,
                                                       Point_data* taken = nullptr)
    {
        std::optional<Eigen::Matrix3Xd> normals;
        if (data.has_normals()) {
            if (data.normals.size() != data.points.size())
                throw Invalid_input(internal::concat("point data: ", data.normals.size(), " normals for ",
                                                     data.points.size(), " points (need one per point, or none)"));
            normals.emplace(3, Eigen::Index(data.normals.size()));
            for (std::size_t i = 0; i < data.normals.size(); ++i) normals->col(Eigen::Index(i)) = data.normals[i];
        }
        // The points go straight from the data into the cloud (no copy between).
        typename Base::Timed_cloud built = Base::timed_cloud(data.points, Identity_point_map<Eigen::Vector3d>(), options);
        if (taken) {
            std::vector<Eigen::Vector3d>().swap(taken->points);
            std::vector<Eigen::Vector3d>().swap(taken->normals);
        }
        return preprocess(std::move(built), std::move(normals), options);
    }

    static std::shared_ptr<const Data> preprocess(typename Base::Timed_cloud built,
                                                  std::optional<Eigen::Matrix3Xd> given_normals,
                                                  Point_cloud_object_options options)
    {
        Point_cloud<K>& cloud = built.cloud;
        Preprocessing_times timings;
        timings.kd_tree = built.milliseconds;
        std::vector<std::uint32_t> input_index = Base::checked_input(built, given_normals, options);
        if (options.orientation_neighbors == 0)
            throw Invalid_input("lean point cloud object: orientation_neighbors must be >= 1, got 0");
        options = resolve_threads(std::move(options));
        Scan_estimate scan;
        scan.input_points = cloud.size();
        std::optional<Local_spacing> spacing = Base::outlier_stage(cloud, given_normals, input_index, options, scan, timings);
        // The spacing's neighbour lists are the orientation graph's when they have its k.
        const std::size_t graph_k = internal::orientation_graph_k(options.orientation_neighbors, cloud.size());
        if (spacing && spacing->k != graph_k) std::vector<std::uint32_t>().swap(spacing->neighbors);
        internal::Stage_timer radius_stage(options, Preprocessing_stage::sampling_radius, cloud.size());
        const double r = PCCD::sampling_radius(cloud, options.sampling_radius);
        cloud = std::move(cloud).with_cell_grid(cell_grid_side * r);
        timings.sampling_radius = radius_stage.finish();

        // The kernel and the normals, with the Euclidean kernel (a second time when the noise asks
        // for a wider automatic kernel, as Point_cloud_object does with the geodesic one).
        Gaussian_weight weight = gaussian_weight(r, options.bandwidth);
        Normal_estimate estimate;
        for (int pass = 0; pass < 2; ++pass) {
            internal::Stage_timer normals_stage(options, Preprocessing_stage::normals, cloud.size());
            estimate = estimate_normals(Euclidean_distance<K>(cloud), weight, options.threads);
            scan.noise = PCCD::noise_estimate(estimate);
            timings.normals += normals_stage.finish();
            const std::optional<Gaussian_weight> wider = noise_aware_weight(weight, scan.noise, options.bandwidth);
            if (!wider || pass == 1) break;
            weight = *wider;
        }
        estimate.residuals.resize(0); // the noise estimate is all they were for

        // The domain radii from the local spacing.
        Eigen::VectorXd domain = Base::domain_stage(cloud, spacing, options, timings);

        // The normals are oriented over a bare symmetric k-NN graph (from the spacing's lists when
        // it kept them), which goes, and the spacing with it.
        Orientation_report orientation;
        {
            internal::Stage_timer stage(options, Preprocessing_stage::graph, cloud.size());
            const internal::Orientation_graph graph =
                spacing && !spacing->neighbors.empty()
                    ? internal::knn_orientation_graph(spacing->neighbors, graph_k, cloud.size())
                    : internal::knn_orientation_graph(cloud, options.orientation_neighbors, options.knn.threads);
            spacing.reset();
            timings.graph = stage.finish();
            internal::Stage_timer orientation_stage(options, Preprocessing_stage::orientation, cloud.size());
            orientation = given_normals
                              ? orient_normals_with_hints(graph, cloud.coordinates(), estimate.normals, *given_normals)
                              : orient_normals(graph, cloud.coordinates(), estimate.normals);
            timings.normals += orientation_stage.finish();
        }
        Base::refit_stage(Euclidean_distance<K>(cloud), weight, options, estimate.normals, timings);
        const bool normals_given = given_normals.has_value();
        given_normals.reset();

        // The hierarchy's reaches are the domain radii (read before the surface takes them).
        internal::Stage_timer stage(options, Preprocessing_stage::hierarchy, cloud.size());
        Point_cloud_hierarchy hierarchy(cloud.coordinates(), domain, options.hierarchy);
        timings.hierarchy = stage.finish();
        Surface surface(Euclidean_distance<K>(cloud), weight, std::move(estimate.normals), std::move(domain),
                        options.surface_fit);
        return std::make_shared<const Data>(Data{std::move(cloud), r, orientation, normals_given, std::move(scan), timings,
                                                 std::move(surface), std::move(hierarchy), std::move(input_index)});
    }

    std::shared_ptr<const Data> m_data;
};

} // namespace PCCD
