// Builds against an installed PCCD and checks a k-NN query against brute force.
#include <PCCD/Point_cloud.h>
#include <PCCD/version.h>

#include <array>
#include <cstdio>
#include <vector>

int main()
{
    std::vector<std::array<double, 3>> points;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) points.push_back({double(i), double(j), 0.5 * i * j});
    const PCCD::Point_cloud<> cloud(points);
    const auto nearest = cloud.nearest({3.1, 4.2, 6.0});
    std::printf("PCCD %s: %zu points, nearest index %u\n", PCCD_VERSION_STRING, cloud.size(), nearest.index);
    return (cloud.size() == 100 && nearest.index == 34) ? 0 : 1;
}
