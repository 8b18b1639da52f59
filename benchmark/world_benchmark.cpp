// benchmark/world_benchmark.cpp -- Collision_world's "all intersecting pairs" on scenes of many
// moving objects, timed against FCL 0.7's DynamicAABBTreeCollisionManager over the source meshes,
// and against all-pairs do_intersect (no broad phase), on the same scenes and motions in one run.
// Results and the command are in doc/benchmarks.md "Collision worlds: all intersecting pairs against
// FCL's DynamicAABBTreeCollisionManager".
//
//   world_benchmark [--models bunny00.off,elephant.off,armadillo.off,ChineseDragon-10kv.off]
//                   [--scales 0.5,1,2] [--points 30000] [--objects 100,1000] [--steps 20]
//                   [--moved 0.1] [--translation 0.2] [--rotation 10] [--contacts 1.5]
//                   [--all-pairs-steps 2] [--seed 1] [--side L] [--box-depth 6] [--fat-margin 0.05]
//                   [--csv OUT]
//
// Shapes: every model of --models, normalized into [-1, 1]^3 (size 2) and sampled by area with
// --points points (seed --seed), at every scale of --scales: one separately preprocessed shared
// Point_cloud_object per (model, scale) and, for FCL, one BVHModel<OBBRSS> of the mesh scaled alike.
// Scene of n objects (each of --objects): instance i takes a uniformly random shape, a uniformly
// random rotation and a uniformly random position in a cube of side L; L is chosen (bisection on the
// first poses, FCL's verdicts) so that each object touches --contacts others on average, i.e. about
// n --contacts / 2 colliding pairs.
// Steps: step 0 answers the scene as built (cold: empty cache); each of the --steps following steps
// moves round(--moved n) distinct random instances by --translation times their size (2 x scale) in
// a random direction (mirrored back into the cube) and turns them by a random angle of at most
// --rotation degrees about a random axis, then asks for all intersecting pairs. Every method sees
// the same motions; the order of the methods rotates from step to step (the all-pairs loop runs
// after them). Methods:
//   fcl          FCL's DynamicAABBTreeCollisionManager<double> over one CollisionObject per instance
//                (sharing the BVHModel of its shape): setTransform + computeAABB of the moved ones,
//                update(moved), collide(callback) where the callback runs fcl::collide with
//                num_max_contacts = 1 on each candidate pair and collects the colliding ones;
//   pccd t1 / t2 Collision_world (World_options::threads 1 or 2) with the result cache on (default)
//                or off: set_poses(moved) then intersecting_pairs();
//   all-pairs    PCCD::do_intersect on every pair of instances with the world's pair seed, one
//                thread, no broad phase: on the first --all-pairs-steps moved steps only (slow);
//                its pairs must equal the world's (counted).
// Times: wall time of the whole step (update and query), and CPU time: the thread's for the
// single-threaded methods, the process's (all threads) for t2. Printed per scene: the cold step, the
// median / mean / p90 over the moved steps, ratios to FCL, the world's counters (fat-box pairs,
// pairs dropped by the tight boxes, cached answers, narrow-phase queries, pairs reported), memory
// per instance (memory_bytes() / size(), shared objects not counted), the agreement of PCCD's pairs
// with FCL's per step, and a profile on the last poses: the broad phases and the narrow phases of
// both, separate and touching pairs apart (thread CPU time), and the pairs the world boxes of each
// hierarchy depth let through. --box-depth and --fat-margin set World_options::box_depth and
// tree.fat_margin (defaults: the library's).
#include "collision_baselines.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/World/Collision_world.h>
#include <PCCD/sample_triangle_mesh.h>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using Object = PCCD::Point_cloud_object<>;
using World = PCCD::Collision_world<Object>;
using Pose = PCCD::Rigid_transform_3<double>;
using Model = fcl::BVHModel<fcl::OBBRSSd>;
using Pair = std::pair<std::uint32_t, std::uint32_t>; // instance indices, first < second

struct Arguments {
    std::vector<std::string> models{"bunny00.off", "elephant.off", "armadillo.off", "ChineseDragon-10kv.off"};
    std::vector<double> scales{0.5, 1.0, 2.0};
    std::size_t points = 30000;
    std::vector<std::size_t> objects{100, 1000};
    std::size_t steps = 20;
    double moved = 0.1;
    double translation = 0.2;
    double rotation_deg = 10.0;
    double contacts = 1.5;
    std::size_t all_pairs_steps = 2;
    double side = 0.0; // > 0: fixed cube side instead of the calibration
    int box_depth = PCCD::World_options{}.box_depth;
    double fat_margin = PCCD::Dynamic_AABB_tree_options{}.fat_margin;
    std::uint64_t seed = 1;
    std::string csv;
};

std::vector<std::string> split(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) items.push_back(item);
    if (items.empty()) throw std::invalid_argument("empty list: " + text);
    return items;
}

