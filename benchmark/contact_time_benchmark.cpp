// benchmark/contact_time_benchmark.cpp -- continuous collision: PCCD::time_of_contact timed against
// FCL's continuousCollide() on the source meshes (the naive solver and conservative advancement)
// and against PCCD's own discrete checks (do_intersect at evenly spaced times), per model over the
// same motions. Results and the command are in doc/benchmarks.md "Continuous collision".
//
//   contact_time_benchmark [--models bunny00.off,elephant.off,fandisk.off] [--points 30000]
//                          [--motions 100] [--ca-motions 10] [--seed 1] [--csv OUT]
//
// Per model: the mesh is normalized into [-1, 1]^3 (object radius 1), FCL's OBBRSS hierarchy is
// built on it, and a cloud of --points points is sampled by area and preprocessed with default
// options. A copy A rests at the identity; copy B, in a random orientation held over the motion,
// translates along a random line (direction u, perpendicular offset o of length uniform in
// [0, 1.5] radii): from -3 u + o to +3 u + o, i.e. from 3 radii before A's centre to 3 radii
// beyond it, a path of 6 radii. The offsets make some motions miss. --motions motions per model,
// drawn with a fixed seed (--seed and the model's index); every method sees the same motions.
// Methods, per motion:
//   fcl_naive  fcl::continuousCollide, CCDC_NAIVE, CCDM_TRANS, num_max_iterations 100: FCL's
//              collide() at t = i / 99, stopping at the first collision;
//   fcl_ca     fcl::continuousCollide, CCDC_CONSERVATIVE_ADVANCEMENT, CCDM_TRANS, num_max_iterations
//              100, GJK solver libccd (FCL's default); only on the first --ca-motions motions per
//              model (slow). In FCL 0.7 this call takes, for two BVHModel<OBBRSS> (and <RSS>), the
//              generic mesh-mesh path: it copies both models and at every step replaces their
//              vertices by the pose of that step applied to the copy's current vertices, so the
//              poses compound from the second step on and the moving copy leaves the scene: it
//              reports no contact on motions that pass through A, after about 1 s each;
//   fcl_ca_or  FCL's oriented mesh-mesh conservative advancement on the same models and motions
//              (fcl::detail::ConservativeAdvancementImpl<double, BVHModel<OBBRSS>, ...>::run, the
//              routine FCL has for OBBRSS meshes but continuousCollide does not reach): relative
//              pose per step, distance bound on the hierarchy, stops when a step falls below
//              1e-5; on every motion;
//   toc        PCCD::time_of_contact with default options (intersection seed --seed + motion);
//   d30, d300  PCCD::do_intersect at t = i / 29 and i / 299 (the same seed), stopping at the
//              first hit.
// Times: this thread's CPU time and wall clock, in us, one run per method per motion, the methods
// in the order above. Printed per model: mean and median time per motion of each method, contacts
// found by each, the contacts the discrete checks find that time_of_contact does not (must be 0) and
// the other way round, the motions where time_of_contact's time lies after the first hit of d300 by
// more than one d300 step, mean |t_toc - t_fcl_naive| x path length in mean spacings of the cloud
// (motions where both found contact), the same against fcl_ca, and time_of_contact's mean counters.
#include "collision_baselines.h"

#include <PCCD/testing/csv.h>
#include <PCCD/testing/pose_generator.h>
#include <PCCD/testing/statistics.h>
#include <PCCD/testing/timing.h>

#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/IO/read_triangle_mesh.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Random.h>
#include <PCCD/Similarity_3.h>
#include <PCCD/sample_triangle_mesh.h>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/motion/translation_motion.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/narrowphase/detail/conservative_advancement_func_matrix.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Arguments {
    std::vector<std::string> models{"bunny00.off", "elephant.off", "fandisk.off"};
    std::size_t points = 30000;
    std::size_t motions = 100;
    std::size_t ca_motions = 10;
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
        else if (key == "--points") a.points = std::stoul(value);
        else if (key == "--motions") a.motions = std::stoul(value);
        else if (key == "--ca-motions") a.ca_motions = std::stoul(value);
        else if (key == "--seed") a.seed = std::stoull(value);
        else if (key == "--csv") a.csv = value;
        else throw std::invalid_argument("unknown option " + key);
    }
    if (a.motions == 0 || a.points < 100) throw std::invalid_argument("--motions must be >= 1, --points >= 100");
    return a;
}

