// PCCD/Intersection/Interpolation_search.h -- the leaf intersector of WSCG05 section 4
// (doc/manual/intersection.md, doc/manual/hierarchy.md): root bracketing with random points of one cloud and partners from
// their CPSP annulus, interpolation search for the sign change of the other surface's f along the
// stored shortest path (bisection fallback), giving approximate intersection points (AIPs).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <PCCD/Error.h>
#include <PCCD/Geodesic/Close_pairs_shortest_paths.h>
#include <PCCD/Geodesic/Paths_on_the_fly.h>
#include <PCCD/Geodesic/Stored_paths.h>
#include <PCCD/Hierarchy/reach_traversal.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/internal/Covering_grid.h>
#include <PCCD/Intersection/internal/Query_state.h>
#include <PCCD/Intersection/internal/overlap_region.h>
#include <PCCD/Intersection/internal/reach_region.h>
#include <PCCD/Random.h>
#include <PCCD/concepts/PathSource.h>

namespace PCCD {

/// How the partners of a root-bracketing sample are chosen in its CPSP annulus.
enum class Partner_choice : std::uint8_t {
    /// Candidates ranked by the first-order prediction f(p_i) + n(p_i) . (p_j - p_i) of the other
    /// surface's f (the normal comes with the evaluation at p_i): opposite-signed ones first, those
    /// predicted half a sampling radius of the other surface across it first (deep enough to be
    /// across despite the prediction's error, shallow enough to stay inside the other surface's
    /// domain). Measured to find a bracket with fewer evaluations than random draws and than the
    /// most strongly opposite first (doc/benchmarks.md).
    predicted = 0,
    /// Random candidates from the annulus, as in WSCG05.
    random = 1,
};

/// Where the interpolation search reads the shortest path of a bracket from: one of the two models
/// of PathSource.
enum class Path_choice : std::uint8_t {
    /// The paths stored in the sampled object's CPSP map (Stored_paths): O(list + path length) per
    /// bracket.
    stored = 0,
    /// Computed per bracket by an A* search over the sampled object's proximity graph, bounded at
    /// its CPSP bound (Paths_on_the_fly, WSCG05 Algorithm 2 in PCCD's form): paths of the same length,
    /// nothing read from the map's path storage; slower (a search of the points within the bound).
    on_the_fly = 1,
};

/// Leaf intersector policy: stochastic root bracketing and interpolation search (WSCG05 section 4).
///
/// For one role (sampled cloud S, tested surface f_T, the other object), with Ŝ the points of S in
/// the overlap region:
/// 1. n = a ln a + c a random points of Ŝ without replacement, at least min_samples, at most |Ŝ|
///    and, for first-hit queries, at most max_samples,
///    where a = |Ŝ| (r(S) / r_s)^2 is the number of conceptual surfels of radius r_s = rho / 2 in the
///    region and rho the outer annulus radius (annulus_outer times S's CPSP bound).
/// 2. A sample with |f_T(p_i)| <= epsilon is a candidate contact; with verified contacts
///    (Intersection_options::verify_contacts) so is one with |f_T(p_i)| <= epsilon + sigma_S, sigma_S
///    the sampled cloud's noise estimate, which the verification then accepts or rejects (this is
///    what finds coincident surfaces, which have no sign change). For a sample p_i with f_T(p_i)
///    defined and |f_T(p_i)| <= lipschitz_slack rho (otherwise no sign
///    change is reachable within rho), up to `partner_candidates` partners p_j from the annulus
///    rho (1 - annulus_width) < g(p_i, p_j) <= rho of p_i's CPSP list; the first with
///    f_T(p_i) f_T(p_j) < 0 makes a bracket.
/// 3. Interpolation search along the stored shortest path p_i = P_0 ... P_m = p_j (WSCG05 Algorithm
///    1): x = l + ceil((r - l) d_l / (d_l - d_r)), clamped inside (l, r); a step that does not halve
///    the interval makes the next step a bisection, so at most 2 ceil(log2 m) + 2 steps are taken.
///    It ends at a path point with |f_T| <= epsilon or at two adjacent points straddling T; the AIP
///    interpolates linearly between them.
///
/// All fields have defaults; use designated initializers. Immutable; thread-safe.
struct Interpolation_search {
    /// n_min: the least number of samples per role (WSCG05: 200 suffice for <= 1 % error).
    std::size_t min_samples = 200;
    /// The most samples per role of the covering formula (>= min_samples), for do_intersect() only:
    /// intersection_points() takes the full covering count, to cover the curves. With CPSP lists bounded
    /// at the kernel support (3 r by default), surfels reachable by the annulus hold only a few
    /// points, so a ln a + c a exceeds the region and the formula alone means visiting every region
    /// point, which makes near misses slow. Default 400: WSCG05 Fig. 7 as measured here
    /// (doc/benchmarks.md) shows no error for n >= 100 per role.
    std::size_t max_samples = 400;
    /// When set: exactly this many samples per role (at most the region's size), instead of the
    /// covering formula; WSCG05 Fig. 7 sweeps it (n = 20 ... 200). Must be >= 1 when set.
    std::optional<std::size_t> samples = std::nullopt;
    /// c of the surfel covering: each surfel is hit with probability exp(-exp(-c)) (3.5: > 97 %).
    double coverage_c = 3.5;
    /// Outer annulus radius rho as a fraction of the sampled cloud's CPSP bound, in (0, 1].
    double annulus_outer = 1.0;
    /// Annulus width as a fraction of rho, in (0, 1].
    double annulus_width = 0.5;
    /// b: partner candidates evaluated per bracketing sample (>= 1).
    std::size_t partner_candidates = 4;
    Partner_choice partner_choice = Partner_choice::predicted;
    /// Where the path of a bracket comes from (default: the stored CPSP paths).
    Path_choice paths = Path_choice::stored;
    /// Walked first-hit queries (Traversal::depth_first, likelihood): a region point within this
    /// fraction of rho of a sample already taken is covered and not sampled (a deterministic surfel
    /// covering, radius r_s = walk_cover rho, in place of the random draws whose count a ln a + c a
    /// is needed to hit every surfel by chance). In (0, 1]. Default 0.5: the surfel radius of the
    /// covering formula.
    double walk_cover = 0.5;
    /// Walked first-hit queries: random points of each object tested for being within the other's
    /// reach (and sampled if so) before the walk starts; they find a contact of a deep overlap
    /// sooner than the walk. Default 8; 0 walks at once.
    std::size_t probe_draws = 8;
    /// Slack of the reachability test |f_T(p_i)| <= slack rho (>= 1; f is about a distance, so 1
    /// would be exact for a true distance function).
    double lipschitz_slack = 1.5;

