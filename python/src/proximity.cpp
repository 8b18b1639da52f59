// python/src/proximity.cpp -- the proximity queries of pccd: distance, within_distance, contacts,
// the batch distance_many and clearance along a path (PCCD/Proximity/), with Distance_options and
// the intersection options that decide the status as keyword arguments, and their results,
// DistanceResult, ClearanceResult, ContactResult, Contact and ClearanceProfile, whose attributes
// are named as the C++ fields. Every
// query runs with the GIL released (doc/manual/proximity-cli-python.md, "Python").
#include "pccd_python.h"
#include "posed_pairs.h"

#include <PCCD/Error.h>
#include <PCCD/Proximity/clearance.h>
#include <PCCD/Proximity/contacts.h>
#include <PCCD/Proximity/distance.h>
#include <PCCD/Proximity/distance_many.h>

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pccd_python {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// What the queries return to Python: PCCD's result, converted on access; the query's wall time
/// (NaN for the results of distance_many, timed as a whole); the counters' dict, built at the
/// first access and the same object afterwards.
template <class R>
struct Held {
    R r;
    double query_us = nan;
    py::object counters = {};
};
using Distance_held = Held<PCCD::Distance_result>;
using Clearance_held = Held<PCCD::Clearance_result>;
using Contact_held = Held<PCCD::Contact_result>;
using Profile_held = Held<PCCD::Clearance_profile>;

/// The keyword arguments of a proximity query: the fields of Distance_options, those of its
/// Intersection_options that do not concern the leaf intersector's budgets, and for
/// distance_many the batch's.
struct Distance_arguments {
    PCCD::Distance_options options;
    std::optional<unsigned> threads;
    std::uint64_t first_index = 0;
};

/// The keyword arguments of a call, checked by the library's rule (PCCD::internal::check_options)
/// before any work: ValueError naming the option. An unknown key raises TypeError.
Distance_arguments distance_arguments(const py::kwargs& kwargs, bool batch, const char* function)
{
    Distance_arguments a;
    PCCD::Distance_options& o = a.options;
    PCCD::Intersection_options& i = o.intersection;
    for (const auto& [key_object, value] : kwargs) {
        Py_ssize_t size = 0;
        const char* text = PyUnicode_AsUTF8AndSize(key_object.ptr(), &size);
        if (text == nullptr) throw py::error_already_set();
        const std::string_view key(text, std::size_t(size));
        const auto is = [&](std::string_view name) { return key == name; };
        if (is("absolute_tolerance")) read_argument(o.absolute_tolerance, value, function, key);
        else if (is("relative_tolerance")) read_argument(o.relative_tolerance, value, function, key);
        else if (is("max_distance")) read_argument(o.max_distance, value, function, key);
        else if (is("max_f_evaluations")) read_argument(o.max_f_evaluations, value, function, key);
        else if (is("max_time_us")) {
            read_argument(o.max_time_us, value, function, key);
            if (o.max_time_us && *o.max_time_us == 0.0) o.max_time_us.reset(); // 0: none, as elsewhere
        }
        else if (is("max_node_pairs")) read_argument(o.max_node_pairs, value, function, key);
        else if (is("penetration")) read_argument(o.penetration, value, function, key);
        else if (is("max_contacts")) read_argument(o.max_contacts, value, function, key);
        else if (is("candidates")) read_argument(o.candidates, value, function, key);
        else if (is("certified_lower_bound")) read_argument(o.certified_lower_bound, value, function, key);
        else if (is("seed")) read_argument(i.seed, value, function, key);
        else if (is("epsilon")) read_argument(i.epsilon, value, function, key);
        else if (is("traversal")) {
            std::string traversal;
            read_argument(traversal, value, function, key);
            if (traversal == "flat") i.traversal = PCCD::Traversal::flat;
            else if (traversal == "depth_first") i.traversal = PCCD::Traversal::depth_first;
            else if (traversal == "likelihood") i.traversal = PCCD::Traversal::likelihood;
            else
                throw py::value_error(std::string(function) + "(): traversal must be 'likelihood', 'depth_first' or "
                                                              "'flat', not '" + traversal + "'");
        }
        else if (is("symmetric")) read_argument(i.symmetric, value, function, key);
        else if (is("verify_contacts")) read_argument(i.verify_contacts, value, function, key);
        else if (is("contact_tolerance")) read_argument(i.contact_tolerance, value, function, key);
        else if (is("contact_core")) read_argument(i.contact_core, value, function, key);
        else if (is("certify_separation")) read_argument(i.certify_separation, value, function, key);
        else if (batch && is("threads")) read_argument(a.threads, value, function, key);
        else if (batch && is("first_index")) read_argument(a.first_index, value, function, key);
        else
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + std::string(key) +
                                 "'");
    }
    PCCD::internal::check_options(o, function);
    if (a.threads && (*a.threads == 0 || *a.threads > PCCD::Batch_options::max_threads))
        throw py::value_error(std::string(function) + "(): threads = " + std::to_string(*a.threads) +
                              " must be from 1 to " + std::to_string(PCCD::Batch_options::max_threads) +
                              " (None: all available threads)");
    return a;
}

