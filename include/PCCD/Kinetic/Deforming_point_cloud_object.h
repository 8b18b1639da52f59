// PCCD/Kinetic/Deforming_point_cloud_object.h -- a point cloud whose points move (along
// flightplans, or set by the caller every frame) and whose implicit surface follows them without a
// rebuild: the neighbourhoods (proximity graph, CPSP lists, kernel) are kept from the rest pose,
// the positions, normals, domain radii and hierarchy boxes are those of the current frame. It
// models CollisionObject, so do_intersect() and intersection_points() take it unchanged, against a
// rigid Point_cloud_object or another deforming object. Implements doc/manual/kinetic.md,
// "Deforming point clouds" (the near-isometry assumption and the stretch rule) and
// doc/algorithms.md, "Deforming point clouds".
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Eigen_kernel.h>
#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Hierarchy/Point_cloud_hierarchy.h>
#include <PCCD/Kinetic/Deformation.h>
#include <PCCD/Kinetic/internal/local_deformation.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Point_cloud_object_options.h>
#include <PCCD/Proximity_graph/Proximity_graph.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/Surface/internal/wls_fit.h>
#include <PCCD/concepts/Flightplan.h>
#include <PCCD/concepts/PointCloudKernel.h>
#include <PCCD/internal/finite.h>
#include <PCCD/internal/parallel.h>
#include <PCCD/internal/timing.h>

namespace PCCD {

/// A point cloud under a near-isometric deformation, ready for the intersection queries at every
/// frame.
///
/// Built once from the rest pose with the whole preprocessing of Point_cloud_object (graph,
/// sampling radius, kernel, CPSP map, oriented normals, domain radii, hierarchy). A frame
/// (set_positions(), advance_to()) then gives every point a new position and, in O(N k) without
/// any neighbour search or shortest path:
/// - the current positions and their kd-tree (the nearest point p* of an evaluation);
/// - the normals re-fitted over the kept CPSP lists at the current positions (the same fit as the
///   rest pose's), each oriented like its rest normal carried by the local deformation gradient
///   (least squares over the list), so any rotation of the cloud keeps the orientation;
/// - the domain radii (the hierarchy's reaches) scaled by each point's mean edge stretch;
/// - the hierarchy refitted over the rest pose's tree (Point_cloud_hierarchy's refit constructor);
/// - the sampling radius scaled by the largest edge stretch.
/// The geodesic distances (CPSP lists), the kernel and the noise estimate stay those of the rest
/// pose. This is right while the deformation is close to an isometry; the stretch rule checks it:
/// every edge of the graph must keep its length within a factor 1 + Deformation_options::
/// stretch_bound, else the frame fails (Deformation_error) or rebuilds the object
/// (Stretch_action::rebuild).
///
/// \tparam K a model of PointCloudKernel.
///
/// The points keep their indices: outlier removal and the spatial order of the rest pose's options
/// are turned off.
/// Copies share the rest data and the current frame (a frame replaces it; copies keep theirs).
/// Thread safety: const members may run concurrently (queries included); set_positions and
/// advance_to need exclusive access.
template <PointCloudKernel K = Eigen_kernel<double>>
class Deforming_point_cloud_object {
public:
    using Kernel = K;
    using FT = typename K::FT;
    using Rest_object = Point_cloud_object<K>;
    using Geodesic_surface = typename Rest_object::Geodesic_surface;
    using Coordinates = typename Point_cloud<K>::Coordinates;

    /// \name Construction
    /// @{

    /// The rest pose: the 3 x N `points` (point i in column i, the index every frame refers to),
    /// preprocessed with `options` (outlier removal and spatial order off).
    /// \throws Invalid_input as Point_cloud_object, or for a stretch bound that is not finite and > 0.
    explicit Deforming_point_cloud_object(const Eigen::Matrix3Xd& points, Point_cloud_object_options options = {},
                                          const Deformation_options& deformation = {})
        : m_options(in_given_order(options)), m_deformation(checked(deformation))
    {
        reset_rest(points);
    }
    /// @}

    /// \name Frames
    /// @{