    /// "isearch".
    static constexpr const char* name() { return "isearch"; }

    /// \throws Invalid_input naming the first invalid field.
    void check() const
    {
        if (min_samples == 0) throw Invalid_input("interpolation search: min_samples must be >= 1");
        if (samples && *samples == 0) throw Invalid_input("interpolation search: samples must be >= 1 when set");
        if (max_samples < min_samples)
            throw Invalid_input(internal::concat("interpolation search: max_samples ", max_samples,
                                                 " must be >= min_samples ", min_samples));
        if (!(std::isfinite(coverage_c) && coverage_c >= 0.0))
            throw Invalid_input(internal::concat("interpolation search: coverage_c ", coverage_c, " must be finite and >= 0"));
        // Quiet comparisons: a NaN field must reach the message, not trap (Debug FP traps).
        if (!(std::isgreater(annulus_outer, 0.0) && std::islessequal(annulus_outer, 1.0)))
            throw Invalid_input(internal::concat("interpolation search: annulus_outer ", annulus_outer, " must be in (0, 1]"));
        if (!(std::isgreater(annulus_width, 0.0) && std::islessequal(annulus_width, 1.0)))
            throw Invalid_input(internal::concat("interpolation search: annulus_width ", annulus_width, " must be in (0, 1]"));
        if (partner_candidates == 0) throw Invalid_input("interpolation search: partner_candidates must be >= 1");
        if (!(std::isgreater(walk_cover, 0.0) && std::islessequal(walk_cover, 1.0)))
            throw Invalid_input(internal::concat("interpolation search: walk_cover ", walk_cover, " must be in (0, 1]"));
        if (!(std::isfinite(lipschitz_slack) && lipschitz_slack >= 1.0))
            throw Invalid_input(internal::concat("interpolation search: lipschitz_slack ", lipschitz_slack, " must be finite and >= 1"));
        if (partner_choice != Partner_choice::predicted && partner_choice != Partner_choice::random)
            throw Invalid_input("interpolation search: unknown partner_choice");
        if (paths != Path_choice::stored && paths != Path_choice::on_the_fly)
            throw Invalid_input("interpolation search: unknown paths choice");
    }