Arguments parse(int argc, char** argv)
{
    Arguments a;
    if (argc % 2 == 0) throw std::invalid_argument(std::string("option ") + argv[argc - 1] + " needs a value");
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--models") a.models = split(value);
        else if (key == "--scales") {
            a.scales.clear();
            for (const auto& s : split(value)) a.scales.push_back(std::stod(s));
        } else if (key == "--points") a.points = std::stoul(value);
        else if (key == "--objects") {
            a.objects.clear();
            for (const auto& s : split(value)) a.objects.push_back(std::stoul(s));
        } else if (key == "--steps") a.steps = std::stoul(value);
        else if (key == "--moved") a.moved = std::stod(value);
        else if (key == "--translation") a.translation = std::stod(value);
        else if (key == "--rotation") a.rotation_deg = std::stod(value);
        else if (key == "--contacts") a.contacts = std::stod(value);
        else if (key == "--all-pairs-steps") a.all_pairs_steps = std::stoul(value);
        else if (key == "--side") a.side = std::stod(value);
        else if (key == "--box-depth") a.box_depth = std::stoi(value);
        else if (key == "--fat-margin") a.fat_margin = std::stod(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--csv") a.csv = value;
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.steps == 0 || a.points < 100) throw std::invalid_argument("--steps must be >= 1, --points >= 100");
    if (!(a.moved > 0.0 && a.moved <= 1.0)) throw std::invalid_argument("--moved must be in (0, 1]");
    if (!(a.contacts > 0.0)) throw std::invalid_argument("--contacts must be > 0");
    for (const double s : a.scales)
        if (!(s > 0.0 && std::isfinite(s))) throw std::invalid_argument("--scales must be finite and > 0");
    for (const std::size_t n : a.objects)
        if (n < 2) throw std::invalid_argument("--objects must be >= 2");
    return a;
}

double process_cpu_us()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e6 + double(t.tv_nsec) * 1e-3;
}

std::string load_average()
{
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

/// One (model, scale): the shared PCCD object and the shared FCL model of the same scaled mesh.
struct Shape {
    std::string name;
    double scale = 1.0;
    double size = 2.0; // the longest side of the scaled mesh's box
    std::shared_ptr<const Object> object;
    std::shared_ptr<Model> fcl_model;
};

std::vector<Shape> make_shapes(const Arguments& args)
{
    std::vector<Shape> shapes;
    for (const std::string& name : args.models) {
        const std::filesystem::path path = std::filesystem::path(PCCD_DATA_DIR) / name;
        PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
        const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
        for (auto& v : mesh.vertices) v = normalization.transform_point(v);
        PCCD::Random_engine engine(args.seed);
        const PCCD::Triangle_mesh_sample sample =
            PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, args.points, engine);
        for (const double scale : args.scales) {
            Shape s;
            s.name = name;
            s.scale = scale;
            s.size = 2.0 * scale;
            const auto start = PCCD::testing::Clock::now();
            s.object = std::make_shared<const Object>(Eigen::Matrix3Xd(scale * sample.points));
            const double preprocess_s = PCCD::testing::seconds_since(start);
            std::vector<fcl::Vector3d> vertices;
            vertices.reserve(mesh.vertices.size());
            for (const auto& v : mesh.vertices) vertices.emplace_back(scale * v);
            std::vector<fcl::Triangle> triangles;
            triangles.reserve(mesh.triangles.size());
            for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
            s.fcl_model = std::make_shared<Model>();
            if (s.fcl_model->beginModel(int(triangles.size()), int(vertices.size())) != fcl::BVH_OK ||
                s.fcl_model->addSubModel(vertices, triangles) != fcl::BVH_OK || s.fcl_model->endModel() != fcl::BVH_OK)
                throw std::runtime_error("FCL could not build the BVH model of " + name);
            s.fcl_model->computeLocalAABB();
            std::printf("  shape %-24s scale %4.2f: %zu triangles, %zu points, mean spacing %.5f, preprocessing %.2f s\n",
                        name.c_str(), scale, mesh.triangles.size(), s.object->size(),
                        s.object->cloud().mean_spacing(), preprocess_s);
            std::fflush(stdout);
            shapes.push_back(std::move(s));
        }
    }
    return shapes;
}

/// An instance of a scene: its shape, and its pose as a unit quaternion and a centre.
struct Instance {
    std::size_t shape = 0;
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();

    Pose pose() const { return Pose(rotation.toRotationMatrix(), centre); }
};

fcl::Transform3d to_fcl(const Instance& instance)
{
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = instance.rotation.toRotationMatrix();
    t.translation() = instance.centre;
    return t;
}

/// FCL's manager over the instances of a scene, and its all-pairs callback.
struct Fcl_scene {
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
    fcl::DynamicAABBTreeCollisionManagerd manager;

    struct Data {
        fcl::CollisionRequestd request;
        std::vector<Pair> pairs;
        std::size_t candidates = 0;
    };