    /// Moves point i to column i of the 3 x N `positions` and updates the surface, normals, domain
    /// radii and hierarchy (see the class). Returns the frame's report.
    /// \throws Invalid_input if positions has not N columns or a coordinate is not finite;
    ///         Deformation_error (an Invalid_input) if an edge leaves the stretch bound under
    ///         Stretch_action::fail. In both cases the object keeps its previous frame.
    /// Complexity: O(N k) for k the mean CPSP list length, plus O(N log N) for the kd-tree.
    const Deformation_report& set_positions(const Eigen::Matrix3Xd& positions)
    {
        const auto start = std::chrono::steady_clock::now();
        if (positions.cols() != Eigen::Index(size()))
            throw Invalid_input(internal::concat("deforming point cloud: ", positions.cols(), " positions given for ",
                                                 size(), " points"));
        if (!internal::all_finite(positions))
            for (Eigen::Index i = 0; i < positions.cols(); ++i)
                if (!internal::all_finite(positions.col(i)))
                    throw Invalid_input(internal::concat("deforming point cloud: the position of point ", i,
                                                         " is not finite"));
        Coordinates current = positions.template cast<FT>();
        Deformation_report report = m_frame->report;
        ++report.frame;
        report.rebuilt = false;
        const std::vector<internal::Point_stretch> stretch = measure(current);
        report.min_stretch = 1.0;
        report.max_stretch = 1.0;
        report.points_beyond = 0;
        const double high = 1.0 + m_deformation.stretch_bound, low = 1.0 / high;
        std::uint32_t worst = 0;
        double worst_off = -1.0;
        bool first = true;
        for (std::uint32_t i = 0; i < std::uint32_t(stretch.size()); ++i) {
            const auto& s = stretch[i];
            if (s.measured == 0) continue; // only virtual edges, or none of positive rest length
            report.min_stretch = first ? s.min : std::min(report.min_stretch, s.min);
            report.max_stretch = first ? s.max : std::max(report.max_stretch, s.max);
            first = false;
            if (s.max > high || s.min < low) ++report.points_beyond;
            const double off = std::max(s.max, 1.0 / std::max(s.min, 1e-300));
            if (off > worst_off) {
                worst_off = off;
                worst = i;
            }
        }
        if (report.points_beyond > 0) {
            if (m_deformation.on_stretch == Stretch_action::fail) {
                const auto& s = stretch[worst];
                const double ratio = s.max > high ? s.max : s.min;
                throw Deformation_error(internal::concat("deforming point cloud: the edge (", worst, ", ", s.worst,
                                                         ") of the proximity graph is at ", ratio,
                                                         " times its rest length, beyond the stretch bound [",
                                                         low, ", ", high, "] of the near-isometry assumption"),
                                        ratio, worst, s.worst);
            }
            reset_rest(positions);
            report.rebuilt = true;
            ++report.rebuilds;
            report.min_stretch = report.max_stretch = 1.0;
            report.milliseconds = internal::ms_since(start);
            auto frame = std::make_shared<Frame>(*m_frame);
            frame->report = report;
            m_frame = std::move(frame);
            return m_frame->report;
        }
        m_frame = make_frame(std::move(current), stretch, report);
        m_frame->report.milliseconds = internal::ms_since(start);
        return m_frame->report;
    }

    /// set_positions() for positions given as one vector per point.
    /// \throws as set_positions(const Eigen::Matrix3Xd&).
    const Deformation_report& set_positions(std::span<const Eigen::Vector3d> positions)
    {
        Eigen::Matrix3Xd matrix(3, Eigen::Index(positions.size()));
        for (std::size_t i = 0; i < positions.size(); ++i) matrix.col(Eigen::Index(i)) = positions[i];
        return set_positions(matrix);
    }

    /// The frame at time t of points moving along `flightplans` (one per point, point i along
    /// flightplans[i]): set_positions() with their positions at t.
    /// \tparam F a model of Flightplan.
    /// \throws Invalid_input if t is not finite or flightplans.size() != size(); as set_positions().
    template <Flightplan F>
    const Deformation_report& advance_to(double t, std::span<const F> flightplans)
    {
        if (!std::isfinite(t)) throw Invalid_input(internal::concat("deforming point cloud: time ", t, " is not finite"));
        if (flightplans.size() != size())
            throw Invalid_input(internal::concat("deforming point cloud: ", flightplans.size(), " flightplans for ",
                                                 size(), " points"));
        Eigen::Matrix3Xd positions(3, Eigen::Index(size()));
        for (std::size_t i = 0; i < flightplans.size(); ++i)
            positions.col(Eigen::Index(i)) = Eigen::Vector3d(flightplans[i].position(t));
        return set_positions(positions);
    }

