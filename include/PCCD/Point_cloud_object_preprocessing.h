// PCCD/Point_cloud_object_preprocessing.h -- the preprocessing pipeline of
// Point_cloud_object: the definitions of its private stages (input checks and point order, outlier
// removal, kernel with CPSP map and normals, orientation, domain, the surfaces and the hierarchy).
// Included by PCCD/Point_cloud_object.h. Implements
// doc/manual/surface.md, "One call: Point_cloud_object" and "Scans: where the surface is defined,
// noise and outliers".
#pragma once

#include <PCCD/Point_cloud_object_class.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

namespace PCCD {

template <PointCloudKernel K>
auto Point_cloud_object<K>::make_data(Point_cloud<K> cloud, std::shared_ptr<const Proximity_graph> graph,
                                      std::shared_ptr<const Close_pairs_shortest_paths> cpsp, double sampling_radius,
                                      const Gaussian_weight& weight, Eigen::Matrix3Xd normals, Eigen::VectorXd domain,
                                      Orientation_report orientation, bool normals_given, Scan_estimate scan,
                                      Preprocessing_times timings, const Point_cloud_object_options& options,
                                      std::vector<std::uint32_t> input_index,
                                      const Point_cloud_hierarchy::Layout* layout) -> Data
{
    // The hierarchy's reach of a point is its domain radius: f is defined only that close to it
    // (doc/manual/hierarchy.md). Without a domain the hierarchy has no reaches (queries walk it flat).
    const Eigen::VectorXd reach = domain;
    // The two surfaces share the normals and the domain radii (one copy of each).
    Geodesic_surface geodesic(Geodesic_distance<K>(cloud, cpsp), weight, std::move(normals), std::move(domain),
                              options.surface_fit);
    Euclidean_surface euclidean = geodesic.with_distance(Euclidean_distance<K>(cloud));
    internal::Stage_timer stage(options, Preprocessing_stage::hierarchy, cloud.size());
    Point_cloud_hierarchy hierarchy = layout ? Point_cloud_hierarchy(*layout, cloud.coordinates(), reach, options.hierarchy.threads)
                                             : Point_cloud_hierarchy(cloud.coordinates(), reach, options.hierarchy);
    timings.hierarchy = stage.finish();
    return Data{std::move(cloud),       std::move(graph),     std::move(cpsp),
                sampling_radius,        orientation,          normals_given,
                std::move(scan),        timings,              std::move(geodesic),
                std::move(euclidean),   std::move(hierarchy), std::move(input_index)};
}

template <PointCloudKernel K>
void Point_cloud_object<K>::remove_outliers(Point_cloud<K>& cloud, std::optional<Eigen::Matrix3Xd>& given_normals,
                                            std::vector<std::uint32_t>& input_index, std::vector<std::uint32_t>& outliers)
{
    if (outliers.empty()) return;
    if (cloud.size() - outliers.size() < 2)
        throw Invalid_input(internal::concat("point cloud object: ", outliers.size(), " of the ", cloud.size(),
                                             " points are isolated outliers; fewer than two points are left"));
    std::vector<std::uint32_t> kept;
    kept.reserve(cloud.size() - outliers.size());
    std::size_t skip = 0;
    for (std::uint32_t i = 0; i < cloud.size(); ++i) {
        if (skip < outliers.size() && outliers[skip] == i) {
            ++skip;
            continue;
        }
        kept.push_back(i);
    }
    // The cloud keeps its kd-tree, without the outliers (no second build).
    cloud = Point_cloud<K>(std::move(cloud), outliers);
    for (std::uint32_t& o : outliers) o = input_index[o];
    if (given_normals) given_normals = internal::gather_columns(*given_normals, kept);
    for (std::size_t k = 0; k < kept.size(); ++k) kept[k] = input_index[kept[k]];
    input_index = std::move(kept);
    std::sort(outliers.begin(), outliers.end());
}

template <PointCloudKernel K>
std::vector<std::uint32_t> Point_cloud_object<K>::checked_input(Timed_cloud& built,
                                                                std::optional<Eigen::Matrix3Xd>& given_normals,
                                                                const Point_cloud_object_options& options)
{
    const Point_cloud<K>& cloud = built.cloud;
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
    internal::check_threads(options.threads, "point cloud object: threads");
    // Quiet comparisons: a NaN must be refused, not trap under floating-point exceptions.
    if (!(std::isgreater(options.normal_bandwidth, 0.0) && std::islessequal(options.normal_bandwidth, 1.0)))
        throw Invalid_input(internal::concat("point cloud object: normal_bandwidth is ", options.normal_bandwidth,
                                             "; it must lie in (0, 1]"));
    if (options.normal_residual_scale &&
        !(std::isfinite(*options.normal_residual_scale) && std::isgreater(*options.normal_residual_scale, 0.0)))
        throw Invalid_input(internal::concat("point cloud object: normal_residual_scale is ", *options.normal_residual_scale,
                                             "; it must be finite and > 0"));

    // Point i of the cloud is point input_index[i] of those given; the normals given follow.
    std::vector<std::uint32_t> input_index = std::move(built.input_index);
    if (input_index.empty()) {
        input_index.resize(cloud.size());
        std::iota(input_index.begin(), input_index.end(), std::uint32_t(0));
    } else if (given_normals) {
        given_normals = internal::gather_columns(*given_normals, input_index);
    }
    return input_index;
}

template <PointCloudKernel K>
std::optional<Local_spacing> Point_cloud_object<K>::outlier_stage(Point_cloud<K>& cloud,
                                                                  std::optional<Eigen::Matrix3Xd>& given_normals,
                                                                  std::vector<std::uint32_t>& input_index,
                                                                  const Point_cloud_object_options& options,
                                                                  Scan_estimate& scan, Preprocessing_times& timings)
{
    std::optional<Local_spacing> spacing;
    internal::Stage_timer stage(options, Preprocessing_stage::outliers, cloud.size());
    if (options.outliers.remove) {
        spacing = local_spacing(cloud, options.outliers.neighbors, true, options.outliers.threads);
        scan.outliers = find_outliers(*spacing, options.outliers);
        if (!scan.outliers.empty()) {
            const std::vector<std::uint32_t> removed = scan.outliers; // indices into the cloud, sorted
            remove_outliers(cloud, given_normals, input_index, scan.outliers);
            // The same spacing as computed afresh on the cloud left, querying only the points
            // that lost a neighbour.
            spacing = local_spacing_without(*spacing, removed, cloud, options.outliers.threads);
        }
    }
    timings.outliers = stage.finish();
    return spacing;
}

template <PointCloudKernel K>
Eigen::VectorXd Point_cloud_object<K>::domain_stage(const Point_cloud<K>& cloud, const std::optional<Local_spacing>& spacing,
                                                    const Point_cloud_object_options& options, Preprocessing_times& timings)
{
    internal::Stage_timer stage(options, Preprocessing_stage::domain, cloud.size());
    const bool reuse = spacing && spacing->k == std::min<std::size_t>(options.domain.neighbors, cloud.size() - 1);
    Eigen::VectorXd domain = reuse ? surface_domain_radii(*spacing, options.domain) : surface_domain_radii(cloud, options.domain);
    timings.outliers += stage.finish();
    return domain;
}

template <PointCloudKernel K>
template <class Distance>
void Point_cloud_object<K>::refit_stage(const Distance& distance, const Gaussian_weight& weight,
                                        const Point_cloud_object_options& options, Eigen::Matrix3Xd& normals,
                                        Preprocessing_times& timings)
{
    if (!(options.normal_bandwidth < 1.0) && !options.normal_residual_scale) return;
    internal::Stage_timer stage(options, Preprocessing_stage::normals, distance.size());
    const Gaussian_weight refit(weight.bandwidth() * options.normal_bandwidth, weight.threshold());
    std::optional<double> residual_scale;
    if (options.normal_residual_scale) residual_scale = *options.normal_residual_scale * refit.bandwidth();
    refit_normals(distance, refit, normals, options.threads, residual_scale);
    timings.normals += stage.finish();
}

template <PointCloudKernel K>
Gaussian_weight Point_cloud_object<K>::fit_kernel(const Point_cloud<K>& cloud, const Proximity_graph& graph, double r,
                                                  const Point_cloud_object_options& options,
                                                  std::shared_ptr<const Close_pairs_shortest_paths>& cpsp,
                                                  Normal_estimate& estimate, Scan_estimate& scan,
                                                  Preprocessing_times& timings)
{
    Gaussian_weight weight = gaussian_weight(r, options.bandwidth);
    // At most twice: a second time when the noise estimate asks for a wider kernel than the
    // sampling radius alone (automatic bandwidth only).
    for (int pass = 0; pass < 2; ++pass) {
        internal::Stage_timer cpsp_stage(options, Preprocessing_stage::cpsp_map, cloud.size());
        // The map must hold every point within the kernel's support radius R; its bound is
        // support * r, so support = R / r (eta itself for the automatic bandwidth).
        cpsp = std::make_shared<const Close_pairs_shortest_paths>(
            graph, r, Cpsp_options{.support = weight.support_radius() / r, .threads = options.threads});
        timings.cpsp += cpsp_stage.finish();
        internal::Stage_timer normals_stage(options, Preprocessing_stage::normals, cloud.size());
        estimate = estimate_normals(Geodesic_distance<K>(cloud, cpsp), weight, options.threads);
        scan.noise = PCCD::noise_estimate(estimate);
        timings.normals += normals_stage.finish();
        const std::optional<Gaussian_weight> wider = noise_aware_weight(weight, scan.noise, options.bandwidth);
        if (!wider || pass == 1) break;
        weight = *wider;
    }
    return weight;
}

template <PointCloudKernel K>
auto Point_cloud_object<K>::preprocess(Timed_cloud built, std::optional<Eigen::Matrix3Xd> given_normals,
                                       Point_cloud_object_options options) -> std::shared_ptr<const Data>
{
    Point_cloud<K>& cloud = built.cloud;
    Preprocessing_times timings;
    timings.kd_tree = built.milliseconds;
    std::vector<std::uint32_t> input_index = checked_input(built, given_normals, options);

    // A stage's own thread count stands; an unset one takes the object's.
    options = resolve_threads(std::move(options));
    Scan_estimate scan;
    scan.input_points = cloud.size();
    // One local-spacing pass serves the outlier test and, when both use the same k, the domain
    // radii below (after a removal, the spacing of the points left: local_spacing_without()).
    std::optional<Local_spacing> spacing = outlier_stage(cloud, given_normals, input_index, options, scan, timings);
    if (spacing) std::vector<std::uint32_t>().swap(spacing->neighbors); // the domain needs only the values

    std::shared_ptr<const Proximity_graph> graph;
    {
        internal::Stage_timer stage(options, Preprocessing_stage::graph, cloud.size());
        graph = std::make_shared<const Proximity_graph>(options.graph == Graph_kind::knn
                                                            ? knn_graph(cloud, options.knn)
                                                            : sphere_of_influence_graph(cloud, options.sphere_of_influence));
        timings.graph = stage.finish();
    }

    internal::Stage_timer radius_stage(options, Preprocessing_stage::sampling_radius, cloud.size());
    const double r = PCCD::sampling_radius(cloud, options.sampling_radius);
    timings.sampling_radius = radius_stage.finish();

    std::shared_ptr<const Close_pairs_shortest_paths> cpsp;
    Normal_estimate estimate;
    const Gaussian_weight weight = fit_kernel(cloud, *graph, r, options, cpsp, estimate, scan, timings);

    internal::Stage_timer orientation_stage(options, Preprocessing_stage::orientation, cloud.size());
    const Orientation_report orientation =
        given_normals ? orient_normals_with_hints(*graph, cloud.coordinates(), estimate.normals, *given_normals)
                      : orient_normals(*graph, cloud.coordinates(), estimate.normals);
    timings.normals += orientation_stage.finish();
    refit_stage(Geodesic_distance<K>(cloud, cpsp), weight, options, estimate.normals, timings);
    Eigen::VectorXd domain = domain_stage(cloud, spacing, options, timings);

    return std::make_shared<const Data>(make_data(std::move(cloud), std::move(graph), std::move(cpsp), r, weight,
                                                  std::move(estimate.normals), std::move(domain), orientation,
                                                  given_normals.has_value(), std::move(scan), timings, options,
                                                  std::move(input_index)));
}

} // namespace PCCD