    Fcl_scene(const std::vector<Shape>& shapes, const std::vector<Instance>& instances)
    {
        std::vector<fcl::CollisionObjectd*> raw;
        for (std::size_t i = 0; i < instances.size(); ++i) {
            objects.push_back(std::make_unique<fcl::CollisionObjectd>(shapes[instances[i].shape].fcl_model, to_fcl(instances[i])));
            objects.back()->setUserData(reinterpret_cast<void*>(i));
            raw.push_back(objects.back().get());
        }
        manager.registerObjects(raw);
        manager.setup();
    }

    static Pair pair_of(const fcl::CollisionObjectd* o1, const fcl::CollisionObjectd* o2)
    {
        const auto a = std::uint32_t(reinterpret_cast<std::uintptr_t>(o1->getUserData()));
        const auto b = std::uint32_t(reinterpret_cast<std::uintptr_t>(o2->getUserData()));
        return {std::min(a, b), std::max(a, b)};
    }

    static bool callback(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* cdata)
    {
        Data& data = *static_cast<Data*>(cdata);
        ++data.candidates;
        fcl::CollisionResultd result;
        fcl::collide(o1, o2, data.request, result);
        if (result.isCollision()) data.pairs.push_back(pair_of(o1, o2));
        return false; // never stop: all pairs
    }

    /// Moves `moved` to the instances' poses, updates the manager and collects all colliding pairs.
    Data step(const std::vector<Instance>& instances, const std::vector<std::uint32_t>& moved)
    {
        std::vector<fcl::CollisionObjectd*> updated;
        for (const std::uint32_t i : moved) {
            objects[i]->setTransform(to_fcl(instances[i]));
            objects[i]->computeAABB();
            updated.push_back(objects[i].get());
        }
        if (!updated.empty()) manager.update(updated);
        Data data;
        data.request.num_max_contacts = 1;
        data.request.enable_contact = false;
        manager.collide(&data, &Fcl_scene::callback);
        std::sort(data.pairs.begin(), data.pairs.end());
        return data;
    }

    /// All poses at once (the calibration), then the colliding pairs.
    std::size_t count_at(const std::vector<Instance>& instances)
    {
        for (std::size_t i = 0; i < instances.size(); ++i) {
            objects[i]->setTransform(to_fcl(instances[i]));
            objects[i]->computeAABB();
        }
        manager.update();
        return step(instances, {}).pairs.size();
    }
};

/// The methods of a step; PCCD worlds first.
struct Method {
    std::string name;
    bool pccd = false;
    unsigned threads = 1;
    bool cache = true;
};

/// What one method did on one step.
struct Record {
    double wall_ms = 0, cpu_ms = 0, update_ms = std::nan("");
    std::size_t pairs = 0, broad_pairs = 0, filtered = 0, cached = 0, narrow_queries = 0;
};

std::vector<Pair> pairs_of(const std::vector<PCCD::World_pair>& pairs)
{
    std::vector<Pair> out;
    out.reserve(pairs.size());
    for (const auto& p : pairs) out.emplace_back(p.a.index, p.b.index);
    return out; // already sorted by (a, b)
}

std::size_t difference_count(const std::vector<Pair>& x, const std::vector<Pair>& y)
{
    std::vector<Pair> d;
    std::set_difference(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(d));
    return d.size();
}

struct Stats {
    double median = std::nan(""), mean = std::nan(""), p90 = std::nan("");
};

Stats stats(std::vector<double> v)
{
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    return {PCCD::testing::median(v), PCCD::testing::mean(v), PCCD::testing::sorted_quantile(v, 90)};
}

std::vector<Instance> random_instances(std::size_t n, std::size_t shape_count, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    std::vector<Instance> instances(n);
    for (Instance& s : instances) {
        s.shape = std::size_t(PCCD::uniform_index(engine, shape_count));
        s.rotation = PCCD::testing::uniform_random_quaternion(engine);
        s.centre = Eigen::Vector3d(PCCD::uniform_01(engine), PCCD::uniform_01(engine), PCCD::uniform_01(engine));
    }
    return instances;
}

std::vector<Instance> scaled(std::vector<Instance> unit, double side)
{
    for (Instance& s : unit) s.centre *= side;
    return unit;
}

/// The cube side that gives about n contacts / 2 colliding pairs on the first poses (FCL's verdicts).
double calibrate_side(const std::vector<Shape>& shapes, const std::vector<Instance>& unit, const Arguments& args)
{
    const std::size_t n = unit.size();
    const double target = args.contacts * double(n) / 2.0;
    // Start: the cube whose volume per object is a few times the mean object's box.
    double mean_size = 0.0;
    for (const Instance& s : unit) mean_size += shapes[s.shape].size;
    mean_size /= double(n);
    double lo = 0.3 * mean_size * std::cbrt(double(n)), hi = 5.0 * mean_size * std::cbrt(double(n));
    Fcl_scene scene(shapes, scaled(unit, hi));
    double best = hi, best_error = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < 16; ++iteration) {
        const double side = std::sqrt(lo * hi);
        const std::size_t pairs = scene.count_at(scaled(unit, side));
        const double error = std::abs(double(pairs) - target);
        if (error < best_error) {
            best_error = error;
            best = side;
        }
        if (error <= 0.03 * target) break;
        (double(pairs) > target ? lo : hi) = side;
    }
    return best;
}

