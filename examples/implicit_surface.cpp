// The implicit surface of a point cloud: build the preprocessed object in one call, then evaluate
// f(x) = n(x) . (x - a(x)) at cloud points and anywhere near the cloud; far away f is undefined.
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Sampling/Torus_shape.h>

#include <iostream>
#include <vector>

using Object = PCCD::Point_cloud_object<>; // Eigen_kernel<double>, geodesic kernel by default

int main()
{
    // 20,000 noisy points on a torus (R = 1, r = 0.4).
    const PCCD::Torus_shape torus(1.0, 0.4);
    PCCD::Random_engine engine(42);
    const PCCD::Surface_sample sample = torus.sample(20000, engine, {.noise_sigma = 0.002});
    std::vector<Eigen::Vector3d> points;
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points.push_back(sample.points.col(i));

    // Graph, sampling radius, bandwidth, CPSP map and oriented normals, with the defaults.
    const Object object(points, PCCD::Identity_point_map<Eigen::Vector3d>(), {.bandwidth = {.eta = 3.0}});
    std::cout << "r(P) = " << object.sampling_radius() << ", h = " << object.bandwidth()
              << ", support radius = " << object.weight().support_radius() << '\n';

    // At a cloud point (reads its CPSP list, no kd-tree query).
    const PCCD::Surface_evaluation at_point = object.surface().evaluate_at(123);
    std::cout << "f(p_123) = " << at_point.value << '\n';

    // Near the surface: f approximates the signed distance (positive outside).
    for (const Eigen::Vector3d& x : {Eigen::Vector3d(1.41, 0, 0), Eigen::Vector3d(1.39, 0, 0), Eigen::Vector3d(0, 0, 0)}) {
        if (const std::optional<double> f = object.surface().value(x))
            std::cout << "f(" << x.transpose() << ") = " << *f << "  (exact " << torus.signed_distance(x) << ")\n";
        else
            std::cout << "f(" << x.transpose() << ") is undefined: no point within the kernel's support\n";
    }
    return 0;
}
