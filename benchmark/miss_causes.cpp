// Why a first-hit query misses a contact: for every non-grazing intersecting pose that do_intersect
// (default options) answers "separate", the same pose is asked again with one part of the pipeline
// changed at a time, and the point-level evidence is counted. Prints one line per missed pose and a
// tally of causes (doc/benchmarks.md "Missed contacts: causes").
//   build/benchmark/miss_causes --models anchor.off part.off --points 500 --rotations 20
#include <PCCD/testing/scan_validation.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

struct Point_evidence {
    std::size_t inside = 0;    // points of one cloud with the other's f defined and < -band
    std::size_t undefined = 0; // points within one spacing of the other cloud where its f is undefined
    double min_distance = 1e300;
};

Point_evidence point_evidence(const PCCD::Point_cloud_object<>& s, const PCCD::Rigid_transform_3<double>& pose_s,
                              const PCCD::Point_cloud_object<>& t, const PCCD::Rigid_transform_3<double>& pose_t,
                              double spacing, double band)
{
    Point_evidence e;
    const auto s_to_t = pose_t.inverse() * pose_s;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const Eigen::Vector3d q = s_to_t.transform_point(s.cloud().position(std::uint32_t(i)).cast<double>());
        const double d = std::sqrt(double(t.cloud().nearest(q).squared_distance));
        e.min_distance = std::min(e.min_distance, d);
        const auto ev = t.surface().evaluate(q);
        if (ev.defined() && ev.value < -band) ++e.inside;
        if (!ev.defined() && d <= spacing) ++e.undefined;
    }
    return e;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"Causes of missed contacts of do_intersect"};
    std::string data_dir = PCCD_DATA_DIR;
    std::vector<std::string> models{"anchor.off"};
    std::size_t rotations = 20, points = 500;
    std::vector<std::size_t> conditions;
    app.add_option("--data", data_dir, "folder of the meshes");
    app.add_option("--models", models, "mesh files");
    app.add_option("--rotations", rotations, "rotations per distance");
    app.add_option("--points", points, "points of the clean cloud");
    app.add_option("--conditions", conditions, "indices of the conditions (default: all)");
    bool rst = false, cad = false;
    app.add_flag("--cad", cad, "the conditions of the CAD validation (clean, noise 0.3, 0.6, 1 % outliers)");
    app.add_flag("--rst", rst, "analyse the misses of RST instead of the interpolation search");
    CLI11_PARSE(app, argc, argv);
    const auto all = cad ? PCCD::testing::cad_conditions() : PCCD::testing::scan_conditions();
    if (conditions.empty())
        for (std::size_t i = 0; i < all.size(); ++i) conditions.push_back(i);
    std::map<std::string, std::size_t> tally;
    std::size_t misses = 0;
    for (const std::string& file : models) {
        const PCCD::testing::Scan_model model = PCCD::testing::load_scan_model(data_dir, file, points, 2026);
        const auto truth = PCCD::testing::exact_truth(model, rotations, 1);
        for (std::size_t c : conditions) {
            const auto& condition = all.at(c);
            const PCCD::testing::Scan_cloud cloud = PCCD::testing::make_scan_cloud(model, condition, 2026 + c);
            const auto& o = *cloud.object;
            std::size_t k = 0;
            for (const auto& t : truth) {
                PCCD::Intersection_options options;
                options.seed = 1000 + k++;
                if (t.cls == PCCD::Pose_class::grazing) continue;
                const auto ask = [&](PCCD::Intersection_options opt, bool all_points = false) {
                    if (rst)
                        return all_points ? PCCD::intersection_points(o, t.pose.pose_a, o, t.pose.pose_b, opt, PCCD::Randomized_sampling{})
                                          : PCCD::do_intersect(o, t.pose.pose_a, o, t.pose.pose_b, opt, PCCD::Randomized_sampling{});
                    return all_points ? PCCD::intersection_points(o, t.pose.pose_a, o, t.pose.pose_b, opt)
                                      : PCCD::do_intersect(o, t.pose.pose_a, o, t.pose.pose_b, opt);
                };
                const auto base = ask(options);
                if (t.cls == PCCD::Pose_class::separated) {
                    auto o_tol = options;
                    o_tol.contact_tolerance = 0.25 * model.clean_r;
                    ++tally["separated poses"];
                    tally["separated: rejected candidates"] += base.counters.candidates_rejected > 0;
                    tally["separated: brackets"] += base.counters.brackets_found > 0;
                    tally["separated: FP"] += base.intersects;
                    if (base.intersects) {
                        const auto& x = base.points.front().position;
                        const auto near_a = o.cloud().nearest(t.pose.pose_a.inverse().transform_point(x));
                        const auto near_b = o.cloud().nearest(t.pose.pose_b.inverse().transform_point(x));
                        std::printf("FP %s / %s d %.2f rot %zu gap %.2f r: unverified %zu, f_a %.3f f_b %.3f r, nearest "
                                    "points %.2f %.2f sp (input %u %u of %zu given)\n",
                                    file.c_str(), condition.name.c_str(), t.pose.distance, t.pose.rotation_index,
                                    t.separation.signed_measure() / model.clean_r,
                                    std::size_t(base.counters.unverified_crossings), base.points.front().f_a / model.clean_r,
                                    base.points.front().f_b / model.clean_r,
                                    std::sqrt(double(near_a.squared_distance)) / cloud.spacing,
                                    std::sqrt(double(near_b.squared_distance)) / cloud.spacing,
                                    o.input_index(near_a.index), o.input_index(near_b.index), cloud.raw->size());
                    }
                    tally["separated: tolerance 0.25 r FP"] += ask(o_tol).intersects;
                    auto o_nv = options;
                    o_nv.verify_contacts = false;
                    tally["separated: unverified FP"] += ask(o_nv).intersects;
                    continue;
                }
                ++tally["intersecting poses"];
                tally["intersecting: rejected candidates"] += base.counters.candidates_rejected > 0;
                if (base.intersects) continue;
                ++misses;
                auto o_flat = options;
                o_flat.traversal = PCCD::Traversal::flat;
                auto o_core = options;
                o_core.contact_core = 1.0;
                auto o_noverify = options;
                o_noverify.verify_contacts = false;
                auto o_tol = options;
                o_tol.contact_tolerance = 0.25 * model.clean_r;
                const bool flat = ask(o_flat).intersects;
                const bool all_pts = ask(options, true).intersects;
                const bool core = ask(o_core).intersects;
                const bool noverify = ask(o_noverify).intersects;
                const bool tol = ask(o_tol).intersects;
                const double band = 2.0 * double(o.noise_estimate());
                const auto ea = point_evidence(o, t.pose.pose_b, o, t.pose.pose_a, cloud.spacing, band);
                const auto eb = point_evidence(o, t.pose.pose_a, o, t.pose.pose_b, cloud.spacing, band);
                std::printf("%s / %s d %.2f rot %zu depth %.2f r (%.2f sp): flat %d all %d core1 %d noverify %d tol %d | "
                            "B in A %zu, A in B %zu (band %.3f sp), undefined-near %zu %zu, min dist %.2f sp | "
                            "rejected %zu brackets %zu samples %zu f %zu\n",
                            file.c_str(), condition.name.c_str(), t.pose.distance, t.pose.rotation_index,
                            -t.separation.signed_measure() / model.clean_r,
                            -t.separation.signed_measure() / cloud.spacing, flat, all_pts, core, noverify, tol,
                            ea.inside, eb.inside, band / cloud.spacing, ea.undefined, eb.undefined,
                            std::min(ea.min_distance, eb.min_distance) / cloud.spacing,
                            std::size_t(base.counters.candidates_rejected), std::size_t(base.counters.brackets_found),
                            std::size_t(base.counters.samples), std::size_t(base.counters.f_evaluations));
                tally["flat finds"] += flat;
                tally["intersection_points finds"] += all_pts;
                tally["core 1 finds"] += core;
                tally["unverified finds"] += noverify;
                tally["tolerance 0.25 r finds"] += tol;
                tally["points inside the other"] += (ea.inside + eb.inside) > 0;
                tally["rejected candidates"] += base.counters.candidates_rejected > 0;
                tally["brackets found"] += base.counters.brackets_found > 0;
                std::fflush(stdout);
            }
        }
    }
    std::printf("\n%zu missed poses\n", misses);
    for (const auto& [what, n] : tally) std::printf("  %-28s %zu\n", what.c_str(), n);
    return 0;
}