PCCD::Distance_options call_options(const py::kwargs& kwargs, const char* function)
{
    return kwargs.empty() ? PCCD::Distance_options{} : distance_arguments(kwargs, false, function).options;
}

/// A point or vector as a new float64 array of shape (3,) (NaN where the query did not compute it).
py::array_t<double> vector_array(const Eigen::Vector3d& v)
{
    py::array_t<double> a(3);
    auto out = a.mutable_unchecked<1>();
    for (int j = 0; j < 3; ++j) out(j) = v(j);
    return a;
}

/// A per-pose number of a profile as a new float64 array of shape (n,).
py::array_t<double> sample_values(const PCCD::Clearance_profile& p, double PCCD::Clearance_sample::*field)
{
    py::array_t<double> a(py::ssize_t(p.samples.size()));
    auto out = a.mutable_unchecked<1>();
    for (std::size_t i = 0; i < p.samples.size(); ++i) out(py::ssize_t(i)) = p.samples[i].*field;
    return a;
}

/// A per-pose point of a profile as a new float64 array of shape (n, 3).
py::array_t<double> sample_points(const PCCD::Clearance_profile& p, Eigen::Vector3d PCCD::Clearance_sample::*field)
{
    py::array_t<double> a({py::ssize_t(p.samples.size()), py::ssize_t(3)});
    auto out = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < p.samples.size(); ++i)
        for (int j = 0; j < 3; ++j) out(py::ssize_t(i), j) = (p.samples[i].*field)(j);
    return a;
}

/// The counters by name: PCCD::for_each_counter's, then those of the intersection query prefixed
/// "intersection_" (unless the library's list names them already), as `pccd distance --json`.
py::dict counters_dict(const PCCD::Distance_counters& c)
{
    py::dict d;
    bool has_intersection = false;
    PCCD::for_each_counter(c, [&](const char* name, std::size_t value) {
        d[name] = value;
        has_intersection = has_intersection || std::string_view(name).starts_with("intersection_");
    });
    if (!has_intersection)
        PCCD::for_each_counter(c.intersection, [&](const char* name, std::size_t value) {
            d[py::str(std::string("intersection_") + name)] = value;
        });
    return d;
}

template <class H>
py::object counters_of(H& h)
{
    if (!h.counters) h.counters = counters_dict(h.r.counters);
    return h.counters;
}

/// Runs `query()` with the GIL released; returns its result and wall time in microseconds.
template <class F>
auto timed(const F& query)
{
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    auto r = query();
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    return std::make_pair(std::move(r), us);
}

std::string number_text(double x)
{
    return PCCD::Rigid_transform_3<double>::full_digits(x);
}

const std::string options_doc = R"doc(absolute_tolerance : float, optional
    The witness refinement stops when a step shortens the distance by less than
    max(absolute_tolerance, relative_tolerance * distance). None (default): 0.01 times the smaller
    sampling radius. Finite and > 0.
relative_tolerance : float, optional
    See absolute_tolerance (default 0; finite and >= 0).
max_distance : float, optional
    Farther apart than this (world units), report only that: status 'separate', distance inf,
    lower_bound >= max_distance, no witnesses -- when no point pair comes within it plus the
    surfaces' radii; a pair that does is refined and its distance reported, even above the limit.
    None (default): no limit. Finite and >= 0.
max_f_evaluations : int, optional
    Budget of evaluations of f (both surfaces, the intersection query included); None (default):
    none. A query that runs out answers with what it has (an honest [lower_bound, upper_bound]),
    status 'undecided' when the intersection query could not decide.
max_time_us : float, optional
    Time budget in microseconds; None (default) or 0: none (as ``pccd distance --budget-us 0``).
