// graph_benchmark: build times and sizes of PCCD's proximity graphs and CPSP map on area-uniform
// samples of the Stanford bunny (libcgal-demo; PCCD's torus when absent), normalized into [-1, 1]^3.
// Figures in doc/benchmarks.md, section "Proximity graphs and CPSP map". CSV on stdout.
//
//   graph_benchmark timing [--sizes 10000,100000,1000000] [--repeats 3] [--threads 1,2] [--r 3]
//                          [--support 3] [--dijkstra hand,boost] [--factor 4] [--seed 1]
//       one row per (size, repeat, threads, dijkstra): kd-tree, r(P), r-SIG and CPSP times (ms),
//       edges and CPSP entries per point, bytes per point.
//   graph_benchmark components [--sizes 100000] [--noise 0.3] [--factor 4] [--seed 1]
//       component counts of k-NN, SIG and r-SIG (r = 2..4) on a sample with Gaussian noise of
//       sigma = noise x (mean spacing of the clean sample), and the number of connected pieces of
//       the mesh itself.
//   graph_benchmark long_edges [--sizes 100000] [--r 3]
//       distribution of edge length / local scale (the long-edge test's statistic) on a clean and a
//       noisy sample: how many edges each factor would mark virtual.
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud.h>
#include <PCCD/Proximity_graph/graph_components.h>
#include <PCCD/Proximity_graph/knn_graph.h>
#include <PCCD/Proximity_graph/sphere_of_influence_graph.h>
#include <PCCD/Random.h>
#include <PCCD/testing/Torus_shape.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>
#include <PCCD/sampling_radius.h>

#include <PCCD/testing/timing.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace {

using PCCD::testing::Clock;
using PCCD::testing::ms_since;

/// CPU time of the whole process (all threads), in ms: on a shared machine it is the figure that
/// other processes' load does not inflate.
double cpu_ms()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

/// Wall and CPU time of one stage.
struct Stopwatch {
    Clock::time_point wall = Clock::now();
    double cpu = cpu_ms();
    std::pair<double, double> stop() const { return {ms_since(wall), cpu_ms() - cpu}; }
};

struct Arguments {
    std::string mode = "timing";
    std::vector<std::size_t> sizes;
    std::size_t repeats = 3;
    std::vector<unsigned> threads = {1, 2};
    unsigned r = 3;
    double support = 3.0;
    std::vector<std::string> dijkstra = {"hand", "boost"};
    double noise = 0.3;
    double factor = 4.0; // long-edge factor (the library default)
    std::uint64_t seed = 1;
};

template <class T>
std::vector<T> parse_list(const std::string& text)
{
    std::vector<T> values;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        std::stringstream one(item);
        T value;
        one >> value;
        values.push_back(value);
    }
    return values;
}

