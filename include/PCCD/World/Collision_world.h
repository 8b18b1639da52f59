// PCCD/World/Collision_world.h -- Collision_world, a scene of many posed point-cloud objects: the
// broad phase (a Dynamic_AABB_tree over the instances' world boxes) finds the pairs that may
// touch, the narrow phase (do_intersect, within_distance) answers them in parallel, and a cache
// keeps the answers of pairs whose instances did not move. Objects are shared: one preprocessed
// object may be inserted any number of times at different poses. Implements doc/algorithms.md,
// "Collision worlds"; manual doc/manual/world.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <queue>
#include <span>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <PCCD/Error.h>
#include <PCCD/internal/keep_going.h>
#include <PCCD/Intersection/Interpolation_search.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Intersection/Ray_hit.h>
#include <PCCD/Intersection/Ray_options.h>
#include <PCCD/Intersection/ray_intersection.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Rigid_transform_3.h>
#include <PCCD/World/Dynamic_AABB_tree.h>
#include <PCCD/World/World_handle.h>
#include <PCCD/World/World_options.h>
#include <PCCD/World/World_results.h>
#include <PCCD/World/world_box.h>
#include <PCCD/concepts/CollisionObject.h>
#include <PCCD/concepts/LeafIntersector.h>
#include <PCCD/concepts/ProximityObject.h>
#include <PCCD/internal/parallel.h>

namespace PCCD {

/// The key of the unordered pair of instances with slot indices i and j: (min << 32) | max. The
/// narrow phase answers pair (a, b), a.index < b.index, as
/// do_intersect(object(a), pose(a), object(b), pose(b), o) with o = World_options::intersection
/// except o.seed = pair_seed(intersection.seed, world_pair_key(a.index, b.index)).
constexpr std::uint64_t world_pair_key(std::uint32_t i, std::uint32_t j)
{
    return i < j ? (std::uint64_t(i) << 32) | j : (std::uint64_t(j) << 32) | i;
}

/// A collision world over instances of `Object` (a CollisionObject, e.g. Point_cloud_object<K>).
///
/// Each instance is an object (held by shared pointer, so one preprocessed object serves many
/// instances), a rigid pose, a Collision_filter, and its world box (world_box()), filed in a
/// Dynamic_AABB_tree. Queries:
/// - intersecting_pairs() / for_each_intersecting_pair(): every pair of instances whose surfaces
///   intersect, i.e. exactly the pairs for which do_intersect() with the documented pair seed
///   (world_pair_key()) answers intersecting (or undecided under a budget), among the pairs the
///   filters allow; in increasing (a.index, b.index) order, independent of the thread count;
/// - intersecting(h) / intersecting(object, pose): the instances one instance or a query object
///   touches;
/// - within_distance(h, margin) / within_distance(object, pose, margin): the instances within a
///   distance (PCCD::within_distance, for ProximityObject types);
/// - overlapping(box): the instances with a cloud point inside an axis-aligned box.
///
/// \tparam Object a model of CollisionObject.
/// \tparam Policy the LeafIntersector of the narrow phase (default Interpolation_search).
///
/// Thread safety: the const queries may run concurrently with each other; insert, set_pose, erase,
/// the filter edits and intersecting_pairs() (which updates the result cache) must not run
/// concurrently with anything else on the same world. The narrow phase uses
/// World_options::threads threads itself.
template <CollisionObject Object, class Policy = Interpolation_search>
    requires LeafIntersector<Policy, Object, Object>
class Collision_world {
public:
    using Object_type = Object;
    using Pose = Rigid_transform_3<double>;
    using Box = Eigen::AlignedBox3d;

    /// An empty world. \throws Invalid_input for invalid options or policy parameters.
    explicit Collision_world(const World_options& options = {}, const Policy& policy = Policy())
        : m_options(options), m_policy(policy), m_tree(options.tree)
    {
        internal::check_options(options.intersection, "Collision_world");
        internal::check_options(options.distance, "Collision_world");
        internal::check_threads(options.threads, "Collision_world: threads");
        if (options.box_depth < 0 || options.box_depth > 32)
            throw Invalid_input(internal::concat("Collision_world: box_depth ", options.box_depth, " must be in [0, 32]"));
        if (options.intersection.visitor)
            throw Invalid_input("Collision_world: options.intersection.visitor is set; the world answers pairs on several "
                                "threads at once, so it takes no visitor");
        policy.check();
    }

    const World_options& options() const { return m_options; }
    const Policy& policy() const { return m_policy; }

    /// \name Instances
    /// @{