    /// The automatic epsilon: 0.05 times the smaller sampling radius.
    double default_epsilon(double smaller_sampling_radius) const { return 0.05 * smaller_sampling_radius; }

    /// The query: the candidate points of both objects (points of A in B's region boxes grown by
    /// B's kernel support, and vice versa), then one role per object, the smaller object's points
    /// sampled first (the second role only with options.symmetric, and in first-hit mode only if
    /// the first found nothing). `closest` is not estimated by this policy (set to NaN).
    template <class A, class B>
    void run(const internal::Posed_object<A>& a, const internal::Posed_object<B>& b, const Intersection_options& options,
             double epsilon, internal::Query_state& state, double& closest) const
    {
        closest = std::numeric_limits<double>::quiet_NaN();
        if (options.traversal != Traversal::flat && state.sink.first_hit() && a.object->hierarchy().has_reach() &&
            b.object->hierarchy().has_reach()) {
            run_traversal(a, b, options, epsilon, state);
            return;
        }
        // The smaller object's points are sampled first; the second role runs only if needed.
        if (a.size() <= b.size()) {
            run_role(a, b, options, epsilon, state);
            if (options.symmetric && !state.stop()) run_role(b, a, options, epsilon, state);
        } else {
            run_role(b, a, options, epsilon, state);
            if (options.symmetric && !state.stop()) run_role(a, b, options, epsilon, state);
        }
    }

    /// The number of samples for a region of `region_points` points of a cloud with sampling radius
    /// r and outer annulus radius rho; `capped`: at most max_samples (first-hit queries).
    std::size_t sample_count(std::size_t region_points, double r, double rho, bool capped = true) const
    {
        if (region_points == 0) return 0;
        if (samples) return std::min(*samples, region_points);
        const double rs = 0.5 * rho;
        const double a = std::max(1.0, double(region_points) * (r / rs) * (r / rs));
        double wanted = std::max(double(min_samples), a * std::log(a) + coverage_c * a);
        if (capped) wanted = std::min(wanted, double(max_samples));
        return wanted >= double(region_points) ? region_points : std::size_t(std::ceil(wanted));
    }

