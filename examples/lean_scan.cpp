// A large scan as the lean object (doc/manual/surface.md "The lean object: the Euclidean kernel for
// large scans"): a scan of two parallel walls 1.6 apart (200,000 points) becomes a
// Euclidean_point_cloud_object -- a fifth of a Point_cloud_object's memory -- which is saved to a
// file and loaded back (the preprocessing is paid once; object_file_info tells which loader a file
// needs, without reading it); a small part, a ball of radius 0.5 (6,000
// points), stays a Point_cloud_object (the geodesic kernel, better on small and sharp parts). The
// queries take the two kinds together: the clearance of the ball moved towards one wall, printed
// beside the true one, 0.8 - 0.5 - |y|.
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/clearance.h>
#include <PCCD/Random.h>
#include <PCCD/object_file_info.h>
#include <PCCD/testing/Parallel_sheets_shape.h>
#include <PCCD/testing/Sphere_shape.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using Pose = PCCD::Rigid_transform_3<double>;

int main()
{
    PCCD::Random_engine engine(13);
    const PCCD::testing::Parallel_sheets_shape walls(Eigen::Vector3d(-2.0, 0.8, -1.0), Eigen::Vector3d(4.0, 0.0, 0.0),
                                                     Eigen::Vector3d(0.0, 0.0, 2.0), 1.6);
    const PCCD::testing::Sphere_shape ball(Eigen::Vector3d::Zero(), 0.5);

    // The scan: built once, saved, and loaded wherever it is needed again.
    const std::string file = (std::filesystem::temp_directory_path() / "pccd_lean_walls.pccdlean").string();
    {
        const PCCD::Euclidean_point_cloud_object<> built(walls.sample(200000, engine).points);
        std::printf("walls: %zu points, %.0f bytes per point, preprocessed in %.0f ms\n", built.size(),
                    double(built.memory_bytes()) / double(built.size()),
                    built.timings().kd_tree + built.timings().outliers + built.timings().sampling_radius +
                        built.timings().normals + built.timings().graph + built.timings().hierarchy);
        built.save(file);
    }
    // What the file holds, from its first bytes: which loader reads it, and how many points it has.
    const PCCD::Object_file_info info = PCCD::object_file_info(file);
    std::printf("%s: a %s object file of %llu points (format version %u)\n", file.c_str(), PCCD::to_string(info.kind),
                static_cast<unsigned long long>(info.points), unsigned(info.version));
    if (info.kind != PCCD::Object_file_kind::euclidean) return 1;
    const auto scan = PCCD::Euclidean_point_cloud_object<>::load(file);
    std::filesystem::remove(file);
    const PCCD::Point_cloud_object<> part(ball.sample(6000, engine).points);

    std::vector<Pose> poses;
    std::vector<double> truth;
    for (int k = 0; k <= 10; ++k) {
        const double y = 0.025 * k; // towards the wall y = 0.8
        poses.emplace_back(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, y, 0.0));
        truth.push_back(0.8 - 0.5 - y);
    }
    const PCCD::Clearance_profile p = PCCD::clearance(part, scan, poses, 0.11, {.max_distance = 0.5});
    std::printf("pose  true clearance  clearance  status\n");
    bool ok = true;
    for (std::size_t i = 0; i < p.samples.size(); ++i) {
        const PCCD::Clearance_sample& s = p.samples[i];
        std::printf("%4zu  %14.4f  %9.4f  %s\n", i, truth[i], s.clearance, PCCD::to_string(s.status));
        ok = ok && std::abs(s.clearance - truth[i]) < 0.01; // within a quarter of the walls' spacing
    }
    return ok ? 0 : 1;
}