    /// Adds an instance of `object` at `pose` with `filter`; returns its handle.
    /// \throws Invalid_input if object is null, or for more than 2^32 - 2 instances.
    /// Complexity: O(log n) (world_box: O(1); tree insertion).
    World_handle insert(std::shared_ptr<const Object> object, const Pose& pose, const Collision_filter& filter = {})
    {
        if (!object) throw Invalid_input("Collision_world::insert: the object is null");
        std::uint32_t index;
        if (!m_free.empty()) {
            index = m_free.back();
            m_free.pop_back();
        } else {
            if (m_slots.size() >= std::size_t(World_handle::no_index) - 1)
                throw Invalid_input("Collision_world::insert: more than 2^32 - 2 instances");
            index = std::uint32_t(m_slots.size());
            m_slots.emplace_back();
        }
        Slot& s = m_slots[index];
        s.object = std::move(object);
        s.pose = pose;
        s.filter = filter;
        s.box = world_box(*s.object, pose, m_options.box_depth);
        s.stamp = ++m_stamp;
        s.alive = true;
        s.proxy = m_tree.insert(s.box, index);
        mark_dirty(index);
        ++m_size;
        return World_handle{index, s.generation};
    }

    /// Moves instance `h` to `pose`. \throws Invalid_input for a stale or unset handle.
    void set_pose(World_handle h, const Pose& pose)
    {
        Slot& s = slot(h, "Collision_world::set_pose");
        s.pose = pose;
        s.box = world_box(*s.object, pose, m_options.box_depth);
        s.stamp = ++m_stamp;
        m_tree.update(s.proxy, s.box);
        mark_dirty(h.index);
    }

    /// set_pose() for each handle with the pose of the same index. All handles are checked before
    /// any is moved. \throws Invalid_input if the spans differ in length or a handle is stale.
    void set_poses(std::span<const World_handle> handles, std::span<const Pose> poses)
    {
        if (handles.size() != poses.size())
            throw Invalid_input(internal::concat("Collision_world::set_poses: ", handles.size(), " handles but ", poses.size(), " poses"));
        for (const World_handle& h : handles) slot(h, "Collision_world::set_poses");
        for (std::size_t i = 0; i < handles.size(); ++i) set_pose(handles[i], poses[i]);
    }

    /// Removes instance `h` (its handle becomes stale). \throws Invalid_input for a stale handle
    /// (e.g. erasing twice).
    void erase(World_handle h)
    {
        Slot& s = slot(h, "Collision_world::erase");
        m_tree.erase(s.proxy);
        for (auto it = m_excluded.begin(); it != m_excluded.end();) {
            if (std::uint32_t(*it >> 32) == h.index || std::uint32_t(*it) == h.index)
                it = m_excluded.erase(it);
            else
                ++it;
        }
        const std::uint32_t generation = s.generation + 1;
        const bool dirty = s.dirty; // m_dirty lists each slot once
        s = Slot{};
        s.generation = generation;
        s.dirty = dirty;
        mark_dirty(h.index);
        m_free.push_back(h.index);
        --m_size;
    }

    /// Whether `h` names a live instance of this world.
    bool contains(World_handle h) const
    {
        return h.index < m_slots.size() && m_slots[h.index].alive && m_slots[h.index].generation == h.generation;
    }
    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }

    /// The handles of all instances, in increasing index order.
    std::vector<World_handle> handles() const
    {
        std::vector<World_handle> out;
        out.reserve(m_size);
        for (std::uint32_t i = 0; i < m_slots.size(); ++i)
            if (m_slots[i].alive) out.push_back(World_handle{i, m_slots[i].generation});
        return out;
    }

    const Object& object(World_handle h) const { return *slot(h, "Collision_world::object").object; }
    const std::shared_ptr<const Object>& shared_object(World_handle h) const
    {
        return slot(h, "Collision_world::shared_object").object;
    }
    const Pose& pose(World_handle h) const { return slot(h, "Collision_world::pose").pose; }
    /// The world box the broad phase files `h` under (world_box() at its pose).
    const Box& box(World_handle h) const { return slot(h, "Collision_world::box").box; }
    const Collision_filter& filter(World_handle h) const { return slot(h, "Collision_world::filter").filter; }

    void set_filter(World_handle h, const Collision_filter& filter)
    {
        slot(h, "Collision_world::set_filter").filter = filter;
        mark_dirty(h.index);
    }

