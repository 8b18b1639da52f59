// Accuracy of distance() against the exact reference on the meshes the clouds come from (label
// exact): the scanned models and the closed CAD parts of libcgal-demo, normalized into [-1, 1]^3,
// each as four clouds -- its mesh vertices and an area sample, each clean and with Gaussian noise
// of 0.3 mean spacings -- posed against itself by the benchmark pose procedure (doc/algorithms.md,
// "Benchmark procedure"). The truth is exact_distance (separate poses) and exact_max_depth
// (intersecting poses) of PCCD/Exact/mesh_distance.h; poses within the grazing band of the cloud
// (classify_pose with its sampling radius) are left out of the status check.
//
// Unit: the mean spacing s of the clean cloud (Point_cloud::mean_spacing, the mean distance from a
// point to its nearest other point, as the scan validation measures it); the noisy cloud is
// measured in the spacing of the clean cloud it was drawn like, since its noise is defined in it.
//
// Prints one row per model and cloud, then asserts what must hold (per row: the status is
// do_intersect()'s on every non-grazing pose, the witnesses lie on their surfaces, the distance
// exceeds exact + |f_A| + |f_B| at the mesh's closest points by a median <= 0.25 s; over all rows: the exact
// distance lies in the widened interval on >= 99.5 % of the poses, and the median over the eight
// models of the clean area clouds' median error is <= 0.4 s), and prints the acceptance
// figures below as met or missed without asserting them (the surfaces' offset at protrusions and the
// depth's inside test on thin parts miss some; doc/benchmarks.md):
// - separate poses with exact distance >= 1 s: |distance - exact| median <= 0.1 s (clean), 0.25 s
//   (noisy); p99 <= 0.5 s (clean), 1 s (noisy); the exact distance lies in [lower_bound - 0.5 s,
//   upper_bound + 0.5 s] on >= 99.5 % of them; the witnesses lie on their surfaces (|f| <= 0.05 s)
//   and |point_a - point_b| is the distance;
// - status equals do_intersect()'s with the same intersection options on every pose outside the
//   grazing band;
// - intersecting poses deeper than 2 s (exact_max_depth, samples 0.1 area-cloud spacings apart,
//   so within 0.1 s of the true maximum for the area clouds and less for the vertex clouds, which
//   are sparser on these models but the bunny's): |depth - exact|
//   median <= 0.25 s, angle between contact_normal and the exact one median <= 15 degrees.
//
// A plain program (no Catch2) so that missing data is reported to ctest as skipped (exit code 77),
// never as passed. Release: 4 rotation pairs per distance, 52 poses per model and cloud (about
// half of them count for the distance and a half for the depth) on the bunny, the elephant and six
// CAD parts; Debug and sanitizer builds run a smoke version (elephant and anchor, 2 rotation pairs)
// with the same bounds, but for the median over the models, which needs all eight and is printed only.
#include "../build_helpers.h"
#include <PCCD/Exact/mesh_distance.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/testing/scan_validation.h>
#include <PCCD/sharp_feature_options.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

constexpr std::size_t rotations = pccd_test::by_build<std::size_t>(4, 2);
/// Points of the area-sampled clouds.
constexpr std::size_t area_points = 8000;
/// The sample spacing of exact_max_depth, in mean spacings of the area cloud (its depths are within
/// it of the true maximum).
constexpr double depth_sample_spacing = 0.1;
const std::vector<std::string> scanned_models =
    pccd_test::by_build(std::vector<std::string>{"bunny00.off", "elephant.off"}, std::vector<std::string>{"elephant.off"});
/// The closed CAD parts of PCCD::testing::cad_models() but cheese.off and pipe.off, whose exact
/// depths take minutes per model: their deepest points lie on wide plateaus of constant depth (a
/// tube's axis, parallel walls), which the depth search must sample finely all over.
const std::vector<std::string> cad_models = pccd_test::by_build(
    std::vector<std::string>{"anchor.off", "joint.off", "helmet.off", "handle.off", "fandisk.off", "itemb.off"},
    std::vector<std::string>{"anchor.off"});

using PCCD::testing::check;
using PCCD::testing::Clock;
using PCCD::testing::us_since;
using Pose = PCCD::Rigid_transform_3<double>;

