// Evaluations of the implicit surface f per second (doc/manual/surface.md), single-threaded:
// at cloud points (by index) and at arbitrary points, Euclidean vs geodesic kernel, and the CPSP
// lists against kd-tree radius queries for the *same* f.
//
// The same f: at a cloud point, the geodesic distance over a graph that joins every pair of points
// closer than the support radius R is the Euclidean distance (the direct edge is a shortest path),
// so the geodesic policy over that graph's CPSP map evaluates exactly the Euclidean f at cloud
// points, reading stored lists instead of querying the kd-tree. The benchmark checks the values
// agree (to float precision: the map stores float distances) and reports both rates.
//
// Usage: surface_benchmark [N = 100000] [evaluations = 200000] [repetitions = 5]
// Cloud: N points uniformly on the unit sphere with noise sigma = 0.1 mean spacing, seed 1;
// default Point_cloud_object options (r-SIG, eta = 3, theta_eps = 1e-2).
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity_graph/internal/graph_construction.h>
#include <PCCD/testing/Sphere_shape.h>

#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using PCCD::testing::Clock;
using PCCD::testing::seconds_since;

template <class Evaluate>
double median_rate(std::size_t count, int repetitions, const Evaluate& evaluate, double& checksum)
{
    std::vector<double> rates;
    for (int r = 0; r < repetitions; ++r) {
        double sum = 0.0;
        const auto start = Clock::now();
        for (std::size_t k = 0; k < count; ++k) sum += evaluate(k);
        rates.push_back(double(count) / seconds_since(start));
        checksum = sum;
    }
    return PCCD::testing::upper_median(std::move(rates));
}

// The value, or 0 where undefined (so that the loop cannot be optimized away).
double value_or_zero(const PCCD::Surface_evaluation& e) { return e.defined() ? e.value : 0.0; }

} // namespace

