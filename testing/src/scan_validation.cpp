// The scan accuracy harness of scan_validation.h, compiled once (target PCCD::testing_scan_validation)
// instead of in every validation test and accuracy benchmark that includes it: its functions
// instantiate the object, both query policies, the exact mesh checks and the mesh reader, about 80 s
// of compilation each time.
#include <PCCD/testing/scan_validation.h>

namespace PCCD::testing {

namespace {

std::vector<Eigen::Vector3d> columns(const Eigen::Matrix3Xd& m)
{
    std::vector<Eigen::Vector3d> out(std::size_t(m.cols()));
    for (Eigen::Index i = 0; i < m.cols(); ++i) out[std::size_t(i)] = m.col(i);
    return out;
}

} // namespace

void set_density(Scan_model& model, std::size_t points, std::uint64_t seed)
{
    model.clean_points = points;
    PCCD::Random_engine engine(seed);
    const auto sample = PCCD::sample_triangle_mesh(model.mesh.vertices, model.mesh.triangles, points, engine);
    const PCCD::Point_cloud<> cloud(sample.points);
    model.clean_spacing = cloud.mean_spacing();
    model.clean_r = PCCD::sampling_radius(cloud);
}

Scan_model load_scan_model(const std::string& dir, const std::string& file, std::size_t points, std::uint64_t seed)
{
    Scan_model m;
    m.name = file;
    m.mesh = PCCD::IO::read_triangle_mesh(dir + "/" + file);
    Eigen::Matrix3Xd v(3, Eigen::Index(m.mesh.vertices.size()));
    for (std::size_t i = 0; i < m.mesh.vertices.size(); ++i) v.col(Eigen::Index(i)) = m.mesh.vertices[i];
    PCCD::normalize_to_unit_cube(v);
    for (std::size_t i = 0; i < m.mesh.vertices.size(); ++i) m.mesh.vertices[i] = v.col(Eigen::Index(i));
    m.exact = std::make_unique<PCCD::Exact_mesh>(m.mesh);
    set_density(m, points, seed);
    return m;
}

Scan_cloud make_scan_cloud(const Scan_model& model, const Scan_condition& condition, std::uint64_t seed,
                           const PCCD::Point_cloud_object_options& options, bool lean)
{
    PCCD::Random_engine engine(seed);
    const std::size_t n = std::max<std::size_t>(16, std::size_t(std::llround(condition.density * double(model.clean_points))));
    const auto sample = PCCD::sample_triangle_mesh(model.mesh.vertices, model.mesh.triangles, n, engine,
                                                   {.noise_sigma = condition.noise * model.clean_spacing});
    std::vector<Eigen::Vector3d> points = columns(sample.points);
    if (condition.outliers > 0.0) {
        Eigen::AlignedBox3d box;
        for (const auto& p : model.mesh.vertices) box.extend(p);
        const std::size_t k = std::size_t(std::llround(condition.outliers * double(n)));
        for (std::size_t i = 0; i < k; ++i) {
            Eigen::Vector3d p;
            for (int d = 0; d < 3; ++d) p(d) = PCCD::uniform_real(engine, box.min()(d), box.max()(d));
            points.push_back(p);
        }
    }
    Scan_cloud c;
    const auto start = Clock::now();
    c.object = std::make_unique<PCCD::Point_cloud_object<>>(points, PCCD::Identity_point_map<Eigen::Vector3d>(), options);
    c.preprocessing_ms = ms_since(start);
    if (lean) c.lean = std::make_unique<PCCD::Euclidean_point_cloud_object<>>(points, options);
    c.raw = std::make_unique<PCCD::Point_cloud<>>(points);
    c.spacing = c.raw->mean_spacing();
    return c;
}

bool naive_point_test(const PCCD::Point_cloud<>& a, const PCCD::Rigid_transform_3<double>& pose_a,
                      const PCCD::Point_cloud<>& b, const PCCD::Rigid_transform_3<double>& pose_b, double radius)
{
    const PCCD::Rigid_transform_3<double> b_to_a = pose_a.inverse() * pose_b;
    Eigen::AlignedBox3d box_a = a.bbox();
    box_a.min().array() -= radius;
    box_a.max().array() += radius;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const Eigen::Vector3d q = b_to_a.transform_point(b.position(std::uint32_t(i)).template cast<double>());
        if (!box_a.contains(q)) continue;
        if (double(a.nearest(q).squared_distance) <= radius * radius) return true;
    }
    return false;
}

std::vector<Posed_truth> exact_truth(const Scan_model& model, std::size_t rotations, std::uint64_t seed)
{
    std::vector<Posed_truth> out;
    for (const auto& pose : generate_benchmark_poses({.rotations_per_distance = rotations, .seed = seed})) {
        const auto separation = PCCD::exact_separation(*model.exact, pose.pose_a, *model.exact, pose.pose_b);
        out.push_back({pose, separation, PCCD::classify_pose(separation, model.clean_r)});
    }
    return out;
}

