// Kinetic AABB tree benchmark (doc/manual/kinetic.md): the talk's table cloth scene at about
// 1,684, 6,891 and 15,503 triangles, played at 30, 60 and 120 query frames per second with the
// kinetic tree, bottom-up refit and full rebuild. Writes one CSV row per (size, rate, method) with
// the BV update and event counts (deterministic) and the median time per frame over repeated runs,
// wall-clock and processor time (the latter is far less inflated on a busy machine).
// Column node_updates counts, per query frame, the distinct nodes whose box description changed
// (kinetic: Kinetic_statistics::node_updates; baselines: every node, as bv_updates).
//
//   kinetic_benchmark [--sizes 1684,6891,15503] [--rates 30,60,120] [--repeats 5] [--csv FILE]
//                     [--rays 64] [--warm-up 0] [--methods kinetic+rays,bottom_up+rays,...]
//                     [--boxes 0.25,0.5,1]
//
// --warm-up S plays the first S seconds untimed and measures the rest (2: the settled cloth).
// --methods runs only the listed methods (names as in the CSV); default all.
// Besides the three methods it also runs, at every size and rate, the kinetic tree with a 4-ary
// event heap (method "kinetic_4ary_heap", for the choice of Event_queue's arity), at the first
// rate all three methods with the cloth's self-overlap added to the queries ("+self" methods), and
// at every rate all three methods answering only ray casts instead of the table overlap ("+rays"
// methods: no overlap query, --rays first-hit rays per frame, the same fixed rays for every method
// and frame; see Kinetic_run_options::rays_per_frame), and the kinetic tree and bottom-up refit
// with the frame's vertex positions handed to them ("+given" methods, overlap and rays: the
// positions a simulation already holds, computed outside the timed part;
// Kinetic_run_options::given_positions). The overlap of the cloth lying on the table
// visits nearly the whole tree, the kinetic tree's worst case (it assembles node boxes lazily at
// query time); a ray touches only the nodes along its path. For "+rays" rows, queries counts rays
// (rays per frame x frames); --rays 0 leaves these rows out. --boxes adds, at every rate, the kinetic
// tree and bottom-up refit answering a range query with a box over part of the table's edge
// instead of the table overlap ("+box<f>" methods): the box spans f times the table's half width on
// either side of the middle of its +x edge, from 0.3 below to 0.1 above the top, so the answer is a
// smaller part of the cloth than the table overlap's (f = 0.25: about 4 %, 1: about a third at
// 6,890 triangles); the query's footprint is what decides between the trees.
#include <PCCD/testing/scenes/Cloth_scene.h>
#include <PCCD/testing/scenes/run_kinetic_scene.h>

#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<double> parse_list(const std::string& text)
{
    std::vector<double> values;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) values.push_back(std::stod(item));
    return values;
}

using PCCD::testing::median;