/// The thread CPU time of `f()` in us, the median of `repetitions` runs.
template <class F>
double cpu_us(F&& f, int repetitions = 3)
{
    std::vector<double> times;
    for (int r = 0; r < repetitions; ++r) {
        const double t0 = PCCD::testing::thread_cpu_us();
        f();
        times.push_back(PCCD::testing::thread_cpu_us() - t0);
    }
    return PCCD::testing::median(times);
}

/// Where a step's time goes, on the last poses (thread CPU time, one thread, each group timed as a
/// whole, median of 3 runs): PCCD's broad-phase walk and the narrow phase of its candidate pairs
/// (tight world boxes overlap), separate and intersecting apart; FCL's broad phase (collide() with a
/// callback that does nothing) and fcl::collide on its candidate pairs, colliding and not apart; and
/// how many pairs the world boxes of each hierarchy depth let through.
void profile(const World& world, const std::vector<PCCD::World_handle>& handles, Fcl_scene& fcl_scene)
{
    std::size_t fat_pairs = 0;
    const double walk = cpu_us([&] {
        fat_pairs = 0;
        world.broad_phase().for_each_overlapping_pair([&](std::uint32_t, std::uint32_t) { ++fat_pairs; });
    });
    std::vector<Pair> candidates;
    world.broad_phase().for_each_overlapping_pair([&](std::uint32_t i, std::uint32_t j) {
        if (world.box(handles[i]).intersects(world.box(handles[j]))) candidates.emplace_back(std::min(i, j), std::max(i, j));
    });
    std::sort(candidates.begin(), candidates.end());
    const auto query = [&](const Pair& p) {
        PCCD::Intersection_options o = world.options().intersection;
        o.seed = PCCD::pair_seed(o.seed, PCCD::world_pair_key(p.first, p.second));
        return PCCD::do_intersect(world.object(handles[p.first]), world.pose(handles[p.first]),
                                  world.object(handles[p.second]), world.pose(handles[p.second]), o);
    };
    std::array<std::vector<Pair>, 2> groups; // separate, intersecting
    std::array<double, 2> node_pairs{0, 0}, f{0, 0};
    for (const Pair& p : candidates) {
        const PCCD::Intersection_result r = query(p);
        const int k = r.status == PCCD::Intersection_status::separate ? 0 : 1;
        groups[k].push_back(p);
        node_pairs[k] += double(r.counters.node_pairs);
        f[k] += double(r.counters.f_evaluations);
    }
    std::array<double, 2> us{0, 0};
    for (int k = 0; k < 2; ++k)
        us[k] = cpu_us([&] {
            for (const Pair& p : groups[k]) static_cast<void>(query(p));
        });
    const auto per = [](double x, std::size_t n) { return n ? x / double(n) : std::nan(""); };
    std::printf("profile PCCD: tree walk %.3f ms (%zu fat pairs); %zu candidates: %zu separate %.1f us each (%.0f node "
                "pairs, %.1f f), %zu intersecting %.1f us each (%.0f node pairs, %.1f f); narrow phase of all %.2f ms\n",
                walk * 1e-3, fat_pairs, candidates.size(), groups[0].size(), per(us[0], groups[0].size()),
                per(node_pairs[0], groups[0].size()), per(f[0], groups[0].size()), groups[1].size(),
                per(us[1], groups[1].size()), per(node_pairs[1], groups[1].size()), per(f[1], groups[1].size()),
                (us[0] + us[1]) * 1e-3);

    // FCL: its candidates and verdicts, then each part timed alone.
    struct Collect {
        std::vector<std::pair<fcl::CollisionObjectd*, fcl::CollisionObjectd*>> objects;
    } collect;
    fcl_scene.manager.collide(&collect, [](fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* cdata) {
        static_cast<Collect*>(cdata)->objects.emplace_back(o1, o2);
        return false;
    });
    fcl::CollisionRequestd request;
    request.num_max_contacts = 1;
    request.enable_contact = false;
    std::array<std::vector<std::pair<fcl::CollisionObjectd*, fcl::CollisionObjectd*>>, 2> fcl_groups;
    for (const auto& [o1, o2] : collect.objects) {
        fcl::CollisionResultd result;
        fcl::collide(o1, o2, request, result);
        fcl_groups[result.isCollision() ? 1 : 0].emplace_back(o1, o2);
    }
    std::size_t count = 0;
    const double fcl_walk = cpu_us([&] {
        fcl_scene.manager.collide(&count, [](fcl::CollisionObjectd*, fcl::CollisionObjectd*, void* c) {
            ++*static_cast<std::size_t*>(c);
            return false;
        });
    });
    std::array<double, 2> fcl_us{0, 0};
    for (int k = 0; k < 2; ++k)
        fcl_us[k] = cpu_us([&] {
            for (const auto& [o1, o2] : fcl_groups[k]) {
                fcl::CollisionResultd result;
                fcl::collide(o1, o2, request, result);
            }
        });
    std::printf("profile FCL: broad phase %.3f ms (%zu candidates): %zu not colliding %.1f us each, %zu colliding %.1f us "
                "each; narrow phase of all %.2f ms\n",
                fcl_walk * 1e-3, collect.objects.size(), fcl_groups[0].size(), per(fcl_us[0], fcl_groups[0].size()),
                fcl_groups[1].size(), per(fcl_us[1], fcl_groups[1].size()), (fcl_us[0] + fcl_us[1]) * 1e-3);

    // The pairs the world boxes of each depth let through (brute force over all pairs), the CPU time
    // of one world box at that depth, and of do_intersect on all those pairs: the depths timed in
    // turn, three rounds, medians.
    const std::vector<int> depths{0, 3, 4, 5, 6, 8, 32};
    std::vector<std::vector<Pair>> depth_pairs;
    std::vector<std::vector<double>> box_us(depths.size()), narrow_us(depths.size());
    for (const int depth : depths) {
        std::vector<Eigen::AlignedBox3d> boxes;
        for (const auto& h : handles) boxes.push_back(PCCD::world_box(world.object(h), world.pose(h), depth));
        std::vector<Pair> pairs;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
            for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
                if (boxes[i].intersects(boxes[j])) pairs.emplace_back(i, j);
        depth_pairs.push_back(std::move(pairs));
    }
    for (int round = 0; round < 3; ++round)
        for (std::size_t d = 0; d < depths.size(); ++d) {
            Eigen::AlignedBox3d sink;
            box_us[d].push_back(cpu_us(
                                    [&] {
                                        for (const auto& h : handles)
                                            sink.extend(PCCD::world_box(world.object(h), world.pose(h), depths[d]));
                                    },
                                    1) /
                                double(handles.size()));
            if (sink.isEmpty()) std::printf("(empty)\n");
            narrow_us[d].push_back(cpu_us(
                [&] {
                    for (const Pair& p : depth_pairs[d]) static_cast<void>(query(p));
                },
                1));
        }
    std::printf("profile: world_box depth: pairs whose boxes overlap, us per box, do_intersect on those pairs ms:");
    for (std::size_t d = 0; d < depths.size(); ++d)
        std::printf(" %d: %zu, %.2f, %.2f;", depths[d], depth_pairs[d].size(), PCCD::testing::median(box_us[d]),
                    PCCD::testing::median(narrow_us[d]) * 1e-3);
    std::printf("\n");
}