max_node_pairs : int, optional
    Budget on the node pairs of the closest-pair walk (deterministic); None (default): none. The
    interval [lower_bound, upper_bound] narrows as it grows.
penetration : bool, optional
    For intersecting poses, also measure the penetration depths (depth, depth_a, depth_b) and the
    contact normal (default False).
max_contacts : int, optional
    contacts(): the most contact regions returned, deepest first (default 8; >= 1).
candidates : int, optional
    Closest point pairs of the clouds whose witnesses are refined (default 2; >= 1).
certified_lower_bound : bool, optional
    Certify lower_bound (default False): the smallest |p - q| - reach(p) - reach(q) over the point
    pairs, reach(p) the domain radius of p capped by the support radius, which holds whatever the
    fit, instead of the closest pair's distance minus r(P) + 2 sigma per surface (a premise that
    fails on a few tenths of a percent of the zero set). 13-27 % more time.
seed : int, optional
    Seed of the intersection query that decides the status (default 24301 = 0x5eed): the same
    seed gives the same answer and counters, on every platform and for any number of threads.
epsilon, traversal, symmetric, verify_contacts, contact_tolerance, contact_core, certify_separation
    Options of that intersection query, as for do_intersect.)doc";

const std::string distance_doc = std::string(R"doc(The distance between the implicit surfaces of two posed objects.

PCCD::distance: the status of the pair (as do_intersect), the distance with an honest interval
[lower_bound, upper_bound] around it, the closest points (witnesses) on both surfaces and the
surfaces' normals there; with penetration=True, the penetration depths of intersecting poses.

Parameters
----------
a, b : Object or LeanObject
    The two objects (either kind, in any mix).
pose_a, pose_b : array_like or None
    Rigid motions from each object's frame to the world: a 3x4 array [R | t] or a 4x4
    homogeneous matrix (last row 0 0 0 1); None is the identity. The rule of do_intersect.
)doc") + options_doc + R"doc(

Returns
-------
DistanceResult
    ``status``, ``distance``, ``lower_bound``, ``upper_bound``, ``point_a``, ``point_b``,
    ``normal_a``, ``normal_b``, ``depth``, ``depth_a``, ``depth_b``, ``contact_normal``,
    ``intersection_points``, ``counters``, ``query_us``: the fields of PCCD::Distance_result.

Raises
------
ValueError
    A pose that is not a 3x4 or 4x4 rigid transform (NaN, scaling, shear, reflection), or an
    invalid option (a negative max_distance, a tolerance <= 0, ...); the message names it.
TypeError
    An unknown keyword argument or a value of the wrong type.

See Also
--------
within_distance, contacts, distance_many

Examples
--------
>>> far = np.array([[1., 0., 0., 2.5], [0., 1., 0., 0.], [0., 0., 1., 0.]])
>>> d = pccd.distance(ball, None, ball, far)
>>> d.status, round(d.distance, 2)
('separate', 0.5)
)doc";

const std::string within_distance_doc = std::string(R"doc(Whether two posed objects come closer than a margin.

PCCD::within_distance: True when the surfaces intersect or come closer than `margin`; cheaper than
distance() when the answer is "no" early.

Parameters
----------
a, b : Object or LeanObject
    The two objects (either kind, in any mix).
pose_a, pose_b : array_like or None
    3x4 or 4x4 rigid transforms (see distance); None is the identity.
margin : float
    The clearance asked for (world units), finite and >= 0.
)doc") + options_doc + R"doc(

Returns
-------
ClearanceResult
    ``within`` (also ``bool(result)``), ``status``, ``margin``, ``lower_bound``, ``upper_bound``,
    ``point_a``, ``point_b``, ``counters``, ``query_us``.

Raises
------
ValueError
    A negative or NaN margin, a bad pose or an invalid option.
)doc";

const std::string contacts_doc = std::string(R"doc(The contact regions of two posed objects.

PCCD::contacts: for intersecting poses, up to max_contacts regions, deepest first, each with a
position, a unit normal (the direction in which B must move to leave A), a depth and its deepest
witness pair, as a physics engine consumes them.

Parameters
----------
a, b : Object or LeanObject
    The two objects (either kind, in any mix).
pose_a, pose_b : array_like or None
    3x4 or 4x4 rigid transforms (see distance); None is the identity.
)doc") + options_doc + R"doc(

Returns
-------
ContactResult
    ``status``, ``contacts`` (a list of Contact), ``regions``, ``counters``, ``query_us``.

Raises
------
ValueError
    A bad pose or an invalid option (max_contacts=0, ...).
)doc";

