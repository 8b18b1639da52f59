// Accuracy of first-hit and curve queries on clouds that look like scans, against CGAL's exact
// answer and next to the naive point test on the very same clouds. Shared by the validation tests
// (scan_validation_test.cpp, cad_validation_test.cpp) and the benchmark programs (scan_accuracy.cpp,
// miss_causes.cpp), which print the same table; doc/benchmarks.md "Accuracy on scans" explains it,
// and it checks the accuracy claims of doc/manual/intersection.md ("Accuracy"). Not library code
// (testing/, never installed): the functions are compiled once, in testing/src/scan_validation.cpp,
// and a program that includes this header links the target PCCD::testing_scan_validation.
//
// For each closed scanned mesh (normalized into [-1, 1]^3) and each cloud condition, one cloud is
// drawn uniformly by area from the mesh and preprocessed once; the benchmark pose procedure (two
// copies, random rotations, B translated by d along x) poses it against itself. The truth of a pose
// is CGAL's exact verdict on the meshes; a pose whose exact separation or penetration is below one
// sampling radius r of the clean cloud is grazing and counted apart.
#pragma once

#include <PCCD/Exact/Exact_mesh.h>
#include <PCCD/Exact/mesh_intersection.h>
#include <PCCD/Exact/mesh_separation.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/sample_triangle_mesh.h>

#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace PCCD::testing {

/// One way a scan differs from clean mesh vertices.
struct Scan_condition {
    std::string name;
    /// Points drawn per cloud, as a fraction of the clean cloud's count.
    double density = 1.0;
    /// Gaussian noise per coordinate, in mean spacings of the clean cloud.
    double noise = 0.0;
    /// Uniform outliers in the mesh's bounding box, as a fraction of the point count.
    double outliers = 0.0;
};

/// The conditions of the validation: clean, noise 0.3 and 0.6 spacings, a quarter of the density,
/// 1 % outliers with noise 0.2 spacings.
inline std::vector<Scan_condition> scan_conditions()
{
    return {{"clean", 1.0, 0.0, 0.0},
            {"noise 0.3", 1.0, 0.3, 0.0},
            {"noise 0.6", 1.0, 0.6, 0.0},
            {"quarter density", 0.25, 0.0, 0.0},
            {"1% outliers + noise 0.2", 1.0, 0.2, 0.01}};
}

/// The conditions of the validation on CAD and mechanical parts (at each density of
/// cad_densities()): clean, noise 0.3 and 0.6 spacings, 1 % outliers.
inline std::vector<Scan_condition> cad_conditions()
{
    return {{"clean", 1.0, 0.0, 0.0}, {"noise 0.3", 1.0, 0.3, 0.0}, {"noise 0.6", 1.0, 0.6, 0.0}, {"1% outliers", 1.0, 0.0, 0.01}};
}

/// Points per clean cloud of the CAD validation: from sparse to dense.
inline std::vector<std::size_t> cad_densities() { return {500, 2000, 8000, 30000}; }

/// Closed CAD and mechanical meshes of libcgal-demo with sharp edges, thin walls and handles.
inline std::vector<std::string> cad_models()
{
    return {"anchor.off", "joint.off", "cheese.off", "helmet.off", "handle.off", "fandisk.off", "pipe.off", "itemb.off"};
}

/// A closed mesh, its exact reference, and the spacing and sampling radius of its clean cloud.
struct Scan_model {
    std::string name;
    PCCD::Triangle_mesh_data mesh;
    std::unique_ptr<PCCD::Exact_mesh> exact;
    std::size_t clean_points = 0;
    double clean_spacing = 0.0;
    double clean_r = 0.0;
};

/// One cloud of a model under a condition, preprocessed.
struct Scan_cloud {
    std::unique_ptr<PCCD::Point_cloud_object<>> object;
    /// The lean object (Euclidean kernel) of the same points, when asked for.
    std::unique_ptr<PCCD::Euclidean_point_cloud_object<>> lean;
    /// The points as drawn (outliers included): what the naive test sees.
    std::unique_ptr<PCCD::Point_cloud<>> raw;
    double spacing = 0.0; // mean spacing of the raw cloud
    double preprocessing_ms = 0.0;
};

/// Sets the clean cloud of `model` to `points` points (seed `seed`): its spacing and sampling radius,
/// which the conditions and the grazing band are relative to. The mesh and its exact reference stay.
void set_density(Scan_model& model, std::size_t points, std::uint64_t seed);

/// Loads `dir/file`, normalizes it into [-1, 1]^3 and measures its clean cloud of `points` points
/// (seed `seed`).
Scan_model load_scan_model(const std::string& dir, const std::string& file, std::size_t points, std::uint64_t seed);

