// The implicit surface of a point cloud (doc/manual/surface.md): build the preprocessed object in
// one call, then evaluate f(x) = n(x) . (x - a(x)) at cloud points and anywhere near the cloud; far
// away f is undefined.
#include <PCCD/Point_cloud_object.h>
#include <PCCD/testing/Torus_shape.h>

#include <iostream>
#include <optional>

using Object = PCCD::Point_cloud_object<>; // Eigen_kernel<double>, geodesic kernel by default
using Torus = PCCD::testing::Torus_shape;
using Vector = Eigen::Vector3d;

int main()
{
    // 20,000 noisy points on a torus (R = 1, r = 0.4), as the columns of a 3 x N matrix.
    const Torus torus(1.0, 0.4);
    PCCD::Random_engine engine(42);
    const Eigen::Matrix3Xd points = torus.sample(20000, engine, {.noise_sigma = 0.002}).points;

    // Graph, sampling radius, bandwidth, CPSP map and oriented normals: eta given, the rest default.
    const Object object(points, {.bandwidth = {.eta = 3.0}});
    std::cout << "r(P) = " << object.sampling_radius() << ", h = " << object.bandwidth()
              << ", support radius = " << object.weight().support_radius() << '\n';

    // At a cloud point (reads its CPSP list, no kd-tree query).
    std::cout << "f(p_123) = " << object.surface().evaluate_at(123).value << '\n';

    // Near the surface f approximates the signed distance (positive outside); far away it is undefined.
    for (const Vector& x : {Vector(1.41, 0, 0), Vector(1.39, 0, 0), Vector(0, 0, 0)}) {
        if (const std::optional<double> f = object.surface().value(x))
            std::cout << "f(" << x.transpose() << ") = " << *f << "  (exact " << torus.signed_distance(x) << ")\n";
        else
            std::cout << "f(" << x.transpose() << ") is undefined: no point within the kernel's support\n";
    }
    return 0;
}
