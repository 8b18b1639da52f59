// Accuracy on scans: false negatives and false positives of do_intersect() (both policies) and of
// the naive point test on clouds with noise, lower density and outliers, against CGAL's exact
// verdict; the curve distances of intersection_points(). The table of doc/benchmarks.md "Accuracy
// on scans" comes from
//   build/benchmark/scan_accuracy --rotations 50
// (test_scan_validation runs the same code with fewer poses and asserts the acceptance figures), and the
// table of "Missed contacts" (CAD and mechanical parts at four densities) from
//   build/benchmark/scan_accuracy --cad --rotations 50
// (test_cad_validation runs it with fewer poses and models).
#include <PCCD/testing/scan_validation.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    CLI::App app{"Accuracy of PCCD's first-hit and curve queries on scan-like clouds, beside the naive point test"};
    std::string data_dir = PCCD_DATA_DIR;
    std::vector<std::string> models{"bunny00.off", "elephant.off"};
    std::size_t rotations = 20, points = 30000, curve_poses = 20;
    std::vector<std::size_t> conditions;
    bool verbose = false;
    PCCD::Point_cloud_object_options object_options;
    PCCD::Intersection_options query_options;
    std::uint64_t pose_seed = 1;
    app.add_option("--data", data_dir, "folder of the meshes (libcgal-demo's data/meshes)");
    app.add_option("--models", models, "mesh files in that folder (closed meshes)");
    app.add_option("--rotations", rotations, "rotations per distance (13 distances, 0 to 3)");
    app.add_option("--points", points, "points of the clean cloud");
    app.add_option("--curve-poses", curve_poses, "intersecting poses for the curve figures (0: none)");
    app.add_option("--conditions", conditions, "indices of the conditions to run (default: all)");
    app.add_option("--pose-seed", pose_seed, "seed of the poses");
    app.add_flag("--verbose", verbose, "print every wrong non-grazing answer");
    app.add_option("--eta", object_options.bandwidth.eta, "kernel support in sampling radii");
    app.add_option("--noise-factor", object_options.bandwidth.noise_factor,
                   "support radius at least this many noise estimates (0: off)");
    std::string fit = "sphere";
    app.add_option("--fit", fit, "surface fit: sphere, plane or imls")->check(CLI::IsMember({"sphere", "plane", "imls"}));
    app.add_option("--theta-eps", object_options.bandwidth.theta_eps, "kernel weight threshold (default 1e-2)");
    app.add_option("--normal-bandwidth", object_options.normal_bandwidth,
                   "refit the oriented normals with this fraction of the kernel (default 1: no refit)");
    app.add_option("--normal-residual-scale", object_options.normal_residual_scale,
                   "refit the oriented normals robustly, residual scale in kernel bandwidths (default: no robust refit)");
    app.add_option("--domain-factor", object_options.domain.factor, "domain radius in k-th neighbour distances");
    app.add_option("--domain-neighbors", object_options.domain.neighbors, "k of the domain radius");
    double tolerance = 0.0;
    app.add_option("--contact-core", query_options.contact_core, "fraction of the domain a contact must lie within");
    app.add_option("--contact-tolerance", tolerance, "verification tolerance in sampling radii (default: automatic)");
    bool no_domain = false, no_verify = false, cad = false, no_certify = false;
    std::vector<std::size_t> densities = PCCD::testing::cad_densities();
    bool lean = false;
    app.add_flag("--lean", lean, "also the lean object (Euclidean kernel) of every cloud, its verdicts against the default's");
    app.add_flag("--cad", cad, "CAD and mechanical parts at four densities (clean, noise 0.3, 0.6, 1 % outliers)");
    app.add_option("--densities", densities, "with --cad: points per clean cloud");
    app.add_flag("--no-certify", no_certify, "answer separate without the certification pass");
    app.add_flag("--no-domain", no_domain, "surfaces without a domain");
    app.add_flag("--no-verify", no_verify, "unverified contacts (the published methods)");
    CLI11_PARSE(app, argc, argv);
    if (data_dir.empty()) {
        std::fprintf(stderr, "scan_accuracy: no mesh folder (install libcgal-demo or pass --data)\n");
        return 1;
    }
    object_options.domain.enabled = !no_domain;
    object_options.surface_fit = PCCD::surface_fit_from_string(fit).value(); // CLI11 checked the name
    query_options.verify_contacts = !no_verify;
    query_options.certify_separation = !no_certify;
    if (cad) {
        if (app.count("--models") == 0) models = PCCD::testing::cad_models();
        const auto cad_conditions = PCCD::testing::cad_conditions();
        std::map<std::string, PCCD::testing::Scan_row> totals;
        for (const std::string& file : models) {
            PCCD::testing::Scan_model model = PCCD::testing::load_scan_model(data_dir, file, densities.front(), 2026);
            const auto separations = PCCD::testing::exact_truth(model, rotations, pose_seed);
            for (std::size_t density : densities) {
                PCCD::testing::set_density(model, density, 2026);
                const auto truth = PCCD::testing::reclassify(separations, model.clean_r);
                for (std::size_t c = 0; c < cad_conditions.size(); ++c) {
                    if (!conditions.empty() && std::find(conditions.begin(), conditions.end(), c) == conditions.end())
                        continue;
                    const auto cloud = PCCD::testing::make_scan_cloud(model, cad_conditions[c], 2026 + c, object_options, lean);
                    auto row = PCCD::testing::evaluate_first_hits(model, cad_conditions[c], cloud, truth, verbose, query_options);
                    row.condition = std::to_string(density) + " " + cad_conditions[c].name;
                    PCCD::testing::print_scan_row(row);
                    PCCD::testing::add_to(totals[row.condition], row);
                    std::fflush(stdout);
                }
            }
        }
        std::printf("\nper density and condition, %zu models, %zu rotations x 13 distances each\n", models.size(), rotations);
        PCCD::testing::print_scan_table_header();
        for (std::size_t density : densities)
            for (std::size_t c = 0; c < cad_conditions.size(); ++c) {
                const std::string name = std::to_string(density) + " " + cad_conditions[c].name;
                if (!totals.count(name)) continue;
                auto& t = totals[name];
                t.model = "all";
                t.condition = name;
                PCCD::testing::print_scan_row(t);
            }
        return 0;
    }
    const auto all = PCCD::testing::scan_conditions();
    if (conditions.empty())
        for (std::size_t i = 0; i < all.size(); ++i) conditions.push_back(i);

    std::vector<PCCD::testing::Scan_row> rows;
    std::vector<std::string> curve_lines;
    for (const std::string& file : models) {
        const PCCD::testing::Scan_model model = PCCD::testing::load_scan_model(data_dir, file, points, 2026);
        const auto truth = PCCD::testing::exact_truth(model, rotations, pose_seed);
        if (tolerance > 0.0) query_options.contact_tolerance = tolerance * model.clean_r;
        std::printf("%s: clean spacing %.5f, r %.5f, %zu poses\n", file.c_str(), model.clean_spacing, model.clean_r,
                    truth.size());
        for (std::size_t c : conditions) {
            const PCCD::testing::Scan_condition& condition = all.at(c);
            const PCCD::testing::Scan_cloud cloud = PCCD::testing::make_scan_cloud(model, condition, 2026 + c, object_options, lean);
            rows.push_back(PCCD::testing::evaluate_first_hits(model, condition, cloud, truth, verbose, query_options));
            PCCD::testing::print_scan_table_header();
            PCCD::testing::print_scan_row(rows.back());
            if (curve_poses > 0) {
                const auto f = PCCD::testing::evaluate_curves(model, cloud, truth, curve_poses, query_options);
                char line[256];
                std::snprintf(line, sizeof line,
                              "%-14s %-24s curves: %zu poses, %zu points, distance median %.3f p95 %.3f max %.3f "
                              "spacings (%zu near-contact points, max elsewhere %.3f), coverage %.1f %%",
                              file.c_str(), condition.name.c_str(), f.poses, f.points, f.median, f.p95, f.max,
                              f.near_contacts, f.max_elsewhere, 100.0 * f.coverage);
                std::printf("%s\n", line);
                curve_lines.push_back(line);
            }
            std::fflush(stdout);
        }
    }
    std::printf("\nsummary (%zu rotations x 13 distances per model)\n", rotations);
    PCCD::testing::print_scan_table_header();
    for (const auto& r : rows) PCCD::testing::print_scan_row(r);
    for (const auto& l : curve_lines) std::printf("%s\n", l.c_str());
    return 0;
}
