// python/src/queries.cpp -- the intersection queries of pccd: do_intersect, intersection_points and
// their batch forms do_intersect_many / intersection_points_many (PCCD/Intersection/
// do_intersect_many.h), with Intersection_options and the leaf intersector's parameters as keyword
// arguments, and pccd.Result, the answer with its points and counters. Every query runs with the
// GIL released (doc/manual/python.md, "Queries").
#include "pccd_python.h"
#include "posed_pairs.h"

#include <PCCD/Error.h>
#include <PCCD/Intersection/Randomized_sampling.h>
#include <PCCD/Intersection/do_intersect.h>
#include <PCCD/Intersection/do_intersect_many.h>

#include <pybind11/stl.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pccd_python {

namespace {

/// What a query returns to Python: PCCD's result, converted on access; the query's wall time
/// (NaN for the results of a batch, timed as a whole); the counters' dict, built at the first
/// access and the same object afterwards.
struct Result {
    PCCD::Intersection_result r;
    double query_us = std::numeric_limits<double>::quiet_NaN();
    py::object counters = {};
};

/// The options and the leaf intersector of one call.
struct Query_parameters {
    bool rst = false;
    PCCD::Intersection_options options;
    PCCD::Interpolation_search isearch;
    PCCD::Randomized_sampling randomized;
};

/// The keyword arguments of a query, with PCCD's defaults.
struct Query_arguments {
    std::string method = "isearch";
    std::uint64_t seed = PCCD::Intersection_options{}.seed;
    std::optional<double> epsilon;
    std::string region = "leaf_boxes";
    std::string refinement = "projection";
    std::optional<double> point_spacing;
    std::size_t refinement_samples = PCCD::Intersection_options{}.refinement_samples;
    std::optional<std::size_t> max_f_evaluations;
    std::string traversal = "likelihood";
    std::optional<double> max_time_us;
    bool symmetric = true;
    bool verify_contacts = true;
    std::optional<double> contact_tolerance;
    double contact_core = PCCD::Intersection_options{}.contact_core;
    bool certify_separation = true;
    std::optional<std::size_t> samples, min_samples, max_samples;
    std::optional<double> coverage_c;
    std::optional<std::size_t> partner_candidates;
    std::optional<double> epsilon_factor;
    // Batch functions only.
    std::optional<unsigned> threads;
    std::uint64_t first_index = 0;
};

Query_parameters parameters(const Query_arguments& arguments)
{
    const auto& [method, seed, epsilon, region, refinement, point_spacing, refinement_samples, max_f_evaluations,
                 traversal, max_time_us, symmetric, verify_contacts, contact_tolerance, contact_core, certify_separation, samples, min_samples, max_samples,
                 coverage_c, partner_candidates, epsilon_factor, threads, first_index] = arguments;
    Query_parameters q;
    if (method == "rst")
        q.rst = true;
    else if (method != "isearch")
        throw py::value_error("method must be 'isearch' (interpolation search) or 'rst' (randomized sampling), not '" +
                              method + "'");
    PCCD::Intersection_options& o = q.options;
    o.seed = seed;
    o.epsilon = epsilon;
    if (region == "object_boxes")
        o.region = PCCD::Overlap_region::object_boxes;
    else if (region != "leaf_boxes")
        throw py::value_error("region must be 'leaf_boxes' or 'object_boxes', not '" + region + "'");
    if (refinement == "none")
        o.refinement = PCCD::Refinement::none;
    else if (refinement == "sampling")
        o.refinement = PCCD::Refinement::sampling;
    else if (refinement != "projection")
        throw py::value_error("refinement must be 'projection', 'sampling' or 'none', not '" + refinement + "'");
    o.point_spacing = point_spacing;
    o.refinement_samples = refinement_samples;
    o.max_f_evaluations = max_f_evaluations;
    if (traversal == "flat")
        o.traversal = PCCD::Traversal::flat;
    else if (traversal == "depth_first")
        o.traversal = PCCD::Traversal::depth_first;
    else if (traversal == "likelihood")
        o.traversal = PCCD::Traversal::likelihood;
    else
        throw py::value_error("traversal must be 'likelihood', 'depth_first' or 'flat', not '" + traversal + "'");
    // 0 means no budget, as `pccd collide --budget-us 0` does.
    o.max_time_us = max_time_us && *max_time_us == 0.0 ? std::nullopt : max_time_us;
    o.symmetric = symmetric;
    o.verify_contacts = verify_contacts;
    o.contact_tolerance = contact_tolerance;
    o.contact_core = contact_core;
    o.certify_separation = certify_separation;
    const auto isearch_only = [&](bool given, const char* name) {
        if (given && q.rst)
            throw py::value_error(std::string(name) + " is a parameter of method='isearch', not of method='rst'");
    };
    isearch_only(samples.has_value(), "samples");
    isearch_only(min_samples.has_value(), "min_samples");
    isearch_only(partner_candidates.has_value(), "partner_candidates");
    if (epsilon_factor && !q.rst)
        throw py::value_error("epsilon_factor is a parameter of method='rst', not of method='isearch'");
    if (samples) q.isearch.samples = samples;
    if (min_samples) q.isearch.min_samples = *min_samples;
    if (partner_candidates) q.isearch.partner_candidates = *partner_candidates;
    if (max_samples) (q.rst ? q.randomized.max_samples : q.isearch.max_samples) = *max_samples;
    if (coverage_c) (q.rst ? q.randomized.coverage_c : q.isearch.coverage_c) = *coverage_c;
    if (epsilon_factor) q.randomized.epsilon_factor = *epsilon_factor;
    return q;
}

/// The keyword arguments of a call, parsed by hand (only the keys given are looked at: pybind11's
/// per-argument matching of twenty defaults would cost more than a small query). An unknown key
/// raises TypeError, like any Python function.
Query_arguments query_arguments(const py::kwargs& kwargs, bool batch, const char* function)
{
    Query_arguments a;
    for (const auto& [key_object, value] : kwargs) {
        Py_ssize_t size = 0;
        const char* text = PyUnicode_AsUTF8AndSize(key_object.ptr(), &size);
        if (text == nullptr) throw py::error_already_set();
        const std::string_view key(text, std::size_t(size));
        const auto is = [&](std::string_view name) { return key == name; };
        if (is("method")) read_argument(a.method, value, function, key);
        else if (is("seed")) read_argument(a.seed, value, function, key);
        else if (is("epsilon")) read_argument(a.epsilon, value, function, key);
        else if (is("region")) read_argument(a.region, value, function, key);
        else if (is("refinement")) read_argument(a.refinement, value, function, key);
        else if (is("point_spacing")) read_argument(a.point_spacing, value, function, key);
        else if (is("refinement_samples")) read_argument(a.refinement_samples, value, function, key);
        else if (is("max_f_evaluations")) read_argument(a.max_f_evaluations, value, function, key);
        else if (is("traversal")) read_argument(a.traversal, value, function, key);
        else if (is("max_time_us")) read_argument(a.max_time_us, value, function, key);
        else if (is("symmetric")) read_argument(a.symmetric, value, function, key);
        else if (is("verify_contacts")) read_argument(a.verify_contacts, value, function, key);
        else if (is("contact_tolerance")) read_argument(a.contact_tolerance, value, function, key);
        else if (is("contact_core")) read_argument(a.contact_core, value, function, key);
        else if (is("certify_separation")) read_argument(a.certify_separation, value, function, key);
        else if (is("samples")) read_argument(a.samples, value, function, key);
        else if (is("min_samples")) read_argument(a.min_samples, value, function, key);
        else if (is("max_samples")) read_argument(a.max_samples, value, function, key);
        else if (is("coverage_c")) read_argument(a.coverage_c, value, function, key);
        else if (is("partner_candidates")) read_argument(a.partner_candidates, value, function, key);
        else if (is("epsilon_factor")) read_argument(a.epsilon_factor, value, function, key);
        else if (batch && is("threads")) read_argument(a.threads, value, function, key);
        else if (batch && is("first_index")) read_argument(a.first_index, value, function, key);
        else
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + std::string(key) +
                                 "'");
    }
    return a;
}