int main(int argc, char** argv)
{
    const std::size_t n = argc > 1 ? std::size_t(std::atoll(argv[1])) : 100000;
    const std::size_t evaluations = argc > 2 ? std::size_t(std::atoll(argv[2])) : 200000;
    const int repetitions = argc > 3 ? std::atoi(argv[3]) : 5;

    const PCCD::testing::Sphere_shape sphere(Eigen::Vector3d::Zero(), 1.0);
    PCCD::Random_engine engine(1);
    const double spacing = 0.5 * std::sqrt(sphere.area() / double(n));
    const auto sample = sphere.sample(n, engine, {.noise_sigma = 0.1 * spacing});
    std::vector<Eigen::Vector3d> points(n);
    for (std::size_t i = 0; i < n; ++i) points[i] = sample.points.col(Eigen::Index(i));

    auto start = Clock::now();
    const PCCD::Point_cloud_object<> object(points);
    const double build = seconds_since(start);
    const auto& t = object.timings();
    const double R = object.weight().support_radius();
    std::printf("N = %zu, r(P) = %.5f, h = %.5f, R = %.5f (%.2f mean spacings), CPSP entries per point %.1f\n", n,
                object.sampling_radius(), object.bandwidth(), R, R / object.cloud().mean_spacing(),
                double(object.cpsp().num_entries()) / double(n));
    std::printf("preprocessing %.0f ms: kd-tree %.0f, graph %.0f, r(P) %.0f, CPSP %.0f, normals %.0f\n", build * 1e3,
                t.kd_tree, t.graph, t.sampling_radius, t.cpsp, t.normals);

    // Query sets: cloud indices, and arbitrary points within 2 mean spacings of the surface.
    std::vector<std::uint32_t> indices(evaluations);
    std::vector<Eigen::Vector3d> arbitrary(evaluations);
    const double s = object.cloud().mean_spacing();
    for (std::size_t k = 0; k < evaluations; ++k) {
        indices[k] = std::uint32_t(PCCD::uniform_index(engine, n));
        const PCCD::testing::Surface_point p = sphere.random_point(engine);
        arbitrary[k] = p.position + PCCD::uniform_real(engine, -2 * s, 2 * s) * p.normal;
    }

    // The radius graph and its CPSP map: geodesic distance == Euclidean distance within R.
    start = Clock::now();
    const auto& tree = object.cloud().kd_tree();
    std::vector<std::uint64_t> rows(n + 1, 0);
    std::vector<std::uint32_t> targets;
    std::vector<PCCD::Proximity_edge> properties;
    std::vector<PCCD::Neighbor<double>> near;
    for (std::size_t i = 0; i < n; ++i) {
        tree.within_radius(object.cloud().position(std::uint32_t(i)), R * (1 + 1e-9), near);
        std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
        for (const auto& q : near)
            if (q.index != i) {
                targets.push_back(q.index);
                properties.push_back({float(std::sqrt(q.squared_distance)), false});
            }
        rows[i + 1] = targets.size();
    }
    const auto radius_graph = PCCD::internal::make_csr_graph(rows, targets, properties);
    const auto radius_map = std::make_shared<const PCCD::Close_pairs_shortest_paths>(
        radius_graph, get(&PCCD::Proximity_edge::length, radius_graph), object.sampling_radius(),
        PCCD::Cpsp_options{.support = R / object.sampling_radius() * (1 + 1e-6)});
    const PCCD::WLS_surface<PCCD::Geodesic_distance<>> euclidean_by_lists(
        PCCD::Geodesic_distance<>(object.cloud(), radius_map), object.weight(), object.normals());
    std::printf("radius graph + its CPSP map: %.0f ms, %.1f entries per point\n", seconds_since(start) * 1e3,
                double(radius_map->num_entries()) / double(n));
    double worst = 0.0;
    for (std::size_t k = 0; k < 2000; ++k) {
        const auto a = object.euclidean_surface().evaluate_at(indices[k]);
        const auto b = euclidean_by_lists.evaluate_at(indices[k]);
        if (a.defined() != b.defined()) worst = INFINITY;
        else if (a.defined()) worst = std::max(worst, std::abs(a.value - b.value) / s);
    }
    std::printf("same f check: max |f_kd-tree - f_lists| over 2000 cloud points = %.2e mean spacings\n", worst);

    double c = 0.0;
    const auto& geodesic = object.surface();
    const auto& euclidean = object.euclidean_surface();
    struct Row {
        const char* what;
        double rate;
    };
    std::vector<Row> rows_out{
        {"cloud points, geodesic kernel (CPSP lists, r-SIG)",
         median_rate(evaluations, repetitions, [&](std::size_t k) { return value_or_zero(geodesic.evaluate_at(indices[k])); }, c)},
        {"cloud points, Euclidean kernel (kd-tree radius query)",
         median_rate(evaluations, repetitions, [&](std::size_t k) { return value_or_zero(euclidean.evaluate_at(indices[k])); }, c)},
        {"cloud points, Euclidean kernel (CPSP lists of the radius graph)",
         median_rate(evaluations, repetitions,
                     [&](std::size_t k) { return value_or_zero(euclidean_by_lists.evaluate_at(indices[k])); }, c)},
        {"arbitrary points, geodesic kernel (1-NN query + CPSP list)",
         median_rate(evaluations, repetitions, [&](std::size_t k) { return value_or_zero(geodesic.evaluate(arbitrary[k])); }, c)},
        {"arbitrary points, Euclidean kernel (kd-tree radius query)",
         median_rate(evaluations, repetitions, [&](std::size_t k) { return value_or_zero(euclidean.evaluate(arbitrary[k])); }, c)},
    };
    std::printf("\n| evaluation | f / s (median of %d) |\n|---|---:|\n", repetitions);
    for (const Row& r : rows_out) std::printf("| %s | %.3g |\n", r.what, r.rate);
    std::printf("\nsame f, lists vs kd-tree at cloud points: %.2fx; geodesic (CPSP) vs Euclidean (kd-tree) at cloud "
                "points: %.2fx; at arbitrary points: %.2fx\n",
                rows_out[2].rate / rows_out[1].rate, rows_out[0].rate / rows_out[1].rate,
                rows_out[3].rate / rows_out[4].rate);
    std::printf("(checksum %g)\n", c);
    return 0;
}