/// The exact answers for one pose of a model (shared by its clouds).
struct Pose_truth {
    PCCD::testing::Posed_truth posed; // pose, exact_separation, class (for the clean area cloud)
    std::optional<PCCD::Exact_distance> distance; // separate poses
    std::optional<PCCD::Exact_depth> depth;       // intersecting poses
};

/// One cloud of a model, preprocessed, with its unit.
struct Cloud {
    std::string name;
    bool noisy = false;
    std::unique_ptr<PCCD::Point_cloud_object<>> object;
    double spacing = 0.0;        // the unit s
    double sampling_radius = 0.0; // of the clean cloud: the grazing band
};

/// Figures of one row.
struct Row {
    std::string model, cloud;
    std::size_t points = 0;
    double spacing = 0.0;
    std::vector<double> distance_errors; // in s, separate poses with exact distance >= 1 s
    std::size_t covered = 0;
    std::size_t witness_off_surface = 0, witness_gap_mismatch = 0;
    std::size_t status_poses = 0, status_mismatches = 0, status_vs_exact = 0;
    std::vector<double> depth_errors, normal_angles; // intersecting poses deeper than 2 s
    // Diagnostics (not asserted): the signed distance error (distance - exact) / s, and the angle
    // between contact_normal and the exact normal at PCCD's own deepest witness (x - y or y - x
    // with y the exact closest point of the other mesh), which is defined even where the exact
    // deepest point has several closest points.
    std::vector<double> signed_errors, witness_normal_angles;
    // f_A + f_B at the exact closest points, / s: how far outside the implicit surfaces the mesh's
    // closest points lie (what the implicit surfaces add to the mesh distance).
    std::vector<double> surface_offsets;
    // (distance - exact) / s minus that offset: the error left to the query itself, beyond where
    // its surfaces lie (asserted: the query finds the distance of its surfaces).
    std::vector<double> query_residuals;
    // Deep poses whose PCCD deepest witness lies outside the other mesh's volume (exact test).
    std::size_t deep_witness_outside = 0;
    // The normal angles on the poses whose exact normal is well posed: the closest point of the
    // exact deepest point moves by less than 20 degrees of normal when the point moves by 0.5 s.
    std::vector<double> well_posed_angles;
    double mean_us = 0.0;
};

double median_of(const std::vector<double>& v) { return v.empty() ? std::nan("") : PCCD::testing::median(v); }

double p99_of(std::vector<double> v)
{
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    return PCCD::testing::sorted_quantile(v, 99);
}

/// Whether the world point x lies inside `model`'s mesh placed by `pose` (exact).
bool inside_mesh(const PCCD::testing::Scan_model& model, const Pose& pose, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d local = pose.inverse().transform_point(x);
    return model.exact->bounded_side(PCCD::Exact_mesh::Point_3(local.x(), local.y(), local.z())) == CGAL::ON_BOUNDED_SIDE;
}

/// The closest point of `model`'s mesh placed by `pose` to the world point x.
Eigen::Vector3d closest_on_mesh(const PCCD::testing::Scan_model& model, const Pose& pose, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d local = pose.inverse().transform_point(x);
    const PCCD::Exact_mesh::Point_3 c = model.exact->tree().closest_point(PCCD::Exact_mesh::Point_3(local.x(), local.y(), local.z()));
    return pose.transform_point(Eigen::Vector3d(c.x(), c.y(), c.z()));
}

double angle_degrees(const Eigen::Vector3d& u, const Eigen::Vector3d& v)
{
    if (u.hasNaN() || v.hasNaN() || u.norm() == 0.0 || v.norm() == 0.0) return 180.0;
    return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

/// Whether the exact contact normal of `depth` is well posed at the scale s: moving the deepest
/// point by 0.5 s along each axis turns the normal (deepest point minus its closest point on the
/// other mesh) by less than 20 degrees. Near the other surface's medial axis the closest point
/// jumps between far-apart places and the normal flips: the deepest point of a deep penetration
/// often lies there.
bool well_posed_normal(const PCCD::testing::Scan_model& model, const Pose& pose_a, const Pose& pose_b,
                       const PCCD::Exact_depth& depth, double s)
{
    const bool a_deeper = depth.depth_a >= depth.depth_b;
    const Eigen::Vector3d x = a_deeper ? depth.deepest_a : depth.deepest_b;
    const Eigen::Vector3d y = a_deeper ? depth.closest_b : depth.closest_a;
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {-1.0, 1.0}) {
            const Eigen::Vector3d moved = x + sign * 0.5 * s * Eigen::Vector3d::Unit(axis);
            const Eigen::Vector3d closest = closest_on_mesh(model, a_deeper ? pose_b : pose_a, moved);
            if (angle_degrees(moved - closest, x - y) >= 20.0) return false;
        }
    return true;
}