/// The parameters of a call: the defaults, built once, when no keyword is given.
Query_parameters call_parameters(const py::kwargs& kwargs, const char* function)
{
    static const Query_parameters defaults = parameters(Query_arguments{});
    return kwargs.empty() ? defaults : parameters(query_arguments(kwargs, false, function));
}

/// Calls `f(policy)` with the leaf intersector the parameters name.
template <class F>
auto with_policy(const Query_parameters& q, const F& f)
{
    return q.rst ? f(q.randomized) : f(q.isearch);
}

template <class A, class B>
Result query(const A& a, const py::handle& pose_a, const B& b, const py::handle& pose_b, bool first_hit,
             const Query_parameters& q)
{
    const PCCD::Rigid_transform_3<double> ta = pose_argument(pose_a, "pose_a");
    const PCCD::Rigid_transform_3<double> tb = pose_argument(pose_b, "pose_b");
    PCCD::Intersection_result r;
    double us = 0.0;
    {
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        r = with_policy(q, [&](const auto& policy) {
            return first_hit ? PCCD::do_intersect(a, ta, b, tb, q.options, policy)
                             : PCCD::intersection_points(a, ta, b, tb, q.options, policy);
        });
        us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    }
    return Result{std::move(r), us};
}

std::vector<Result> many(const py::iterable& pairs, std::optional<unsigned> threads, std::uint64_t first_index, bool first_hit,
                         const Query_parameters& q)
{
    const Posed_pairs posed = posed_pairs(pairs);
    std::vector<PCCD::Intersection_result> results;
    {
        py::gil_scoped_release release;
        results = run_posed_pairs<PCCD::Intersection_result>(posed, first_index, [&](auto list, std::uint64_t first) {
            const PCCD::Batch_options batch{.threads = threads, .first_index = first};
            return with_policy(q, [&](const auto& policy) {
                return first_hit ? PCCD::do_intersect_many(list, batch, q.options, policy)
                                 : PCCD::intersection_points_many(list, batch, q.options, policy);
            });
        });
    }
    std::vector<Result> out;
    out.reserve(results.size());
    for (PCCD::Intersection_result& r : results) out.push_back(Result{std::move(r)});
    return out;
}