    /// One role: the points of `sampled` in the region (flat traversal: those within `tested`'s leaf
    /// boxes grown by its kernel support; otherwise those within the reach of `tested`'s points,
    /// where f_T can be defined) are tested against the surface of `tested`. AIPs go to state.sink
    /// (world coordinates); returns when the sink is done, the budget is spent or the samples are
    /// exhausted. \pre epsilon > 0
    template <class S, class T>
    void run_role(const internal::Posed_object<S>& sampled, const internal::Posed_object<T>& tested,
                  const Intersection_options& options, double epsilon, internal::Query_state& state) const
    {
        const Rigid_transform_3<double> s_to_t = tested.from_world * sampled.to_world;
        const Point_cloud_hierarchy& hs = sampled.object->hierarchy();
        const Point_cloud_hierarchy& ht = tested.object->hierarchy();
        if (options.traversal == Traversal::flat || !hs.has_reach() || !ht.has_reach()) {
            const auto position = [&sampled](std::uint32_t i) { return sampled.position(i); };
            internal::Region_sampler<decltype(position)> sampler(hs, ht, s_to_t, tested.support_radius(), options.region,
                                                                 position, state.counters);
            run_role_paths(sampled, tested, sampler, epsilon, state);
        } else {
            internal::Reach_region_sampler sampler(hs, ht, s_to_t, Reach_rule{.scale = 1.0, .cap = tested.support_radius()},
                                                   state.counters);
            run_role_paths(sampled, tested, sampler, epsilon, state);
        }
    }

private:
    /// First-hit queries under the depth_first and likelihood traversals: the two hierarchies are
    /// walked together (for_each_leaf_pair_within_reach) and, at each leaf pair, the points of
    /// either leaf within the reach of the other leaf's points are sampled at once in both roles
    /// (each point once per role; per role at most `samples` or max_samples). The walk stops at the
    /// first verified contact, when the budget is spent, or when both roles have their samples.
    template <class A, class B>
    void run_traversal(const internal::Posed_object<A>& a, const internal::Posed_object<B>& b,
                       const Intersection_options& options, double epsilon, internal::Query_state& state) const
    {
        using Index = Point_cloud_hierarchy::Index;
        const bool use_a = options.symmetric || a.size() <= b.size();
        const bool use_b = options.symmetric || a.size() > b.size();
        // The covering bounds the samples; max_samples (or a fixed count) still caps them.
        const std::size_t cap = samples ? *samples : max_samples;
        constexpr double tiny = 1e-300; // a covering radius must be > 0 for the grid
        const Point_cloud_hierarchy& ha = a.object->hierarchy();
        const Point_cloud_hierarchy& hb = b.object->hierarchy();
        const Reach_rule rule_a{.scale = 1.0, .cap = a.support_radius()};
        const Reach_rule rule_b{.scale = 1.0, .cap = b.support_radius()};
        with_paths(a, [&](const auto& source_a) {
            with_paths(b, [&](const auto& source_b) {
                Role<A, B, std::remove_cvref_t<decltype(source_a)>> role_a{*this, a, b, source_a, state, epsilon};
                Role<B, A, std::remove_cvref_t<decltype(source_b)>> role_b{*this, b, a, source_b, state, epsilon};
                std::unordered_set<std::uint32_t> done_a, done_b;
                internal::Covering_grid cover_a(std::max(walk_cover * role_a.rho, tiny));
                internal::Covering_grid cover_b(std::max(walk_cover * role_b.rho, tiny));
                const auto active = [&] { return (use_a && role_a.taken < cap) || (use_b && role_b.taken < cap); };
                // A deep overlap has contacts all over: a few random points within reach find one
                // sooner than the walk, which goes to the leaves first.
                for (std::size_t k = 0; k < probe_draws && !state.stop(); ++k) {
                    if (use_a && !probe(ha, hb, rule_b, cap, done_a, cover_a, role_a)) return;
                    if (use_b && !state.stop() && !probe(hb, ha, rule_a, cap, done_b, cover_b, role_b)) return;
                }
                if (state.stop()) return;
                const Reach_counters c = for_each_leaf_pair_within_reach(
                    ha, hb, role_a.s_to_t, rule_a, rule_b,
                    [&](Index la, Index lb) {
                        if (state.out_of_budget()) return false;
                        if (use_a && !sample_leaf(ha, la, hb, lb, rule_b, cap, done_a, cover_a, role_a)) return false;
                        if (use_b && !sample_leaf(hb, lb, ha, la, rule_a, cap, done_b, cover_b, role_b)) return false;
                        return active();
                    },
                    options.traversal == Traversal::likelihood, true);
                state.counters.node_pairs += c.node_pairs;
                state.counters.leaf_pairs += c.leaf_pairs;
            });
        });
    }

    /// One random point of s (uniform, with replacement): sampled in `role` when it lies within the
    /// reach of t and is neither sampled nor covered yet. Returns false when the query must stop.
    template <class Role_type>
    static bool probe(const Point_cloud_hierarchy& s, const Point_cloud_hierarchy& t, const Reach_rule& rule_t,
                      std::size_t cap, std::unordered_set<std::uint32_t>& done, internal::Covering_grid& cover,
                      Role_type& role)
    {
        if (role.taken >= cap || s.empty()) return true;
        const auto k = Eigen::Index(uniform_index(role.state.engine, s.size()));
        const Eigen::Vector3d local = s.ordered_points().col(k).head<3>();
        if (!within_reach(t, role.s_to_t.transform_point(local), rule_t)) return true;
        const std::uint32_t index = s.order()[std::size_t(k)];
        if (cover.covers(local) || !done.insert(index).second) return true;
        cover.add(local);
        ++role.state.counters.candidate_points;
        return role.sample(index) && !role.state.stop();
    }