/// The box of a "+box<f>" method (see the header comment); none for f <= 0.
std::optional<Eigen::AlignedBox3d> box_over_table_edge(const PCCD::testing::Kinetic_scene<PCCD::Kinetic_triangle>& scene,
                                                       double f)
{
    if (!(f > 0.0)) return std::nullopt;
    Eigen::AlignedBox3d table;
    for (const auto& plan : scene.obstacle_flightplans) table.extend(plan.position(scene.start_time));
    const double h = f * 0.5 * table.sizes().x();
    const Eigen::Vector3d edge(table.max().x(), table.center().y(), table.max().z());
    return Eigen::AlignedBox3d(edge - Eigen::Vector3d(h, h, 0.3), edge + Eigen::Vector3d(h, h, 0.1));
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<double> sizes{1684, 6891, 15503}, rates{30, 60, 120};
    int repeats = 5;
    std::size_t rays = 64;
    double warm_up = 0.0;
    std::vector<std::string> only;
    std::vector<double> boxes;
    std::string csv_file = "kinetic_benchmark.csv";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--sizes")
            sizes = parse_list(value);
        else if (key == "--rates")
            rates = parse_list(value);
        else if (key == "--repeats")
            repeats = std::max(1, std::stoi(value));
        else if (key == "--csv")
            csv_file = value;
        else if (key == "--methods") {
            std::stringstream in(value);
            for (std::string item; std::getline(in, item, ',');) only.push_back(item);
        } else if (key == "--warm-up")
            warm_up = std::stod(value);
        else if (key == "--boxes")
            boxes = parse_list(value);
        else if (key == "--rays")
            rays = std::size_t(std::stoul(value));
        else {
            std::cerr << "unknown option " << key << '\n';
            return 1;
        }
    }
    std::ofstream csv(csv_file);
    csv << "scene,triangles,nodes,duration_s,query_hz,frames,queries,method,bv_updates,events,"
           "certificate_computations,build_ms,update_ms_median,query_ms_median,ms_per_frame_median,ms_per_frame_min,"
           "ms_per_frame_max,repeats,node_updates,cpu_update_ms_median,cpu_query_ms_median,cpu_ms_per_frame_median,"
           "certificate_reuses\n";
    std::cout << std::fixed << std::setprecision(3);
    for (const double size : sizes) {
        const auto sim_start = std::chrono::steady_clock::now();
        const auto scene = PCCD::testing::make_cloth_scene({.triangles = std::size_t(size)});
        const double sim_s = PCCD::testing::seconds_since(sim_start);
        std::cout << "cloth: " << scene.primitives.size() << " triangles, " << scene.flightplans.size() << " vertices, "
                  << scene.end_time << " s recorded in " << sim_s << " s of simulation\n";
        struct Variant {
            std::string name;
            PCCD::testing::Kinetic_method method;
            bool four_ary_heap;
            bool self;
            bool rays;
            bool given = false;
            double box = 0.0; // > 0: a range query with the box of that fraction instead of the overlap
        };
        for (const double rate : rates) {
            std::vector<Variant> variants{{"kinetic", PCCD::testing::Kinetic_method::kinetic, false, false, false},
                                          {"bottom_up", PCCD::testing::Kinetic_method::bottom_up, false, false, false},
                                          {"rebuild", PCCD::testing::Kinetic_method::rebuild, false, false, false},
                                          {"kinetic_4ary_heap", PCCD::testing::Kinetic_method::kinetic, true, false, false}};
            constexpr PCCD::testing::Kinetic_method methods[] = {PCCD::testing::Kinetic_method::kinetic, PCCD::testing::Kinetic_method::bottom_up,
                                                        PCCD::testing::Kinetic_method::rebuild};
            if (rate == rates.front())
                for (const auto m : methods) variants.push_back({PCCD::testing::to_string(m) + "+self", m, false, true, false});
            if (rays > 0)
                for (const auto m : methods) variants.push_back({PCCD::testing::to_string(m) + "+rays", m, false, false, true});
            // The frame's positions handed to the trees (advance_to(t, positions)), overlap and rays.
            for (const auto m : {PCCD::testing::Kinetic_method::kinetic, PCCD::testing::Kinetic_method::bottom_up}) {
                variants.push_back({PCCD::testing::to_string(m) + "+given", m, false, false, false, true});
                if (rays > 0) variants.push_back({PCCD::testing::to_string(m) + "+rays+given", m, false, false, true, true});
            }
            for (const double f : boxes)
                for (const auto m : {PCCD::testing::Kinetic_method::kinetic, PCCD::testing::Kinetic_method::bottom_up}) {
                    std::ostringstream name;
                    name << PCCD::testing::to_string(m) << "+box" << f;
                    variants.push_back({name.str(), m, false, false, false, false, f});
                }
            for (const Variant& v : variants) {
                if (!only.empty() && std::find(only.begin(), only.end(), v.name) == only.end()) continue;
                const PCCD::testing::Kinetic_run_options options{.query_hz = rate,
                                                        .overlap_query = !v.rays,
                                                        .self_overlap_query = v.self,
                                                        .rays_per_frame = v.rays ? rays : 0,
                                                        .given_positions = v.given,
                                                        .query_box = box_over_table_edge(scene, v.box),
                                                        .warm_up = warm_up};
                std::vector<double> times, updates, queries, cpu_times, cpu_updates, cpu_queries;
                PCCD::testing::Kinetic_run_result first;
                for (int r = 0; r < repeats; ++r) {
                    const auto result = v.four_ary_heap
                                            ? PCCD::testing::run_kinetic_scene<PCCD::Kinetic_triangle, PCCD::Event_queue<4>>(
                                                  scene, v.method, options)
                                            : PCCD::testing::run_kinetic_scene(scene, v.method, options);
                    if (r == 0) first = result;
                    times.push_back(result.ms_per_frame);
                    updates.push_back(result.update_ms_per_frame);
                    queries.push_back(result.query_ms_per_frame);
                    cpu_times.push_back(result.cpu_ms_per_frame);
                    cpu_updates.push_back(result.update_cpu_ms_per_frame);
                    cpu_queries.push_back(result.query_cpu_ms_per_frame);
                }
                const double med = median(times);
                csv << "cloth," << scene.primitives.size() << ',' << first.nodes << ',' << scene.end_time << ',' << rate
                    << ',' << first.frames << ',' << first.queries << ',' << v.name << ',' << first.bv_updates << ','
                    << first.events << ',' << first.certificate_computations << ',' << first.build_ms << ','
                    << median(updates) << ',' << median(queries) << ',' << med
                    << ',' << *std::min_element(times.begin(), times.end()) << ','
                    << *std::max_element(times.begin(), times.end()) << ',' << repeats << ','
                    << (v.method == PCCD::testing::Kinetic_method::kinetic ? first.node_updates : first.bv_updates) << ','
                    << median(cpu_updates) << ',' << median(cpu_queries) << ',' << median(cpu_times) << ','
                    << first.certificate_reuses << '\n';
                std::cout << "  " << std::setw(5) << rate << " Hz " << std::setw(22) << v.name << "  bv_updates "
                          << std::setw(9) << first.bv_updates << "  node_updates " << std::setw(9)
                          << (v.method == PCCD::testing::Kinetic_method::kinetic ? first.node_updates : first.bv_updates)
                          << "  events " << std::setw(8) << first.events
                          << "  build " << std::setw(8) << first.build_ms << " ms  per frame (median): update "
                          << median(updates) << " + queries " << median(queries) << " = " << med << " ms (CPU "
                          << median(cpu_updates) << " + " << median(cpu_queries) << " = " << median(cpu_times) << ")\n";
                csv.flush();
            }
        }
    }
    std::cout << "CSV written to " << csv_file << '\n';
    return 0;
}
