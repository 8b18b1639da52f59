// Sharp edges and corners (doc/manual/surface.md, "Sharp features: the IMLS fit"): the default
// surface of a sampled cube lies inside its corners; the sharp-feature options (the IMLS fit, a
// narrower Gaussian within the same support, normals refitted robustly) keep them. Also
// refit_normals() on its own, on normals from estimate_normals(): with a narrower kernel, and robust.
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Surface/Euclidean_distance.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/sample_triangle_mesh.h>
#include <PCCD/sharp_feature_options.h>

#include <array>
#include <iostream>
#include <vector>

int main()
{
    // The cube [-1, 1]^3 as 12 triangles, sampled by area with 6,000 points.
    std::vector<Eigen::Vector3d> corners;
    for (int k = 0; k < 8; ++k) corners.emplace_back(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
    const std::vector<std::array<int, 3>> triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                                       {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    PCCD::Random_engine engine(7);
    const Eigen::Matrix3Xd points = PCCD::sample_triangle_mesh(corners, triangles, 6000, engine).points;

    // The sharp-feature options in one call: the IMLS fit, theta_eps 3e-5 and the robust normal refit
    // (normal_residual_scale 0.25: neighbours off a point's face lose their weight).
    const PCCD::Point_cloud_object_options sharp = PCCD::sharp_feature_options();
    const PCCD::Point_cloud_object<> by_default(points);
    const PCCD::Point_cloud_object<> with_edges(points, sharp);

    // f at a corner of the cube (exact signed distance 0): how far inside each surface puts it.
    const Eigen::Vector3d corner(1, 1, 1);
    std::cout << "mean spacing " << by_default.cloud().mean_spacing() << "; f at the corner (1, 1, 1): "
              << "default " << by_default.surface().evaluate(corner).value << ", sharp-feature "
              << with_edges.surface().evaluate(corner).value << '\n';

    // refit_normals() by hand: normals estimated with a wide kernel, refitted with half of it.
    const PCCD::Point_cloud<> cloud(points);
    const PCCD::Euclidean_distance<> distance(cloud);
    Eigen::Matrix3Xd normals = PCCD::estimate_normals(distance, PCCD::Gaussian_weight(0.1, 0.01)).normals;
    const std::size_t refitted = PCCD::refit_normals(distance, PCCD::Gaussian_weight(0.05, 0.01), normals);
    // The same kernel made robust: residual scale 0.025 (a quarter of the bandwidth).
    const std::size_t robust = PCCD::refit_normals(distance, PCCD::Gaussian_weight(0.1, 0.01), normals, std::nullopt, 0.025);
    std::cout << "refitted " << refitted << " of " << normals.cols() << " normals, then " << robust << " robustly\n";
    return 0;
}