std::vector<Pose_truth> exact_answers(const PCCD::testing::Scan_model& model, double depth_spacing)
{
    std::vector<Pose_truth> out;
    for (PCCD::testing::Posed_truth& t : PCCD::testing::exact_truth(model, rotations, 1)) {
        Pose_truth p{t, std::nullopt, std::nullopt};
        if (t.separation.surfaces_intersect)
            p.depth = PCCD::exact_max_depth(*model.exact, t.pose.pose_a, *model.exact, t.pose.pose_b, depth_spacing);
        else
            p.distance = PCCD::exact_distance(*model.exact, t.pose.pose_a, *model.exact, t.pose.pose_b);
        out.push_back(std::move(p));
    }
    return out;
}

/// The cloud of the mesh vertices, with Gaussian noise of `noise` times their mean spacing.
Cloud vertex_cloud(const PCCD::testing::Scan_model& model, double noise, std::uint64_t seed)
{
    const PCCD::Point_cloud<> clean(model.mesh.vertices);
    Cloud c;
    c.name = noise > 0.0 ? "vertices, noise 0.3" : "vertices";
    c.noisy = noise > 0.0;
    c.spacing = clean.mean_spacing();
    c.sampling_radius = PCCD::sampling_radius(clean);
    std::vector<Eigen::Vector3d> points = model.mesh.vertices;
    PCCD::Random_engine engine(seed);
    if (noise > 0.0)
        for (Eigen::Vector3d& p : points)
            for (int d = 0; d < 3; ++d) p(d) += noise * c.spacing * PCCD::standard_normal(engine);
    c.object = std::make_unique<PCCD::Point_cloud_object<>>(points);
    return c;
}

/// The area sample of the model (its clean cloud's density), with noise in its clean spacing; with
/// `sharp`, the same points made into the sharp-feature surface.
Cloud area_cloud(const PCCD::testing::Scan_model& model, double noise, std::uint64_t seed, bool sharp = false)
{
    Cloud c;
    c.name = std::string(noise > 0.0 ? "area, noise 0.3" : "area") + (sharp ? ", sharp" : "");
    c.noisy = noise > 0.0;
    c.spacing = model.clean_spacing;
    c.sampling_radius = model.clean_r;
    c.object = PCCD::testing::make_scan_cloud(model, {c.name, 1.0, noise, 0.0}, seed,
                                              sharp ? PCCD::sharp_feature_options() : PCCD::Point_cloud_object_options{})
                   .object;
    return c;
}