const std::string distance_many_doc = std::string(R"doc(distance for many pairs in one call, on several threads.

Parameters
----------
pairs : iterable of tuple
    Tuples (object_a, pose_a, object_b, pose_b), poses as in distance (3x4, 4x4 or None).
threads : int, optional
    Worker threads, 1 to 4096; None (default) uses all available. The results do not depend on
    it.
first_index : int, optional
    Index of pairs[0] in a larger batch split into chunks (default 0): pair i is seeded as pair
    first_index + i of the whole.
)doc") + options_doc + R"doc(

Returns
-------
list of DistanceResult
    One result per pair, in input order: result i is what
    ``distance(*pairs[i], seed=pccd.pair_seed(seed, first_index + i))`` returns, for any number of
    threads (``query_us`` is NaN: the pairs run concurrently).

Raises
------
ValueError
    A pair that is not a 4-tuple, a bad pose (naming the pair), threads=0 or an invalid option;
    nothing is computed then.
TypeError
    Items 0 and 2 of a pair are not Object or LeanObject instances.
)doc";

const char* distance_result_doc = R"doc(The answer of distance() and distance_many(): PCCD::Distance_result.

Points and normals are float64 arrays of shape (3,) in world coordinates (new arrays at each
access); what the query did not compute is NaN (never a made-up 0).

Attributes
----------
status : str
    'intersecting', 'separate' or 'undecided' (a budget ran out before the intersection query
    could decide): the status do_intersect gives with the same options.
distance : float
    Separate: the distance between the surfaces, |point_a - point_b| (inf beyond max_distance).
    Intersecting: 0. Undecided: NaN.
lower_bound, upper_bound : float
    An honest interval around the true distance (0 and 0 for intersecting poses).
point_a, point_b : numpy.ndarray
    The closest points found on surface A and surface B (separate), or the witnesses of the
    deeper penetration (intersecting, penetration=True).
normal_a, normal_b : numpy.ndarray
    The surfaces' outward unit normals at the witnesses.
depth, depth_a, depth_b : float
    Penetration depths (penetration=True, intersecting poses): depth_a the deepest point of
    surface A inside B, depth_b the other way round, depth the larger.
contact_normal : numpy.ndarray
    Intersecting with penetration: the unit direction in which B must move to leave A. Separate:
    the unit vector from point_a to point_b.
intersection_points : numpy.ndarray
    (M, 3): the point of the intersection query when the surfaces intersect.
counters : dict
    The work counters (node_pairs, leaf_pairs, point_pairs, f_evaluations, ...; those of the
    intersection query prefixed 'intersection_'), named as in ``pccd distance --json``. Built at
    the first access, the same dict afterwards.
query_us : float
    Wall-clock microseconds of the query in PCCD's C++; NaN for the results of distance_many.
)doc";

const char* clearance_result_doc = R"doc(The answer of within_distance(): PCCD::Clearance_result.

Attributes
----------
within : bool
    True when the surfaces intersect or come closer than the margin (also ``bool(result)``).
status : str
    As DistanceResult.status.
margin : float
    The margin asked for.
lower_bound, upper_bound : float
    As in DistanceResult, as far as the query had to look.
point_a, point_b : numpy.ndarray
    Separate and within: witnesses closer than the margin; NaN otherwise.
counters : dict
    As DistanceResult.counters.
query_us : float
    Wall-clock microseconds of the query in PCCD's C++.
)doc";

const char* contact_result_doc = R"doc(The answer of contacts(): PCCD::Contact_result.

Attributes
----------
status : str
    As DistanceResult.status.
contacts : list of Contact
    The contact regions, deepest first (at most max_contacts).
regions : int
    Regions found in all (may exceed len(contacts)).
counters : dict
    As DistanceResult.counters.
query_us : float
    Wall-clock microseconds of the query in PCCD's C++.
)doc";

const char* contact_doc = R"doc(One contact region: PCCD::Contact.

Attributes
----------
position : numpy.ndarray
    The representative point (3,).
normal : numpy.ndarray
    Unit direction in which B must move to leave A here.
depth : float
    The region's largest local depth (>= 0).
point_a, point_b : numpy.ndarray
    The deepest witness pair, on surface A and surface B.
points_inside : int
    Cloud points of both objects found inside the other object in this region.
)doc";


