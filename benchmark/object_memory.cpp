// benchmark/object_memory.cpp -- the memory of a preprocessed Point_cloud_object per point, and
// where it goes (doc/benchmarks.md, "Memory per point, and where it goes"). The bunny of
// libcgal-demo, normalized to the unit cube, sampled by area with N points (default 10^6, seed 1),
// is preprocessed with the default options; the progress callback samples the resident set at the
// start and end of each stage (VmRSS of /proc/self/status) and its peak during the stage (VmHWM,
// reset at each start by writing 5 to /proc/self/clear_refs; the peak between two stages is shown
// on the next stage's row). Then the bytes of each part the object keeps, from its containers'
// sizes and capacities (Kd_tree, Proximity_graph, Close_pairs_shortest_paths and
// Point_cloud_hierarchy report their own through memory_bytes()), and the resident set the object
// holds once built (the resident set after the mesh and the sample are freed, minus the one before
// they were made).
//
// With `--kernel euclidean` the same for the lean object (Euclidean_point_cloud_object): its
// stages and its parts (no graph or CPSP map kept).
//
// With `--save FILE` the object is then saved to FILE and loaded back (wall times, file size, and
// whether the loaded object has the same points, normals and hierarchy).
//
// Usage: object_memory [--points 1000000] [--threads T] [--kernel geodesic|euclidean] [--graph sig|knn]
//                      [--save FILE]
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <PCCD/testing/process_memory.h>
#include <vector>

namespace {

using PCCD::testing::reset_peak;
using PCCD::testing::status_bytes;

struct Stage_row {
    PCCD::Preprocessing_stage stage;
    long long start = 0, peak = 0, end = 0, gap_peak = 0;
    double ms = 0;
};

template <class Object>
int measure(std::size_t n, std::optional<unsigned> threads, PCCD::Graph_kind graph, const std::string& save);

struct Part {
    const char* name;
    std::size_t bytes;
};

void print_table(const std::vector<Part>& parts, double N)
{
    std::printf("%-34s %14s %10s\n", "part", "bytes", "B/point");
    std::size_t total = 0;
    for (const Part& p : parts) {
        std::printf("%-34s %14zu %10.1f\n", p.name, p.bytes, double(p.bytes) / N);
        total += p.bytes;
    }
    std::printf("%-34s %14zu %10.1f\n", "total", total, double(total) / N);
}

/// The parts of the geodesic object.
void print_parts(const PCCD::Point_cloud_object<>& o, double N)
{
    const std::size_t points = std::size_t(o.cloud().coordinates().size()) * sizeof(double);
    const std::size_t kd_tree = o.cloud().kd_tree().memory_bytes() - points;
    const std::size_t input_index = o.input_indices().capacity() * sizeof(std::uint32_t);
    const std::size_t graph = o.graph().memory_bytes();
    const auto& cpsp = o.cpsp();
    const std::size_t cpsp_offsets = (cpsp.size() + 1) * sizeof(std::uint64_t);
    const std::size_t cpsp_entry = cpsp.num_entries() * sizeof(std::uint32_t); // each of targets, distances, predecessors
    const std::size_t normals = std::size_t(o.surface().normals().size()) * sizeof(double);
    const std::size_t domain = std::size_t(o.surface().domain_radii().size()) * sizeof(double);
    const bool shared_normals = &o.surface().normals() == &o.euclidean_surface().normals();
    const bool shared_domain = &o.surface().domain_radii() == &o.euclidean_surface().domain_radii();
    const std::size_t euclidean = (shared_normals ? 0 : normals) + (shared_domain ? 0 : domain);
    const std::size_t hierarchy = o.hierarchy().memory_bytes();
    const std::size_t outliers = o.scan().outliers.capacity() * sizeof(std::uint32_t);
    const std::vector<Part> parts{
        {"points (kd-tree's coordinates)", points},
        {"kd-tree (permutation, nodes)", kd_tree},
        {"input_index", input_index},
        {"proximity graph", graph},
        {"CPSP map: offsets", cpsp_offsets},
        {"CPSP map: targets", cpsp_entry},
        {"CPSP map: distances (float)", cpsp_entry},
        {"CPSP map: predecessors", cpsp_entry},
        {"normals (geodesic surface)", normals},
        {"domain radii (geodesic surface)", domain},
        {"euclidean surface's own copies", euclidean},
        {"hierarchy", hierarchy},
        {"outlier list", outliers},
    };
    std::printf("\nParts of the object (%zu points, %zu graph edges, %.2f CPSP entries per point, hierarchy %zu B):\n",
                o.size(), o.graph().num_edges(), double(cpsp.num_entries()) / N, hierarchy);
    print_table(parts, N);
    std::printf("euclidean surface shares the normals: %s, the domain radii: %s\n", shared_normals ? "yes" : "no",
                shared_domain ? "yes" : "no");
}

/// The parts of the lean object.
void print_parts(const PCCD::Euclidean_point_cloud_object<>& o, double N)
{
    const std::size_t points = std::size_t(o.cloud().coordinates().size()) * sizeof(double);
    const std::vector<Part> parts{
        {"points (kd-tree's coordinates)", points},
        {"kd-tree (permutation, nodes)", o.cloud().kd_tree().memory_bytes() - points},
        {"input_index", o.input_indices().capacity() * sizeof(std::uint32_t)},
        {"normals", std::size_t(o.normals().size()) * sizeof(double)},
        {"domain radii", std::size_t(o.domain_radii().size()) * sizeof(double)},
        {"hierarchy", o.hierarchy().memory_bytes()},
        {"outlier list", o.scan().outliers.capacity() * sizeof(std::uint32_t)},
    };
    std::printf("\nParts of the lean object (%zu points, Euclidean kernel, no graph or CPSP map):\n", o.size());
    print_table(parts, N);
}

} // namespace

