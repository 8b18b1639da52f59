// PCCD/Proximity/distance_many.h -- distance() for a batch of posed pairs, in parallel on TBB when it
// is available, with the results in the order of the pairs and bit for bit those of the sequential
// calls whatever the number of threads (doc/manual/proximity.md "Many pairs"; the batch rules of
// doc/manual/intersection.md "Many pairs at once": pair i is seeded with pair_seed()).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/Proximity/Distance_options.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/concepts/ProximityObject.h>

namespace PCCD {

/// distance() for every pair of `pairs`: result i answers pair i with options' =
/// options except options'.intersection.seed = pair_seed(options.intersection.seed,
/// batch.first_index + i), and is bit for bit that sequential call's result (without a time
/// budget), for any batch.threads and with or without TBB.
/// \throws Invalid_input for invalid options, options.intersection.visitor set, an invalid thread
///         count or a null object (naming the pair), before any query runs; an exception of a
///         pair's query after the others are done (that of the lowest index).
template <ProximityObject A, ProximityObject B>
std::vector<Distance_result> distance_many(std::span<const Posed_pair<A, B>> pairs, const Batch_options& batch = {},
                                           const Distance_options& options = {})
{
    const char* function = "distance_many";
    internal::check_options(options, function);
    if (options.intersection.visitor)
        throw Invalid_input(internal::concat(function, ": options.intersection.visitor is set; the batch runs its queries on "
                                                       "several threads at once, so a visitor is taken by the single queries only"));
    return internal::run_batch<Distance_result>(pairs, batch, function, [&](const Posed_pair<A, B>& p, std::uint64_t index) {
        Distance_options pair_options = options;
        pair_options.intersection.seed = pair_seed(options.intersection.seed, index);
        return internal::run_distance(*p.a, p.pose_a, *p.b, p.pose_b, pair_options, std::nullopt, function);
    });
}

/// The same for a vector of pairs.
template <ProximityObject A, ProximityObject B>
std::vector<Distance_result> distance_many(const std::vector<Posed_pair<A, B>>& pairs, const Batch_options& batch = {},
                                           const Distance_options& options = {})
{
    return distance_many(std::span<const Posed_pair<A, B>>(pairs), batch, options);
}

} // namespace PCCD