const std::string clearance_doc = std::string(R"doc(The clearance of an object moved along a path of poses through a scene.

PCCD::clearance: at every pose the distance between the two implicit surfaces (one distance query
per pose, on several threads), placed against `margin`: 'clear', 'below_margin' (strictly closer
than the margin), 'intersecting', 'beyond_cap' (farther than max_distance) or 'undecided' (a
budget ran out); over the path the first pose below the margin with its witness points and the
minimum clearance.

Parameters
----------
object, scene : Object or LeanObject
    The moving object and the scene (the scene stays at the identity).
poses : array_like
    (n, 3, 4) or (n, 4, 4): the object's poses in the scene's frame, [R | t] row by row; n may be 0.
margin : float
    The safety margin (world units), finite and >= 0.
max_distance : float, optional
    The cap: a pose farther apart than this is reported 'beyond_cap' (clearance inf,
    lower_bound >= the cap), cheaply. None (default): no cap, every pose gets its distance.
    Finite and >= margin.
threads : int, optional
    Worker threads, 1 to 4096; None (default) uses all available. The results do not depend on it.
first_index : int, optional
    Index of poses[0] in a longer path split into chunks (default 0): pose i is seeded as pose
    first_index + i of the whole (pccd.pair_seed(seed, first_index + i)).
)doc") + options_doc + R"doc(

Returns
-------
ClearanceProfile
    ``margin``, ``max_distance``, per pose ``status`` (list of str), ``clearance``,
    ``lower_bound``, ``upper_bound``, ``depth`` ((n,) arrays), ``point_object``, ``point_scene``
    ((n, 3) arrays); ``first_below_margin``, ``first_point_object``, ``first_point_scene``,
    ``minimum``, ``minimum_clearance``, ``first_undecided``, ``all_clear``, ``counters``,
    ``query_us``: the fields of PCCD::Clearance_profile.

Raises
------
ValueError
    A negative or NaN margin, a cap below the margin, poses of another shape or a pose that is not
    rigid (naming its index), or an invalid option; nothing is computed then.

Examples
--------
>>> path = np.array([[[1., 0., 0., x], [0., 1., 0., 0.], [0., 0., 1., 0.]] for x in (3.0, 2.5, 2.1)])
>>> p = pccd.clearance(ball, ball, path, 0.3)
>>> p.status, p.first_below_margin
(['clear', 'clear', 'below_margin'], 2)
)doc";

const char* clearance_profile_doc = R"doc(The answer of clearance(): PCCD::Clearance_profile.

Per-pose values are arrays over the poses (new arrays at each access); points are in the scene's
frame; what was not computed is NaN.

Attributes
----------
margin : float
    The margin asked for.
max_distance : float or None
    The cap asked for.
status : list of str
    Per pose: 'clear', 'below_margin', 'intersecting', 'beyond_cap' or 'undecided'.
clearance : numpy.ndarray
    (n,): the distance between the surfaces (0 intersecting, inf beyond the cap, NaN undecided).
lower_bound, upper_bound : numpy.ndarray
    (n,): the honest interval around each clearance.
point_object, point_scene : numpy.ndarray
    (n, 3): the closest points found on the object's and on the scene's surface.
depth : numpy.ndarray
    (n,): intersecting poses with penetration=True: the penetration depth; NaN otherwise.
first_below_margin : int or None
    The first pose 'below_margin' or 'intersecting'.
first_point_object, first_point_scene : numpy.ndarray
    (3,): its witness points.
minimum : int or None
    The first pose of the smallest finite clearance; minimum_clearance is that clearance (inf when
    there is none).
first_undecided : int or None
    The first 'undecided' pose.
all_clear : bool
    No pose below the margin, intersecting or undecided.
counters : dict
    Poses by status ('clear', 'below_margin', 'intersecting', 'beyond_cap', 'undecided') and
    'work': the sum of the poses' work counters, named as DistanceResult.counters.
query_us : float
    Wall-clock microseconds of the whole path in PCCD's C++.
)doc";

} // namespace

py::object clearance_result(const PCCD::Clearance_result& r) { return py::cast(Clearance_held{r}); }