Row evaluate(const PCCD::testing::Scan_model& model, const Cloud& cloud, const std::vector<Pose_truth>& truth,
             bool verbose)
{
    Row row;
    row.model = model.name;
    row.cloud = cloud.name;
    row.points = cloud.object->size();
    row.spacing = cloud.spacing;
    const double s = cloud.spacing;
    const PCCD::Point_cloud_object<>& o = *cloud.object;
    const double tolerance = 0.02 * o.sampling_radius(); // distance()'s default absolute tolerance
    double total_us = 0.0;
    std::size_t k = 0;
    for (const Pose_truth& t : truth) {
        const Pose& pa = t.posed.pose.pose_a;
        const Pose& pb = t.posed.pose.pose_b;
        PCCD::Distance_options options{.penetration = true};
        options.intersection.seed = 1000 + k++;
        const auto start = Clock::now();
        const PCCD::Distance_result r = PCCD::distance(o, pa, o, pb, options);
        total_us += us_since(start);

        const PCCD::Pose_class cls = PCCD::classify_pose(t.posed.separation, cloud.sampling_radius);
        if (cls != PCCD::Pose_class::grazing) {
            ++row.status_poses;
            const PCCD::Intersection_result di = PCCD::do_intersect(o, pa, o, pb, options.intersection);
            if (di.status != r.status) {
                ++row.status_mismatches;
                if (verbose)
                    std::printf("    %s / %s: d = %.2f rot %zu: distance() status %d, do_intersect() status %d\n",
                                model.name.c_str(), cloud.name.c_str(), t.posed.pose.distance, t.posed.pose.rotation_index,
                                int(r.status), int(di.status));
            }
            const bool exact_intersecting = cls == PCCD::Pose_class::intersecting;
            if (r.intersecting() != exact_intersecting) ++row.status_vs_exact;
        }

        if (t.distance && t.distance->distance >= s) {
            const double exact = t.distance->distance;
            const double error = std::abs(r.distance - exact); // NaN or infinity if no distance: counts as error
            row.distance_errors.push_back(std::isfinite(error) ? error / s : std::numeric_limits<double>::infinity());
            if (std::isfinite(error)) row.signed_errors.push_back((r.distance - exact) / s);
            const PCCD::Surface_evaluation ea = o.surface().evaluate(pa.inverse().transform_point(t.distance->point_a));
            const PCCD::Surface_evaluation eb = o.surface().evaluate(pb.inverse().transform_point(t.distance->point_b));
            if (ea.defined() && eb.defined()) {
                row.surface_offsets.push_back((ea.value + eb.value) / s);
                // |f| is about the distance to the zero set, so the surfaces' distance is at most
                // exact + |f_A| + |f_B| (whatever the sign, which a misoriented patch flips).
                if (std::isfinite(error))
                    row.query_residuals.push_back((r.distance - exact - std::abs(ea.value) - std::abs(eb.value)) / s);
            }
            const bool covered = exact >= r.lower_bound - 0.5 * s && exact <= r.upper_bound + 0.5 * s;
            row.covered += covered;
            bool on_surface = false, gap_ok = false;
            if (r.status == PCCD::Intersection_status::separate && !r.point_a.hasNaN() && !r.point_b.hasNaN()) {
                const PCCD::Surface_evaluation fa = o.surface().evaluate(pa.inverse().transform_point(r.point_a));
                const PCCD::Surface_evaluation fb = o.surface().evaluate(pb.inverse().transform_point(r.point_b));
                on_surface = fa.defined() && fb.defined() && std::abs(fa.value) <= 0.05 * s && std::abs(fb.value) <= 0.05 * s;
                gap_ok = std::abs((r.point_a - r.point_b).norm() - r.distance) <= tolerance;
            }
            row.witness_off_surface += !on_surface;
            row.witness_gap_mismatch += !gap_ok;
            if (verbose && (!covered || !(error <= 0.5 * s) || !on_surface))
                std::printf("    %s / %s: d = %.2f rot %zu: exact %.4f, distance %.4f in [%.4f, %.4f] (%.2f s off)%s\n",
                            model.name.c_str(), cloud.name.c_str(), t.posed.pose.distance, t.posed.pose.rotation_index,
                            exact, r.distance, r.lower_bound, r.upper_bound, error / s,
                            on_surface ? "" : ", witness off its surface");
        }
        if (t.depth && cls == PCCD::Pose_class::intersecting && t.depth->depth > 2.0 * s) {
            const double error = std::abs(r.depth - t.depth->depth);
            row.depth_errors.push_back(std::isfinite(error) ? error / s : std::numeric_limits<double>::infinity());
            const double angle = angle_degrees(r.contact_normal, t.depth->contact_normal);
            row.normal_angles.push_back(angle);
            if (well_posed_normal(model, pa, pb, *t.depth, s)) row.well_posed_angles.push_back(angle);
            if (!r.point_a.hasNaN() && !r.point_b.hasNaN()) {
                const bool a_deeper = r.depth_a >= r.depth_b;
                const Eigen::Vector3d x = a_deeper ? r.point_a : r.point_b;
                const Eigen::Vector3d y = closest_on_mesh(model, a_deeper ? pb : pa, x);
                row.witness_normal_angles.push_back(angle_degrees(r.contact_normal, a_deeper ? Eigen::Vector3d(x - y) : Eigen::Vector3d(y - x)));
                row.deep_witness_outside += !inside_mesh(model, a_deeper ? pb : pa, x);
            }
            if (verbose && (!(error <= 0.5 * s) || angle > 30.0))
                std::printf("    %s / %s: d = %.2f rot %zu: exact depth %.4f (a %.4f, b %.4f), depth %.4f (a %.4f, b %.4f) "
                            "(%.2f s off), normal %.1f deg off\n",
                            model.name.c_str(), cloud.name.c_str(), t.posed.pose.distance, t.posed.pose.rotation_index,
                            t.depth->depth, t.depth->depth_a, t.depth->depth_b, r.depth, r.depth_a, r.depth_b, error / s,
                            angle);
        }
    }
    row.mean_us = total_us / double(std::max<std::size_t>(1, truth.size()));
    return row;
}