    /// Never test the pair (a, b) (e.g. two parts bolted together); erased with either instance.
    /// \throws Invalid_input for stale handles or a == b.
    void exclude_pair(World_handle a, World_handle b)
    {
        check_pair(a, b, "Collision_world::exclude_pair");
        m_excluded.insert(world_pair_key(a.index, b.index));
        mark_dirty(a.index);
        mark_dirty(b.index);
    }
    /// Tests the pair (a, b) again. \throws Invalid_input for stale handles or a == b.
    void include_pair(World_handle a, World_handle b)
    {
        check_pair(a, b, "Collision_world::include_pair");
        m_excluded.erase(world_pair_key(a.index, b.index));
        mark_dirty(a.index);
        mark_dirty(b.index);
    }
    bool excluded(World_handle a, World_handle b) const
    {
        check_pair(a, b, "Collision_world::excluded");
        return m_excluded.contains(world_pair_key(a.index, b.index));
    }
    /// Whether the pair (a, b) is tested at all: filters allow it and it is not excluded.
    bool tested(World_handle a, World_handle b) const
    {
        check_pair(a, b, "Collision_world::tested");
        return allowed(a.index, b.index);
    }
    /// @}

    /// \name Queries
    /// @{

    /// Every pair of instances whose surfaces intersect (see the class): status intersecting, or
    /// undecided when a budget of the options ran out. Sorted by (a.index, b.index).
    /// Complexity: broad phase O(n log n + k) for k overlapping boxes; one do_intersect() per
    /// candidate pair whose answer is not cached, on World_options::threads threads.
    std::vector<World_pair> intersecting_pairs()
    {
        std::vector<World_pair> out;
        for_each_intersecting_pair([&](const World_pair& p) { out.push_back(p); });
        return out;
    }

    /// Calls `f(const World_pair&)` for each pair intersecting_pairs() would return, in its order;
    /// `f` may return bool, false stopping the query (the pairs after it are then not answered).
    /// The narrow phase runs in blocks of pairs in parallel; `f` runs on the calling thread.
    template <class F>
    void for_each_intersecting_pair(F&& f)
    {
        m_counters = World_counters{};
        const std::vector<Candidate> candidates = candidate_pairs();
        ++m_epoch;
        // Chunks of candidates holding up to `block` pairs the cache cannot answer: those are
        // computed (in parallel) before `f` sees the chunk's pairs. A callback that can stop the
        // query (returns bool) gets chunks that double, so an early stop wastes at most as many
        // narrow-phase queries as were already answered; one that cannot (returns void, as
        // intersecting_pairs()' own) gets a single chunk: one parallel loop for the whole step.
        constexpr bool can_stop = !std::is_void_v<std::invoke_result_t<F&, const World_pair&>>;
        std::size_t block = can_stop ? first_block() : candidates.size();
        bool stopped = false;
        std::vector<Cache_entry> answers;
        std::vector<std::size_t> todo;
        std::vector<Cache_entry> computed;
        in_arena([&] {
            for (std::size_t begin = 0; begin < candidates.size() && !stopped;) {
                answers.clear();
                todo.clear();
                std::size_t end = begin;
                for (; end < candidates.size() && todo.size() < block; ++end) {
                    const Candidate& c = candidates[end];
                    if (m_options.cache_results) {
                        const auto it = m_cache.find(c.key);
                        if (it != m_cache.end() && it->second.stamp_a == m_slots[c.a].stamp &&
                            it->second.stamp_b == m_slots[c.b].stamp) {
                            it->second.epoch = m_epoch;
                            answers.push_back(it->second);
                            ++m_counters.cached_pairs;
                            continue;
                        }
                    }
                    todo.push_back(end);
                    answers.emplace_back();
                }
                m_counters.narrow_phase_queries += todo.size();
                computed.assign(todo.size(), Cache_entry{});
                parallel_here(todo.size(), [&](std::size_t t) { computed[t] = answer(candidates[todo[t]]); });
                for (std::size_t t = 0; t < todo.size(); ++t) {
                    answers[todo[t] - begin] = computed[t];
                    if (m_options.cache_results) m_cache[candidates[todo[t]].key] = computed[t];
                }
                for (std::size_t i = begin; i < end && !stopped; ++i) {
                    const Cache_entry& e = answers[i - begin];
                    if (e.status == Intersection_status::separate) continue;
                    const Candidate& c = candidates[i];
                    const World_pair p{World_handle{c.a, m_slots[c.a].generation},
                                       World_handle{c.b, m_slots[c.b].generation}, e.status, e.point};
                    ++m_counters.reported_pairs;
                    if (!internal::keep_going(f, p)) stopped = true;
                }
                begin = end;
                if constexpr (can_stop) block = std::max(block, m_counters.narrow_phase_queries);
            }
        });
        // Forget the answers of pairs that are no longer candidates (after a complete pass only).
        if (!stopped && m_options.cache_results)
            std::erase_if(m_cache, [&](const auto& item) { return item.second.epoch != m_epoch; });
    }

