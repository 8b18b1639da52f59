// clearance() along a path (doc/manual/proximity.md "Clearance along a path"): the wall time of
// the whole path for 1 and 2 threads, without a cap and with one, and whether the samples are bit
// for bit the same for both thread counts. The object and the scene are the vertices of libcgal-demo's
// bunny00.off (37,706 points, in [-0.5, 0.5]^3); the object passes over the scene along x while it
// sinks from a gap of about 0.17 to 0.05 and turns about y (400 poses). Prints one CSV row per
// configuration: threads,cap,median_ms,min_ms,beyond_cap,first_below_margin,minimum_clearance.
// Usage: clearance_benchmark [--repeats N] (default 7).
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/clearance.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

bool same(const PCCD::Clearance_profile& a, const PCCD::Clearance_profile& b)
{
    if (a.samples.size() != b.samples.size()) return false;
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
        const PCCD::Clearance_sample& x = a.samples[i];
        const PCCD::Clearance_sample& y = b.samples[i];
        if (x.status != y.status || !same_bits(x.clearance, y.clearance) || !same_bits(x.lower_bound, y.lower_bound) ||
            !same_bits(x.upper_bound, y.upper_bound) || !(x.counters == y.counters))
            return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    int repeats = 7;
    for (int i = 1; i + 1 < argc; i += 2)
        if (std::string(argv[i]) == "--repeats") repeats = std::max(1, std::atoi(argv[i + 1]));
    const auto path = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    if (!std::filesystem::exists(path)) {
        std::fprintf(stderr, "clearance_benchmark: %s is missing (libcgal-demo's meshes)\n", path.c_str());
        return 1;
    }
    const PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Point_cloud_object<> bunny(mesh.vertices);

    std::vector<PCCD::Rigid_transform_3<double>> poses;
    const int n = 400;
    for (int k = 0; k < n; ++k) {
        const double t = double(k) / double(n - 1), a = 0.3 * t;
        Eigen::Matrix3d r;
        r << std::cos(a), 0.0, std::sin(a), 0.0, 1.0, 0.0, -std::sin(a), 0.0, std::cos(a);
        poses.emplace_back(r, Eigen::Vector3d(-0.6 + 1.2 * t, 1.15 - 0.17 * t, 0.0));
    }
    const double margin = 0.06;
    std::printf("# %zu points, %d poses, margin %g, %d repeats\n", bunny.size(), n, margin, repeats);
    std::printf("threads,cap,median_ms,min_ms,beyond_cap,first_below_margin,minimum_clearance\n");
    bool identical = true;
    for (const std::optional<double> cap : {std::optional<double>(), std::optional<double>(0.12)}) {
        std::optional<PCCD::Clearance_profile> reference;
        for (const unsigned threads : {1u, 2u}) {
            std::vector<double> ms;
            PCCD::Clearance_profile p;
            for (int r = 0; r < repeats; ++r) {
                const auto start = PCCD::testing::Clock::now();
                p = PCCD::clearance(bunny, bunny, poses, margin, {.max_distance = cap, .batch = {.threads = threads}});
                ms.push_back(PCCD::testing::ms_since(start));
            }
            if (reference)
                identical = identical && same(*reference, p);
            else
                reference = p;
            std::printf("%u,%s,%.2f,%.2f,%zu,%ld,%.6f\n", threads, cap ? std::to_string(*cap).c_str() : "none",
                        PCCD::testing::median(ms), *std::min_element(ms.begin(), ms.end()), p.counters.beyond_cap,
                        p.first_below_margin ? long(*p.first_below_margin) : -1L, p.minimum_clearance);
        }
    }
    std::printf("# samples bit for bit the same for 1 and 2 threads: %s\n", identical ? "yes" : "NO");
    return identical ? 0 : 1;
}
