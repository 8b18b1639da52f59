// How many of PCCD's oriented normals point against the mesh's (doc/benchmarks.md, "Normal
// orientation"): closed models of libcgal-demo, normalized into [-1, 1]^3, sampled by area (clean
// and with Gaussian noise of 0.3 mean spacings of the clean sample), each point compared with the
// normal of the triangle it was drawn on (outward on these meshes). Beside PCCD's orientation, the
// plain rule of Hoppe et al. on the same graph and the same unoriented normals: a minimum spanning
// tree for 1 - |n_i . n_j| from the smallest index, each normal flipped when n_i . n_parent < 0,
// then the whole component flipped if it faces the centroid.
//
//   normal_orientation [--points 8000,30000] [--models elephant.off,...] [--seed 7]
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <cstdio>
#include <functional>
#include <iostream>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

std::vector<std::string> split(const std::string& s)
{
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

/// The plain rule on the object's graph, from its normals with their signs as PCCD left them (the
/// rule only reads signs relative to each other, so the starting signs do not matter but for the
/// root's, which the outward flip settles).
Eigen::Matrix3Xd plain_rule(const PCCD::Point_cloud_object<>& o)
{
    Eigen::Matrix3Xd n = o.normals();
    const auto& g = o.graph().graph();
    const auto is_virtual = o.graph().virtual_map();
    const std::size_t size = o.size();
    std::vector<char> in_tree(size, 0);
    using Item = std::tuple<double, std::uint32_t, std::uint32_t>;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < size; ++i) centroid += o.cloud().position(std::uint32_t(i)).cast<double>();
    centroid /= double(size);
    for (std::size_t root = 0; root < size; ++root) {
        if (in_tree[root] || n.col(Eigen::Index(root)).isZero(0.0)) continue;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
        heap.emplace(0.0, std::uint32_t(root), std::uint32_t(root));
        std::vector<std::uint32_t> order;
        while (!heap.empty()) {
            const auto [w, v, parent] = heap.top();
            heap.pop();
            if (in_tree[v]) continue;
            in_tree[v] = 1;
            order.push_back(v);
            if (v != parent && n.col(v).dot(n.col(parent)) < 0.0) n.col(v) = -n.col(v);
            for (auto [e, end] = out_edges(v, g); e != end; ++e) {
                if (get(is_virtual, *e)) continue;
                const auto u = std::uint32_t(target(*e, g));
                if (in_tree[u] || n.col(u).isZero(0.0)) continue;
                heap.emplace(1.0 - std::abs(n.col(v).normalized().dot(n.col(u).normalized())), u, v);
            }
        }
        double outward = 0.0;
        for (const std::uint32_t v : order) outward += n.col(v).normalized().dot(o.cloud().position(v).cast<double>() - centroid);
        if (outward < 0.0)
            for (const std::uint32_t v : order) n.col(v) = -n.col(v);
    }
    return n;
}

double reversed_percent(const PCCD::Point_cloud_object<>& o, const Eigen::Matrix3Xd& normals, const Eigen::Matrix3Xd& truth)
{
    std::size_t reversed = 0;
    for (std::size_t i = 0; i < o.size(); ++i)
        if (!(normals.col(Eigen::Index(i)).dot(truth.col(Eigen::Index(o.input_index(i)))) > 0.0)) ++reversed;
    return 100.0 * double(reversed) / double(o.size());
}

} // namespace

int main(int argc, char** argv)
try {
    std::vector<std::string> models = split("bunny00.off,elephant.off,armadillo.off,anchor.off,joint.off,helmet.off,"
                                            "handle.off,fandisk.off,itemb.off,cheese.off,pipe.off,part.off,knot1.off");
    std::vector<std::size_t> sizes{8000, 30000};
    std::uint64_t seed = 7;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--models") models = split(value);
        else if (key == "--points") {
            sizes.clear();
            for (const auto& s : split(value)) sizes.push_back(std::stoul(s));
        } else if (key == "--seed") seed = std::stoull(value);
        else throw std::invalid_argument("unknown option " + key);
    }
    const std::string dir = PCCD_DATA_DIR;
    if (dir.empty()) throw std::runtime_error("no libcgal-demo data directory configured");
    std::printf("%-14s %7s %6s | %9s %9s\n", "model", "points", "noise", "plain %", "PCCD %");
    for (const std::string& model : models) {
        PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(dir + "/" + model);
        Eigen::Matrix3Xd v(3, Eigen::Index(mesh.vertices.size()));
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) v.col(Eigen::Index(i)) = mesh.vertices[i];
        PCCD::normalize_to_unit_cube(v);
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) mesh.vertices[i] = v.col(Eigen::Index(i));
        for (const std::size_t size : sizes) {
            PCCD::Random_engine clean_engine(1);
            const double spacing =
                PCCD::Point_cloud<>(PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, size, clean_engine).points).mean_spacing();
            for (const double noise : {0.0, 0.3}) {
                PCCD::Random_engine engine(seed);
                const auto sample =
                    PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, size, engine, {.noise_sigma = noise * spacing});
                const PCCD::Point_cloud_object<> o(sample.points);
                std::printf("%-14s %7zu %6.1f | %9.3f %9.3f\n", model.c_str(), size, noise,
                            reversed_percent(o, plain_rule(o), sample.normals), reversed_percent(o, o.normals(), sample.normals));
            }
        }
    }
    return 0;
} catch (const std::exception& e) {
    std::cerr << "normal_orientation: " << e.what() << "\n";
    return 1;
}