    /// What the last frame measured.
    const Deformation_report& deformation() const { return m_frame->report; }
    /// @}

    /// \name CollisionObject (the current frame)
    /// @{
    std::size_t size() const { return m_rest->cloud().size(); }
    /// The current positions and their kd-tree.
    const Point_cloud<K>& cloud() const { return m_frame->cloud; }
    /// The implicit surface at the current positions (geodesic kernel, rest CPSP lists).
    const Geodesic_surface& surface() const { return m_frame->surface; }
    /// The rest pose's proximity graph.
    const Proximity_graph& graph() const { return m_rest->graph(); }
    /// The rest pose's CPSP map.
    const Close_pairs_shortest_paths& cpsp() const { return m_rest->cpsp(); }
    /// The rest pose's tree, refitted to the current positions, with the current domain radii as reaches.
    const Point_cloud_hierarchy& hierarchy() const { return m_frame->hierarchy; }
    /// r(P) of the rest pose times the largest edge stretch of the frame.
    double sampling_radius() const { return m_frame->sampling_radius; }
    double noise_estimate() const { return m_rest->noise_estimate(); }
    /// @}

    /// \name More of the current frame and the rest pose
    /// @{
    /// The oriented normals at the current positions, 3 x N (zero columns: undetermined).
    const Eigen::Matrix3Xd& normals() const { return m_frame->surface.normals(); }
    /// The current domain radii (empty when the rest pose has no domain).
    const Eigen::VectorXd& domain_radii() const { return m_frame->surface.domain_radii(); }
    /// The rest pose (its own surface, hierarchy and positions).
    const Rest_object& rest() const { return *m_rest; }
    const Deformation_options& options() const { return m_deformation; }
    /// @}

private:
    struct Frame {
        Point_cloud<K> cloud;
        Geodesic_surface surface;
        Point_cloud_hierarchy hierarchy;
        double sampling_radius;
        Deformation_report report;
    };

    /// Readable property map from an index to a column of a 3 x N matrix.
    struct Column_map {
        const Eigen::Matrix3Xd* points;
        friend Eigen::Vector3d get(const Column_map& m, std::size_t i) { return m.points->col(Eigen::Index(i)); }
    };

    static Point_cloud_object_options in_given_order(Point_cloud_object_options options)
    {
        options.outliers.remove = false;
        options.spatial_order = false;
        return options;
    }

    static const Deformation_options& checked(const Deformation_options& d)
    {
        if (!(std::isfinite(d.stretch_bound) && d.stretch_bound > 0.0))
            throw Invalid_input(internal::concat("deforming point cloud: stretch_bound ", d.stretch_bound,
                                                 " must be finite and > 0"));
        if (d.on_stretch != Stretch_action::fail && d.on_stretch != Stretch_action::rebuild)
            throw Invalid_input(internal::concat("deforming point cloud: unknown stretch action ", int(d.on_stretch)));
        if (d.normals != Normal_update::transport && d.normals != Normal_update::refit)
            throw Invalid_input(internal::concat("deforming point cloud: unknown normal update ", int(d.normals)));
        internal::check_threads(d.threads, "deforming point cloud: threads");
        return d;
    }

    /// (Re)builds the rest pose from `points`; the frame becomes the rest pose's own state.
    void reset_rest(const Eigen::Matrix3Xd& points)
    {
        std::vector<std::size_t> items(std::size_t(points.cols()));
        for (std::size_t i = 0; i < items.size(); ++i) items[i] = i;
        auto rest = std::make_shared<const Rest_object>(items, Column_map{&points}, m_options);
        if (rest->size() != std::size_t(points.cols()))
            throw Invalid_input("deforming point cloud: the rest pose lost points"); // outliers are off: unreachable
        m_rest_lengths = std::make_shared<const std::vector<double>>(
            internal::rest_edge_lengths(rest->graph(), rest->cloud().coordinates()));
        Deformation_report report = m_frame ? m_frame->report : Deformation_report{};
        m_frame = std::make_shared<Frame>(Frame{rest->cloud(), rest->surface(), rest->hierarchy(),
                                                rest->sampling_radius(), report});
        m_rest = std::move(rest);
    }

    std::vector<internal::Point_stretch> measure(const Coordinates& current) const
    {
        std::vector<internal::Point_stretch> stretch(size());
        internal::with_threads(m_deformation.threads, [&] {
            internal::parallel_for_ranges(size(), 512, [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i)
                    stretch[i] = internal::point_stretch(graph(), *m_rest_lengths, current, std::uint32_t(i));
            });
        });
        return stretch;
    }

