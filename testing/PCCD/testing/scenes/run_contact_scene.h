// PCCD/testing/scenes/run_contact_scene.h -- plays the deforming contact scene (Bunny_contact_scene.h)
// frame by frame: the deforming object follows the moved points (Deforming_point_cloud_object::
// set_positions) and is queried against the rigid obstacle; the reference rebuilds a
// Point_cloud_object from the same points and asks the same query; the exact verdict of the mesh
// says which frames are grazing. Used by `pccd kinetic-bench --scene bunny-contact` and the
// deforming-cloud tests (doc/manual/kinetic.md, "Deforming point clouds"; doc/benchmarks.md,
// "Deforming contact"). Not library code (testing/, target PCCD::testing; never installed).
#pragma once

#include <chrono>
#include <cstddef>
#include <ctime>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Kinetic/Deforming_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>

#include <PCCD/testing/scenes/Bunny_contact_scene.h>

namespace PCCD::testing {

/// Options of run_contact_scene.
struct Contact_run_options {
    /// Worker threads of both the frame update and the rebuild (0: all); default 1.
    unsigned threads = 1;
    /// How the deforming object updates its normals.
    Normal_update normals = Normal_update::transport;
    /// The stretch rule of the deforming object.
    double stretch_bound = Deformation_options{}.stretch_bound;
};

/// One frame of the run.
struct Contact_frame {
    double time = 0.0;
    bool kinetic = false;  ///< verdict of the deforming object
    bool rebuild = false;  ///< verdict of the object rebuilt from the frame's points
    bool truth = false;    ///< exact verdict (deformed mesh against the sphere)
    /// True when the exact verdict is within one sampling radius (of the rebuilt cloud) of changing:
    /// no cloud of this density decides such a frame, so it is left out of the agreement.
    bool grazing = false;
    double margin = 0.0;          ///< Contact_truth::margin
    double kinetic_ms = 0.0;      ///< update + query, wall-clock
    double kinetic_cpu_ms = 0.0;  ///< the same, processor time
    double update_ms = 0.0;       ///< the update alone, wall-clock
    double rebuild_ms = 0.0;      ///< rebuild + query, wall-clock
    double rebuild_cpu_ms = 0.0;  ///< the same, processor time
    double max_stretch = 1.0;     ///< Deformation_report::max_stretch
    double min_stretch = 1.0;
};

/// The whole run.
struct Contact_run {
    std::vector<Contact_frame> frames;
    /// Frames not grazing, and among them those where the kinetic and rebuilt verdicts agree.
    std::size_t compared = 0;
    std::size_t agreeing = 0;
    /// Among the compared frames, those where each verdict equals the exact one.
    std::size_t kinetic_exact = 0;
    std::size_t rebuild_exact = 0;
    /// Frames whose exact verdict is contact.
    std::size_t contact_frames = 0;
    double rest_build_ms = 0.0;

    double agreement() const { return compared == 0 ? 1.0 : double(agreeing) / double(compared); }
    template <class Field>
    double mean(Field field) const
    {
        double sum = 0.0;
        for (const Contact_frame& f : frames) sum += f.*field;
        return frames.empty() ? 0.0 : sum / double(frames.size());
    }
};

namespace detail {

inline double cpu_ms_since(std::clock_t start) { return 1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC; }
inline double wall_ms_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// Readable property map from an index to a column of a 3 x N matrix.
struct Matrix_column_map {
    const Eigen::Matrix3Xd* points;
    friend Eigen::Vector3d get(const Matrix_column_map& m, std::size_t i) { return m.points->col(Eigen::Index(i)); }
};

} // namespace detail

/// Plays every frame of `scene` (see the header's comment).
/// \throws what the objects and queries throw (Deformation_error if the scene breaks the stretch rule).
inline Contact_run run_contact_scene(const Bunny_contact_scene& scene, const Contact_run_options& options = {})
{
    // 0 asks for all available threads: the options' unset count.
    const std::optional<unsigned> threads = options.threads == 0 ? std::nullopt : std::optional<unsigned>(options.threads);
    Point_cloud_object_options object_options;
    object_options.threads = threads;
    object_options.outliers.remove = false; // both objects keep every point
    std::vector<std::size_t> obstacle_items(std::size_t(scene.obstacle_points.cols()));
    for (std::size_t i = 0; i < obstacle_items.size(); ++i) obstacle_items[i] = i;
    const Point_cloud_object<> obstacle(obstacle_items, detail::Matrix_column_map{&scene.obstacle_points},
                                        object_options);
    Contact_run run;
    const auto rest_start = std::chrono::steady_clock::now();
    Deforming_point_cloud_object<> deforming(
        scene.rest_points, object_options,
        Deformation_options{.stretch_bound = options.stretch_bound, .normals = options.normals, .threads = threads});
    run.rest_build_ms = detail::wall_ms_since(rest_start);
    std::vector<std::size_t> items(std::size_t(scene.rest_points.cols()));
    for (std::size_t i = 0; i < items.size(); ++i) items[i] = i;

    for (std::size_t k = 0; k < scene.frames(); ++k) {
        Contact_frame frame;
        frame.time = scene.time_of(k);
        const Eigen::Matrix3Xd points = scene.points_at(frame.time);

        auto wall = std::chrono::steady_clock::now();
        auto cpu = std::clock();
        const Deformation_report& report = deforming.set_positions(points);
        frame.update_ms = detail::wall_ms_since(wall);
        frame.kinetic = do_intersect(deforming, obstacle).intersects;
        frame.kinetic_ms = detail::wall_ms_since(wall);
        frame.kinetic_cpu_ms = detail::cpu_ms_since(cpu);
        frame.max_stretch = report.max_stretch;
        frame.min_stretch = report.min_stretch;

        wall = std::chrono::steady_clock::now();
        cpu = std::clock();
        const Point_cloud_object<> rebuilt(items, detail::Matrix_column_map{&points}, object_options);
        frame.rebuild = do_intersect(rebuilt, obstacle).intersects;
        frame.rebuild_ms = detail::wall_ms_since(wall);
        frame.rebuild_cpu_ms = detail::cpu_ms_since(cpu);

        const Contact_truth truth = scene.truth_at(frame.time);
        frame.truth = truth.intersecting;
        frame.margin = truth.margin;
        frame.grazing = truth.margin < rebuilt.sampling_radius();
        if (frame.truth) ++run.contact_frames;
        if (!frame.grazing) {
            ++run.compared;
            if (frame.kinetic == frame.rebuild) ++run.agreeing;
            if (frame.kinetic == frame.truth) ++run.kinetic_exact;
            if (frame.rebuild == frame.truth) ++run.rebuild_exact;
        }
        run.frames.push_back(frame);
    }
    return run;
}

} // namespace PCCD::testing
