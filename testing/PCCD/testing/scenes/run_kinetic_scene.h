// PCCD/testing/scenes/run_kinetic_scene.h -- plays a recorded scene with one of the three update
// strategies of doc/manual/kinetic.md ("Building and advancing", "Baselines with the same
// interface": kinetic events, bottom-up refit, full rebuild), answering queries at a fixed rate, and
// reports the counters and timings of "When to use which". Used by benchmark/kinetic_benchmark.cpp,
// `pccd kinetic-bench` and the kinetic tests; usable on any recorded Kinetic_scene. Not library code
// (testing/, target PCCD::testing; never installed).
//
// The queries of a frame (Kinetic_run_options): the overlap with the scene's obstacle (or a range
// query without one), optionally the self-overlap, and optionally `rays_per_frame` first-hit ray
// casts (triangle scenes only). The overlap of the cloth lying on the table visits nearly the whole
// tree, the worst case for the kinetic tree, which assembles node boxes lazily at query time; a ray
// opens only the nodes along its path, a query touching a small part of the tree.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/Random.h>
#include <PCCD/Kinetic/Event_queue.h>
#include <PCCD/Kinetic/Kinetic_AABB_tree.h>
#include <PCCD/Kinetic/Refit_AABB_tree.h>
#include <PCCD/testing/scenes/Kinetic_scene.h>