using Pose = PCCD::Rigid_transform_3<double>;

struct Motion {
    Pose start, end;
    double path_length = 0.0;
};

Eigen::Vector3d random_unit(PCCD::Random_engine& engine)
{
    const Eigen::Vector3d d(PCCD::standard_normal(engine), PCCD::standard_normal(engine), PCCD::standard_normal(engine));
    return d.normalized();
}

std::vector<Motion> draw_motions(std::size_t count, std::uint64_t seed)
{
    PCCD::Random_engine engine(seed);
    std::vector<Motion> out;
    for (std::size_t k = 0; k < count; ++k) {
        const Eigen::Vector3d u = random_unit(engine);
        Eigen::Vector3d p = random_unit(engine);
        p = (p - p.dot(u) * u).normalized();
        const Eigen::Vector3d offset = PCCD::uniform_real(engine, 0.0, 1.5) * p;
        const Eigen::Matrix3d r = PCCD::testing::uniform_random_rotation(engine);
        out.push_back({Pose(r, -3.0 * u + offset), Pose(r, 3.0 * u + offset), 6.0});
    }
    return out;
}

fcl::Transform3d to_fcl(const Pose& pose)
{
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = pose.rotation();
    t.translation() = pose.translation();
    return t;
}

template <class BV>
std::shared_ptr<fcl::BVHModel<BV>> fcl_model(const PCCD::Triangle_mesh_data& mesh, const std::string& name)
{
    const auto model = std::make_shared<fcl::BVHModel<BV>>();
    std::vector<fcl::Vector3d> vertices(mesh.vertices.begin(), mesh.vertices.end());
    std::vector<fcl::Triangle> triangles;
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    if (model->beginModel(int(triangles.size()), int(vertices.size())) != fcl::BVH_OK ||
        model->addSubModel(vertices, triangles) != fcl::BVH_OK || model->endModel() != fcl::BVH_OK)
        throw std::runtime_error("FCL could not build the BVH model of " + name);
    return model;
}

enum Method { fcl_naive, fcl_ca, fcl_ca_oriented, toc, d30, d300, method_count };
const std::array<const char*, method_count> method_names{"fcl_naive", "fcl_ca", "fcl_ca_or", "toc", "d30", "d300"};

struct Run {
    bool done = false; // fcl_ca runs on the first --ca-motions motions only
    bool contact = false;
    double t = std::nan("");
    double cpu_us = 0.0, wall_us = 0.0;
};

struct Timer {
    double cpu0 = PCCD::testing::thread_cpu_us();
    PCCD::testing::Clock::time_point wall0 = PCCD::testing::Clock::now();
    void stop(Run& r) const
    {
        r.cpu_us = PCCD::testing::thread_cpu_us() - cpu0;
        r.wall_us = PCCD::testing::us_since(wall0);
        r.done = true;
    }
};

double mean_of(const std::vector<double>& v) { return v.empty() ? std::nan("") : PCCD::testing::mean(v); }
double median_of(const std::vector<double>& v) { return v.empty() ? std::nan("") : PCCD::testing::median(v); }

struct Model_summary {
    std::string model;
    std::size_t motions = 0;
    std::array<std::size_t, method_count> runs{}, contacts{};
    std::array<double, method_count> cpu_mean{}, cpu_median{}, wall_mean{}, wall_median{};
    std::size_t toc_not_d30 = 0, d30_not_toc = 0, toc_not_d300 = 0, d300_not_toc = 0, discrete_not_toc = 0, toc_after_d300 = 0;
    std::size_t fcl_not_toc = 0, toc_not_fcl = 0;
    double err_naive = std::nan(""), err_ca = std::nan("");
    std::size_t err_naive_n = 0, err_ca_n = 0;
    double advancement = 0, near = 0, bisection = 0, node_pairs = 0, f_evaluations = 0;
    double spacing = 0.0;
};