    /// Samples, in `role`, the points of leaf `ls` of s within the reach of leaf `lt` of t that the
    /// role has not sampled yet, up to `cap` samples. Returns false when the query must stop.
    template <class Role_type>
    static bool sample_leaf(const Point_cloud_hierarchy& s, Point_cloud_hierarchy::Index ls,
                            const Point_cloud_hierarchy& t, Point_cloud_hierarchy::Index lt, const Reach_rule& rule_t,
                            std::size_t cap, std::unordered_set<std::uint32_t>& done, internal::Covering_grid& cover,
                            Role_type& role)
    {
        const auto& ns = s.node(ls);
        const auto& nt = t.node(lt);
        const Eigen::Matrix4Xd& ps = s.ordered_points();
        const Eigen::Matrix4Xd& pt = t.ordered_points();
        for (auto k = ns.first; k < ns.first + ns.count; ++k) {
            if (role.taken >= cap) return true;
            const Eigen::Vector3d q = role.s_to_t.transform_point(Eigen::Vector3d(ps.col(k).head<3>()));
            bool inside = false;
            for (auto m = nt.first; m < nt.first + nt.count && !inside; ++m) {
                const double reach = rule_t(pt(3, m));
                inside = (pt.col(m).head<3>() - q).squaredNorm() <= reach * reach;
            }
            if (!inside || !done.insert(s.order()[k]).second) continue;
            ++role.state.counters.candidate_points;
            const Eigen::Vector3d local = ps.col(k).head<3>();
            if (cover.covers(local)) continue;
            cover.add(local);
            if (!role.sample(s.order()[k]) || role.state.stop()) return false;
        }
        return true;
    }

    /// run_role() with its region sampler: the paths of brackets from the stored map or on the fly.
    template <class S, class T, class Sampler>
    void run_role_paths(const internal::Posed_object<S>& sampled, const internal::Posed_object<T>& tested,
                        Sampler& sampler, double epsilon, internal::Query_state& state) const
    {
        with_paths(sampled, [&](const auto& source) { run_role_with(sampled, tested, sampler, epsilon, state, source); });
    }

    /// One role's state: the sampled object S, the tested surface f_T, and what a sample needs
    /// (annulus, partner buffers, the path source).
    template <class S, class T, class Paths>
    struct Role {
        const Interpolation_search& policy;
        const internal::Posed_object<S>& sampled;
        const internal::Posed_object<T>& tested;
        const Paths& path_source;
        internal::Query_state& state;
        double epsilon;
        Rigid_transform_3<double> s_to_t = tested.from_world * sampled.to_world;
        const Close_pairs_shortest_paths& cpsp = sampled.object->cpsp();
        double rho = policy.annulus_outer * cpsp.bound();
        double inner = rho * (1.0 - policy.annulus_width);
        double noise_band = sampled.noise_estimate();
        double partner_depth = 0.5 * tested.sampling_radius();
        std::size_t taken = 0; // samples of this role
        std::vector<std::uint32_t> path{};
        std::vector<std::pair<double, std::uint32_t>> ranked{};

        Surface_evaluation evaluate_point(std::uint32_t i)
        {
            return state.evaluate_local(tested, s_to_t.transform_point(sampled.position(i)));
        }

        /// Steps 2 and 3 for the sample p_i: a candidate contact, or a bracket and its search.
        /// Returns false when the query must stop (budget spent).
        bool sample(std::uint32_t i)
        {
            ++taken;
            ++state.counters.samples;
            const Eigen::Vector3d pi_world = sampled.to_world.transform_point(sampled.position(i));
            // intersection_points(): a sample next to a point already found adds nothing.
            if (state.sink.near(pi_world, state.sink.spacing())) return true;
            const Surface_evaluation ei = evaluate_point(i);
            if (!ei.defined()) return true;
            const double di = ei.value;
            // With verified contacts, a sample as close to the tested surface as the noise keeps it
            // from its own is a candidate too: coincident surfaces have no sign change to bracket.
            if (std::abs(di) <= epsilon || (state.verifier && std::abs(di) <= epsilon + noise_band)) {
                if (state.offer(aip(pi_world)) || state.stop() || std::abs(di) <= epsilon) return true;
            }
            if (std::abs(di) > policy.lipschitz_slack * rho) return true;
            ++state.counters.brackets_tried;
            const auto [first, last] = annulus_range(cpsp, i, inner, rho);
            if (first >= last) return true;
            policy.choose_partners(sampled, s_to_t, cpsp, i, first, last, ei, partner_depth, ranked, state);
            for (const auto& [score, entry] : ranked) {
                if (state.out_of_budget()) return false;
                const std::uint32_t j = cpsp.targets(i)[entry];
                ++state.counters.partner_candidates;
                const Surface_evaluation ej = evaluate_point(j);
                if (!ej.defined()) continue;
                if (std::abs(ej.value) <= epsilon) { // the partner lies on T itself
                    state.offer(aip(sampled.to_world.transform_point(sampled.position(j))));
                    break;
                }
                if ((di < 0.0) == (ej.value < 0.0)) continue;
                ++state.counters.brackets_found;
                if (!path_source.path(i, j, path)) break; // no path within the bound (on the fly)
                if (auto found = search_path(sampled, tested, s_to_t, path, di, ej.value, epsilon, state))
                    state.offer(*found);
                break;
            }
            return true;
        }
    };