std::vector<Posed_truth> reclassify(std::vector<Posed_truth> truth, double r)
{
    for (Posed_truth& t : truth) t.cls = PCCD::classify_pose(t.separation, r);
    return truth;
}

Scan_row evaluate_first_hits(const Scan_model& model, const Scan_condition& condition, const Scan_cloud& cloud,
                             const std::vector<Posed_truth>& truth, bool verbose,
                             PCCD::Intersection_options options)
{
    Scan_row row;
    row.model = model.name;
    row.condition = condition.name;
    row.points = cloud.object->size();
    const PCCD::Point_cloud_object<>& o = *cloud.object;
    double t_is = 0.0, t_rst = 0.0;
    std::size_t k = 0;
    for (const Posed_truth& t : truth) {
        options.seed = 1000 + k++;
        auto start = Clock::now();
        const auto is = PCCD::do_intersect(o, t.pose.pose_a, o, t.pose.pose_b, options);
        t_is += us_since(start);
        start = Clock::now();
        const auto rst = PCCD::do_intersect(o, t.pose.pose_a, o, t.pose.pose_b, options, PCCD::Randomized_sampling{});
        t_rst += us_since(start);
        const bool naive = naive_point_test(*cloud.raw, t.pose.pose_a, *cloud.raw, t.pose.pose_b, cloud.spacing);
        row.isearch.add(t.cls, is.intersects);
        row.rst.add(t.cls, rst.intersects);
        bool lean_answer = is.intersects;
        if (cloud.lean) {
            start = Clock::now();
            lean_answer = PCCD::do_intersect(*cloud.lean, t.pose.pose_a, *cloud.lean, t.pose.pose_b, options).intersects;
            row.lean_mean_us += us_since(start);
            row.lean.add(t.cls, lean_answer);
            row.lean_differs += lean_answer != is.intersects;
        }
        row.naive.add(t.cls, naive);
        if (verbose && t.cls != PCCD::Pose_class::grazing) {
            const bool truth_answer = t.cls == PCCD::Pose_class::intersecting;
            if (is.intersects != truth_answer || rst.intersects != truth_answer || naive != truth_answer ||
                lean_answer != truth_answer)
                std::printf("    %s / %s: d = %.2f rot %zu exact %+.3f r: isearch %d rst %d naive %d lean %d\n",
                            model.name.c_str(), condition.name.c_str(), t.pose.distance, t.pose.rotation_index,
                            t.separation.signed_measure() / model.clean_r, int(is.intersects), int(rst.intersects),
                            int(naive), int(lean_answer));
        }
    }
    row.isearch_mean_us = t_is / double(std::max<std::size_t>(1, truth.size()));
    row.rst_mean_us = t_rst / double(std::max<std::size_t>(1, truth.size()));
    row.lean_mean_us /= double(std::max<std::size_t>(1, truth.size()));
    return row;
}

void add_to(Scan_row& sum, const Scan_row& part)
{
    for (auto [s, p] : {std::pair{&sum.isearch, &part.isearch}, std::pair{&sum.rst, &part.rst},
                        std::pair{&sum.naive, &part.naive}, std::pair{&sum.lean, &part.lean}}) {
        s->intersecting += p->intersecting;
        s->separated += p->separated;
        s->grazing += p->grazing;
        s->false_negatives += p->false_negatives;
        s->false_positives += p->false_positives;
        s->grazing_reported += p->grazing_reported;
    }
    sum.points += part.points;
    sum.lean_differs += part.lean_differs;
}

std::pair<std::size_t, std::size_t> one_truth_violations(const Scan_cloud& cloud, const std::vector<Posed_truth>& truth)
{
    const PCCD::Point_cloud_object<>& o = *cloud.object;
    std::size_t found = 0, violations = 0;
    std::size_t k = 0;
    for (const Posed_truth& t : truth) {
        const PCCD::Intersection_options options{.seed = 1000 + k++};
        const auto all = PCCD::intersection_points(o, t.pose.pose_a, o, t.pose.pose_b, options);
        if (!all.points.empty()) {
            ++found;
            violations += !PCCD::do_intersect(o, t.pose.pose_a, o, t.pose.pose_b, options).intersects;
        }
        const auto all_rst = PCCD::intersection_points(o, t.pose.pose_a, o, t.pose.pose_b, options, PCCD::Randomized_sampling{});
        if (!all_rst.points.empty()) {
            ++found;
            violations +=
                !PCCD::do_intersect(o, t.pose.pose_a, o, t.pose.pose_b, options, PCCD::Randomized_sampling{}).intersects;
        }
    }
    return {found, violations};
}

int& failures()
{
    static int count = 0;
    return count;
}

void check(bool ok, const std::string& what)
{
    std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
    if (!ok) ++failures();
}

