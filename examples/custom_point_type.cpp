// A user-defined point type from a laser scanner, read by PCCD through a Boost.PropertyMap-style
// point map: no copy into a PCCD type is needed before building the cloud.
#include <PCCD/Eigen_kernel.h>
#include <PCCD/Point_cloud.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

using Kernel = PCCD::Eigen_kernel<float>;
using Cloud = PCCD::Point_cloud<Kernel>;

// The user's own type: PCCD knows nothing about it.
struct Scan_point {
    float x, y, z;
    std::uint8_t intensity;
};

// A readable property map: `get(map, item)` returns a point PCCD can read (here an Eigen vector).
struct Scan_point_map {
    using key_type = Scan_point;
    using value_type = Eigen::Vector3f;
    using reference = Eigen::Vector3f;
    using category = boost::readable_property_map_tag;
    friend Eigen::Vector3f get(const Scan_point_map&, const Scan_point& p) { return {p.x, p.y, p.z}; }
};

int main()
{
    std::vector<Scan_point> scan;
    for (int i = 0; i < 50; ++i)
        for (int j = 0; j < 50; ++j)
            scan.push_back({0.02f * float(i), 0.02f * float(j), 0.0f, std::uint8_t((i * j) % 256)});

    const Cloud cloud(scan, Scan_point_map{});
    const auto near = cloud.k_nearest(Eigen::Vector3f(0.5f, 0.5f, 0.1f), 4);

    std::printf("%zu points, mean spacing %.4f\n", cloud.size(), cloud.mean_spacing());
    for (const auto& n : near)
        std::printf("neighbour %u (intensity %u) at distance %.4f\n", n.index, unsigned(scan[n.index].intensity),
                    std::sqrt(n.squared_distance));

    // A grid of cubic cells answers the radius queries whose ball meets few cells: the same points
    // as the kd-tree, by a few hash look-ups (faster in large clouds). Laid here on a copy, which
    // then gets a kd-tree of its own, so that both can be asked.
    const Cloud gridded = Cloud(cloud).with_cell_grid(0.1);
    const Eigen::Vector3f centre(0.5f, 0.5f, 0.0f);
    std::printf("%zu points within 0.05 from the grid, %zu from the tree\n", gridded.within_radius(centre, 0.05f).size(),
                cloud.within_radius(centre, 0.05f).size());
    return 0;
}