const char* kind_name(PCCD::Intersection_point_kind kind)
{
    switch (kind) {
    case PCCD::Intersection_point_kind::approximate: return "approximate";
    case PCCD::Intersection_point_kind::refined: return "refined";
    case PCCD::Intersection_point_kind::sampled: return "sampled";
    }
    return "unknown";
}

py::dict counters_dict(const PCCD::Intersection_counters& c)
{
    py::dict d;
    PCCD::for_each_counter(c, [&](const char* name, std::size_t value) { d[name] = value; });
    return d;
}

const std::string query_doc_parameters = R"doc(method : {'isearch', 'rst'}, optional
    The leaf intersector: 'isearch', the interpolation search (default), or 'rst', randomized
    sampling.
seed : int, optional
    Seed of every random choice (default 24301 = 0x5eed). The same seed gives the same answer,
    points and counters, on every platform and for any number of threads.
epsilon : float, optional
    Tolerance on |f| (world units); None (default): automatic, a fraction of the smaller sampling
    radius.
region : {'leaf_boxes', 'object_boxes'}, optional
    Where to look: overlapping hierarchy leaves (default) or the intersection of the two
    objects' boxes.
refinement : {'projection', 'sampling', 'none'}, optional
    Refinement of the points of intersection_points when `verify_contacts` is False (default
    'projection').
point_spacing : float, optional
    Smallest distance between two returned points; None (default): the larger mean spacing of
    the two clouds.
refinement_samples : int, optional
    Samples per point with refinement='sampling' (default 64).
max_f_evaluations : int, optional
    Budget of evaluations of f; None (default): no budget. A query that runs out answers with
    status 'undecided'.
traversal : {'likelihood', 'depth_first', 'flat'}, optional
    How the two objects' hierarchies are walked (default 'likelihood'); 'flat' is the published
    method. See doc/manual/hierarchy.md.
max_time_us : float, optional
    Time budget in microseconds; None (default) or 0: no limit (as ``pccd collide --budget-us
    0``). A query that runs out before finding a contact answers with status 'undecided' (never
    'separate').
symmetric : bool, optional
    Sample both objects (default True) or only the one with fewer candidate points.
verify_contacts : bool, optional
    Accept a candidate only where both surfaces reach a common zero inside their domains
    (default True).
contact_tolerance : float, optional
    Tolerance of that verification; None (default): 0.05 times the smaller sampling radius.
contact_core : float, optional
    Fraction of the domain radii a verified contact must lie within, in (0, 1] (default 0.6).
certify_separation : bool, optional
    Before answering 'separate', search the whole region as intersection_points does and answer
    'intersecting' at a crossing the verification rejected (default True; see the manual, "When
    PCCD says separate").
samples, min_samples, partner_candidates : int, optional
    Interpolation search only: exact sample count per role, least sample count (default 200),
    partner candidates per bracketing sample (default 4).
max_samples : int, optional
    Most samples per role (isearch, default 400) or per query (rst, default 20000).
coverage_c : float, optional
    c of the covering formula (default 3.5).
epsilon_factor : float, optional
    RST only: the automatic epsilon as a fraction of the smaller sampling radius (default 0.35).)doc";