    /// What the last intersecting_pairs() / for_each_intersecting_pair() did.
    const World_counters& counters() const { return m_counters; }

    /// The instances whose surfaces instance `h` intersects (or might, status undecided), in
    /// increasing index order; each answered as its pair in intersecting_pairs() (same seed), so
    /// the two agree. Filters and excluded pairs apply. Does not use or change the cache.
    /// \throws Invalid_input for a stale handle.
    std::vector<World_hit> intersecting(World_handle h) const
    {
        std::vector<World_hit> out;
        for_each_intersecting(h, [&](const World_hit& hit) { out.push_back(hit); });
        return out;
    }

    /// Calls `f(const World_hit&)` for each hit intersecting(h) would return, in its order; `f`
    /// may return bool, false stopping the query. The instances are answered in parallel blocks;
    /// `f` runs on the calling thread.
    template <class F>
    void for_each_intersecting(World_handle h, F&& f) const
    {
        const Slot& s = slot(h, "Collision_world::intersecting");
        std::vector<std::uint32_t> others;
        m_tree.for_each_overlapping(s.box, [&](std::uint32_t j) {
            if (j != h.index && s.box.intersects(m_slots[j].box) && allowed(h.index, j)) others.push_back(j);
        });
        std::sort(others.begin(), others.end());
        in_blocks<Cache_entry>(
            others.size(),
            [&](std::size_t t) {
                return answer(Candidate{std::min(h.index, others[t]), std::max(h.index, others[t]),
                                        world_pair_key(h.index, others[t])});
            },
            [&](std::size_t t, const Cache_entry& e) {
                if (e.status == Intersection_status::separate) return true;
                return internal::keep_going(f, World_hit{World_handle{others[t], m_slots[others[t]].generation}, e.status, e.point});
            });
    }

    /// The instances whose surfaces a query object `query` at `pose` intersects (or might), in
    /// increasing index order, among those whose filter agrees with `filter` (may_collide). Each
    /// instance i is answered as do_intersect(query, pose, object(i), pose(i), o) with
    /// o = World_options::intersection except o.seed = pair_seed(intersection.seed, i).
    template <CollisionObject Query>
        requires LeafIntersector<Policy, Query, Object>
    std::vector<World_hit> intersecting(const Query& query, const Pose& pose, const Collision_filter& filter = {}) const
    {
        std::vector<World_hit> out;
        for_each_intersecting(query, pose, filter, [&](const World_hit& hit) { out.push_back(hit); });
        return out;
    }

    /// Calls `f(const World_hit&)` for each hit intersecting(query, pose, filter) would return, in
    /// its order; `f` may return bool, false stopping the query.
    template <CollisionObject Query, class F>
        requires LeafIntersector<Policy, Query, Object>
    void for_each_intersecting(const Query& query, const Pose& pose, const Collision_filter& filter, F&& f) const
    {
        const Box qbox = world_box(query, pose, m_options.box_depth);
        std::vector<std::uint32_t> others;
        m_tree.for_each_overlapping(qbox, [&](std::uint32_t j) {
            if (qbox.intersects(m_slots[j].box) && may_collide(filter, m_slots[j].filter)) others.push_back(j);
        });
        std::sort(others.begin(), others.end());
        in_blocks<World_hit>(
            others.size(),
            [&](std::size_t t) {
                const Slot& o = m_slots[others[t]];
                Intersection_options options = m_options.intersection;
                options.seed = pair_seed(options.seed, others[t]);
                const Intersection_result r = do_intersect(query, pose, *o.object, o.pose, options, m_policy);
                return World_hit{World_handle{others[t], o.generation}, r.status, first_point(r)};
            },
            [&](std::size_t, const World_hit& hit) {
                return hit.status == Intersection_status::separate ? true : internal::keep_going(f, hit);
            });
    }

    /// The instances whose surfaces come within `margin` of instance `h`'s (PCCD::within_distance
    /// with World_options::distance, h as object a), in increasing index order; filters and
    /// excluded pairs apply. \throws Invalid_input for a stale handle or a margin that is negative
    /// or not finite.
    std::vector<World_proximity> within_distance(World_handle h, double margin) const
        requires ProximityObject<Object>
    {
        std::vector<World_proximity> out;
        for_each_within_distance(h, margin, [&](const World_proximity& w) { out.push_back(w); });
        return out;
    }

