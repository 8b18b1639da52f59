// How far the implicit surface lies from its samples (doc/manual/continuous.md, "What is
// guaranteed"): on area-sampled clouds of scanned models and CAD parts of libcgal-demo (8,000
// points, normalized into [-1, 1]^3, clean and with noise of 0.3 mean spacings), for the default
// fit and the sharp-feature options (IMLS), points of the zero set are found by projecting 40,000
// points (a cloud point pushed off by up to twice the surface radius in a random direction, then
// Newton steps x -= f(x) n(x) until |f| < 1e-7) and their distance to the nearest sample is
// compared with two radii: the surface radius r(P) + 2 sigma that the proximity queries' lower
// bound assumes, and the nearest sample's domain radius D_p, which time_of_contact's bound uses
// (by construction of the domain every zero lies within it: the column "> D" must read 0).
//
// Usage: surface_reach [--csv F]     (about 10 s)
#include <PCCD/Random.h>
#include <PCCD/testing/scan_validation.h>
#include <PCCD/sharp_feature_options.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char** argv)
try {
    std::string csv;
    for (int i = 1; i < argc; i += 2) {
        const std::string key = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument("option " + key + " needs a value");
        if (key == "--csv") csv = argv[i + 1];
        else throw std::invalid_argument("unknown option " + key + " (usage: surface_reach [--csv F])");
    }
    const std::string dir = PCCD_DATA_DIR;
    if (dir.empty() || !std::filesystem::exists(std::filesystem::path(dir) / "bunny00.off"))
        throw std::runtime_error("the meshes of libcgal-demo are not in PCCD_DATA_DIR (\"" + dir + "\")");
    std::ofstream out;
    if (!csv.empty()) {
        out.open(csv);
        out << "model,fit,noise,projected,unconverged,median_rho,p99_rho,p999_rho,max_rho,beyond_rho,max_domain,beyond_domain\n";
    }
    std::printf("%-14s %-7s %5s %9s %7s %7s %7s %7s %9s %8s %6s\n", "model", "fit", "noise", "zeros", "median", "p99", "p99.9",
                "max", "> r+2s", "max/D", "> D");
    for (const char* file : {"bunny00.off", "elephant.off", "armadillo.off", "anchor.off", "joint.off", "handle.off", "fandisk.off"}) {
        const PCCD::testing::Scan_model model = PCCD::testing::load_scan_model(dir, file, 8000, 2026);
        for (const bool sharp : {false, true}) {
            for (const double noise : {0.0, 0.3}) {
                const auto cloud = PCCD::testing::make_scan_cloud(model, {"c", 1.0, noise, 0.0}, noise > 0.0 ? 2027 : 2026,
                                                                  sharp ? PCCD::sharp_feature_options()
                                                                        : PCCD::Point_cloud_object_options{});
                const PCCD::Point_cloud_object<>& o = *cloud.object;
                const double rho = o.sampling_radius() + 2.0 * o.noise_estimate();
                PCCD::Random_engine engine(5);
                std::vector<double> in_rho;
                double max_domain = 0.0;
                std::size_t unconverged = 0, beyond_domain = 0;
                std::vector<PCCD::Point_cloud<>::Neighbor> nn;
                for (int k = 0; k < 40000; ++k) {
                    const std::size_t i = std::size_t(PCCD::uniform_real(engine, 0.0, double(o.size()))) % o.size();
                    Eigen::Vector3d d(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
                    Eigen::Vector3d x = Eigen::Vector3d(o.cloud().position(i)) + PCCD::uniform_real(engine, 0.0, 2.0 * rho) * d.normalized();
                    bool zero = false;
                    for (int step = 0; step < 30 && !zero; ++step) {
                        const PCCD::Surface_evaluation e = o.surface().evaluate(x);
                        if (!e.defined()) break;
                        if (std::abs(e.value) < 1e-7) zero = true;
                        else x -= e.value * e.normal;
                    }
                    if (!zero) {
                        ++unconverged;
                        continue;
                    }
                    o.cloud().k_nearest(x, 1, nn);
                    const double gap = std::sqrt(double(nn[0].squared_distance));
                    in_rho.push_back(gap / rho);
                    const double in_domain = gap / o.domain_radii()(Eigen::Index(nn[0].index));
                    max_domain = std::max(max_domain, in_domain);
                    beyond_domain += in_domain > 1.0;
                }
                if (in_rho.empty()) throw std::runtime_error(std::string(file) + ": no projection reached the surface");
                std::sort(in_rho.begin(), in_rho.end());
                const auto q = [&](double percent) { // the sample quantile, nearest rank
                    const std::size_t n = in_rho.size();
                    return in_rho[std::min(n - 1, std::size_t(percent / 100.0 * double(n)))];
                };
                const std::size_t beyond = std::size_t(in_rho.end() - std::upper_bound(in_rho.begin(), in_rho.end(), 1.0));
                std::printf("%-14s %-7s %5.1f %9zu %7.3f %7.3f %7.3f %7.3f %9zu %8.3f %6zu\n", file, sharp ? "imls" : "default",
                            noise, in_rho.size(), q(50), q(99), q(99.9), in_rho.back(), beyond, max_domain, beyond_domain);
                std::fflush(stdout);
                if (out)
                    out << file << ',' << (sharp ? "imls" : "default") << ',' << noise << ',' << in_rho.size() << ',' << unconverged
                        << ',' << q(50) << ',' << q(99) << ',' << q(99.9) << ',' << in_rho.back() << ',' << beyond << ','
                        << max_domain << ',' << beyond_domain << '\n';
            }
        }
    }
    std::printf("\ncolumns: zeros = projected points that reached |f| < 1e-7 (of 40,000); median ... max = their distance to\n"
                "the nearest sample in units of r(P) + 2 sigma; > r+2s = how many lie farther; max/D = the largest distance in\n"
                "units of the nearest sample's domain radius; > D = how many lie beyond it (0 by construction)\n");
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "surface_reach: %s\n", e.what());
    return 1;
}