int main(int argc, char** argv)
{
    // Large blocks mapped and unmapped: a freed block leaves the resident set at once.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    std::size_t n = 1000000;
    std::optional<unsigned> threads;
    std::string kernel = "geodesic";
    PCCD::Graph_kind graph = PCCD::Graph_kind::sphere_of_influence;
    std::string save;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--points")
            n = std::size_t(std::atoll(argv[i + 1]));
        else if (a == "--threads")
            threads = unsigned(std::atoi(argv[i + 1]));
        else if (a == "--kernel" && (std::string(argv[i + 1]) == "geodesic" || std::string(argv[i + 1]) == "euclidean"))
            kernel = argv[i + 1];
        else if (a == "--graph" && (std::string(argv[i + 1]) == "knn" || std::string(argv[i + 1]) == "sig"))
            graph = std::string(argv[i + 1]) == "knn" ? PCCD::Graph_kind::knn : PCCD::Graph_kind::sphere_of_influence;
        else if (a == "--save")
            save = argv[i + 1];
        else {
            std::fprintf(stderr, "usage: object_memory [--points 1000000] [--threads T] [--kernel geodesic|euclidean] [--graph sig|knn] "
                                 "[--save FILE]\n");
            return 2;
        }
    }
    if (kernel == "euclidean") return measure<PCCD::Euclidean_point_cloud_object<>>(n, threads, graph, save);
    return measure<PCCD::Point_cloud_object<>>(n, threads, graph, save);
}

namespace {

template <class Object>
int measure(std::size_t n, std::optional<unsigned> threads, PCCD::Graph_kind graph, const std::string& save)
{
    const auto path = std::filesystem::path(PCCD_DATA_DIR) / "bunny00.off";
    std::optional<Object> object;
    std::vector<Stage_row> rows;
    long long before = 0, built_peak = 0;
    const long long baseline = status_bytes("VmRSS");
    {
        PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
        const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
        for (auto& v : mesh.vertices) v = normalization.transform_point(v);
        PCCD::Random_engine engine(1);
        PCCD::Triangle_mesh_sample cloud = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, n, engine);
        cloud.normals = Eigen::Matrix3Xd(); // only the points are given to the object
        PCCD::Point_cloud_object_options options;
        options.threads = threads;
        options.graph = graph;
        options.progress = [&](const PCCD::Preprocessing_progress& p) {
            if (!p.finished) {
                Stage_row row{p.stage};
                row.gap_peak = status_bytes("VmHWM");
                reset_peak();
                row.start = status_bytes("VmRSS");
                rows.push_back(row);
            } else {
                rows.back().peak = status_bytes("VmHWM");
                rows.back().end = status_bytes("VmRSS");
                rows.back().ms = p.milliseconds;
                reset_peak();
            }
        };
        before = status_bytes("VmRSS");
        reset_peak();
        object.emplace(cloud.points, options);
        built_peak = status_bytes("VmHWM"); // since the end of the last stage
        for (const Stage_row& r : rows) built_peak = std::max({built_peak, r.peak, r.gap_peak});
    }
    const long long held = status_bytes("VmRSS") - baseline; // the mesh and the sample are freed
    const double N = double(object->size());

    std::printf("Preprocessing of %zu points (bunny00.off sampled by area, seed 1), resident set in MB:\n", n);
    std::printf("%-16s %10s %10s %10s %10s %12s %10s\n", "stage", "ms", "start", "peak", "end", "peak-start", "B/point");
    for (const Stage_row& r : rows)
        std::printf("%-16s %10.0f %10.1f %10.1f %10.1f %12.1f %10.1f%s\n", PCCD::to_string(r.stage), r.ms, r.start / 1e6,
                    r.peak / 1e6, r.end / 1e6, (r.peak - r.start) / 1e6, double(r.peak - r.start) / N,
                    r.gap_peak > std::max(r.start, (&r == rows.data() ? r.start : (&r - 1)->end)) + (1 << 20)
                        ? ("   (peak " + std::to_string(r.gap_peak / 1000000) + " MB before it)").c_str()
                        : "");
    std::printf("before: %.1f MB, peak during construction: %.1f MB (%.1f B/point above the start)\n", before / 1e6,
                built_peak / 1e6, double(built_peak - before) / N);

    print_parts(*object, N);
    std::printf("resident set held by the object: %.1f MB (%.1f B/point)\n", held / 1e6, double(held) / N);
    if (!save.empty()) {
        const auto start = std::chrono::steady_clock::now();
        object->save(save);
        const auto saved = std::chrono::steady_clock::now();
        const Object loaded = Object::load(save);
        const auto done = std::chrono::steady_clock::now();
        const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
        const bool same = loaded.cloud().coordinates() == object->cloud().coordinates() && loaded.normals() == object->normals() &&
                          loaded.hierarchy().layout().counts == object->hierarchy().layout().counts &&
                          loaded.hierarchy().layout().order == object->hierarchy().layout().order;
        std::printf("saved to %s in %.2f s (%.1f MB, %.1f B/point), loaded in %.2f s; the same points, normals and "
                    "hierarchy: %s\n",
                    save.c_str(), seconds(start, saved), double(std::filesystem::file_size(save)) / 1e6,
                    double(std::filesystem::file_size(save)) / N, seconds(saved, done), same ? "yes" : "NO");
        if (!same) return 1;
    }
    return 0;
}

} // namespace