    /// Calls `f(const World_proximity&)` for each answer within_distance(h, margin) would return,
    /// in its order; `f` may return bool, false stopping the query.
    template <class F>
    void for_each_within_distance(World_handle h, double margin, F&& f) const
        requires ProximityObject<Object>
    {
        const Slot& s = slot(h, "Collision_world::within_distance");
        check_margin(margin);
        near_instances(*s.object, s.pose, margin, [&](std::uint32_t j) { return j != h.index && allowed(h.index, j); }, f);
    }

    /// The instances whose surfaces come within `margin` of a query object at `pose`, among those
    /// whose filter agrees with `filter`, in increasing index order.
    template <ProximityObject Query>
    std::vector<World_proximity> within_distance(const Query& query, const Pose& pose, double margin,
                                                 const Collision_filter& filter = {}) const
        requires ProximityObject<Object>
    {
        std::vector<World_proximity> out;
        for_each_within_distance(query, pose, margin, filter, [&](const World_proximity& w) { out.push_back(w); });
        return out;
    }

    /// Calls `f(const World_proximity&)` for each answer within_distance(query, pose, margin,
    /// filter) would return, in its order; `f` may return bool, false stopping the query.
    template <ProximityObject Query, class F>
    void for_each_within_distance(const Query& query, const Pose& pose, double margin, const Collision_filter& filter,
                                  F&& f) const
        requires ProximityObject<Object>
    {
        check_margin(margin);
        near_instances(query, pose, margin, [&](std::uint32_t j) { return may_collide(filter, m_slots[j].filter); }, f);
    }

    /// The instances with at least one cloud point inside `box` (world frame, boundary included),
    /// in increasing index order. The cloud samples the surface, so this is the surface's overlap
    /// with the box up to the sampling radius. \throws Invalid_input for an empty or non-finite box.
    std::vector<World_handle> overlapping(const Box& box) const
    {
        std::vector<World_handle> out;
        for_each_overlapping(box, [&](World_handle h) { out.push_back(h); });
        return out;
    }

    /// Calls `f(World_handle)` for each instance overlapping(box) would return, in its order; `f`
    /// may return bool, false stopping the query.
    template <class F>
    void for_each_overlapping(const Box& box, F&& f) const
    {
        if (!box.min().allFinite() || !box.max().allFinite() || box.isEmpty())
            throw Invalid_input(internal::concat("Collision_world::overlapping: the box [", box.min().transpose(), "] - [",
                                                 box.max().transpose(), "] is empty or not finite"));
        std::vector<std::uint32_t> candidates;
        m_tree.for_each_overlapping(box, [&](std::uint32_t j) {
            if (box.intersects(m_slots[j].box)) candidates.push_back(j);
        });
        std::sort(candidates.begin(), candidates.end());
        in_blocks<char>(
            candidates.size(),
            [&](std::size_t t) {
                const Slot& o = m_slots[candidates[t]];
                return char(has_point_in(*o.object, o.pose, box));
            },
            [&](std::size_t t, char inside) {
                return inside ? internal::keep_going(f, World_handle{candidates[t], m_slots[candidates[t]].generation}) : true;
            });
    }

