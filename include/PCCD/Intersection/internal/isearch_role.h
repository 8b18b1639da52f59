// PCCD/Intersection/internal/isearch_role.h -- one role of the interpolation search
// (doc/manual/intersection.md, "The leaf intersector policies"; WSCG05 section 4): for a sample p_i of
// the sampled cloud S, the candidate test on f_T, the partners from p_i's annulus (its CPSP list, or a
// radius query for objects without one: isearch_partners.h), the bracket and the interpolation
// search along its path, giving an approximate intersection point (AIP).
// Shared by the flat traversal's random draws and the hierarchy walk (isearch_walk.h); internal to
// Interpolation_search.h, whose public fields (`Policy`) parameterize it.
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

#include <PCCD/Intersection/Intersection_result.h>
#include <PCCD/Intersection/internal/Covering_grid.h>
#include <PCCD/Intersection/internal/isearch_partners.h>
#include <PCCD/Intersection/Query_state.h>
#include <PCCD/Random.h>

namespace PCCD::internal {

inline Intersection_point isearch_aip(const Eigen::Vector3d& world)
{
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    return Intersection_point{world, nan, nan, Intersection_point_kind::approximate};
}

/// The annulus of p's list; when the list ends before the inner radius (sparse or boundary
/// points), its outer half.
template <class Map>
std::pair<std::size_t, std::size_t> annulus_range(const Map& lists, std::uint32_t p, double inner, double outer)
{
    auto [first, last] = lists.annulus(p, inner, outer);
    if (first >= last) {
        const std::size_t size = lists.targets(p).size();
        last = size;
        first = std::max<std::size_t>(1, size / 2);
    }
    return {first, last};
}

/// The prediction of partner choice: f_T at p_j from f_T(p_i) and T's normal there, as a distance on
/// p_i's side of T (negative: across T). pi and pj in T's frame.
inline double predicted_same_side(const Surface_evaluation& ei, const Eigen::Vector3d& pi, const Eigen::Vector3d& pj)
{
    const double sign = ei.value < 0.0 ? -1.0 : 1.0;
    return sign * (ei.value + ei.normal.dot(pj - pi));
}

template <class Policy, class S, class Map>
void choose_partners(const Policy& policy, const Posed_object<S>& sampled, const Rigid_transform_3<double>& s_to_t,
                     const Map& lists, std::uint32_t i, std::size_t first, std::size_t last,
                     const Surface_evaluation& ei, double depth,
                     std::vector<std::pair<double, std::uint32_t>>& ranked, Query_state& state)
{
    ranked.clear();
    const auto targets = lists.targets(i);
    if (policy.partner_choice == std::remove_cvref_t<decltype(policy.partner_choice)>::random) {
        const std::size_t count = std::min(policy.partner_candidates, last - first);
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
    for (std::size_t e = first; e < last; ++e) {
        const double predicted = predicted_same_side(ei, pi, s_to_t.transform_point(sampled.position(targets[e])));
        // Opposite: a key in [-1, 0), -1 at the preferred depth; same sign: the key >= 0.
        const double key = predicted < 0.0 ? -1.0 / (1.0 + std::abs(-predicted - depth) / depth) : predicted;
        ranked.emplace_back(key, std::uint32_t(e));
    }
    const std::size_t count = std::min(policy.partner_candidates, ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(count), ranked.end());
    ranked.resize(count);
    // Keep the predicted crossings only. (Trying the best candidate once when none is predicted
    // across cost an evaluation per sample on every near miss and, at the default sample counts,
    // found no bracket the others did not: the same verdicts and curves on the scan validation;
    // 4 of 1,280 poses with 20 samples per role in object boxes, doc/benchmarks.md "Fig. 7".)
    const auto crossing_end = std::find_if(ranked.begin(), ranked.end(), [](const auto& x) { return x.first >= 0.0; });
    ranked.erase(crossing_end, ranked.end());
}

/// WSCG05 Algorithm 1 on the path, with the bisection fallback and the step bound.
template <class S, class T>
std::optional<Intersection_point> search_path(const Posed_object<S>& sampled,
                                                     const Posed_object<T>& tested,
                                                     const Rigid_transform_3<double>& s_to_t,
                                                     const std::vector<std::uint32_t>& path, double d_first,
                                                     double d_last, double epsilon, Query_state& state)
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
    return isearch_aip(sampled.to_world.transform_point(local));
}

/// One role of the interpolation search (WSCG05 section 4): its state and steps 2 and 3 for one
/// sample. One role's state: the sampled object S, the tested surface f_T, and what a sample needs
/// (annulus, partner buffers, the path source).
template <class Policy, class S, class T, class Paths>
struct Isearch_role {
    const Policy& policy;
    const Posed_object<S>& sampled;
    const Posed_object<T>& tested;
    const Paths& path_source;
    Query_state& state;
    double epsilon;
    Rigid_transform_3<double> s_to_t = tested.from_world * sampled.to_world;
    using Partners = decltype(partner_lists(std::declval<const Posed_object<S>&>()));
    Partners partners = partner_lists(sampled);
    double rho = policy.annulus_outer * partners.bound();
    double inner = rho * (1.0 - policy.annulus_width);
    double noise_band = sampled.noise_estimate();
    double partner_depth = 0.5 * tested.sampling_radius();
    std::size_t taken = 0; // samples of this role
    std::vector<std::uint32_t> path{};
    std::vector<std::pair<double, std::uint32_t>> ranked{};
    /// The walk's covering of this role (Interpolation_search::walk_predicted_cover); none for the
    /// flat traversal's random draws.
    Covering_grid* cover = nullptr;
    /// The walk's region points (hierarchy positions) that the covering skipped, when the walk is to
    /// be completed before a "separate" (Intersection_options::certify_separation); none otherwise.
    std::vector<std::uint32_t>* skipped = nullptr;

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
        state.closest_sample = std::min(state.closest_sample, std::abs(di));
        // With verified contacts, a sample as close to the tested surface as the noise keeps it
        // from its own is a candidate too: coincident surfaces have no sign change to bracket.
        if (std::abs(di) <= epsilon || (state.verifier && std::abs(di) <= epsilon + noise_band)) {
            if (state.offer(isearch_aip(pi_world)) || state.stop() || std::abs(di) <= epsilon) return true;
        }
        if (std::abs(di) > policy.lipschitz_slack * rho) return true;
        ++state.counters.brackets_tried;
        const auto [first, last] = annulus_range(partners, i, inner, rho);
        if (first >= last) return true;
        choose_partners(policy, sampled, s_to_t, partners, i, first, last, ei, partner_depth, ranked, state);
        if (ranked.empty() && cover) cover_predicted(i, first, last, ei);
        for (const auto& [score, entry] : ranked) {
            if (state.out_of_budget()) return false;
            const std::uint32_t j = partners.targets(i)[entry];
            ++state.counters.partner_candidates;
            const Surface_evaluation ej = evaluate_point(j);
            if (!ej.defined()) continue;
            if (std::abs(ej.value) <= epsilon) { // the partner lies on T itself
                state.offer(isearch_aip(sampled.to_world.transform_point(sampled.position(j))));
                break;
            }
            if ((di < 0.0) == (ej.value < 0.0)) continue;
            ++state.counters.brackets_found;
            if (state.visitor)
                state.visitor->bracket(pi_world, sampled.to_world.transform_point(sampled.position(j)));
            if (!path_source.path(i, j, path)) break; // no path within the bound (on the fly)
            if (auto found = search_path(sampled, tested, s_to_t, path, di, ej.value, epsilon, state))
                state.offer(*found, true);
            break;
        }
        return true;
    }

    /// No partner of p_i is predicted across T: its annulus points predicted well on p_i's side
    /// (walk_predicted_cover) join the covering.
    void cover_predicted(std::uint32_t i, std::size_t first, std::size_t last, const Surface_evaluation& ei)
    {
        const double least = policy.walk_predicted_cover * std::abs(ei.value);
        if (!std::isfinite(least)) return;
        const Eigen::Vector3d pi = s_to_t.transform_point(sampled.position(i));
        const auto targets = partners.targets(i);
        for (std::size_t e = first; e < last; ++e) {
            const Eigen::Vector3d local = sampled.position(targets[e]);
            if (predicted_same_side(ei, pi, s_to_t.transform_point(local)) >= least) cover->add(local);
        }
    }
};

} // namespace PCCD::internal