namespace PCCD::testing {

/// The update strategy of a run.
enum class Kinetic_method { kinetic, bottom_up, rebuild };

inline std::string to_string(Kinetic_method m)
{
    return m == Kinetic_method::kinetic ? "kinetic" : m == Kinetic_method::bottom_up ? "bottom_up" : "rebuild";
}

/// Options of run_kinetic_scene.
struct Kinetic_run_options {
    /// Query frames per second of animation time; default 30.
    double query_hz = 30.0;
    /// Per frame: the overlap of the scene with its obstacle (if any), else a range query with the
    /// box of the middle eighth of the scene's initial bounding box; default true.
    bool overlap_query = true;
    /// Per frame, also the self-overlap of the scene's primitives (non-adjacent pairs); default false.
    bool self_overlap_query = false;
    /// Per frame, also that many first-hit ray casts (`first_hit`, triangle scenes only); default 0.
    /// The rays are drawn once per run from a fixed seed, so they are the same in every frame and
    /// for every method: origins uniform on the sphere around the centre of the scene's initial
    /// bounding box whose radius is the box's diagonal, each aimed at a uniform point inside the
    /// box (direction = target - origin, not normalised; s in [0, inf); radius 1 if the box is a
    /// point). Each ray counts as one query; each ray that hits adds 1 to `reported`.
    std::size_t rays_per_frame = 0;
    /// Where the trees get the vertex positions of a frame. false (default): each tree evaluates
    /// the flightplans (the refit all of them in advance_to, the kinetic tree those its queries
    /// touch). true: the positions at the frame time are computed before the timed part, as the
    /// state a simulation already holds, and handed to both trees with advance_to(t, positions)
    /// (the refit copies them and refits; the kinetic tree reads them in its queries).
    bool given_positions = false;
    /// If set, the overlap query is a range query with this box (the primitives whose boxes overlap
    /// it) instead of the overlap with the obstacle: a query that touches only part of the scene,
    /// for the regime study of doc/benchmarks.md (a box over part of the table's edge). Unset by
    /// default.
    std::optional<Eigen::AlignedBox3d> query_box = std::nullopt;
    /// Seconds of animation played before the measured frames (the trees advance to
    /// start_time + warm_up untimed, answering no query, and the counters start there); default
    /// 0. A warm-up of 2 s measures the settled cloth, whose events are few.
    double warm_up = 0.0;
};

/// What a run measured. Counts are deterministic; times are wall-clock on the calling thread.
struct Kinetic_run_result {
    Kinetic_method method = Kinetic_method::kinetic;
    std::uint64_t frames = 0;                   ///< query frames played
    std::uint64_t nodes = 0;                    ///< nodes of the tree over the scene
    std::uint64_t bv_updates = 0;               ///< kinetic: bound changes; baselines: node boxes recomputed
    /// kinetic only: distinct nodes changed per query frame, summed (Kinetic_statistics::node_updates)
    std::uint64_t node_updates = 0;
    std::uint64_t events = 0;                   ///< kinetic only: certificate failures processed
    std::uint64_t certificate_computations = 0; ///< kinetic only, after construction
    std::uint64_t certificate_reuses = 0;       ///< kinetic only: failure times reused from the cache
    std::uint64_t queries = 0;                  ///< queries answered
    std::uint64_t reported = 0;                 ///< pairs, primitives, ray hits reported (a checksum)
    double build_ms = 0.0;                      ///< construction (kinetic: including all first certificates)
    double update_ms_per_frame = 0.0;           ///< mean time of advance_to per frame
    double query_ms_per_frame = 0.0;            ///< mean time of the queries per frame
    double ms_per_frame = 0.0;                  ///< update + queries
    /// The same three as processor time of the process (std::clock), which a busy machine inflates
    /// far less than wall-clock time (it excludes the time the thread waits for a core).
    double update_cpu_ms_per_frame = 0.0;
    double query_cpu_ms_per_frame = 0.0;
    double cpu_ms_per_frame = 0.0;
};

namespace detail {

/// The rays of Kinetic_run_options::rays_per_frame around `bounds` (see there); deterministic.
inline std::vector<Kinetic_ray> kinetic_run_rays(const Eigen::AlignedBox3d& bounds, std::size_t count)
{
    std::vector<Kinetic_ray> rays;
    if (count == 0) return rays;
    const bool empty = bounds.isEmpty();
    const Eigen::Vector3d center = empty ? Eigen::Vector3d::Zero() : Eigen::Vector3d(bounds.center());
    const Eigen::Vector3d sizes = empty ? Eigen::Vector3d::Zero() : Eigen::Vector3d(bounds.sizes());
    double radius = sizes.norm();
    if (!(radius > 0.0)) radius = 1.0; // a single point: any sphere around it will do
    Random_engine rng(0x5eed'4a75'2024'0001ULL);
    rays.reserve(count);
    while (rays.size() < count) {
        const Eigen::Vector3d g(standard_normal(rng), standard_normal(rng), standard_normal(rng));
        const double norm = g.norm();
        if (!(norm > 1e-12)) continue; // practically never; keeps the direction on the sphere defined
        const Eigen::Vector3d origin = center + radius * g / norm;
        const Eigen::Vector3d target =
            center + Eigen::Vector3d(uniform_01(rng) - 0.5, uniform_01(rng) - 0.5, uniform_01(rng) - 0.5)
                         .cwiseProduct(sizes);
        rays.push_back({.origin = origin, .direction = target - origin});
    }
    return rays;
}

template <class Tree, class Obstacle>
void answer_queries(const Tree& tree, const Obstacle& obstacle, bool overlap_with_obstacle, const Eigen::AlignedBox3d& range,
                    const std::vector<Kinetic_ray>& rays, const Kinetic_run_options& o, Kinetic_run_result& r,
                    std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, std::vector<std::uint32_t>& hits)
{
    if (o.overlap_query) {
        if (overlap_with_obstacle) {
            tree.overlapping_pairs(obstacle, pairs);
            r.reported += pairs.size();
        } else {
            tree.range_query(range, hits);
            r.reported += hits.size();
        }
        ++r.queries;
    }
    if (o.self_overlap_query) {
        tree.self_overlapping_pairs(pairs);
        r.reported += pairs.size();
        ++r.queries;
    }
    if constexpr (requires(const Kinetic_ray& ray) { tree.first_hit(ray); }) {
        if (!rays.empty()) {
            // One batch per frame: the kinetic tree assembles each node box once for all rays.
            std::vector<std::optional<Kinetic_ray_hit>> ray_hits;
            tree.first_hits(rays, ray_hits);
            for (const auto& hit : ray_hits)
                if (hit) ++r.reported;
            r.queries += rays.size();
        }
    }
}

} // namespace detail

/// Plays `scene` from start_time to end_time with `method`, advancing to every query frame
/// (start + k / query_hz, k >= 1) and answering the queries of `options` there.
/// \tparam P the scene's KineticPrimitive; \tparam Queue the kinetic tree's event queue.
/// \throws Invalid_input if query_hz is not positive, or if rays_per_frame > 0 and P is not a
/// triangle (ray casting is defined on triangles only).
template <class P, class Queue = Event_queue<>>
Kinetic_run_result run_kinetic_scene(const Kinetic_scene<P>& scene, Kinetic_method method,
                                     const Kinetic_run_options& options = {})
{
    if (!std::isgreater(options.query_hz, 0.0))
        throw Invalid_input(internal::concat("run_kinetic_scene: query_hz ", options.query_hz, " must be > 0"));
    if (!(options.warm_up >= 0.0 && options.warm_up <= scene.end_time - scene.start_time))
        throw Invalid_input(internal::concat("run_kinetic_scene: warm_up ", options.warm_up,
                                             " must be in [0, the scene's length ", scene.end_time - scene.start_time,
                                             "]"));
    if constexpr (P::vertex_count != 3)
        if (options.rays_per_frame > 0)
            throw Invalid_input(internal::concat("run_kinetic_scene: rays_per_frame ", options.rays_per_frame,
                                                 " needs a scene of triangles (ray casting hits triangles only); "
                                                 "scene '", scene.name, "' has primitives of ", P::vertex_count,
                                                 " vertices"));
    using Clock = std::chrono::steady_clock;
    using F = Piecewise_linear_flightplan;
    Kinetic_run_result r;
    r.method = method;
    Kinetic_AABB_tree<F> obstacle(scene.obstacle_flightplans, scene.obstacle_triangles, scene.start_time);
    // The overlap query: with the obstacle, or a range query with the query box (if set) or else
    // the middle eighth of the scene's initial bounding box.
    const bool overlap_with_obstacle = !scene.obstacle_triangles.empty() && !options.query_box;
    Eigen::AlignedBox3d bounds;
    for (const F& f : scene.flightplans) bounds.extend(f.position(scene.start_time));
    const Eigen::AlignedBox3d range = options.query_box.value_or(
        Eigen::AlignedBox3d(bounds.center() - 0.25 * bounds.sizes(), bounds.center() + 0.25 * bounds.sizes()));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    std::vector<std::uint32_t> hits;
    const std::vector<Kinetic_ray> rays = detail::kinetic_run_rays(bounds, options.rays_per_frame);

    std::vector<Eigen::Vector3d> positions(options.given_positions ? scene.flightplans.size() : 0);
    auto play = [&](auto& tree) {
        double update = 0.0, query = 0.0;
        std::clock_t update_cpu = 0, query_cpu = 0;
        const double first = scene.start_time + options.warm_up;
        if (options.warm_up > 0.0) {
            tree.advance_to(first);
            obstacle.advance_to(first);
            tree.reset_statistics();
        }
        for (std::uint64_t k = 1;; ++k) {
            const double t = first + double(k) / options.query_hz;
            if (t > scene.end_time) break;
            if (options.given_positions)
                for (std::size_t v = 0; v < positions.size(); ++v) positions[v] = scene.flightplans[v].position(t);
            const std::clock_t c0 = std::clock();
            const auto t0 = Clock::now();
            if (options.given_positions)
                tree.advance_to(t, positions);
            else
                tree.advance_to(t);
            obstacle.advance_to(t);
            const auto t1 = Clock::now();
            const std::clock_t c1 = std::clock();
            detail::answer_queries(tree, obstacle, overlap_with_obstacle, range, rays, options, r, pairs, hits);
            const auto t2 = Clock::now();
            const std::clock_t c2 = std::clock();
            update += std::chrono::duration<double, std::milli>(t1 - t0).count();
            query += std::chrono::duration<double, std::milli>(t2 - t1).count();
            update_cpu += c1 - c0;
            query_cpu += c2 - c1;
            ++r.frames;
        }
        const double frames = double(std::max<std::uint64_t>(r.frames, 1));
        r.update_ms_per_frame = update / frames;
        r.query_ms_per_frame = query / frames;
        r.ms_per_frame = (update + query) / frames;
        const double cpu_ms = 1000.0 / double(CLOCKS_PER_SEC) / frames;
        r.update_cpu_ms_per_frame = double(update_cpu) * cpu_ms;
        r.query_cpu_ms_per_frame = double(query_cpu) * cpu_ms;
        r.cpu_ms_per_frame = double(update_cpu + query_cpu) * cpu_ms;
    };

    const auto build_start = Clock::now();
    if (method == Kinetic_method::kinetic) {
        Kinetic_AABB_tree<F, P, Queue> tree(scene.flightplans, scene.primitives, scene.start_time);
        r.build_ms = std::chrono::duration<double, std::milli>(Clock::now() - build_start).count();
        tree.reset_statistics();
        play(tree);
        r.nodes = tree.node_count();
        r.bv_updates = tree.statistics().bv_updates;
        r.events = tree.statistics().events;
        r.node_updates = tree.statistics().node_updates;
        r.certificate_computations = tree.statistics().certificate_computations;
        r.certificate_reuses = tree.statistics().certificate_reuses;
    } else {
        Refit_AABB_tree<F, P> tree(scene.flightplans, scene.primitives, scene.start_time,
                                   {.update = method == Kinetic_method::bottom_up ? Refit_update::bottom_up
                                                                                  : Refit_update::rebuild});
        r.build_ms = std::chrono::duration<double, std::milli>(Clock::now() - build_start).count();
        play(tree);
        r.nodes = tree.node_count();
        r.bv_updates = tree.statistics().bv_updates;
    }
    return r;
}

} // namespace PCCD::testing