void add_proximity(py::module_& m)
{
    py::class_<Distance_held>(m, "DistanceResult", distance_result_doc)
        .def_property_readonly("status", [](const Distance_held& h) { return PCCD::to_string(h.r.status); })
        .def_property_readonly("distance", [](const Distance_held& h) { return h.r.distance; })
        .def_property_readonly("lower_bound", [](const Distance_held& h) { return h.r.lower_bound; })
        .def_property_readonly("upper_bound", [](const Distance_held& h) { return h.r.upper_bound; })
        .def_property_readonly("point_a", [](const Distance_held& h) { return vector_array(h.r.point_a); })
        .def_property_readonly("point_b", [](const Distance_held& h) { return vector_array(h.r.point_b); })
        .def_property_readonly("normal_a", [](const Distance_held& h) { return vector_array(h.r.normal_a); })
        .def_property_readonly("normal_b", [](const Distance_held& h) { return vector_array(h.r.normal_b); })
        .def_property_readonly("depth", [](const Distance_held& h) { return h.r.depth; })
        .def_property_readonly("depth_a", [](const Distance_held& h) { return h.r.depth_a; })
        .def_property_readonly("depth_b", [](const Distance_held& h) { return h.r.depth_b; })
        .def_property_readonly("contact_normal", [](const Distance_held& h) { return vector_array(h.r.contact_normal); })
        .def_property_readonly("intersection_points",
                               [](const Distance_held& h) {
                                   const auto& points = h.r.intersection_points;
                                   py::array_t<double> a({py::ssize_t(points.size()), py::ssize_t(3)});
                                   auto out = a.mutable_unchecked<2>();
                                   for (std::size_t i = 0; i < points.size(); ++i)
                                       for (int j = 0; j < 3; ++j) out(py::ssize_t(i), j) = points[i].position(j);
                                   return a;
                               })
        .def_property_readonly("counters", [](Distance_held& h) { return counters_of(h); })
        .def_property_readonly("query_us", [](const Distance_held& h) { return h.query_us; })
        .def_property_readonly("intersecting", [](const Distance_held& h) { return h.r.intersecting(); },
                               "bool: True when the surfaces intersect (status 'intersecting'; intersecting() in C++).")
        .def("__repr__", [](const Distance_held& h) {
            return std::string("<pccd.DistanceResult: ") + PCCD::to_string(h.r.status) + ", distance " +
                   number_text(h.r.distance) + " in [" + number_text(h.r.lower_bound) + ", " +
                   number_text(h.r.upper_bound) + "]>";
        });

    py::class_<Clearance_held>(m, "ClearanceResult", clearance_result_doc)
        .def_property_readonly("within", [](const Clearance_held& h) { return h.r.within; })
        .def_property_readonly("status", [](const Clearance_held& h) { return PCCD::to_string(h.r.status); })
        .def_property_readonly("margin", [](const Clearance_held& h) { return h.r.margin; })
        .def_property_readonly("lower_bound", [](const Clearance_held& h) { return h.r.lower_bound; })
        .def_property_readonly("upper_bound", [](const Clearance_held& h) { return h.r.upper_bound; })
        .def_property_readonly("point_a", [](const Clearance_held& h) { return vector_array(h.r.point_a); })
        .def_property_readonly("point_b", [](const Clearance_held& h) { return vector_array(h.r.point_b); })
        .def_property_readonly("counters", [](Clearance_held& h) { return counters_of(h); })
        .def_property_readonly("query_us", [](const Clearance_held& h) { return h.query_us; })
        .def("__bool__", [](const Clearance_held& h) { return h.r.within; })
        .def("__repr__", [](const Clearance_held& h) {
            return std::string("<pccd.ClearanceResult: ") + (h.r.within ? "within " : "not within ") +
                   number_text(h.r.margin) + ", " + PCCD::to_string(h.r.status) + ">";
        });

    py::class_<PCCD::Contact>(m, "Contact", contact_doc)
        .def_property_readonly("position", [](const PCCD::Contact& c) { return vector_array(c.position); })
        .def_property_readonly("normal", [](const PCCD::Contact& c) { return vector_array(c.normal); })
        .def_property_readonly("depth", [](const PCCD::Contact& c) { return c.depth; })
        .def_property_readonly("point_a", [](const PCCD::Contact& c) { return vector_array(c.point_a); })
        .def_property_readonly("point_b", [](const PCCD::Contact& c) { return vector_array(c.point_b); })
        .def_property_readonly("points_inside", [](const PCCD::Contact& c) { return c.points_inside; })
        .def("__repr__", [](const PCCD::Contact& c) {
            return "<pccd.Contact: depth " + number_text(c.depth) + ", " + std::to_string(c.points_inside) +
                   " points inside>";
        });

    py::class_<Contact_held>(m, "ContactResult", contact_result_doc)
        .def_property_readonly("status", [](const Contact_held& h) { return PCCD::to_string(h.r.status); })
        .def_property_readonly("contacts", [](const Contact_held& h) { return h.r.contacts; })
        .def_property_readonly("regions", [](const Contact_held& h) { return h.r.regions; })
        .def_property_readonly("counters", [](Contact_held& h) { return counters_of(h); })
        .def_property_readonly("query_us", [](const Contact_held& h) { return h.query_us; })
        .def("__len__", [](const Contact_held& h) { return h.r.contacts.size(); })
        .def("__repr__", [](const Contact_held& h) {
            return std::string("<pccd.ContactResult: ") + PCCD::to_string(h.r.status) + ", " +
                   std::to_string(h.r.contacts.size()) + " of " + std::to_string(h.r.regions) + " regions>";
        });

    m.def(
        "distance",
        [](const py::object& a, const py::object& pose_a, const py::object& b, const py::object& pose_b,
           const py::kwargs& kwargs) {
            const PCCD::Distance_options options = call_options(kwargs, "distance");
            const auto ta = pose_argument(pose_a, "pose_a");
            const auto tb = pose_argument(pose_b, "pose_b");
            return with_objects(a, "a", b, "b", "distance", [&](const auto& oa, const auto& ob) {
                auto [r, us] = timed([&] { return PCCD::distance(oa, ta, ob, tb, options); });
                return Distance_held{std::move(r), us};
            });
        },
        py::arg("a"), py::arg("pose_a"), py::arg("b"), py::arg("pose_b"), distance_doc.c_str());
    m.def(
        "within_distance",
        [](const py::object& a, const py::object& pose_a, const py::object& b, const py::object& pose_b, double margin,
           const py::kwargs& kwargs) {
            if (!(std::isfinite(margin) && margin >= 0.0))
                throw py::value_error("within_distance(): margin " + number_text(margin) +
                                      " must be finite and >= 0 (world units)");
            const PCCD::Distance_options options = call_options(kwargs, "within_distance");
            const auto ta = pose_argument(pose_a, "pose_a");
            const auto tb = pose_argument(pose_b, "pose_b");
            return with_objects(a, "a", b, "b", "within_distance", [&](const auto& oa, const auto& ob) {
                auto [r, us] = timed([&] { return PCCD::within_distance(oa, ta, ob, tb, margin, options); });
                return Clearance_held{std::move(r), us};
            });
        },
        py::arg("a"), py::arg("pose_a"), py::arg("b"), py::arg("pose_b"), py::arg("margin"),
        within_distance_doc.c_str());
    m.def(
        "contacts",
        [](const py::object& a, const py::object& pose_a, const py::object& b, const py::object& pose_b,
           const py::kwargs& kwargs) {
            const PCCD::Distance_options options = call_options(kwargs, "contacts");
            const auto ta = pose_argument(pose_a, "pose_a");
            const auto tb = pose_argument(pose_b, "pose_b");
            return with_objects(a, "a", b, "b", "contacts", [&](const auto& oa, const auto& ob) {
                auto [r, us] = timed([&] { return PCCD::contacts(oa, ta, ob, tb, options); });
                return Contact_held{std::move(r), us};
            });
        },
        py::arg("a"), py::arg("pose_a"), py::arg("b"), py::arg("pose_b"), contacts_doc.c_str());
    m.def(
        "distance_many",
        [](const py::iterable& pairs, const py::kwargs& kwargs) {
            const Distance_arguments arguments = distance_arguments(kwargs, true, "distance_many");
            const Posed_pairs posed = posed_pairs(pairs);
            std::vector<PCCD::Distance_result> results;
            {
                py::gil_scoped_release release;
                results = run_posed_pairs<PCCD::Distance_result>(posed, arguments.first_index, [&](auto list, std::uint64_t first) {
                    const PCCD::Batch_options batch{.threads = arguments.threads, .first_index = first};
                    return PCCD::distance_many(list, batch, arguments.options);
                });
            }
            std::vector<Distance_held> out;
            out.reserve(results.size());
            for (PCCD::Distance_result& r : results) out.push_back(Distance_held{std::move(r)});
            return out;
        },
        py::arg("pairs"), distance_many_doc.c_str());

    py::class_<Profile_held>(m, "ClearanceProfile", clearance_profile_doc)
        .def_property_readonly("margin", [](const Profile_held& h) { return h.r.margin; })
        .def_property_readonly("max_distance", [](const Profile_held& h) { return h.r.max_distance; })
        .def_property_readonly("status",
                               [](const Profile_held& h) {
                                   py::list out;
                                   for (const PCCD::Clearance_sample& x : h.r.samples) out.append(PCCD::to_string(x.status));
                                   return out;
                               })
        .def_property_readonly("clearance", [](const Profile_held& h) { return sample_values(h.r, &PCCD::Clearance_sample::clearance); })
        .def_property_readonly("lower_bound", [](const Profile_held& h) { return sample_values(h.r, &PCCD::Clearance_sample::lower_bound); })
        .def_property_readonly("upper_bound", [](const Profile_held& h) { return sample_values(h.r, &PCCD::Clearance_sample::upper_bound); })
        .def_property_readonly("depth", [](const Profile_held& h) { return sample_values(h.r, &PCCD::Clearance_sample::depth); })
        .def_property_readonly("point_object", [](const Profile_held& h) { return sample_points(h.r, &PCCD::Clearance_sample::point_object); })
        .def_property_readonly("point_scene", [](const Profile_held& h) { return sample_points(h.r, &PCCD::Clearance_sample::point_scene); })
        .def_property_readonly("first_below_margin", [](const Profile_held& h) { return h.r.first_below_margin; })
        .def_property_readonly("first_point_object", [](const Profile_held& h) { return vector_array(h.r.first_point_object); })
        .def_property_readonly("first_point_scene", [](const Profile_held& h) { return vector_array(h.r.first_point_scene); })
        .def_property_readonly("minimum", [](const Profile_held& h) { return h.r.minimum; })
        .def_property_readonly("minimum_clearance", [](const Profile_held& h) { return h.r.minimum_clearance; })
        .def_property_readonly("first_undecided", [](const Profile_held& h) { return h.r.first_undecided; })
        .def_property_readonly("all_clear", [](const Profile_held& h) { return h.r.all_clear(); })
        .def_property_readonly("counters",
                               [](Profile_held& h) {
                                   if (!h.counters) {
                                       const PCCD::Clearance_counters& c = h.r.counters;
                                       py::dict d;
                                       d["clear"] = c.clear;
                                       d["below_margin"] = c.below_margin;
                                       d["intersecting"] = c.intersecting;
                                       d["beyond_cap"] = c.beyond_cap;
                                       d["undecided"] = c.undecided;
                                       d["work"] = counters_dict(c.work);
                                       h.counters = d;
                                   }
                                   return h.counters;
                               })
        .def_property_readonly("query_us", [](const Profile_held& h) { return h.query_us; })
        .def("__len__", [](const Profile_held& h) { return h.r.samples.size(); })
        .def("__repr__", [](const Profile_held& h) {
            return "<pccd.ClearanceProfile: " + std::to_string(h.r.samples.size()) + " poses, margin " +
                   number_text(h.r.margin) + ", first below " +
                   (h.r.first_below_margin ? std::to_string(*h.r.first_below_margin) : std::string("none")) +
                   ", minimum " + number_text(h.r.minimum_clearance) + ">";
        });
    m.def(
        "clearance",
        [](const py::object& object, const py::object& scene, const py::object& poses, double margin,
           const py::kwargs& kwargs) {
            if (!(std::isfinite(margin) && margin >= 0.0))
                throw py::value_error("clearance(): margin " + number_text(margin) + " must be finite and >= 0 (world units)");
            Distance_arguments arguments = distance_arguments(kwargs, true, "clearance");
            PCCD::Clearance_options options{.max_distance = arguments.options.max_distance,
                                            .distance = arguments.options,
                                            .batch = {.threads = arguments.threads, .first_index = arguments.first_index}};
            options.distance.max_distance.reset();
            PCCD::internal::check_options(options, margin, "clearance()");
            const std::vector<PCCD::Rigid_transform_3<double>> path = pose_stack(poses, "clearance", "poses");
            return with_objects(object, "object", scene, "scene", "clearance", [&](const auto& o, const auto& sc) {
                auto [r, us] = timed([&] { return PCCD::clearance(o, sc, path, margin, options); });
                return Profile_held{std::move(r), us};
            });
        },
        py::arg("object"), py::arg("scene"), py::arg("poses"), py::arg("margin"), clearance_doc.c_str());
}

} // namespace pccd_python