    /// Calls `body(path_source)` with the path source of `sampled` that `paths` selects.
    template <class S, class Body>
    void with_paths(const internal::Posed_object<S>& sampled, const Body& body) const
    {
        const Close_pairs_shortest_paths& cpsp = sampled.object->cpsp();
        if (paths == Path_choice::stored) {
            body(Stored_paths(cpsp));
        } else {
            // The map's distances are floats: a bound a little above it keeps its farthest targets.
            const Proximity_graph& graph = sampled.object->graph();
            const auto& coordinates = sampled.object->cloud().coordinates();
            using FT = typename std::remove_cvref_t<decltype(coordinates)>::Scalar;
            body(Paths_on_the_fly<Proximity_graph::Graph, Proximity_graph::Length_map, Proximity_graph::Virtual_map, FT>(
                graph.graph(), graph.length_map(), coordinates, {.bound = double(cpsp.bound()) * (1.0 + 1e-6)},
                graph.virtual_map()));
        }
    }

    /// run_role() with the paths of brackets read from `path_source`.
    template <class S, class T, class Sampler, PathSource Paths>
    void run_role_with(const internal::Posed_object<S>& sampled, const internal::Posed_object<T>& tested,
                       Sampler& region_sampler, double epsilon, internal::Query_state& state,
                       const Paths& path_source) const
    {
        Role<S, T, Paths> role{*this, sampled, tested, path_source, state, epsilon};
        const double r = sampled.sampling_radius();
        std::uint32_t i = 0;
        while (!state.stop()) {
            // n = a ln a + c a samples of the region (an estimate until the region size is known).
            const std::size_t drawn = region_sampler.accepted();
            // The caps hold from the first draw (the region-size estimate below waits for 64 draws):
            // a fixed count, or max_samples for first-hit queries.
            if (samples && drawn >= *samples) return;
            if (!samples && state.sink.first_hit() && drawn >= max_samples) return;
            if (drawn >= 64 || region_sampler.region_size_known()) {
                const std::size_t size = std::size_t(std::ceil(region_sampler.region_size()));
                if (drawn >= sample_count(size, r, role.rho, state.sink.first_hit())) return;
            }
            if (!region_sampler.next(state.engine, i)) return;
            if (!role.sample(i)) return;
        }
    }

    static Intersection_point aip(const Eigen::Vector3d& world)
    {
        constexpr double nan = std::numeric_limits<double>::quiet_NaN();
        return Intersection_point{world, nan, nan, Intersection_point_kind::approximate};
    }

    /// The annulus of p's list; when the list ends before the inner radius (sparse or boundary
    /// points), its outer half.
    template <class Map>
    static std::pair<std::size_t, std::size_t> annulus_range(const Map& cpsp, std::uint32_t p, double inner, double outer)
    {
        auto [first, last] = cpsp.annulus(p, inner, outer);
        if (first >= last) {
            const std::size_t size = cpsp.targets(p).size();
            last = size;
            first = std::max<std::size_t>(1, size / 2);
        }
        return {first, last};
    }

