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
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Intersection/internal/overlap_region.h>
#include <PCCD/Intersection/internal/isearch_role.h>
#include <PCCD/Intersection/internal/isearch_walk.h>
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
    /// domain); only candidates predicted across are tried. Measured to find a bracket with fewer
    /// evaluations than random draws and than the most strongly opposite first (doc/benchmarks.md).
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
    /// Walked first-hit queries: when a sample p_i has no annulus partner predicted across T (the
    /// prediction of partner_choice `predicted`: f_T(p_i) + n_T(p_i) . (p_j - p_i)), the annulus points
    /// predicted at least this fraction of |f_T(p_i)| on p_i's side of T are covered too, as if
    /// sampled: the prediction that ruled them out as partners says their own annuli start on the
    /// same side. >= 0 (smaller covers more); +infinity switches it off. Default 0.5: at 10^6
    /// points, near contacts take a quarter of the samples (doc/benchmarks.md "Scale: 10^6 points").
    double walk_predicted_cover = 0.5;
    /// Walked first-hit queries: probes per object before the walk starts. A probe starts at a random
    /// point and takes up to probe_steps alternating nearest-point steps between the two clouds,
    /// which lead to where they come closest (where they cross, in a deep overlap); the first point
    /// found within the other's reach is sampled. They find a contact of a deep overlap sooner than
    /// the walk, all the more in dense clouds, where the reach is short. Default 2; 0 walks at once.
    std::size_t probe_draws = 2;
    /// Alternating nearest-point steps per probe (default 4; 0: the random point only). Measured
    /// (doc/benchmarks.md "Point cloud hierarchy"): 2 probes of 4 steps beat 8 random points by
    /// 10-40 % at 3·10^4 points and 3x at 10^6.
    std::size_t probe_steps = 4;
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
        if (!std::isgreaterequal(walk_predicted_cover, 0.0)) // NaN fails too, without trapping
            throw Invalid_input(internal::concat("interpolation search: walk_predicted_cover ", walk_predicted_cover,
                                                 " must be >= 0 (+infinity: off)"));
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
    /// the first found nothing). `closest`: the smallest |f_T(p)| over the samples p (points of one
    /// cloud) where the other surface's f_T was defined, +infinity when there was none: how near
    /// the other surface passes to the points sampled (at a cloud point p, f_S(p) is about 0, so
    /// this estimates max(|f_A|, |f_B|) there). An undecided answer reports what it saw so far.
    template <class A, class B>
    void run(const Posed_object<A>& a, const Posed_object<B>& b, const Intersection_options& options,
             double epsilon, Query_state& state, double& closest) const
    {
        if (options.traversal != Traversal::flat && state.first_hit_search() && a.object->hierarchy().has_reach() &&
            b.object->hierarchy().has_reach()) {
            const bool certify = options.verify_contacts && options.certify_separation;
            state.region_searched = internal::walk_first_hit(*this, a, b, options, epsilon, state, certify);
        } else {
            run_roles(a, b, options, epsilon, state);
        }
        closest = state.closest_sample;
    }

    /// Both roles of the flat traversal and of intersection_points(): the smaller object's points
    /// first, the other's with options.symmetric (in first-hit mode only if the first found
    /// nothing). Also the complete search that certifies a "separate"
    /// (Intersection_options::certify_separation).
    template <class A, class B>
    void run_roles(const Posed_object<A>& a, const Posed_object<B>& b,
                   const Intersection_options& options, double epsilon, Query_state& state) const
    {
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
    void run_role(const Posed_object<S>& sampled, const Posed_object<T>& tested,
                  const Intersection_options& options, double epsilon, Query_state& state) const
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
                                                   state.counters,
                                                   internal::Visitor_pairs{state.visitor, &sampled != state.posed_a});
            run_role_paths(sampled, tested, sampler, epsilon, state);
        }
    }

private:
    /// run_role() with its region sampler: the paths of brackets from the stored map or on the fly.
    template <class S, class T, class Sampler>
    void run_role_paths(const Posed_object<S>& sampled, const Posed_object<T>& tested,
                        Sampler& sampler, double epsilon, Query_state& state) const
    {
        internal::with_path_source(*this, sampled,
                                   [&](const auto& source) { run_role_with(sampled, tested, sampler, epsilon, state, source); });
    }

    /// run_role() with the paths of brackets read from `path_source`.
    template <class S, class T, class Sampler, PathSource Paths>
    void run_role_with(const Posed_object<S>& sampled, const Posed_object<T>& tested,
                       Sampler& region_sampler, double epsilon, Query_state& state,
                       const Paths& path_source) const
    {
        internal::Isearch_role<Interpolation_search, S, T, Paths> role{*this, sampled, tested, path_source, state, epsilon};
        const double r = sampled.sampling_radius();
        std::uint32_t i = 0;
        while (!state.stop()) {
            // n = a ln a + c a samples of the region (an estimate until the region size is known).
            const std::size_t drawn = region_sampler.accepted();
            // The caps hold from the first draw (the region-size estimate below waits for 64 draws):
            // a fixed count, or max_samples for first-hit queries.
            if (samples && drawn >= *samples) return;
            if (!samples && state.first_hit_search() && drawn >= max_samples) return;
            if (drawn >= 64 || region_sampler.region_size_known()) {
                const std::size_t size = std::size_t(std::ceil(region_sampler.region_size()));
                if (drawn >= sample_count(size, r, role.rho, state.first_hit_search())) return;
            }
            if (!region_sampler.next(state.engine, i)) return;
            if (!role.sample(i)) return;
        }
    }

};

} // namespace PCCD