void print_header()
{
    std::printf("%-13s %-27s %6s %8s | %4s %7s %7s %7s %7s %9s %7s | %9s %6s | %4s %7s %7s %10s %7s %5s | %9s\n", "model",
                "cloud", "points", "s", "n", "med/s", "p99/s", "bias/s", "f@ex/s", "covered", "wit.bad", "status", "vs ex.", "n",
                "depth/s", "angle", "angle(wp)", "ang@wit", "out", "us/query");
}

void print_row(const Row& r)
{
    const std::size_t n = r.distance_errors.size();
    char status[32];
    std::snprintf(status, sizeof status, "%zu/%zu", r.status_mismatches, r.status_poses);
    char covered[32];
    std::snprintf(covered, sizeof covered, "%zu/%zu", r.covered, n);
    char well_posed[32];
    std::snprintf(well_posed, sizeof well_posed, "%.1f (%zu)", median_of(r.well_posed_angles), r.well_posed_angles.size());
    std::printf("%-13s %-27s %6zu %8.5f | %4zu %7.3f %7.3f %+7.3f %+7.3f %9s %7zu | %9s %6zu | %4zu %7.3f %7.1f %10s %7.1f %5zu | %9.0f\n",
                r.model.c_str(), r.cloud.c_str(), r.points, r.spacing, n, median_of(r.distance_errors), p99_of(r.distance_errors),
                median_of(r.signed_errors), median_of(r.surface_offsets), covered, r.witness_off_surface + r.witness_gap_mismatch,
                status, r.status_vs_exact, r.depth_errors.size(), median_of(r.depth_errors), median_of(r.normal_angles),
                well_posed, median_of(r.witness_normal_angles), r.deep_witness_outside, r.mean_us);
}

/// The acceptance figures of the proximity queries, printed per row as met or missed (not asserted:
/// the distance is that of the implicit surfaces, which lie inside the meshes at the protrusions
/// where two objects come closest, and the depth's inside test fails on the scans' thin parts; both
/// are measured in doc/benchmarks.md). Returns the number missed.
std::size_t report_targets(const Row& r, bool noisy)
{
    const std::string name = r.model + " / " + r.cloud + ": ";
    const double median_bound = noisy ? 0.25 : 0.1, p99_bound = noisy ? 1.0 : 0.5;
    const std::size_t m = r.depth_errors.size();
    struct Target {
        const char* what;
        double value, bound;
    };
    const Target targets[] = {{"distance error median", median_of(r.distance_errors), median_bound},
                              {"distance error p99", p99_of(r.distance_errors), p99_bound},
                              {"depth error median", m ? median_of(r.depth_errors) : 0.0, 0.25},
                              {"contact normal angle median (degrees)", m ? median_of(r.normal_angles) : 0.0, 15.0}};
    std::size_t missed = 0;
    for (const Target& t : targets) {
        const bool met = t.value <= t.bound; // NaN: missed
        missed += !met;
        std::printf("  target %s %s: %s %.3f (bound %.2f)\n", met ? "met   " : "MISSED", name.c_str(), t.what, t.value, t.bound);
    }
    return missed;
}