    template <class S, class Map>
    void choose_partners(const internal::Posed_object<S>& sampled, const Rigid_transform_3<double>& s_to_t,
                         const Map& cpsp, std::uint32_t i, std::size_t first, std::size_t last,
                         const Surface_evaluation& ei, double depth,
                         std::vector<std::pair<double, std::uint32_t>>& ranked, internal::Query_state& state) const
    {
        ranked.clear();
        const auto targets = cpsp.targets(i);
        if (partner_choice == Partner_choice::random) {
            const std::size_t count = std::min(partner_candidates, last - first);
            std::vector<std::uint32_t> entries(last - first);
            for (std::size_t e = first; e < last; ++e) entries[e - first] = std::uint32_t(e);
            for (std::size_t k = 0; k < count; ++k) {
                const std::size_t pick = k + std::size_t(uniform_index(state.engine, entries.size() - k));
                std::swap(entries[k], entries[pick]);
                ranked.emplace_back(0.0, entries[k]);
            }
            return;
        }
        // Predicted f_T at p_j: f_T(p_i) + n_T(p_i) . (p_j - p_i), all in T's frame. Candidates whose
        // prediction has the opposite sign come first, those predicted `depth` across T first: deep
        // enough to be across it despite the prediction's error, not so deep that T's surface is
        // undefined there (its domain ends about one sampling radius from its points).
        const Eigen::Vector3d pi = s_to_t.transform_point(sampled.position(i));
        const double sign = ei.value < 0.0 ? -1.0 : 1.0;
        for (std::size_t e = first; e < last; ++e) {
            const Eigen::Vector3d pj = s_to_t.transform_point(sampled.position(targets[e]));
            const double predicted = sign * (ei.value + ei.normal.dot(pj - pi));
            // Opposite: a key in [-1, 0), -1 at the preferred depth; same sign: the key >= 0.
            const double key = predicted < 0.0 ? -1.0 / (1.0 + std::abs(-predicted - depth) / depth) : predicted;
            ranked.emplace_back(key, std::uint32_t(e));
        }
        const std::size_t count = std::min(partner_candidates, ranked.size());
        std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(count), ranked.end());
        ranked.resize(count);
        // Keep the predicted crossings; if none is predicted, still try the best candidate once.
        const auto crossing_end = std::find_if(ranked.begin(), ranked.end(), [](const auto& x) { return x.first >= 0.0; });
        ranked.erase(crossing_end == ranked.begin() ? ranked.begin() + 1 : crossing_end, ranked.end());
    }

    /// WSCG05 Algorithm 1 on the path, with the bisection fallback and the step bound.
    template <class S, class T>
    static std::optional<Intersection_point> search_path(const internal::Posed_object<S>& sampled,
                                                         const internal::Posed_object<T>& tested,
                                                         const Rigid_transform_3<double>& s_to_t,
                                                         const std::vector<std::uint32_t>& path, double d_first,
                                                         double d_last, double epsilon, internal::Query_state& state)
    {
        if (path.size() < 2) return std::nullopt;
        std::size_t l = 0, r = path.size() - 1;
        double dl = d_first, dr = d_last;
        std::size_t bound = 2;
        for (std::size_t m = r; m > 1; m = (m + 1) / 2) bound += 2;
        bool bisect = false;
        for (std::size_t step = 0; l + 1 < r && std::abs(dl) > epsilon && std::abs(dr) > epsilon; ++step) {
            if (step >= bound || state.out_of_budget()) break;
            std::size_t x;
            if (bisect) {
                x = l + (r - l) / 2;
                ++state.counters.bisection_steps;
            } else {
                const double t = dl / (dl - dr); // in (0, 1): dl and dr have opposite signs
                x = l + std::size_t(std::ceil(double(r - l) * t));
            }
            x = std::clamp(x, l + 1, r - 1);
            ++state.counters.search_steps;
            const Surface_evaluation ex =
                state.evaluate_local(tested, s_to_t.transform_point(sampled.position(path[x])));
            if (!ex.defined()) {
                if (bisect) return std::nullopt; // the path leaves the other surface's support
                bisect = true;
                continue;
            }
            const std::size_t before = r - l;
            if ((ex.value < 0.0) == (dl < 0.0) && ex.value != 0.0) {
                l = x;
                dl = ex.value;
            } else {
                r = x;
                dr = ex.value;
            }
            bisect = 2 * (r - l) > before;
        }
        Eigen::Vector3d local;
        if (std::abs(dl) <= epsilon) {
            local = sampled.position(path[l]);
        } else if (std::abs(dr) <= epsilon) {
            local = sampled.position(path[r]);
        } else {
            const double wl = std::abs(dr) / (std::abs(dl) + std::abs(dr));
            local = wl * sampled.position(path[l]) + (1.0 - wl) * sampled.position(path[r]);
        }
        return aip(sampled.to_world.transform_point(local));
    }
};

} // namespace PCCD