Arguments parse(int argc, char** argv)
{
    Arguments a;
    int i = 1;
    if (argc > 1 && argv[1][0] != '-') a.mode = argv[i++];
    for (; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--sizes") a.sizes = parse_list<std::size_t>(value);
        else if (key == "--repeats") a.repeats = std::stoul(value);
        else if (key == "--threads") a.threads = parse_list<unsigned>(value);
        else if (key == "--r") a.r = unsigned(std::stoul(value));
        else if (key == "--support") a.support = std::stod(value);
        else if (key == "--dijkstra") a.dijkstra = parse_list<std::string>(value);
        else if (key == "--noise") a.noise = std::stod(value);
        else if (key == "--factor") a.factor = std::stod(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.sizes.empty()) a.sizes = a.mode == "timing" ? std::vector<std::size_t>{10000, 100000, 1000000}
                                                      : std::vector<std::size_t>{100000};
    return a;
}

struct Model {
    std::string name;
    PCCD::Triangle_mesh_data mesh; // empty for the torus
};

Model load_model()
{
    const std::filesystem::path bunny = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    if (std::string(PCCD_DATA_DIR).empty() || !std::filesystem::exists(bunny)) {
        std::cerr << "# bunny00.off not found (libcgal-demo); using PCCD's torus\n";
        return {"torus", {}};
    }
    Model model{"bunny", PCCD::IO::read_triangle_mesh(bunny.string())};
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(model.mesh.vertices);
    for (auto& v : model.mesh.vertices) v = normalization.transform_point(v);
    return model;
}

Eigen::Matrix3Xd sample(const Model& model, std::size_t n, std::uint64_t seed, double noise_sigma)
{
    PCCD::Random_engine engine(seed);
    if (model.mesh.triangles.empty())
        return PCCD::testing::Torus_shape(0.7, 0.3).sample(n, engine, {.noise_sigma = noise_sigma}).points;
    return PCCD::sample_triangle_mesh(model.mesh.vertices, model.mesh.triangles, n, engine,
                                      {.noise_sigma = noise_sigma})
        .points;
}

std::size_t mesh_pieces(const Model& model)
{
    if (model.mesh.triangles.empty()) return 1;
    std::vector<std::uint32_t> parent(model.mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::vector<bool> used(parent.size(), false);
    for (const auto& t : model.mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            used[t[k]] = true;
            parent[find(t[k])] = find(t[(k + 1) % 3]);
        }
    std::size_t pieces = 0;
    for (std::uint32_t v = 0; v < parent.size(); ++v) pieces += used[v] && find(v) == v;
    return pieces;
}

void timing(const Arguments& a, const Model& model)
{
    std::cout << "model,n,repeat,threads,r,support,dijkstra,kd_tree_ms,sampling_radius_ms,graph_ms,cpsp_ms,"
                 "kd_tree_cpu_ms,sampling_radius_cpu_ms,graph_cpu_ms,cpsp_cpu_ms,sampling_radius,edges_per_point,"
                 "virtual_edges,components,cpsp_entries_per_point,graph_bytes_per_point,cpsp_bytes_per_point,"
                 "total_bytes_per_point\n";
    for (std::size_t n : a.sizes) {
        const Eigen::Matrix3Xd points = sample(model, n, a.seed, 0.0);
        for (std::size_t repeat = 0; repeat < a.repeats; ++repeat)
            for (unsigned threads : a.threads) {
                Stopwatch watch;
                const PCCD::Point_cloud<> cloud(points);
                const auto kd = watch.stop();
                watch = Stopwatch();
                const double radius = PCCD::sampling_radius(cloud, {.threads = threads});
                const auto radius_time = watch.stop();
                watch = Stopwatch();
                const auto graph = PCCD::sphere_of_influence_graph(
                    cloud, {.r = a.r, .long_edges = {.factor = a.factor}, .threads = threads});
                const auto graph_time = watch.stop();
                const std::size_t components = PCCD::graph_components(graph).count;
                for (const std::string& which : a.dijkstra) {
                    const auto algorithm =
                        which == "boost" ? PCCD::Bounded_dijkstra::boost : PCCD::Bounded_dijkstra::hand_written;
                    watch = Stopwatch();
                    const PCCD::Close_pairs_shortest_paths cpsp(
                        graph, radius, {.support = a.support, .algorithm = algorithm, .threads = threads});
                    const auto cpsp_time = watch.stop();
                    const double dn = double(n);
                    std::cout << model.name << ',' << n << ',' << repeat << ',' << threads << ',' << a.r << ','
                              << a.support << ',' << which << ',' << kd.first << ',' << radius_time.first << ','
                              << graph_time.first << ',' << cpsp_time.first << ',' << kd.second << ','
                              << radius_time.second << ',' << graph_time.second << ',' << cpsp_time.second << ','
                              << radius << ',' << double(graph.num_edges()) / dn << ',' << graph.num_virtual_edges()
                              << ',' << components << ',' << double(cpsp.num_entries()) / dn << ','
                              << double(graph.memory_bytes()) / dn << ',' << double(cpsp.memory_bytes()) / dn << ','
                              << double(graph.memory_bytes() + cpsp.memory_bytes()) / dn << std::endl;
                }
            }
    }
}

void describe_components(const std::string& model, std::size_t n, double noise, const std::string& graph_name,
                         const PCCD::Proximity_graph& graph)
{
    for (bool include_virtual : {false, true}) {
        const auto c = PCCD::graph_components(graph, include_virtual);
        std::vector<std::size_t> sizes(c.count, 0);
        for (auto label : c.label) ++sizes[label];
        const auto isolated = std::count(sizes.begin(), sizes.end(), std::size_t(1));
        const auto large = std::count_if(sizes.begin(), sizes.end(), [&](std::size_t s) { return s * 100 >= n; });
        std::cout << model << ',' << n << ',' << noise << ',' << graph_name << ',' << include_virtual << ','
                  << double(graph.num_edges()) / double(n) << ',' << graph.num_virtual_edges() << ',' << c.count
                  << ',' << isolated << ',' << large << ',' << *std::max_element(sizes.begin(), sizes.end())
                  << std::endl;
    }
}

void components(const Arguments& a, const Model& model)
{
    std::cout << "# mesh pieces: " << mesh_pieces(model) << '\n';
    std::cout << "model,n,noise,graph,with_virtual,edges_per_point,virtual_edges,components,isolated_points,"
                 "components_over_1pct,largest\n";
    for (std::size_t n : a.sizes) {
        const double spacing = PCCD::Point_cloud<>(sample(model, n, a.seed, 0.0)).mean_spacing();
        for (double noise : {0.0, a.noise}) {
            const PCCD::Point_cloud<> cloud(sample(model, n, a.seed, noise * spacing));
            describe_components(model.name, n, noise, "knn8",
                                PCCD::knn_graph(cloud, {.k = 8, .long_edges = {.factor = a.factor}}));
            for (unsigned r = 1; r <= 4; ++r)
                describe_components(model.name, n, noise, r == 1 ? "sig" : "r" + std::to_string(r) + "-sig",
                                    PCCD::sphere_of_influence_graph(cloud, {.r = r, .long_edges = {.factor = a.factor}}));
        }
    }
}

void long_edges(const Arguments& a, const Model& model)
{
    std::cout << "model,n,noise,r,factor,virtual_edges,virtual_fraction\n";
    for (std::size_t n : a.sizes) {
        const double spacing = PCCD::Point_cloud<>(sample(model, n, a.seed, 0.0)).mean_spacing();
        for (double noise : {0.0, a.noise}) {
            const PCCD::Point_cloud<> cloud(sample(model, n, a.seed, noise * spacing));
            for (double factor : {2.0, 2.5, 3.0, 4.0, 6.0}) {
                const auto g = PCCD::sphere_of_influence_graph(cloud, {.r = a.r, .long_edges = {.factor = factor}});
                std::cout << model.name << ',' << n << ',' << noise << ',' << a.r << ',' << factor << ','
                          << g.num_virtual_edges() << ',' << double(g.num_virtual_edges()) / double(g.num_edges())
                          << std::endl;
            }
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const Arguments a = parse(argc, argv);
        const Model model = load_model();
        if (a.mode == "timing") timing(a, model);
        else if (a.mode == "components") components(a, model);
        else if (a.mode == "long_edges") long_edges(a, model);
        else throw std::invalid_argument("unknown mode " + a.mode + " (timing, components, long_edges)");
    } catch (const std::exception& e) {
        std::cerr << "graph_benchmark: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