const std::string do_intersect_doc = std::string(R"doc(Whether two posed objects intersect.

The search stops at the first intersection point found (PCCD::do_intersect), which the result
carries.

Parameters
----------
a, b : Object or LeanObject
    The two objects (either kind, in any mix).
pose_a, pose_b : array_like or None
    Rigid motions from each object's frame to the world: a 3x4 array [R | t] or a 4x4
    homogeneous matrix (last row 0 0 0 1); None is the identity. A matrix that scales, shears or
    reflects is rejected.
)doc") + query_doc_parameters + R"doc(

Returns
-------
Result
    ``intersects``, ``status``, ``points`` (at most one), ``counters``.

Raises
------
ValueError
    A pose that is not a 3x4 or 4x4 rigid transform (wrong shape, NaN, scaling, shear,
    reflection) or an invalid option; the message names it.

See Also
--------
intersection_points : points along the intersection curves.
do_intersect_many : many pairs in one call, on several threads.

Notes
-----
The objects are only read and the GIL is released during the query: several Python threads may
query the same objects at once.

Examples
--------
>>> pose_b = np.array([[0., -1., 0., 0.5], [1., 0., 0., 0.], [0., 0., 1., 0.]])
>>> r = pccd.do_intersect(bunny, None, bunny, pose_b, seed=7)
>>> r.intersects, r.status, r.points.shape
(True, 'intersecting', (1, 3))
)doc";

const std::string intersection_points_doc = std::string(R"doc(Points on the intersection curves of two posed objects.

The whole sample the leaf intersector asks for is searched (PCCD::intersection_points); the
points are no two closer than `point_spacing`, in world coordinates.

Parameters
----------
a, b : Object or LeanObject
    The two objects (either kind, in any mix).
pose_a, pose_b : array_like or None
    3x4 or 4x4 rigid transforms (see do_intersect); None is the identity.
)doc") + query_doc_parameters + R"doc(

Returns
-------
Result
    ``points`` holds an (M, 3) array of the points found (M = 0 when the objects are apart).

Raises
------
ValueError
    As do_intersect.

See Also
--------
do_intersect, intersection_points_many

Examples
--------
>>> curve = pccd.intersection_points(bunny, None, bunny, pose_b)
>>> pccd.write_points("curve.ply", curve.points)
)doc";

const std::string many_doc_head = R"doc(

Parameters
----------
pairs : iterable of tuple
    Tuples (object_a, pose_a, object_b, pose_b), poses as in do_intersect (3x4, 4x4 or None). The
    same object may appear in any number of pairs.
threads : int, optional
    Worker threads, 1 to 4096; None (default) uses all available. The results do not depend on
    it.
first_index : int, optional
    Index of pairs[0] in a larger batch split into chunks (default 0): pair i is seeded as pair
    first_index + i of the whole, so the chunks' results together equal the whole batch's.
)doc";

const std::string many_doc_tail = R"doc(

Returns
-------
list of Result
    One result per pair, in input order. Result i is exactly (bit for bit) what the single query
    returns with ``seed=pccd.pair_seed(seed, first_index + i)``, for any number of threads.

Raises
------
ValueError
    A pair that is not a 4-tuple, a bad pose (the message names the pair), or an invalid option;
    nothing is computed then.
TypeError
    Items 0 and 2 of a pair are not Object or LeanObject instances.

Notes
-----
The GIL is released while the pairs are answered (on TBB's threads).
)doc";

const std::string do_intersect_many_doc =
    "do_intersect for many pairs in one call, on several threads." + many_doc_head + query_doc_parameters +
    many_doc_tail + R"doc(
See Also
--------
pair_seed, intersection_points_many

Examples
--------
>>> pairs = [(bunny, None, bunny, pose) for pose in poses]
>>> [r.intersects for r in pccd.do_intersect_many(pairs, threads=2)]
)doc";

const std::string intersection_points_many_doc =
    "intersection_points for many pairs in one call, on several threads." + many_doc_head +
    query_doc_parameters + many_doc_tail + R"doc(
See Also
--------
pair_seed, do_intersect_many
)doc";

const char* result_doc = R"doc(The answer of an intersection query.

Attributes
----------
intersects : bool
    True when an intersection was found (also ``bool(result)``).