    /// The first hit of the ray origin + t direction / |direction|, t in [0, t_max], on the surfaces
    /// of the instances whose filter agrees with `filter`: the instance and its Ray_hit
    /// (PCCD::ray_intersection with `options`); nullopt when the ray meets none. An instance whose
    /// query ran out of its budget (status undecided) before any hit is returned as it is, so that a
    /// budget never turns into a miss. \throws Invalid_input as ray_intersection for a bad ray.
    std::optional<World_ray_hit> ray_cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                          double t_max = std::numeric_limits<double>::infinity(),
                                          const Ray_options& options = {}, const Collision_filter& filter = {}) const
    {
        std::optional<World_ray_hit> first;
        for_each_ray_hit(origin, direction, t_max, options, filter, [&](const World_ray_hit& h) {
            first = h;
            return false;
        });
        return first;
    }

    /// Calls `f(const World_ray_hit&)` for every instance the ray meets (its first hit on that
    /// instance), in increasing t, among those whose filter agrees with `filter`; `f` may return
    /// bool, false stopping the query (the instances behind are then not evaluated). An undecided
    /// instance is reported where the ray enters its box. \throws Invalid_input for a bad ray.
    template <class F>
    void for_each_ray_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_max,
                          const Ray_options& options, const Collision_filter& filter, F&& f) const
    {
        if (!origin.allFinite() || !direction.allFinite() || !(direction.norm() > 0.0) || std::isnan(t_max) || t_max < 0.0)
            throw Invalid_input(internal::concat("Collision_world::ray_cast: origin [", origin.transpose(), "], direction [",
                                                 direction.transpose(), "] and t_max ", t_max,
                                                 " must be finite, the direction non-zero, t_max >= 0 (+infinity allowed)"));
        const Eigen::Vector3d d = direction.normalized();
        // Best first: an instance waits under the t where the ray enters its box until evaluated,
        // then under its hit; a hit popped before every other key is the next in t.
        struct Entry {
            double key;
            std::uint32_t index;
            bool evaluated;
            Ray_hit hit;
        };
        const auto later = [](const Entry& x, const Entry& y) {
            return x.key > y.key || (x.key == y.key && x.index > y.index);
        };
        std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
        m_tree.for_each_crossed(origin, d, t_max, [&](std::uint32_t j, double t_enter) {
            if (may_collide(filter, m_slots[j].filter)) queue.push(Entry{t_enter, j, false, Ray_hit{}});
        });
        while (!queue.empty()) {
            Entry e = queue.top();
            queue.pop();
            const Slot& s = m_slots[e.index];
            if (e.evaluated) {
                if (!internal::keep_going(f, World_ray_hit{World_handle{e.index, s.generation}, e.hit})) return;
                continue;
            }
            const Ray_hit hit = ray_intersection(*s.object, s.pose, origin, direction, t_max, options);
            if (hit.status == Ray_status::hit)
                queue.push(Entry{hit.t, e.index, true, hit});
            else if (hit.status == Ray_status::undecided)
                queue.push(Entry{e.key, e.index, true, hit});
        }
    }

    /// @}

    /// \name Broad phase and memory
    /// @{
    const Dynamic_AABB_tree& broad_phase() const { return m_tree; }
    /// Bytes the world holds besides the objects themselves: instance slots, tree nodes, the last
    /// candidate pairs, the result cache and the excluded pairs (allocated capacity; hash-table
    /// nodes counted as key, value and two pointers).
    std::size_t memory_bytes() const
    {
        const std::size_t node_overhead = 2 * sizeof(void*);
        return sizeof(*this) + m_slots.capacity() * sizeof(Slot) + m_free.capacity() * sizeof(std::uint32_t) +
               m_dirty.capacity() * sizeof(std::uint32_t) + m_candidates.capacity() * sizeof(Candidate) +
               m_tree.memory_bytes() + m_cache.bucket_count() * sizeof(void*) +
               m_cache.size() * (sizeof(std::pair<const std::uint64_t, Cache_entry>) + node_overhead) +
               m_excluded.bucket_count() * sizeof(void*) + m_excluded.size() * (sizeof(std::uint64_t) + node_overhead);
    }
    /// @}