    std::shared_ptr<Frame> make_frame(Coordinates current, const std::vector<internal::Point_stretch>& stretch,
                                      const Deformation_report& report) const
    {
        const std::size_t n = size();
        const Rest_object& rest = *m_rest;
        Point_cloud<K> cloud(std::move(current));
        const auto& now = cloud.coordinates();
        const auto& then = rest.cloud().coordinates();
        const Eigen::Matrix3Xd& rest_normals = rest.normals();
        const Gaussian_weight& weight = rest.weight();
        const double support = weight.support_radius();
        const Close_pairs_shortest_paths& map = rest.cpsp();

        const Proximity_graph& g = rest.graph();
        const auto& rows = g.row_offsets();
        const auto& adjacent = g.targets();
        const bool refit = m_deformation.normals == Normal_update::refit;
        Eigen::Matrix3Xd normals = Eigen::Matrix3Xd::Zero(3, Eigen::Index(n));
        internal::with_threads(m_deformation.threads, [&] {
            internal::parallel_for_ranges(n, 256, [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) {
                    const Eigen::Vector3d n0 = rest_normals.col(Eigen::Index(i));
                    if (n0.isZero(0.0)) continue; // undetermined at rest: stays so
                    const Eigen::Vector3d x = now.col(Eigen::Index(i)).template cast<double>();
                    const Eigen::Vector3d q = then.col(Eigen::Index(i)).template cast<double>();
                    // The rest normal carried by the local deformation gradient, fitted over the
                    // graph neighbours (the rest normal itself where they do not determine it).
                    const auto [t1, t2] = internal::tangent_basis(n0);
                    internal::Deformation_sums gradient;
                    for (std::uint64_t e = rows[i]; e < rows[i + 1]; ++e) {
                        if ((*m_rest_lengths)[e] == 0.0) continue; // virtual or duplicate
                        const Eigen::Index j = Eigen::Index(adjacent[e]);
                        const Eigen::Vector3d u = then.col(j).template cast<double>() - q;
                        gradient.add(Eigen::Vector3d(t1.dot(u), t2.dot(u), n0.dot(u)), now.col(j).template cast<double>() - x);
                    }
                    const Eigen::Vector3d transported = gradient.transported_normal().value_or(n0);
                    if (!refit) {
                        normals.col(Eigen::Index(i)) = transported;
                        continue;
                    }
                    // The rest pose's fit over the kept CPSP list at the current positions, oriented
                    // like the transported normal.
                    internal::Wls_sums sums;
                    const auto targets = map.targets(std::uint32_t(i));
                    const auto distances = map.distances(std::uint32_t(i));
                    for (std::size_t k = 0; k < targets.size(); ++k) {
                        const double gd = double(distances[k]);
                        if (gd > support) break;
                        sums.add(now.col(Eigen::Index(targets[k])).template cast<double>() - x, double(weight(gd)));
                    }
                    if (sums.count == 0 || !(sums.weight > 0.0)) continue;
                    const internal::Wls_fit fit = internal::finish_fit(x, sums);
                    if (!fit.determined) continue;
                    normals.col(Eigen::Index(i)) =
                        fit.normal.dot(transported) < 0.0 ? Eigen::Vector3d(-fit.normal) : fit.normal;
                }
            });
        });

        Eigen::VectorXd domain = rest.domain_radii();
        for (Eigen::Index i = 0; i < domain.size(); ++i) domain(i) *= stretch[std::size_t(i)].mean;
        Deformation_report r = report;
        Point_cloud_hierarchy hierarchy(rest.hierarchy(), now, domain);
        Geodesic_surface surface(Geodesic_distance<K>(cloud, rest.surface().distance().shared_map()), weight, std::move(normals),
                                 std::move(domain), rest.surface().fit());
        return std::make_shared<Frame>(Frame{std::move(cloud), std::move(surface), std::move(hierarchy),
                                             rest.sampling_radius() * r.max_stretch, r});
    }

    Point_cloud_object_options m_options;
    Deformation_options m_deformation;
    std::shared_ptr<const Rest_object> m_rest;
    std::shared_ptr<const std::vector<double>> m_rest_lengths;
    std::shared_ptr<Frame> m_frame;
};

} // namespace PCCD