status : str
    'intersecting', 'separate' (nothing found after the whole sampling) or 'undecided'
    (the evaluation budget ran out first: the "no" is not backed by the full sampling).
points : numpy.ndarray
    (M, 3) float64 array of the points found, world coordinates (a new array at each access).
f_values : numpy.ndarray
    (M, 2) array of f_A and f_B at the points (NaN where not evaluated).
kinds : list of str
    How each point was obtained: 'approximate', 'refined' or 'sampled'.
counters : dict
    The query's work counters (f_evaluations, brackets_tried, ...), deterministic for a seed, named
    as in ``pccd collide --json``. Built at the first access; later accesses return the same dict
    (copy it before changing it).
closest_estimate : float
    How far the surfaces are from touching, as far as the query looked; both methods. Interpolation
    search ('isearch'): the smallest |f| of one surface at the other cloud's sampled points;
    randomized sampling ('rst'): the smallest max(|f_A|, |f_B|) over its samples. inf when no
    sample had the value defined, or when the hierarchies' separation test decided.
query_us : float
    Wall-clock microseconds of the query in PCCD's C++ (without the conversion of the arguments),
    as ``query_us`` of ``pccd collide --json``; NaN for the results of ``do_intersect_many`` and
    ``intersection_points_many``, whose pairs run concurrently and are timed as a whole.
)doc";

} // namespace

World_narrow_phase world_narrow_phase(const py::kwargs& kwargs, const char* function)
{
    const Query_parameters q = parameters(query_arguments(kwargs, false, function));
    if (q.rst)
        throw py::value_error(std::string(function) + "(): method must be 'isearch': a world answers its pairs with the "
                                                      "interpolation search");
    return World_narrow_phase{q.options, q.isearch};
}

Posed_pairs posed_pairs(const py::iterable& pairs)
{
    Posed_pairs out;
    std::size_t i = 0;
    for (const py::handle item : pairs) {
        const std::string where = "pairs[" + std::to_string(i) + "]";
        if (!PySequence_Check(item.ptr()) || py::isinstance<py::str>(item) || py::len(item) != 4)
            throw py::value_error(where + " must be a tuple (object_a, pose_a, object_b, pose_b)");
        const py::sequence pair = py::reinterpret_borrow<py::sequence>(item);
        const py::object a = pair[0];
        const py::object b = pair[2];
        const char* requirement = "items 0 and 2 must be pccd.Object or pccd.LeanObject instances";
        Any_posed_pair posed;
        posed.a = any_object(a, where, requirement);
        posed.b = any_object(b, where, requirement);
        try {
            posed.pose_a = pose_argument(pair[1], "pose_a");
            posed.pose_b = pose_argument(pair[3], "pose_b");
        } catch (const std::exception& e) {
            throw py::value_error(where + ": " + e.what());
        }
        out.pairs.push_back(posed);
        out.keep.push_back(a);
        out.keep.push_back(b);
        ++i;
    }
    return out;
}