private:
    struct Slot {
        std::shared_ptr<const Object> object;
        Pose pose;
        Box box;
        Collision_filter filter;
        std::uint64_t stamp = 0; // a new value at every pose change: the cache's validity
        Dynamic_AABB_tree::Proxy proxy = Dynamic_AABB_tree::no_proxy;
        std::uint32_t generation = 0;
        bool alive = false;
        bool dirty = false; // moved, inserted, erased or refiltered since the last candidate_pairs()
    };
    struct Candidate {
        std::uint32_t a; // a < b
        std::uint32_t b;
        std::uint64_t key;
    };
    struct Cache_entry {
        std::uint64_t stamp_a = 0;
        std::uint64_t stamp_b = 0;
        std::uint64_t epoch = 0;
        Eigen::Vector3d point = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
        Intersection_status status = Intersection_status::separate;
    };

    static Eigen::Vector3d first_point(const Intersection_result& r)
    {
        return r.points.empty() ? Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()) : r.points.front().position;
    }

    static void check_margin(double margin)
    {
        if (!(std::isfinite(margin) && margin >= 0.0))
            throw Invalid_input(internal::concat("Collision_world::within_distance: margin ", margin, " must be finite and >= 0"));
    }

    const Slot& slot(World_handle h, const char* function) const
    {
        if (!h.is_set()) throw Invalid_input(internal::concat(function, ": the handle is unset (default-constructed)"));
        if (h.index >= m_slots.size())
            throw Invalid_input(internal::concat(function, ": handle ", h.index, " was never issued by this world"));
        const Slot& s = m_slots[h.index];
        if (!s.alive || s.generation != h.generation)
            throw Invalid_input(internal::concat(function, ": handle ", h.index, " (generation ", h.generation,
                                       ") is stale: that instance was erased"));
        return s;
    }
    Slot& slot(World_handle h, const char* function)
    {
        return const_cast<Slot&>(static_cast<const Collision_world&>(*this).slot(h, function));
    }

    void check_pair(World_handle a, World_handle b, const char* function) const
    {
        slot(a, function);
        slot(b, function);
        if (a.index == b.index) throw Invalid_input(internal::concat(function, ": both handles name instance ", a.index));
    }

    bool allowed(std::uint32_t i, std::uint32_t j) const
    {
        return may_collide(m_slots[i].filter, m_slots[j].filter) && !m_excluded.contains(world_pair_key(i, j));
    }

    std::size_t worker_count() const
    {
        return m_options.threads ? std::size_t(*m_options.threads) : std::size_t(2);
    }

    /// The first chunk of parallel queries of a query that may stop early.
    std::size_t first_block() const { return std::max<std::size_t>(64, 16 * worker_count()); }

    /// Runs `body()` with the options' threads available to parallel_here(): in one task arena of
    /// that many threads (none for one thread), so that a query entering several parallel loops
    /// pays for its arena once.
    template <class Body>
    void in_arena(const Body& body) const
    {
        if (worker_count() == 1)
            body();
        else
            internal::with_threads(m_options.threads, body);
    }

    /// Calls body(t) for t in [0, n), in parallel unless one thread is asked for; call it inside
    /// in_arena(). The exception of the lowest t is rethrown after all have run.
    template <class Body>
    void parallel_here(std::size_t n, const Body& body) const
    {
        if (n == 0) return;
        if (n == 1 || worker_count() == 1) {
            for (std::size_t t = 0; t < n; ++t) body(t);
            return;
        }
        std::vector<std::exception_ptr> errors(n);
        internal::parallel_for_ranges(n, 1, [&](std::size_t begin, std::size_t end) {
            for (std::size_t t = begin; t < end; ++t) {
                try {
                    body(t);
                } catch (...) {
                    errors[t] = std::current_exception();
                }
            }
        });
        for (const std::exception_ptr& e : errors)
            if (e) std::rethrow_exception(e);
    }

    void mark_dirty(std::uint32_t index)
    {
        if (m_slots[index].dirty) return;
        m_slots[index].dirty = true;
        m_dirty.push_back(index);
    }

    /// Whether the pair (i, j) is a candidate: tight world boxes overlap and the filters allow it.
    bool candidate(std::uint32_t i, std::uint32_t j)
    {
        ++m_counters.broad_phase_pairs;
        if (!m_slots[i].box.intersects(m_slots[j].box) || !allowed(i, j)) {
            ++m_counters.filtered_pairs;
            return false;
        }
        return true;
    }

    /// The pairs of instances the narrow phase must answer, sorted by key: those whose tight world
    /// boxes overlap and whose filters allow them. While few instances changed since the last call
    /// (at most a quarter), the last call's candidates among unchanged instances are kept (their
    /// boxes and filters are those that made them candidates) and only the changed instances' boxes
    /// are looked up in the tree; otherwise the tree is walked against itself. Both give the same
    /// pairs.
    std::vector<Candidate> candidate_pairs()
    {
        std::vector<Candidate> out;
        if (m_candidates_valid && 4 * m_dirty.size() <= m_size) {
            for (const Candidate& c : m_candidates)
                if (!m_slots[c.a].dirty && !m_slots[c.b].dirty) out.push_back(c);
            m_counters.broad_phase_pairs += out.size();
            for (const std::uint32_t i : m_dirty) {
                if (!m_slots[i].alive) continue;
                m_tree.for_each_overlapping(m_slots[i].box, [&](std::uint32_t j) {
                    // A pair of two changed instances is taken from the lower index's lookup.
                    if (j == i || (m_slots[j].dirty && j < i) || !candidate(i, j)) return;
                    out.push_back(Candidate{std::min(i, j), std::max(i, j), world_pair_key(i, j)});
                });
            }
        } else {
            m_tree.for_each_overlapping_pair([&](std::uint32_t i, std::uint32_t j) {
                if (candidate(i, j)) out.push_back(Candidate{std::min(i, j), std::max(i, j), world_pair_key(i, j)});
            });
        }
        std::sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y) { return x.key < y.key; });
        for (const std::uint32_t i : m_dirty) m_slots[i].dirty = false;
        m_dirty.clear();
        m_candidates = out;
        m_candidates_valid = true;
        return out;
    }

    Cache_entry answer(const Candidate& c) const
    {
        const Slot& a = m_slots[c.a];
        const Slot& b = m_slots[c.b];
        Intersection_options options = m_options.intersection;
        options.seed = pair_seed(options.seed, c.key);
        const Intersection_result r = do_intersect(*a.object, a.pose, *b.object, b.pose, options, m_policy);
        Cache_entry e;
        e.stamp_a = a.stamp;
        e.stamp_b = b.stamp;
        e.epoch = m_epoch;
        e.status = r.status;
        e.point = first_point(r);
        return e;
    }

    template <class Query, class Accept, class F>
    void near_instances(const Query& query, const Pose& pose, double margin, const Accept& accept, F& f) const
    {
        Box qbox = world_box(query, pose, m_options.box_depth);
        qbox.min().array() -= margin;
        qbox.max().array() += margin;
        std::vector<std::uint32_t> others;
        m_tree.for_each_overlapping(qbox, [&](std::uint32_t j) {
            if (qbox.intersects(m_slots[j].box) && accept(j)) others.push_back(j);
        });
        std::sort(others.begin(), others.end());
        in_blocks<World_proximity>(
            others.size(),
            [&](std::size_t t) {
                const Slot& o = m_slots[others[t]];
                return World_proximity{World_handle{others[t], o.generation},
                                       PCCD::within_distance(query, pose, *o.object, o.pose, margin, m_options.distance)};
            },
            [&](std::size_t, const World_proximity& w) { return w.clearance.within ? internal::keep_going(f, w) : true; });
    }

    /// Computes `compute(t)` for t in [0, n) in parallel blocks and hands each answer to
    /// `consume(t, answer)` in index order on the calling thread, stopping when it returns false
    /// (the blocks after it are not computed). Blocks double (each as large as all before it), so a
    /// stop wastes at most as many computations as were consumed, in few parallel loops.
    template <class Answer, class Compute, class Consume>
    void in_blocks(std::size_t n, const Compute& compute, const Consume& consume) const
    {
        std::size_t block = first_block();
        std::vector<Answer> answers;
        in_arena([&] {
            for (std::size_t begin = 0; begin < n;) {
                const std::size_t end = std::min(n, begin + block);
                answers.assign(end - begin, Answer{});
                parallel_here(end - begin, [&](std::size_t t) { answers[t] = compute(begin + t); });
                for (std::size_t t = begin; t < end; ++t)
                    if (!consume(t, answers[t - begin])) return;
                begin = end;
                block = std::max(block, end);
            }
        });
    }

    /// Whether a cloud point of `object` at `pose` lies in the world box `box`: a walk of its
    /// hierarchy pruned by the world boxes of the nodes.
    static bool has_point_in(const Object& object, const Pose& pose, const Box& box)
    {
        const Point_cloud_hierarchy& h = object.hierarchy();
        const Eigen::Matrix3d r_abs = pose.rotation().cwiseAbs();
        std::vector<std::uint32_t> stack{0u};
        while (!stack.empty()) {
            const std::uint32_t i = stack.back();
            stack.pop_back();
            const auto& node = h.node(i);
            const Eigen::Vector3d centre = pose.transform_point(node.box.center());
            const Eigen::Vector3d extent = r_abs * (0.5 * node.box.sizes());
            if (((centre + extent).array() < box.min().array()).any() || ((centre - extent).array() > box.max().array()).any())
                continue;
            if (!node.is_leaf()) {
                stack.push_back(std::uint32_t(node.right));
                stack.push_back(i + 1);
                continue;
            }
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                const Eigen::Vector3d p = pose.transform_point(object.cloud().position(h.order()[k]).template cast<double>());
                if (box.contains(p)) return true;
            }
        }
        return false;
    }

    World_options m_options;
    Policy m_policy;
    Dynamic_AABB_tree m_tree;
    std::vector<Slot> m_slots;
    std::vector<std::uint32_t> m_free;
    std::size_t m_size = 0;
    std::uint64_t m_stamp = 0;
    std::uint64_t m_epoch = 0;
    std::unordered_map<std::uint64_t, Cache_entry> m_cache;
    std::unordered_set<std::uint64_t> m_excluded;
    std::vector<std::uint32_t> m_dirty;      // the slots marked dirty, each once
    std::vector<Candidate> m_candidates;     // the last candidate_pairs(), sorted by key
    bool m_candidates_valid = false;
    World_counters m_counters;
};

} // namespace PCCD