void run_scene(std::size_t n, const std::vector<Shape>& shapes, const Arguments& args, std::ofstream* csv)
{
    const std::vector<Instance> unit = random_instances(n, shapes.size(), args.seed * 1000003 + n);
    const auto calibration_start = PCCD::testing::Clock::now();
    const double side = args.side > 0.0 ? args.side : calibrate_side(shapes, unit, args);
    const double calibration_s = PCCD::testing::seconds_since(calibration_start);
    std::vector<Instance> instances = scaled(unit, side);

    std::vector<Method> methods{{"pccd t1 cache", true, 1, true},
                                {"pccd t2 cache", true, 2, true},
                                {"pccd t1 nocache", true, 1, false},
                                {"pccd t2 nocache", true, 2, false},
                                {"fcl", false, 1, false}};
    const std::size_t fcl_method = methods.size() - 1;

    // Build the worlds and FCL's manager (timed: insertion cost).
    std::vector<std::unique_ptr<World>> worlds;
    std::vector<std::vector<PCCD::World_handle>> handles;
    std::vector<double> build_ms;
    for (const Method& m : methods) {
        if (!m.pccd) continue;
        PCCD::World_options options;
        options.intersection.seed = args.seed;
        options.threads = m.threads;
        options.cache_results = m.cache;
        options.box_depth = args.box_depth;
        options.tree.fat_margin = args.fat_margin;
        const auto start = PCCD::testing::Clock::now();
        auto world = std::make_unique<World>(options);
        std::vector<PCCD::World_handle> h;
        for (const Instance& s : instances) h.push_back(world->insert(shapes[s.shape].object, s.pose()));
        build_ms.push_back(PCCD::testing::ms_since(start));
        worlds.push_back(std::move(world));
        handles.push_back(std::move(h));
    }
    const auto fcl_start = PCCD::testing::Clock::now();
    Fcl_scene fcl_scene(shapes, instances);
    build_ms.push_back(PCCD::testing::ms_since(fcl_start));

    std::printf("\nscene of %zu objects: cube side %.3f (mean object size %.3f; calibration %.1f s), %zu moved per step, "
                "load average %s\n",
                n, side,
                [&] {
                    double s = 0;
                    for (const Instance& i : instances) s += shapes[i.shape].size;
                    return s / double(n);
                }(),
                calibration_s, std::size_t(std::lround(args.moved * double(n))), load_average().c_str());
    std::fflush(stdout);

    PCCD::Random_engine motion(args.seed * 7919 + n);
    const std::size_t moved_count = std::max<std::size_t>(1, std::size_t(std::lround(args.moved * double(n))));
    const double max_angle = args.rotation_deg * std::numbers::pi / 180.0;

    // records[method][step]
    std::vector<std::vector<Record>> records(methods.size(), std::vector<Record>(args.steps + 1));
    std::vector<Record> all_pairs_records;
    std::vector<std::size_t> moved_pairs(args.steps + 1), pccd_pairs(args.steps + 1), fcl_pairs(args.steps + 1), only_pccd(args.steps + 1),
        only_fcl(args.steps + 1);
    std::size_t world_mismatches = 0, all_pairs_mismatches = 0;
    std::vector<std::size_t> memory_bytes(worlds.size(), 0);

    for (std::size_t step = 0; step <= args.steps; ++step) {
        std::vector<std::uint32_t> moved;
        if (step > 0) {
            // round(moved n) distinct instances (partial Fisher-Yates), each moved and turned.
            std::vector<std::uint32_t> order(n);
            for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
            for (std::size_t k = 0; k < moved_count; ++k) {
                const std::size_t j = k + std::size_t(PCCD::uniform_index(motion, n - k));
                std::swap(order[k], order[j]);
                moved.push_back(order[k]);
            }
            std::sort(moved.begin(), moved.end());
            for (const std::uint32_t i : moved) {
                Instance& s = instances[i];
                Eigen::Vector3d direction;
                do {
                    direction = Eigen::Vector3d(PCCD::standard_normal(motion), PCCD::standard_normal(motion),
                                                PCCD::standard_normal(motion));
                } while (direction.norm() < 1e-9);
                s.centre += args.translation * shapes[s.shape].size * direction.normalized();
                for (int k = 0; k < 3; ++k) { // mirrored back into the cube
                    if (s.centre[k] < 0.0) s.centre[k] = -s.centre[k];
                    if (s.centre[k] > side) s.centre[k] = 2.0 * side - s.centre[k];
                }
                Eigen::Vector3d axis;
                do {
                    axis = Eigen::Vector3d(PCCD::standard_normal(motion), PCCD::standard_normal(motion),
                                           PCCD::standard_normal(motion));
                } while (axis.norm() < 1e-9);
                const double angle = PCCD::uniform_real(motion, -max_angle, max_angle);
                s.rotation = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())) * s.rotation).normalized();
            }
        }
        std::vector<PCCD::World_handle> moved_handles(moved.size());
        std::vector<Pose> moved_poses(moved.size());
        for (std::size_t k = 0; k < moved.size(); ++k) moved_poses[k] = instances[moved[k]].pose();

        // The methods in an order that rotates with the step.
        std::vector<std::vector<Pair>> answers(methods.size());
        for (std::size_t r = 0; r < methods.size(); ++r) {
            const std::size_t m = (r + step) % methods.size();
            Record& rec = records[m][step];
            if (methods[m].pccd) {
                World& world = *worlds[m];
                for (std::size_t k = 0; k < moved.size(); ++k) moved_handles[k] = handles[m][moved[k]];
                const bool one_thread = methods[m].threads == 1;
                const double cpu0 = one_thread ? PCCD::testing::thread_cpu_us() : process_cpu_us();
                const auto wall0 = PCCD::testing::Clock::now();
                world.set_poses(moved_handles, moved_poses);
                const double update_ms = PCCD::testing::ms_since(wall0);
                const std::vector<PCCD::World_pair> pairs = world.intersecting_pairs();
                rec.wall_ms = PCCD::testing::ms_since(wall0);
                rec.cpu_ms = ((one_thread ? PCCD::testing::thread_cpu_us() : process_cpu_us()) - cpu0) * 1e-3;
                rec.update_ms = update_ms;
                const PCCD::World_counters& c = world.counters();
                rec.broad_pairs = c.broad_phase_pairs;
                rec.filtered = c.filtered_pairs;
                rec.cached = c.cached_pairs;
                rec.narrow_queries = c.narrow_phase_queries;
                rec.pairs = pairs.size();
                answers[m] = pairs_of(pairs);
                memory_bytes[m] = std::max(memory_bytes[m], world.memory_bytes());
            } else {
                const double cpu0 = PCCD::testing::thread_cpu_us();
                const auto wall0 = PCCD::testing::Clock::now();
                Fcl_scene::Data data = fcl_scene.step(instances, moved);
                rec.wall_ms = PCCD::testing::ms_since(wall0);
                rec.cpu_ms = (PCCD::testing::thread_cpu_us() - cpu0) * 1e-3;
                rec.broad_pairs = data.candidates;
                rec.narrow_queries = data.candidates;
                rec.pairs = data.pairs.size();
                answers[m] = std::move(data.pairs);
            }
        }
        for (std::size_t m = 1; m < fcl_method; ++m)
            if (answers[m] != answers[0]) ++world_mismatches;
        pccd_pairs[step] = answers[0].size();
        moved_pairs[step] = std::size_t(std::count_if(answers[0].begin(), answers[0].end(), [&](const Pair& p) {
            return std::binary_search(moved.begin(), moved.end(), p.first) ||
                   std::binary_search(moved.begin(), moved.end(), p.second);
        }));
        fcl_pairs[step] = answers[fcl_method].size();
        only_pccd[step] = difference_count(answers[0], answers[fcl_method]);
        only_fcl[step] = difference_count(answers[fcl_method], answers[0]);

        // All pairs with do_intersect, on the first moved steps.
        if (step >= 1 && step <= args.all_pairs_steps) {
            const World& world = *worlds[0];
            const PCCD::Intersection_options base = world.options().intersection;
            std::vector<Pose> poses(n);
            for (std::size_t i = 0; i < n; ++i) poses[i] = instances[i].pose();
            std::vector<Pair> found;
            const double cpu0 = PCCD::testing::thread_cpu_us();
            const auto wall0 = PCCD::testing::Clock::now();
            for (std::uint32_t i = 0; i < n; ++i)
                for (std::uint32_t j = i + 1; j < n; ++j) {
                    PCCD::Intersection_options o = base;
                    o.seed = PCCD::pair_seed(base.seed, PCCD::world_pair_key(i, j));
                    const PCCD::Intersection_result r = PCCD::do_intersect(*shapes[instances[i].shape].object, poses[i],
                                                                           *shapes[instances[j].shape].object, poses[j], o);
                    if (r.status != PCCD::Intersection_status::separate) found.emplace_back(i, j);
                }
            Record rec;
            rec.wall_ms = PCCD::testing::ms_since(wall0);
            rec.cpu_ms = (PCCD::testing::thread_cpu_us() - cpu0) * 1e-3;
            rec.pairs = found.size();
            rec.narrow_queries = std::size_t(n) * (n - 1) / 2;
            if (found != answers[0]) ++all_pairs_mismatches;
            all_pairs_records.push_back(rec);
            if (csv)
                *csv << n << ',' << step << ",all-pairs," << rec.wall_ms << ',' << rec.cpu_ms << ",," << rec.pairs
                     << ",,,," << rec.narrow_queries << '\n';
        }
        if (csv)
            for (std::size_t m = 0; m < methods.size(); ++m) {
                const Record& r = records[m][step];
                *csv << n << ',' << step << ',' << methods[m].name << ',' << r.wall_ms << ',' << r.cpu_ms << ','
                     << r.update_ms << ',' << r.pairs << ',' << r.broad_pairs << ',' << r.filtered
                     << ',' << r.cached << ',' << r.narrow_queries << '\n';
            }
    }

    // The table: cold step, then the moved steps.
    const auto column = [&](std::size_t m, double Record::*field) {
        std::vector<double> v;
        for (std::size_t s = 1; s <= args.steps; ++s) v.push_back(records[m][s].*field);
        return stats(v);
    };
    const auto count_column = [&](std::size_t m, std::size_t Record::*field) {
        std::vector<double> v;
        for (std::size_t s = 1; s <= args.steps; ++s) v.push_back(double(records[m][s].*field));
        return stats(v);
    };
    const Stats fcl_wall = column(fcl_method, &Record::wall_ms);
    const Stats fcl_cpu = column(fcl_method, &Record::cpu_ms);
    std::printf("%-18s %9s %9s %9s | %9s %9s %9s %9s | %8s %8s | %8s %8s %8s %8s %8s | %9s\n", "method", "build ms",
                "cold wall", "cold cpu", "wall med", "wall mean", "wall p90", "cpu med", "wall/FCL", "cpu/FCL", "broad",
                "filtered", "cached", "narrow", "pairs", "B/inst");
    for (std::size_t m = 0; m < methods.size(); ++m) {
        const Stats wall = column(m, &Record::wall_ms), cpu = column(m, &Record::cpu_ms);
        std::printf("%-18s %9.1f %9.1f %9.1f | %9.2f %9.2f %9.2f %9.2f | %8.3f %8.3f | %8.0f %8.0f %8.0f %8.0f %8.0f | %9.0f\n",
                    methods[m].name.c_str(), build_ms[m], records[m][0].wall_ms, records[m][0].cpu_ms, wall.median, wall.mean, wall.p90,
                    cpu.median, wall.median / fcl_wall.median, cpu.median / fcl_cpu.median,
                    count_column(m, &Record::broad_pairs).median, count_column(m, &Record::filtered).median,
                    count_column(m, &Record::cached).median, count_column(m, &Record::narrow_queries).median,
                    count_column(m, &Record::pairs).median,
                    methods[m].pccd ? double(memory_bytes[m]) / double(worlds[m]->size()) : std::nan(""));
    }
    if (!all_pairs_records.empty()) {
        std::vector<double> wall, cpu;
        for (const Record& r : all_pairs_records) {
            wall.push_back(r.wall_ms);
            cpu.push_back(r.cpu_ms);
        }
        const Stats w = stats(wall), c = stats(cpu);
        std::printf("%-18s %9s %9s %9s | %9.2f %9.2f %9.2f %9.2f | %8.3f %8.3f | %8s %8s %8s %8zu %8zu | (%zu steps)\n",
                    "all-pairs t1", "-", "-", "-", w.median, w.mean, w.p90, c.median, w.median / fcl_wall.median,
                    c.median / fcl_cpu.median, "-", "-", "-", all_pairs_records.front().narrow_queries,
                    all_pairs_records.front().pairs, all_pairs_records.size());
        const Stats t1 = column(0, &Record::cpu_ms), t1_nocache = column(2, &Record::cpu_ms);
        std::printf("all-pairs / world, CPU medians: %.1fx (t1 cache), %.1fx (t1 nocache); all-pairs answers != world's "
                    "on %zu of %zu steps\n",
                    c.median / t1.median, c.median / t1_nocache.median, all_pairs_mismatches, all_pairs_records.size());
    }
    // Where the time goes (medians over the moved steps).
    {
        const Stats up1 = column(0, &Record::update_ms), up3 = column(2, &Record::update_ms);
        std::printf("profile: set_poses of the moved instances %.3f ms of %.2f (t1 cache), %.3f ms of %.2f (t1 nocache), "
                    "wall medians\n",
                    up1.median, column(0, &Record::wall_ms).median, up3.median, column(2, &Record::wall_ms).median);
    }
    // Agreement with FCL.
    {
        std::vector<double> p, f, op, of, sym, mp;
        for (std::size_t s = 1; s <= args.steps; ++s) mp.push_back(double(moved_pairs[s]));
        for (std::size_t s = 0; s <= args.steps; ++s) {
            p.push_back(double(pccd_pairs[s]));
            f.push_back(double(fcl_pairs[s]));
            op.push_back(double(only_pccd[s]));
            of.push_back(double(only_fcl[s]));
            sym.push_back(double(only_pccd[s] + only_fcl[s]));
        }
        std::size_t total_p = 0, total_f = 0, total_op = 0, total_of = 0;
        for (std::size_t s = 0; s <= args.steps; ++s) {
            total_p += pccd_pairs[s];
            total_f += fcl_pairs[s];
            total_op += only_pccd[s];
            total_of += only_fcl[s];
        }
        std::printf("pairs per step (all %zu steps): PCCD median %.0f (min %.0f, max %.0f), FCL median %.0f (min %.0f, "
                    "max %.0f); contacts per object (PCCD) %.2f; symmetric difference per step median %.0f, max %.0f "
                    "(PCCD only %zu, FCL only %zu of %zu / %zu pairs in total); PCCD worlds disagreeing with each "
                    "other on %zu step-answers; intersecting pairs with a moved instance per moved step: median %.0f\n",
                    args.steps + 1, PCCD::testing::median(p), *std::min_element(p.begin(), p.end()),
                    *std::max_element(p.begin(), p.end()), PCCD::testing::median(f), *std::min_element(f.begin(), f.end()),
                    *std::max_element(f.begin(), f.end()), 2.0 * PCCD::testing::median(p) / double(n),
                    PCCD::testing::median(sym), *std::max_element(sym.begin(), sym.end()), total_op, total_of, total_p,
                    total_f, world_mismatches, PCCD::testing::median(mp));
    }
    profile(*worlds[0], handles[0], fcl_scene);
    const auto stats_tree = worlds[0]->broad_phase().statistics();
    std::printf("broad phase (t1 cache): height %zu, reinsertions %zu, rebuilds %zu; load average %s\n", stats_tree.height,
                stats_tree.reinsertions, stats_tree.rebuilds, load_average().c_str());
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const Arguments args = parse(argc, argv);
        if (std::string(PCCD_DATA_DIR).empty()) throw std::runtime_error("no libcgal-demo data directory configured");
        std::printf("world_benchmark: %zu models x %zu scales, %zu points per cloud, %zu moved steps after a cold one, "
                    "%.0f %% moved per step by %.2f sizes and up to %.1f degrees, %.2f contacts per object, seed %llu; "
                    "times in ms per step (wall; CPU: thread for t1 and FCL, process for t2)\n",
                    args.models.size(), args.scales.size(), args.points, args.steps, 100.0 * args.moved,
                    args.translation, args.rotation_deg, args.contacts, (unsigned long long)args.seed);
        const std::vector<Shape> shapes = make_shapes(args);
        std::ofstream csv;
        if (!args.csv.empty()) {
            csv = PCCD::testing::open_csv(args.csv);
            csv << "objects,step,method,wall_ms,cpu_ms,update_ms,pairs,broad_pairs,filtered,cached,"
                   "narrow_queries\n";
        }
        for (const std::size_t n : args.objects) run_scene(n, shapes, args, args.csv.empty() ? nullptr : &csv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "world_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