void add_queries(py::module_& m)
{
    py::class_<Result>(m, "Result", result_doc)
        .def_property_readonly("intersects", [](const Result& r) { return r.r.intersects; })
        .def_property_readonly("status", [](const Result& r) { return PCCD::to_string(r.r.status); })
        .def_property_readonly("points",
                               [](const Result& r) {
                                   py::array_t<double> a({py::ssize_t(r.r.points.size()), py::ssize_t(3)});
                                   auto out = a.mutable_unchecked<2>();
                                   for (std::size_t i = 0; i < r.r.points.size(); ++i)
                                       for (int j = 0; j < 3; ++j) out(py::ssize_t(i), j) = r.r.points[i].position(j);
                                   return a;
                               })
        .def_property_readonly("f_values",
                               [](const Result& r) {
                                   py::array_t<double> a({py::ssize_t(r.r.points.size()), py::ssize_t(2)});
                                   auto out = a.mutable_unchecked<2>();
                                   for (std::size_t i = 0; i < r.r.points.size(); ++i) {
                                       out(py::ssize_t(i), 0) = r.r.points[i].f_a;
                                       out(py::ssize_t(i), 1) = r.r.points[i].f_b;
                                   }
                                   return a;
                               })
        .def_property_readonly("kinds",
                               [](const Result& r) {
                                   py::list kinds;
                                   for (const auto& p : r.r.points) kinds.append(kind_name(p.kind));
                                   return kinds;
                               })
        .def_property_readonly("counters",
                               [](Result& r) {
                                   if (!r.counters) r.counters = counters_dict(r.r.counters);
                                   return r.counters;
                               })
        .def_property_readonly("closest_estimate", [](const Result& r) { return r.r.closest_estimate; })
        .def_property_readonly("query_us", [](const Result& r) { return r.query_us; })
        .def("__bool__", [](const Result& r) { return r.r.intersects; })
        .def("__repr__", [](const Result& r) {
            return std::string("<pccd.Result: ") + PCCD::to_string(r.r.status) + ", " + std::to_string(r.r.points.size()) +
                   " point" + (r.r.points.size() == 1 ? "" : "s") + ", " + std::to_string(r.r.counters.f_evaluations) +
                   " f evaluations>";
        });

    m.def(
        "do_intersect",
        [](const py::object& a, const py::object& pose_a, const py::object& b, const py::object& pose_b,
           const py::kwargs& kwargs) {
            const Query_parameters q = call_parameters(kwargs, "do_intersect");
            return with_objects(a, "a", b, "b", "do_intersect", [&](const auto& oa, const auto& ob) {
                return query(oa, pose_a, ob, pose_b, true, q);
            });
        },
        py::arg("a"), py::arg("pose_a"), py::arg("b"), py::arg("pose_b"), do_intersect_doc.c_str());
    m.def(
        "intersection_points",
        [](const py::object& a, const py::object& pose_a, const py::object& b, const py::object& pose_b,
           const py::kwargs& kwargs) {
            const Query_parameters q = call_parameters(kwargs, "intersection_points");
            return with_objects(a, "a", b, "b", "intersection_points", [&](const auto& oa, const auto& ob) {
                return query(oa, pose_a, ob, pose_b, false, q);
            });
        },
        py::arg("a"), py::arg("pose_a"), py::arg("b"), py::arg("pose_b"), intersection_points_doc.c_str());
    m.def(
        "do_intersect_many",
        [](const py::iterable& pairs, const py::kwargs& kwargs) {
            const Query_arguments arguments = query_arguments(kwargs, true, "do_intersect_many");
            return many(pairs, arguments.threads, arguments.first_index, true, parameters(arguments));
        },
        py::arg("pairs"), do_intersect_many_doc.c_str());
    m.def(
        "intersection_points_many",
        [](const py::iterable& pairs, const py::kwargs& kwargs) {
            const Query_arguments arguments = query_arguments(kwargs, true, "intersection_points_many");
            return many(pairs, arguments.threads, arguments.first_index, false, parameters(arguments));
        },
        py::arg("pairs"), intersection_points_many_doc.c_str());
    m.def("orthonormalize", &orthonormalize_pose, py::arg("pose"),
          R"doc(The rigid pose nearest to `pose`, and how far it is: the opt-in repair of a rotation that is
not quite one.

Queries accept a pose whose R^T R differs from the identity by at most 1e-5 per entry (a rotation
printed with 6 decimals always passes) and refuse the others with a ValueError. This function
replaces R by its nearest rotation matrix in the Frobenius norm (the orthogonal polar factor, by
SVD), however far that is, and says how far it moved: compare that with what the source's
rounding explains before using the result.

Parameters
----------
pose : array_like
    A 3x4 [R | t] or 4x4 homogeneous matrix (last row 0 0 0 1 within 1e-5).

Returns
-------
pose : numpy.ndarray
    The same shape, float64, with R replaced by the nearest rotation (t unchanged).
moved : float
    The largest absolute change of an entry of R.

Raises
------
ValueError
    Wrong shape, a NaN or infinite entry, or an R that is singular or a reflection (det < 0):
    it has no nearest proper rotation.
TypeError
    `pose` is None.

Examples
--------
>>> pose, moved = pccd.orthonormalize(np.round(pose, 3))
>>> moved < 1e-3
True
)doc");
    m.def("pair_seed", &PCCD::pair_seed, py::arg("seed"), py::arg("index"),
          R"doc(The seed of pair `index` of a batch whose seed is `seed`.

Pair i of ``do_intersect_many(pairs, seed=s, first_index=k)`` is answered exactly as
``do_intersect(*pairs[i], seed=pair_seed(s, k + i))``. The value is the SplitMix64 output
function of s + (index + 1) * 0x9e3779b97f4a7c15 modulo 2**64.

Parameters
----------
seed : int
    The batch's seed (0 <= seed < 2**64).
index : int
    The pair's index in the whole batch.

Returns
-------
int
)doc");
}

} // namespace pccd_python
