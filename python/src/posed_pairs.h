// python/src/posed_pairs.h -- the `pairs` argument of the batch functions (do_intersect_many,
// intersection_points_many, distance_many): an iterable of (object_a, pose_a, object_b, pose_b)
// tuples, each object a pccd.Object or a pccd.LeanObject, read into PCCD's Posed_pair lists and run
// as batches of equal kinds (doc/manual/python.md, "Many pairs at once").
#pragma once

#include "pccd_python.h"

#include <PCCD/Intersection/do_intersect_many.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace pccd_python {

/// One pair of a batch call, either object a pccd.Object or a pccd.LeanObject.
struct Any_posed_pair {
    Any_object a;
    PCCD::Rigid_transform_3<double> pose_a;
    Any_object b;
    PCCD::Rigid_transform_3<double> pose_b;
};

/// The pairs of a batch call, and the Python objects that must stay alive while the GIL is
/// released (the pairs point into them).
struct Posed_pairs {
    std::vector<Any_posed_pair> pairs;
    std::vector<py::object> keep;
};

/// Reads `pairs`. Raises ValueError for an item that is not a 4-sequence or has a bad pose (naming
/// the pair), TypeError when items 0 and 2 are not pccd.Object or pccd.LeanObject instances.
Posed_pairs posed_pairs(const py::iterable& pairs);

namespace detail {

template <class A, class B, class Result, class Run>
void run_kinds(const Posed_pairs& posed, std::size_t begin, std::size_t end, std::uint64_t first_index, Run& run,
               std::vector<Result>& out)
{
    std::vector<PCCD::Posed_pair<A, B>> list;
    list.reserve(end - begin);
    for (std::size_t i = begin; i < end; ++i) {
        const Any_posed_pair& p = posed.pairs[i];
        list.push_back({static_cast<const A*>(p.a.object), p.pose_a, static_cast<const B*>(p.b.object), p.pose_b});
    }
    std::vector<Result> results = run(std::span<const PCCD::Posed_pair<A, B>>(list), first_index + begin);
    for (Result& r : results) out.push_back(std::move(r));
}

} // namespace detail

/// Answers the pairs as `run(std::span<const PCCD::Posed_pair<A, B>> pairs, std::uint64_t
/// first_index)` answers a batch of one kind (a library *_many call), once per maximal run of
/// consecutive pairs of the same kinds, with the first index of that run in the whole call: pair i
/// is seeded by pair_seed(seed, first_index + i) as in one batch, so the answers are the same
/// whatever the mix. (A list alternating kinds runs in many short batches: correct, less parallel.)
template <class Result, class Run>
std::vector<Result> run_posed_pairs(const Posed_pairs& posed, std::uint64_t first_index, Run&& run)
{
    std::vector<Result> out;
    out.reserve(posed.pairs.size());
    for (std::size_t begin = 0; begin < posed.pairs.size();) {
        const Any_posed_pair& first = posed.pairs[begin];
        std::size_t end = begin + 1;
        while (end < posed.pairs.size() && posed.pairs[end].a.lean == first.a.lean && posed.pairs[end].b.lean == first.b.lean)
            ++end;
        visit_objects(first.a, first.b, [&](const auto& a, const auto& b) {
            using A = std::remove_cvref_t<decltype(a)>;
            using B = std::remove_cvref_t<decltype(b)>;
            detail::run_kinds<A, B>(posed, begin, end, first_index, run, out);
        });
        begin = end;
    }
    return out;
}

} // namespace pccd_python