/// The cloud of `model` under `condition` (seed `seed`; the clean condition with the model's seed
/// gives the model's clean cloud).
Scan_cloud make_scan_cloud(const Scan_model& model, const Scan_condition& condition, std::uint64_t seed,
                           const PCCD::Point_cloud_object_options& options = {}, bool lean = false);

/// The naive test users write: the posed clouds collide iff some point of B lies within `radius`
/// of a point of A (here: one mean spacing of A).
bool naive_point_test(const PCCD::Point_cloud<>& a, const PCCD::Rigid_transform_3<double>& pose_a,
                      const PCCD::Point_cloud<>& b, const PCCD::Rigid_transform_3<double>& pose_b, double radius);

/// False negatives and positives of one method over poses.
struct Error_tally {
    std::size_t intersecting = 0, separated = 0, grazing = 0;
    std::size_t false_negatives = 0, false_positives = 0, grazing_reported = 0;
    double fn_rate() const { return intersecting ? double(false_negatives) / double(intersecting) : 0.0; }
    double fp_rate() const { return separated ? double(false_positives) / double(separated) : 0.0; }
    void add(PCCD::Pose_class cls, bool answer)
    {
        if (cls == PCCD::Pose_class::grazing) {
            ++grazing;
            grazing_reported += answer;
        } else if (cls == PCCD::Pose_class::intersecting) {
            ++intersecting;
            false_negatives += !answer;
        } else {
            ++separated;
            false_positives += answer;
        }
    }
};

/// The exact verdicts of the poses of one model (computed once, shared by every condition).
struct Posed_truth {
    Benchmark_pose pose;
    PCCD::Exact_separation separation;
    PCCD::Pose_class cls;
};

std::vector<Posed_truth> exact_truth(const Scan_model& model, std::size_t rotations, std::uint64_t seed);

/// The poses of `truth` classified again for another sampling radius r (the grazing band of a
/// cloud of another density); the exact separations are kept.
std::vector<Posed_truth> reclassify(std::vector<Posed_truth> truth, double r);

/// One row of the table: a model under a condition.
struct Scan_row {
    std::string model, condition;
    std::size_t points = 0;
    Error_tally isearch, rst, naive;
    double isearch_mean_us = 0.0, rst_mean_us = 0.0;
    /// With a lean object: its interpolation search, and the poses (grazing ones included) where its
    /// verdict differs from the default object's (with the same seed).
    Error_tally lean;
    std::size_t lean_differs = 0;
    double lean_mean_us = 0.0;
};

/// Runs both policies and the naive test on every pose of `truth`; prints each wrong non-grazing
/// answer when `verbose`.
Scan_row evaluate_first_hits(const Scan_model& model, const Scan_condition& condition, const Scan_cloud& cloud,
                             const std::vector<Posed_truth>& truth, bool verbose,
                             PCCD::Intersection_options options = {});

/// Adds the counts of `part` to `sum`.
void add_to(Scan_row& sum, const Scan_row& part);

/// One truth for both queries: on every pose of `truth` (grazing ones included), with the seeds of
/// evaluate_first_hits(), the poses where intersection_points() finds a point, and among them those
/// where do_intersect() with the same options says anything but intersecting. Both policies.
std::pair<std::size_t, std::size_t> one_truth_violations(const Scan_cloud& cloud, const std::vector<Posed_truth>& truth);

/// The validation programs' assertions: prints "ok" or "FAIL" and the claim; failures() counts
/// the failed ones (the exit code).
int& failures();

void check(bool ok, const std::string& what);

/// "k/n = p %".
std::string percent(std::size_t k, std::size_t n);

void print_scan_table_header();

void print_scan_row(const Scan_row& r);

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// Distances of intersection_points() to the exact polylines, in mean spacings of the clean cloud,
/// and the coverage of the exact curves (samples every half spacing with a point within 3 spacings).
/// A point more than 3 spacings from every polyline but within one clean sampling radius r of both
/// meshes lies on a near-contact: there the meshes come closer than the grazing band of the
/// first-hit table without crossing, which no cloud of this density can tell from a crossing. Such
/// points are counted apart, and `max_elsewhere` is the largest distance of the other points.
struct Curve_figures {
    std::size_t poses = 0, points = 0, near_contacts = 0;
    double median = 0.0, p95 = 0.0, max = 0.0, max_elsewhere = 0.0, coverage = 0.0;
};

/// Distance from the world point x to `model`'s mesh posed by `pose`.
double mesh_distance(const Scan_model& model, const PCCD::Rigid_transform_3<double>& pose, const Eigen::Vector3d& x);

Curve_figures evaluate_curves(const Scan_model& model, const Scan_cloud& cloud, const std::vector<Posed_truth>& truth,
                              std::size_t max_poses, PCCD::Intersection_options options = {});

} // namespace PCCD::testing