/// What must hold on every row: enough poses; the status is do_intersect()'s on every non-grazing
/// pose; the witnesses lie on their surfaces and their distance is the distance; the query finds
/// its surfaces' distance (the error beyond the surfaces' offset at the exact closest points,
/// median within 0.25 s).
void check_row(const Row& r)
{
    const std::string name = r.model + " / " + r.cloud + ": ";
    const std::size_t n = r.distance_errors.size();
    char buf[256];
    check(n >= 10, name + std::to_string(n) + " separate poses >= 1 s apart (>= 10)");
    std::snprintf(buf, sizeof buf, "witnesses on their surfaces (|f| <= 0.05 s) on all %zu poses: %zu off, %zu with |a - b| != distance",
                  n, r.witness_off_surface, r.witness_gap_mismatch);
    check(r.witness_off_surface == 0 && r.witness_gap_mismatch == 0, name + buf);
    std::snprintf(buf, sizeof buf, "status as do_intersect() on every non-grazing pose: %zu/%zu differ", r.status_mismatches,
                  r.status_poses);
    check(r.status_poses > 0 && r.status_mismatches == 0, name + buf);
    // One-sided: the surfaces' distance is at most exact + |f_A| + |f_B| at the mesh's closest points
    // (each lies within about |f| of its surface), and less where the surfaces come closer elsewhere.
    const std::vector<double>& residual = r.query_residuals;
    std::snprintf(buf, sizeof buf,
                  "distance - (exact + |f_A| + |f_B| at the exact closest points): median %.3f s <= 0.25 s over %zu poses",
                  median_of(residual), residual.size());
    check(residual.size() >= n / 2 && median_of(residual) <= 0.25, name + buf);
    check(r.depth_errors.size() >= 5, name + std::to_string(r.depth_errors.size()) + " intersecting poses deeper than 2 s (>= 5)");
}

} // namespace