std::string percent(std::size_t k, std::size_t n)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%zu/%zu = %.2f %%", k, n, n ? 100.0 * double(k) / double(n) : 0.0);
    return buf;
}

void print_scan_table_header()
{
    std::printf("%-14s %-24s %7s | %-15s %-15s | %-15s %-15s | %-15s %-15s | %9s %9s\n", "model", "condition", "points",
                "isearch FN", "isearch FP", "rst FN", "rst FP", "naive FN", "naive FP", "is. us", "rst us");
}

void print_scan_row(const Scan_row& r)
{
    const auto cell = [](std::size_t k, std::size_t n) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%zu/%zu %.1f%%", k, n, n ? 100.0 * double(k) / double(n) : 0.0);
        return std::string(buf);
    };
    std::printf("%-14s %-24s %7zu | %-15s %-15s | %-15s %-15s | %-15s %-15s | %9.1f %9.1f\n", r.model.c_str(),
                r.condition.c_str(), r.points, cell(r.isearch.false_negatives, r.isearch.intersecting).c_str(),
                cell(r.isearch.false_positives, r.isearch.separated).c_str(),
                cell(r.rst.false_negatives, r.rst.intersecting).c_str(), cell(r.rst.false_positives, r.rst.separated).c_str(),
                cell(r.naive.false_negatives, r.naive.intersecting).c_str(),
                cell(r.naive.false_positives, r.naive.separated).c_str(), r.isearch_mean_us, r.rst_mean_us);
    const std::size_t poses = r.lean.intersecting + r.lean.separated + r.lean.grazing;
    if (poses > 0)
        std::printf("%-14s %-24s %7s | lean (Euclidean) FN %-15s FP %-15s | verdicts differing from the default %zu/%zu | %9.1f us\n",
                    "", "", "", cell(r.lean.false_negatives, r.lean.intersecting).c_str(),
                    cell(r.lean.false_positives, r.lean.separated).c_str(), r.lean_differs, poses, r.lean_mean_us);
}

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}

double mesh_distance(const Scan_model& model, const PCCD::Rigid_transform_3<double>& pose, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d local = pose.inverse().transform_point(x);
    return std::sqrt(model.exact->tree().squared_distance(PCCD::Exact_mesh::Point_3(local.x(), local.y(), local.z())));
}

Curve_figures evaluate_curves(const Scan_model& model, const Scan_cloud& cloud, const std::vector<Posed_truth>& truth,
                              std::size_t max_poses, PCCD::Intersection_options options)
{
    const double s = model.clean_spacing;
    std::vector<double> errors;
    std::size_t curve_samples = 0, covered = 0;
    Curve_figures f;
    for (std::size_t k = 0; k < truth.size() && f.poses < max_poses; ++k) {
        const Posed_truth& t = truth[(k * 7) % truth.size()];
        if (t.cls != PCCD::Pose_class::intersecting) continue;
        ++f.poses;
        const auto polylines = PCCD::exact_intersection_polylines(*model.exact, t.pose.pose_a, *model.exact, t.pose.pose_b);
        options.seed = k;
        const auto result = PCCD::intersection_points(*cloud.object, t.pose.pose_a, *cloud.object, t.pose.pose_b, options);
        f.points += result.points.size();
        for (const auto& p : result.points) {
            double best = std::numeric_limits<double>::infinity();
            for (const auto& line : polylines)
                for (std::size_t i = 0; i + 1 < line.size(); ++i)
                    best = std::min(best, point_segment_distance(p.position, line[i], line[i + 1]));
            errors.push_back(best / s);
            if (best > 3.0 * s && mesh_distance(model, t.pose.pose_a, p.position) <= model.clean_r &&
                mesh_distance(model, t.pose.pose_b, p.position) <= model.clean_r)
                ++f.near_contacts;
            else
                f.max_elsewhere = std::max(f.max_elsewhere, best / s);
        }
        for (const auto& line : polylines)
            for (std::size_t i = 0; i + 1 < line.size(); ++i) {
                const double length = (line[i + 1] - line[i]).norm();
                const std::size_t steps = std::max<std::size_t>(1, std::size_t(std::ceil(length / (0.5 * s))));
                for (std::size_t j = 0; j < steps; ++j) {
                    const Eigen::Vector3d c = line[i] + (double(j) / double(steps)) * (line[i + 1] - line[i]);
                    ++curve_samples;
                    for (const auto& p : result.points)
                        if ((p.position - c).norm() <= 3.0 * s) {
                            ++covered;
                            break;
                        }
                }
            }
    }
    if (!errors.empty()) {
        std::sort(errors.begin(), errors.end());
        f.median = sorted_quantile(errors, 50);
        f.p95 = sorted_quantile(errors, 95);
        f.max = errors.back();
    }
    f.coverage = curve_samples ? double(covered) / double(curve_samples) : 0.0;
    return f;
}

} // namespace PCCD::testing
