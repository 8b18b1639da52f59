// Accuracy of the implicit surface against the exact signed distance as a function of the kernel
// parameters eta and theta_eps (doc/manual/surface.md), the measurement behind the defaults in
// PCCD/Surface/bandwidth.h (table in doc/manual/surface.md, "Choosing eta and theta_eps").
//
// Usage: surface_parameters [eta theta_eps]  (default: the grid eta 1.5..3 x theta_eps 1e-2..1e-4)
// For sphere (radius 1), torus (1, 0.4) and plane patch (2 x 2), N = 4000 and 16000, noise 0 and 0.2
// spacing: 4000 queries within 2 mean spacings s of the surface; prints, per kernel, the max, 99th
// percentile and median of |f - d| / s, the number of undefined (outside_support) and degenerate
// evaluations and the mean neighbour count; per cloud r(P) / s, R / s, CPSP entries per point and
// the number of stored normals facing inward ("badorient"; for the open plane any global sign is
// right).
#include <PCCD/Point_cloud.h>
#include <PCCD/sampling_radius.h>
#include <PCCD/testing/Sphere_shape.h>
#include <PCCD/testing/Torus_shape.h>
#include <PCCD/testing/Plane_patch_shape.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Surface/Euclidean_distance.h>
#include <PCCD/Surface/Geodesic_distance.h>
#include <PCCD/Surface/WLS_surface.h>
#include <PCCD/Surface/bandwidth.h>
#include <PCCD/Surface/estimate_normals.h>
#include <PCCD/Surface/orient_normals.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
using namespace PCCD;
using PCCD::testing::Plane_patch_shape;
using PCCD::testing::Sphere_shape;
using PCCD::testing::Surface_point;
using PCCD::testing::Torus_shape;
template <class Surface, class Shape>
void measure(const char* label, const Surface& surf, const Shape& shape, double s)
{
    std::vector<double> err; std::size_t undef = 0, degen = 0; double nb = 0;
    Random_engine qe(99);
    for (int k = 0; k < 4000; ++k) {
        Surface_point p = shape.random_point(qe);
        const double t = uniform_real(qe, -2 * s, 2 * s);
        Eigen::Vector3d x = p.position + t * p.normal;
        auto ev = surf.evaluate(x);
        if (ev.status == Surface_status::outside_support) { ++undef; continue; }
        if (ev.status == Surface_status::degenerate) { ++degen; continue; }
        nb += ev.neighbor_count;
        err.push_back(std::abs(ev.value - shape.signed_distance(x)) / s);
    }
    std::sort(err.begin(), err.end());
    std::printf("  %s max=%.3f p99=%.3f p50=%.3f undef=%zu degen=%zu nb=%.1f\n", label, err.back(), err[err.size() * 99 / 100], err[err.size() / 2], undef, degen, nb / err.size());
}
template <class Shape>
void run(const char* name, const Shape& shape, std::size_t n, double noise_rel, double eta, double theta)
{
    Random_engine engine(7);
    const double s0 = 0.5 * std::sqrt(shape.area() / double(n));
    auto sample = shape.sample(n, engine, {.noise_sigma = noise_rel * s0});
    Point_cloud<> cloud(sample.points);
    const double s = cloud.mean_spacing();
    const double r = sampling_radius(cloud);
    auto w = gaussian_weight(r, {.eta = eta, .theta_eps = theta});
    auto graph = sphere_of_influence_graph(cloud);
    auto map = std::make_shared<const Close_pairs_shortest_paths>(graph, r, Cpsp_options{.support = eta});
    Euclidean_distance<> euc(cloud);
    Geodesic_distance<> geo(cloud, map);
    auto est = estimate_normals(geo, w);
    auto rep = orient_normals(graph, cloud.coordinates(), est.normals);
    std::size_t bad = 0;
    for (Eigen::Index i = 0; i < est.normals.cols(); ++i) if (est.normals.col(i).dot(sample.normals.col(i)) < 0) ++bad;
    std::printf("%-7s N=%6zu noise=%.2f eta=%.1f theta=%g s=%.4f r/s=%.2f R/s=%.2f cpsp/pt=%.1f comps=%zu badorient=%zu undetermined=%zu\n", name, n, noise_rel, eta, theta, s, r / s, w.support_radius() / s,
                double(map->num_entries()) / n, rep.components, bad, est.undetermined);
    measure("euc", WLS_surface<Euclidean_distance<>>(euc, w, est.normals), shape, s);
    measure("geo", WLS_surface<Geodesic_distance<>>(geo, w, est.normals), shape, s);
}
int main(int argc, char** argv)
{
    Sphere_shape sphere(Eigen::Vector3d::Zero(), 1.0);
    Torus_shape torus(1.0, 0.4);
    Plane_patch_shape plane(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0));
    std::vector<double> etas = {1.5, 2.0, 2.5, 3.0};
    std::vector<double> thetas = {1e-2, 1e-3, 1e-4};
    if (argc > 1) etas = {std::atof(argv[1])};
    if (argc > 2) thetas = {std::atof(argv[2])};
    for (std::size_t n : {4000, 16000})
        for (double noise : {0.0, 0.2})
            for (double eta : etas)
                for (double th : thetas) {
                    run("sphere", sphere, n, noise, eta, th);
                    run("torus", torus, n, noise, eta, th);
                    run("plane", plane, n, noise, eta, th);
                }
}