int main()
{
    const std::string dir = PCCD_DATA_DIR;
    if (dir.empty() || !std::ifstream(dir + "/" + scanned_models.front())) {
        std::printf("the meshes of libcgal-demo are not in PCCD_DATA_DIR (\"%s\"): distance accuracy skipped\n", dir.c_str());
        return 77;
    }
    std::vector<std::string> models = scanned_models;
    models.insert(models.end(), cad_models.begin(), cad_models.end());
    std::vector<Row> rows;
    std::vector<bool> noisy, sharp;
    std::size_t closed_models = 0;
    const auto start = Clock::now();
    print_header();
    for (const std::string& file : models) {
        PCCD::testing::Scan_model model = PCCD::testing::load_scan_model(dir, file, area_points, 2026);
        if (!model.exact->encloses_volume()) {
            std::printf("%-13s does not enclose a volume (%s): left out\n", file.c_str(),
                        model.exact->is_closed() ? "self-intersecting" : "not closed");
            continue;
        }
        ++closed_models;
        std::vector<Cloud> clouds;
        if (file == "bunny00.off") { // the only model whose vertices sample it densely (35,947)
            clouds.push_back(vertex_cloud(model, 0.0, 2026));
            clouds.push_back(vertex_cloud(model, 0.3, 2027));
        }
        clouds.push_back(area_cloud(model, 0.0, 2026));
        clouds.push_back(area_cloud(model, 0.3, 2027));
        clouds.push_back(area_cloud(model, 0.0, 2026, true));
        clouds.push_back(area_cloud(model, 0.3, 2027, true));
        const auto truth_start = Clock::now();
        const std::vector<Pose_truth> truth = exact_answers(model, depth_sample_spacing * model.clean_spacing);
        std::printf("%-13s exact truth of %zu poses: %.1f s\n", file.c_str(), truth.size(), PCCD::testing::ms_since(truth_start) / 1e3);
        for (const Cloud& c : clouds) {
            rows.push_back(evaluate(model, c, truth, true));
            noisy.push_back(c.noisy);
            sharp.push_back(c.name.ends_with(", sharp"));
            print_row(rows.back());
            std::fflush(stdout);
        }
    }
    std::printf("\n%zu models, %zu poses per model and cloud, %.0f s\n", closed_models, 13 * rotations,
                PCCD::testing::ms_since(start) / 1e3);
    std::printf("\ncolumns: n = separate poses with exact distance >= 1 s; med/s, p99/s = |distance - exact| / s;\n"
                "bias/s = median (distance - exact) / s; f@ex/s = median (f_A + f_B) / s at the exact closest points; covered = exact in [lower - 0.5 s, upper + 0.5 s]; wit.bad = witness pairs off the surfaces (|f| > 0.05 s)\n"
                "or with |a - b| != distance; status = poses (non-grazing) where distance() and do_intersect() differ;\n"
                "vs ex. = non-grazing poses where the status differs from the exact one; n (depth) = intersecting poses\n"
                "deeper than 2 s; depth/s = median |depth - exact| / s; angle = median angle of the contact normals;\n"
                "angle(wp) = the same on the poses whose exact normal is well posed (their number); ang@wit = median angle\n"
                "between contact_normal and the exact normal at PCCD's own deepest witness; out = deep poses whose PCCD\n"
                "deepest witness is outside the other mesh's volume (not asserted: diagnostics)\n");

    std::printf("\nassertions:\n");
    check(closed_models >= 2 + (pccd_test::debug_build ? 0 : 4), "closed models evaluated: " + std::to_string(closed_models));
    std::size_t covered = 0, separate = 0, sharp_covered = 0, sharp_separate = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (sharp[i]) { // the sharp-feature surface: what it is for, below
            sharp_covered += rows[i].covered;
            sharp_separate += rows[i].distance_errors.size();
            continue;
        }
        check_row(rows[i]);
        covered += rows[i].covered;
        separate += rows[i].distance_errors.size();
    }
    // The sharp-feature surface (IMLS): the status is still do_intersect()'s on every non-grazing
    // pose, and where the default surface rounds sharp edges most (its median error on the clean
    // area cloud above 0.5 s: the anchor and the fandisk, 0.92 and 1.16 s) its distance error is
    // well below the default surface's (measured 0.27 and 0.29 times; asserted <= 0.7 times). On
    // smooth parts it is not: it lies a little outside the points on convex parts, and the
    // witnesses find that (bunny 0.31 s against 0.14 s). Its interval is printed, not asserted:
    // the true distance can exceed upper_bound, which bounds the implicit surfaces' distance
    // (doc/manual/surface.md, "Sharp features").
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!sharp[i]) continue;
        const Row& r = rows[i];
        const std::string name = r.model + " / " + r.cloud + ": ";
        check(r.status_poses > 0 && r.status_mismatches == 0,
              name + "status as do_intersect() on every non-grazing pose: " + std::to_string(r.status_mismatches) + "/" +
                  std::to_string(r.status_poses) + " differ");
        if (noisy[i]) continue;
        for (std::size_t j = 0; j < rows.size(); ++j)
            if (!sharp[j] && !noisy[j] && rows[j].model == r.model && rows[j].cloud == "area" &&
                median_of(rows[j].distance_errors) > 0.5) {
                char line[200];
                std::snprintf(line, sizeof line, "distance error median %.3f s <= 0.7 x the default surface's %.3f s",
                              median_of(r.distance_errors), median_of(rows[j].distance_errors));
                check(median_of(r.distance_errors) <= 0.7 * median_of(rows[j].distance_errors), name + line);
            }
    }
    // The witnesses reach the surfaces' closest points, edges included: over the models' clean area
    // clouds (default surface), the median of the per-model median errors is at most 0.4 s
    // (measured 0.29 s; 0.55 s when the refinement's step did not back off at an edge). Asserted
    // on the eight models of the Release run; the smoke version's two are printed only.
    {
        std::vector<double> medians;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (!sharp[i] && !noisy[i] && rows[i].cloud == "area" && !rows[i].distance_errors.empty())
                medians.push_back(median_of(rows[i].distance_errors));
        char line[200];
        std::snprintf(line, sizeof line, "median over %zu models of the clean area clouds' median distance error: %.3f s <= 0.4 s",
                      medians.size(), medians.empty() ? 0.0 : median_of(medians));
        if (medians.size() >= 8)
            check(median_of(medians) <= 0.4, line);
        else
            std::printf("(not asserted on %zu models) %s\n", medians.size(), line);
    }
    std::printf("sharp-feature surface: exact distance in [lower - 0.5 s, upper + 0.5 s] on %zu of %zu separate poses "
                "(not asserted)\n",
                sharp_covered, sharp_separate);
    char buf[160];
    std::snprintf(buf, sizeof buf, "exact distance in [lower - 0.5 s, upper + 0.5 s] on %zu of %zu separate poses (>= 99.5 %%)",
                  covered, separate);
    check(separate > 0 && double(covered) >= 0.995 * double(separate), buf);
    std::printf("\nacceptance targets:\n");
    std::size_t missed = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) missed += report_targets(rows[i], noisy[i]);
    std::printf("%zu of %zu targets missed (not asserted; see doc/benchmarks.md)\n", missed, 4 * rows.size());
    return PCCD::testing::failures() ? 1 : 0;
}