Model_summary run_model(const std::string& name, std::size_t index, const Arguments& args, std::ofstream* csv)
{
    const std::filesystem::path path = std::filesystem::path(PCCD_DATA_DIR) / name;
    PCCD::Triangle_mesh_data mesh = PCCD::IO::read_triangle_mesh(path.string());
    const PCCD::Similarity_3 normalization = PCCD::compute_unit_cube_normalization(mesh.vertices);
    for (auto& v : mesh.vertices) v = normalization.transform_point(v);

    // FCL's mesh: a BVHModel<OBBRSS> (conservative advancement between meshes is defined for RSS
    // and OBBRSS models only).
    const auto fcl_mesh = fcl_model<fcl::OBBRSSd>(mesh, name);

    PCCD::Random_engine engine(args.seed);
    const PCCD::Triangle_mesh_sample sample = PCCD::sample_triangle_mesh(mesh.vertices, mesh.triangles, args.points, engine);
    std::vector<Eigen::Vector3d> points(std::size_t(sample.points.cols()));
    for (Eigen::Index i = 0; i < sample.points.cols(); ++i) points[std::size_t(i)] = sample.points.col(i);
    const PCCD::Point_cloud_object<> object(points);
    const double spacing = object.cloud().mean_spacing();
    std::printf("\n%s: %zu triangles, %zu points sampled by area, mean spacing %.5f, r(P) %.5f; path 6 radii = %.0f "
                "mean spacings; a step of the 100 naive FCL checks = %.1f mean spacings, of d30 %.1f, of d300 %.2f\n",
                name.c_str(), mesh.triangles.size(), object.size(), spacing, object.sampling_radius(), 6.0 / spacing,
                6.0 / 99.0 / spacing, 6.0 / 29.0 / spacing, 6.0 / 299.0 / spacing);
    std::fflush(stdout);

    const std::vector<Motion> motions = draw_motions(args.motions, args.seed * 1000 + index);
    const Pose rest;
    const fcl::Transform3d rest_fcl = fcl::Transform3d::Identity();
    const PCCD::Linear_motion still(rest, rest);

    Model_summary s;
    s.model = name;
    s.motions = motions.size();
    s.spacing = spacing;
    std::array<std::vector<double>, method_count> cpu, wall;
    std::vector<double> err_naive, err_ca;
    for (std::size_t k = 0; k < motions.size(); ++k) {
        const Motion& m = motions[k];
        std::array<Run, method_count> runs{};
        // FCL, naive: 100 discrete collide() calls.
        {
            fcl::ContinuousCollisionRequestd request(100);
            request.ccd_motion_type = fcl::CCDM_TRANS;
            request.ccd_solver_type = fcl::CCDC_NAIVE;
            fcl::ContinuousCollisionResultd result;
            const Timer timer;
            fcl::continuousCollide(fcl_mesh.get(), rest_fcl, rest_fcl, fcl_mesh.get(), to_fcl(m.start), to_fcl(m.end),
                                   request, result);
            timer.stop(runs[fcl_naive]);
            runs[fcl_naive].contact = result.is_collide;
            if (result.is_collide) runs[fcl_naive].t = result.time_of_contact;
        }
        if (k < args.ca_motions) {
            fcl::ContinuousCollisionRequestd request(100);
            request.ccd_motion_type = fcl::CCDM_TRANS;
            request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
            fcl::ContinuousCollisionResultd result;
            const Timer timer;
            fcl::continuousCollide(fcl_mesh.get(), rest_fcl, rest_fcl, fcl_mesh.get(), to_fcl(m.start), to_fcl(m.end),
                                   request, result);
            timer.stop(runs[fcl_ca]);
            runs[fcl_ca].contact = result.is_collide;
            if (result.is_collide) runs[fcl_ca].t = result.time_of_contact;
        }
        {
            // FCL's oriented mesh-mesh conservative advancement, called directly (the one
            // continuousCollide does not reach for OBBRSS models, see the header comment).
            const fcl::TranslationMotiond still_fcl(rest_fcl, rest_fcl), moving_fcl(to_fcl(m.start), to_fcl(m.end));
            fcl::CollisionRequestd request;
            fcl::CollisionResultd result;
            double t = 1.0;
            const Timer timer;
            const bool hit = fcl::detail::ConservativeAdvancementImpl<double, fcl::BVHModel<fcl::OBBRSSd>,
                                                                      fcl::detail::GJKSolver_libccdd>::run(*fcl_mesh, &still_fcl, *fcl_mesh, &moving_fcl, nullptr, request, result, t);
            timer.stop(runs[fcl_ca_oriented]);
            runs[fcl_ca_oriented].contact = hit;
            if (hit) runs[fcl_ca_oriented].t = t;
        }
        PCCD::Contact_time_options options;
        options.distance.intersection.seed = args.seed + k;
        PCCD::Contact_time_result r;
        {
            const PCCD::Linear_motion moving(m.start, m.end);
            const Timer timer;
            r = PCCD::time_of_contact(object, still, object, moving, options);
            timer.stop(runs[toc]);
            runs[toc].contact = r.status == PCCD::Contact_time_status::contact;
            runs[toc].t = r.t;
        }
        const PCCD::Linear_motion moving(m.start, m.end);
        for (const Method d : {d30, d300}) {
            const int n = d == d30 ? 30 : 300;
            const Timer timer;
            for (int i = 0; i < n; ++i) {
                const double t = double(i) / double(n - 1);
                if (PCCD::do_intersect(object, rest, object, moving.pose(t), options.distance.intersection).intersects) {
                    runs[d].contact = true;
                    runs[d].t = t;
                    break;
                }
            }
            timer.stop(runs[d]);
        }

        for (int j = 0; j < method_count; ++j) {
            const Run& x = runs[std::size_t(j)];
            if (!x.done) continue;
            ++s.runs[std::size_t(j)];
            s.contacts[std::size_t(j)] += x.contact;
            cpu[std::size_t(j)].push_back(x.cpu_us);
            wall[std::size_t(j)].push_back(x.wall_us);
            if (csv)
                *csv << name << ',' << k << ',' << method_names[std::size_t(j)] << ',' << int(x.contact) << ',' << x.t << ','
                     << x.cpu_us << ',' << x.wall_us << ',' << m.path_length / spacing << ','
                     << (j == toc ? r.counters.advancement_steps : 0) << ',' << (j == toc ? r.counters.near_checks : 0) << ','
                     << (j == toc ? r.counters.bisection_steps : 0) << ',' << (j == toc ? r.counters.node_pairs : 0) << ','
                     << (j == toc ? r.counters.f_evaluations : 0) << '\n';
        }
        const bool c = runs[toc].contact;
        s.toc_not_d30 += c && !runs[d30].contact;
        s.d30_not_toc += !c && runs[d30].contact;
        s.toc_not_d300 += c && !runs[d300].contact;
        s.d300_not_toc += !c && runs[d300].contact;
        s.discrete_not_toc += !c && (runs[d30].contact || runs[d300].contact);
        // time_of_contact reports the first contact: a d300 hit more than one step earlier means it
        // skipped an earlier contact.
        if (c && runs[d300].contact && r.t > runs[d300].t + 1.0 / 299.0) {
            ++s.toc_after_d300;
            std::printf("  motion %zu: toc contact at t %.4f (bracket [%.4f, %.4f]), d300's first hit at t %.4f: %.1f mean "
                        "spacings earlier\n",
                        k, r.t, r.t_low, r.t_high, runs[d300].t, (r.t - runs[d300].t) * m.path_length / spacing);
        }
        s.fcl_not_toc += runs[fcl_naive].contact && !c;
        s.toc_not_fcl += c && !runs[fcl_naive].contact;
        if (c && runs[fcl_naive].contact) err_naive.push_back(std::abs(r.t - runs[fcl_naive].t) * m.path_length / spacing);
        if (c && runs[fcl_ca_oriented].contact) err_ca.push_back(std::abs(r.t - runs[fcl_ca_oriented].t) * m.path_length / spacing);
        s.advancement += double(r.counters.advancement_steps);
        s.near += double(r.counters.near_checks);
        s.bisection += double(r.counters.bisection_steps);
        s.node_pairs += double(r.counters.node_pairs);
        s.f_evaluations += double(r.counters.f_evaluations);
    }
    for (int j = 0; j < method_count; ++j) {
        s.cpu_mean[std::size_t(j)] = mean_of(cpu[std::size_t(j)]);
        s.cpu_median[std::size_t(j)] = median_of(cpu[std::size_t(j)]);
        s.wall_mean[std::size_t(j)] = mean_of(wall[std::size_t(j)]);
        s.wall_median[std::size_t(j)] = median_of(wall[std::size_t(j)]);
    }
    s.err_naive = mean_of(err_naive);
    s.err_naive_n = err_naive.size();
    s.err_ca = mean_of(err_ca);
    s.err_ca_n = err_ca.size();
    const double n = double(motions.size());
    s.advancement /= n;
    s.near /= n;
    s.bisection /= n;
    s.node_pairs /= n;
    s.f_evaluations /= n;

    std::printf("%-10s %6s %8s %11s %11s %11s %11s\n", "method", "runs", "contacts", "cpu mean", "cpu median", "wall mean",
                "wall median");
    for (int j = 0; j < method_count; ++j)
        std::printf("%-10s %6zu %8zu %11.0f %11.0f %11.0f %11.0f\n", method_names[std::size_t(j)], s.runs[std::size_t(j)],
                    s.contacts[std::size_t(j)], s.cpu_mean[std::size_t(j)], s.cpu_median[std::size_t(j)],
                    s.wall_mean[std::size_t(j)], s.wall_median[std::size_t(j)]);
    std::printf("toc contacts that d30 misses %zu, d30 contacts toc misses %zu; toc not d300 %zu, d300 not toc %zu; toc "
                "later than d300's first hit + 1 step %zu; fcl_naive not toc %zu, toc not fcl_naive %zu\n",
                s.toc_not_d30, s.d30_not_toc, s.toc_not_d300, s.d300_not_toc, s.toc_after_d300, s.fcl_not_toc, s.toc_not_fcl);
    std::printf("mean |t_toc - t_fcl_naive| x path = %.2f mean spacings (%zu motions), against fcl_ca_or %.2f (%zu motions)\n",
                s.err_naive, s.err_naive_n, s.err_ca, s.err_ca_n);
    std::printf("toc mean counters per motion: %.1f walks (advancement steps and near-band steps that took a new bound), %.1f near checks, "
                "%.1f bisection steps, %.0f node pairs, %.0f f evaluations\n",
                s.advancement, s.near, s.bisection, s.node_pairs, s.f_evaluations);
    std::fflush(stdout);
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const Arguments args = parse(argc, argv);
        if (std::string(PCCD_DATA_DIR).empty()) throw std::runtime_error("no libcgal-demo data directory configured");
        std::printf("contact_time_benchmark: %zu points per cloud, %zu motions per model (fcl_ca on the first %zu), seed "
                    "%llu; times per motion in us, thread CPU and wall clock, one run each, one thread\n",
                    args.points, args.motions, args.ca_motions, (unsigned long long)args.seed);
        std::ofstream csv;
        if (!args.csv.empty()) {
            csv = PCCD::testing::open_csv(args.csv);
            csv << "model,motion,method,contact,t,cpu_us,wall_us,path_spacings,advancement_steps,near_checks,"
                   "bisection_steps,node_pairs,f_evaluations\n";
        }
        std::vector<Model_summary> all;
        for (std::size_t i = 0; i < args.models.size(); ++i)
            all.push_back(run_model(args.models[i], i, args, args.csv.empty() ? nullptr : &csv));

        std::printf("\nsummary (times: mean / median per motion, thread CPU, ms)\n");
        std::printf("%-13s %5s %15s %15s %15s %15s %15s %15s %-24s %6s %6s %6s %7s %7s\n", "model", "n", "fcl_naive", "fcl_ca", "fcl_ca_or",
                    "toc", "d30", "d300", "contacts n/ca/or/t/30/300", "t!d30", "d!t", "late", "err_n/s", "err_ca/s");
        for (const Model_summary& s : all) {
            std::printf("%-13s %5zu", s.model.c_str(), s.motions);
            for (int j = 0; j < method_count; ++j)
                std::printf(" %7.2f/%7.2f", s.cpu_mean[std::size_t(j)] / 1e3, s.cpu_median[std::size_t(j)] / 1e3);
            const std::string contacts = std::to_string(s.contacts[fcl_naive]) + "/" + std::to_string(s.contacts[fcl_ca]) + "/" + std::to_string(s.contacts[fcl_ca_oriented]) + "/" +
                                         std::to_string(s.contacts[toc]) + "/" + std::to_string(s.contacts[d30]) + "/" +
                                         std::to_string(s.contacts[d300]);
            std::printf(" %-24s %6zu %6zu %6zu %7.2f %7.2f\n", contacts.c_str(), s.toc_not_d30, s.discrete_not_toc, s.toc_after_d300,
                        s.err_naive, s.err_ca);
        }
        std::printf("(fcl_ca: first %zu motions per model; t!d30 = toc contacts d30 misses; d!t = contacts d30 or "
                    "d300 find that toc misses; late = toc contacts more than one d300 step after d300's first hit; err_n, "
                    "err_ca = mean |t_toc - t_fcl| x path in mean spacings against fcl_naive, fcl_ca_or)\n",
                    args.ca_motions);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "contact_time_benchmark: %s\n", e.what());
        return 1;
    }
    return 0;
}
