// python/src/continuous.cpp -- continuous collision detection in pccd: time_of_contact and the batch
// time_of_contact_many (PCCD/Continuous/), two objects moving rigidly over t in [0, 1] (linear or
// screw motions between a start and an end pose) with the fields of Contact_time_options as keyword
// arguments, and ContactTimeResult, whose attributes are named as the fields of
// PCCD::Contact_time_result. Every query runs with the GIL released (doc/manual/continuous.md,
// "CLI and Python").
#include "pccd_python.h"

#include <PCCD/Continuous/Contact_time_names.h>
#include <PCCD/Continuous/Contact_time_options.h>
#include <PCCD/Continuous/Rigid_motion.h>
#include <PCCD/Continuous/time_of_contact.h>
#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/internal/parallel.h>

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pccd_python {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// What the queries return to Python: PCCD's result, converted on access; the query's wall time
/// (NaN for the results of time_of_contact_many); the counters' dict, built at the first access
/// and the same object afterwards.
struct Contact_time_held {
    PCCD::Contact_time_result r;
    double query_us = nan;
    py::object counters = {};
};

/// The start and end poses of one object's motion, and the centre of a linear motion.
struct Motion_poses {
    PCCD::Rigid_transform_3<double> from;
    PCCD::Rigid_transform_3<double> to;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// One query: the objects (kept alive by `keep`) and their motions.
struct Motion_case {
    Any_object a;
    Motion_poses motion_a;
    Any_object b;
    Motion_poses motion_b;
};

/// The length of a sequence argument, or -1 for anything else (a str or bytes, a 0-d array, ...).
Py_ssize_t sequence_length(py::handle value)
{
    if (!PySequence_Check(value.ptr()) || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) return -1;
    const Py_ssize_t n = PyObject_Length(value.ptr());
    if (n < 0) PyErr_Clear();
    return n;
}

/// A motion argument: a pair (pose at t = 0, pose at t = 1) of 3x4 / 4x4 array-likes or None
/// (identity), or None for an object at rest at the identity.
Motion_poses motion_argument(py::handle value, const std::string& name)
{
    Motion_poses m;
    if (value.is_none()) return m;
    const Py_ssize_t n = sequence_length(value);
    if (n != 2) {
        std::string got = n >= 0 ? "a sequence of length " + std::to_string(n)
                                 : std::string(py::str(py::type::handle_of(value).attr("__name__")));
        if (py::isinstance<py::array>(value)) {
            const py::array a = py::reinterpret_borrow<py::array>(value);
            got = "an array of shape (";
            for (py::ssize_t d = 0; d < a.ndim(); ++d) got += (d ? ", " : "") + std::to_string(a.shape(d));
            got += a.ndim() == 1 ? ",)" : ")";
        }
        throw py::value_error(name + " must be a pair (pose at t = 0, pose at t = 1) of 3x4 or 4x4 rigid poses, or "
                                     "None for an object at rest at the identity; got " + got +
                              " (an object at rest at a pose p: (p, p))");
    }
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
    m.from = pose_argument(pair[0], (name + "[0]").c_str());
    m.to = pose_argument(pair[1], (name + "[1]").c_str());
    return m;
}

/// A centre argument: None (the local origin) or 3 finite numbers.
Eigen::Vector3d centre_argument(py::handle value, const char* name)
{
    if (value.is_none()) return Eigen::Vector3d::Zero();
    py::array any = py::array::ensure(value);
    const char kind = any ? any.dtype().kind() : 'O';
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw py::value_error(std::string(name) + " must be 3 numbers (a point in the object's own frame) or None");
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(any);
    if (a.ndim() != 1 || a.shape(0) != 3)
        throw py::value_error(std::string(name) + " must have shape (3,), got " + std::to_string(a.size()) +
                              " numbers in " + std::to_string(a.ndim()) + " dimensions");
    const Eigen::Vector3d c(a.data()[0], a.data()[1], a.data()[2]);
    if (!c.allFinite())
        throw py::value_error(std::string(name) + " must be finite, got [" +
                              PCCD::Rigid_transform_3<double>::full_digits(c.x()) + ", " +
                              PCCD::Rigid_transform_3<double>::full_digits(c.y()) + ", " +
                              PCCD::Rigid_transform_3<double>::full_digits(c.z()) + "]");
    return c;
}

/// The motion kind of the `motion` argument: true for screw.
bool screw_argument(const std::string& motion, const char* function)
{
    if (motion == "linear") return false;
    if (motion == "screw") return true;
    throw py::value_error(std::string(function) + "(): motion must be 'linear' or 'screw', not '" + motion + "'");
}

/// The library's options from the keyword arguments, checked by its own rule (ValueError naming the
/// field).
PCCD::Contact_time_options contact_time_options(double tolerance, const std::optional<double>& time_accuracy,
                                                double near_step, std::size_t max_steps, std::uint64_t seed,
                                                const char* function)
{
    PCCD::Contact_time_options o;
    o.tolerance = tolerance;
    o.time_accuracy = time_accuracy;
    o.near_step = near_step;
    o.max_steps = max_steps;
    o.distance.intersection.seed = seed;
    PCCD::internal::check_options(o, function);
    return o;
}

/// PCCD::time_of_contact on one case, both objects moving linearly or both by screws.
PCCD::Contact_time_result run_case(const Motion_case& c, bool screw, const PCCD::Contact_time_options& options)
{
    return visit_objects(c.a, c.b, [&](const auto& a, const auto& b) {
        if (screw)
            return PCCD::time_of_contact(a, PCCD::Screw_motion(c.motion_a.from, c.motion_a.to), b,
                                         PCCD::Screw_motion(c.motion_b.from, c.motion_b.to), options);
        return PCCD::time_of_contact(a, PCCD::Linear_motion(c.motion_a.from, c.motion_a.to, c.motion_a.centre), b,
                                     PCCD::Linear_motion(c.motion_b.from, c.motion_b.to, c.motion_b.centre), options);
    });
}

py::array_t<double> vector_array(const Eigen::Vector3d& v)
{
    py::array_t<double> a(3);
    auto out = a.mutable_unchecked<1>();
    for (int j = 0; j < 3; ++j) out(j) = v(j);
    return a;
}

py::dict counters_dict(const PCCD::Contact_time_counters& c)
{
    py::dict d;
    PCCD::for_each_counter(c, [&](const char* name, std::size_t value) { d[name] = value; });
    return d;
}

std::string number_text(double x)
{
    return PCCD::Rigid_transform_3<double>::full_digits(x);
}

const std::string options_doc = R"doc(motion : {'linear', 'screw'}, optional
    How both objects move from their pose at t = 0 to their pose at t = 1. 'linear' (default,
    PCCD::Linear_motion): the centre moves on a straight line at constant speed while the rotation
    turns about it at constant angular speed (slerp, the shorter way). 'screw'
    (PCCD::Screw_motion): the constant screw (rotation about one axis and translation along it)
    from the start pose to the end pose.
tolerance : float, optional
    Surfaces closer than this (world units) are in contact. Default 0: contact means the implicit
    surfaces intersect. Finite and >= 0.
time_accuracy : float, optional
    The bracket [t_low, t_high] of a contact is narrowed until no point moves farther than this
    (world units) within it. None (default): the library's, a fraction of the smaller sampling
    radius (Contact_time_options::time_accuracy). Finite and > 0.
near_step : float, optional
    Near contact the motion is checked at sub-steps across which no point moves farther than
    near_step sampling radii (default 0.5; in (0, 4]).
max_steps : int, optional
    Budget of steps (advancement, near checks and bisection together; default 100000, >= 1); once
    spent the status is 'undecided'.
seed : int, optional
    Seed of the contact checks (default 24301 = 0x5eed): the same seed gives the same answer and
    counters, on every platform and for any number of threads.)doc";

const std::string time_of_contact_doc = std::string(R"doc(When two objects moving rigidly first come into contact.

PCCD::time_of_contact: the first time t in [0, 1] at which the implicit surfaces of `a` and `b`,
each moving from its pose at t = 0 to its pose at t = 1, intersect (or come closer than
`tolerance`), found by conservative advancement on a certified lower bound of their distance,
contact checks at short sub-steps near contact and bisection. A contact shorter than the near
sub-step can be missed (it is then shallower than about near_step sampling radii).

Parameters
----------
a, b : Object or LeanObject
    The two objects (either kind, in any mix).
motion_a, motion_b : tuple
    (pose at t = 0, pose at t = 1), each a 3x4 array [R | t] or a 4x4 homogeneous matrix (last
    row 0 0 0 1) or None (the identity), under the rigidity rule of do_intersect; None for an
    object at rest at the identity.
centre_a, centre_b : array_like of 3 floats, optional
    motion='linear' only: the point of each object (its own frame) that moves on a straight line.
    None (default): the object's origin. The object's centre gives the tightest speed bound.
)doc") + options_doc + R"doc(

Returns
-------
ContactTimeResult
    ``status`` ('contact', 'no_contact' or 'undecided'), ``t``, ``t_low``, ``t_high``, ``point``,
    ``normal``, ``counters``, ``query_us``: the fields of PCCD::Contact_time_result;
    ``bool(result)`` is True for a contact.

Raises
------
ValueError
    A motion that is not a pair of rigid poses (NaN, scaling, shear, reflection, wrong shape), a
    centre that is not 3 finite numbers or is given for a screw motion, an unknown motion, an
    invalid option (a negative or NaN tolerance, time_accuracy <= 0, near_step outside (0, 4],
    max_steps=0), or motions too fast for a finite speed bound; the message names it.
TypeError
    A value of the wrong type.

See Also
--------
time_of_contact_many, do_intersect, distance

Examples
--------
>>> still = (None, None)
>>> through = (np.array([[1., 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0]]),
...            np.array([[1., 0, 0, -4], [0, 1, 0, 0], [0, 0, 1, 0]]))
>>> r = pccd.time_of_contact(ball, still, ball, through)
>>> r.status, round(r.t, 2)
('contact', 0.25)
)doc";

const std::string time_of_contact_many_doc = std::string(R"doc(time_of_contact for many pairs in one call, on several threads.

Parameters
----------
pairs : iterable of tuple
    Tuples (object_a, motion_a, object_b, motion_b) or (object_a, motion_a, object_b, motion_b,
    centre_a, centre_b), the arguments of time_of_contact.
threads : int, optional
    Worker threads, 1 to 4096; None (default) uses all available. The results do not depend on
    it.
first_index : int, optional
    Index of pairs[0] in a larger batch split into chunks (default 0): pair i is seeded as pair
    first_index + i of the whole.
)doc") + options_doc + R"doc(

Returns
-------
list of ContactTimeResult
    One result per pair, in input order: result i is what
    ``time_of_contact(*pairs[i], seed=pccd.pair_seed(seed, first_index + i), ...)`` returns, for
    any number of threads (``query_us`` is NaN: the pairs run concurrently).

Raises
------
ValueError
    A pair that is not a 4- or 6-tuple, a bad motion or centre (naming the pair), threads=0 or an
    invalid option; nothing is computed then.
TypeError
    Items 0 and 2 of a pair are not Object or LeanObject instances.
)doc";

const char* result_doc = R"doc(The answer of time_of_contact() and time_of_contact_many(): PCCD::Contact_time_result.

Attributes
----------
status : str
    'contact' (the surfaces come within the tolerance at time t), 'no_contact' (they stay
    farther apart over [0, 1]) or 'undecided' (the step budget ran out: no contact before t_low,
    unknown after).
t : float
    contact: the first time found in contact (= t_high). NaN otherwise.
t_low, t_high : float
    The bracket. contact: t_low <= t = t_high, no contact before t_low (t_low = t_high = 0 for a
    contact at the start). no_contact: t_low = 1, t_high NaN. undecided: t_low is how far the
    query got, t_high NaN.
point : numpy.ndarray
    contact: a point of the contact (world frame, at time t), shape (3,). NaN otherwise.
normal : numpy.ndarray
    contact: the unit contact normal there, the direction in which B must move to leave A. NaN
    otherwise (and where the surfaces' normals cancel).
counters : dict
    advancement_steps, near_checks, bisection_steps, node_pairs, f_evaluations (the names of
    ``pccd contact-time --json``). Built at the first access, the same dict afterwards.
query_us : float
    Wall-clock microseconds of the query in PCCD's C++; NaN for the results of
    time_of_contact_many.
)doc";

} // namespace

void add_continuous(py::module_& m)
{
    py::class_<Contact_time_held>(m, "ContactTimeResult", result_doc)
        .def_property_readonly("status", [](const Contact_time_held& h) { return PCCD::to_string(h.r.status); })
        .def_property_readonly("t", [](const Contact_time_held& h) { return h.r.t; })
        .def_property_readonly("t_low", [](const Contact_time_held& h) { return h.r.t_low; })
        .def_property_readonly("t_high", [](const Contact_time_held& h) { return h.r.t_high; })
        .def_property_readonly("point", [](const Contact_time_held& h) { return vector_array(h.r.point); })
        .def_property_readonly("normal", [](const Contact_time_held& h) { return vector_array(h.r.normal); })
        .def_property_readonly("counters",
                               [](Contact_time_held& h) {
                                   if (!h.counters) h.counters = counters_dict(h.r.counters);
                                   return h.counters;
                               })
        .def_property_readonly("query_us", [](const Contact_time_held& h) { return h.query_us; })
        .def("__bool__", [](const Contact_time_held& h) { return bool(h.r); })
        .def("__repr__", [](const Contact_time_held& h) {
            const std::string status = PCCD::to_string(h.r.status);
            if (h.r.status == PCCD::Contact_time_status::contact)
                return "<pccd.ContactTimeResult: contact at t = " + number_text(h.r.t) + " (after " +
                       number_text(h.r.t_low) + ")>";
            if (h.r.status == PCCD::Contact_time_status::no_contact) return std::string("<pccd.ContactTimeResult: no_contact>");
            return "<pccd.ContactTimeResult: undecided, no contact before " + number_text(h.r.t_low) + ">";
        });

    m.def(
        "time_of_contact",
        [](const py::object& a, const py::object& motion_a, const py::object& b, const py::object& motion_b,
           const std::string& motion, const py::object& centre_a, const py::object& centre_b, double tolerance,
           const std::optional<double>& time_accuracy, double near_step, std::size_t max_steps, std::uint64_t seed) {
            const char* function = "time_of_contact";
            const bool screw = screw_argument(motion, function);
            const PCCD::Contact_time_options options =
                contact_time_options(tolerance, time_accuracy, near_step, max_steps, seed, function);
            if (screw && !(centre_a.is_none() && centre_b.is_none()))
                throw py::value_error(std::string(function) + "(): " + (centre_a.is_none() ? "centre_b" : "centre_a") +
                                      " applies to motion='linear' only (a screw turns about its own axis)");
            Motion_case c;
            c.a = any_object(a, function + std::string("()"), "a must be a pccd.Object or a pccd.LeanObject");
            c.b = any_object(b, function + std::string("()"), "b must be a pccd.Object or a pccd.LeanObject");
            c.motion_a = motion_argument(motion_a, "motion_a");
            c.motion_b = motion_argument(motion_b, "motion_b");
            c.motion_a.centre = centre_argument(centre_a, "centre_a");
            c.motion_b.centre = centre_argument(centre_b, "centre_b");
            Contact_time_held out;
            {
                py::gil_scoped_release release;
                const auto start = std::chrono::steady_clock::now();
                out.r = run_case(c, screw, options);
                out.query_us =
                    std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
            }
            return out;
        },
        py::arg("a"), py::arg("motion_a"), py::arg("b"), py::arg("motion_b"), py::kw_only(), py::arg("motion") = "linear",
        py::arg("centre_a") = py::none(), py::arg("centre_b") = py::none(), py::arg("tolerance") = 0.0,
        py::arg("time_accuracy") = py::none(), py::arg("near_step") = PCCD::Contact_time_options{}.near_step,
        py::arg("max_steps") = PCCD::Contact_time_options{}.max_steps,
        py::arg("seed") = PCCD::Intersection_options{}.seed, time_of_contact_doc.c_str());

    m.def(
        "time_of_contact_many",
        [](const py::iterable& pairs, const std::string& motion, double tolerance, const std::optional<double>& time_accuracy,
           double near_step, std::size_t max_steps, std::uint64_t seed, const std::optional<unsigned>& threads,
           std::uint64_t first_index) {
            const char* function = "time_of_contact_many";
            const bool screw = screw_argument(motion, function);
            const PCCD::Contact_time_options options =
                contact_time_options(tolerance, time_accuracy, near_step, max_steps, seed, function);
            if (threads && (*threads == 0 || *threads > PCCD::Batch_options::max_threads))
                throw py::value_error(std::string(function) + "(): threads = " + std::to_string(*threads) +
                                      " must be from 1 to " + std::to_string(PCCD::Batch_options::max_threads) +
                                      " (None: all available threads)");
            std::vector<Motion_case> cases;
            std::vector<py::object> keep;
            for (const py::handle item : pairs) {
                const std::string where = "pairs[" + std::to_string(cases.size()) + "]";
                const Py_ssize_t n = sequence_length(item);
                if (n != 4 && n != 6)
                    throw py::value_error(where + " must be a tuple (object_a, motion_a, object_b, motion_b) or "
                                                  "(object_a, motion_a, object_b, motion_b, centre_a, centre_b)");
                const py::sequence pair = py::reinterpret_borrow<py::sequence>(item);
                const py::object a = pair[0];
                const py::object b = pair[2];
                Motion_case c;
                const char* requirement = "items 0 and 2 must be pccd.Object or pccd.LeanObject instances";
                c.a = any_object(a, where, requirement);
                c.b = any_object(b, where, requirement);
                try {
                    c.motion_a = motion_argument(pair[1], "motion_a");
                    c.motion_b = motion_argument(pair[3], "motion_b");
                    if (n == 6) {
                        const py::object ca = pair[4], cb = pair[5];
                        if (screw && !(ca.is_none() && cb.is_none()))
                            throw py::value_error(std::string(ca.is_none() ? "centre_b" : "centre_a") +
                                                  " applies to motion='linear' only (a screw turns about its own axis)");
                        c.motion_a.centre = centre_argument(ca, "centre_a");
                        c.motion_b.centre = centre_argument(cb, "centre_b");
                    }
                } catch (const std::exception& e) {
                    throw py::value_error(where + ": " + e.what());
                }
                cases.push_back(c);
                keep.push_back(a);
                keep.push_back(b);
            }
            std::vector<PCCD::Contact_time_result> results(cases.size());
            std::vector<std::exception_ptr> errors(cases.size());
            {
                py::gil_scoped_release release;
                // Each pair is seeded by its index only, and answered on its own: the results do
                // not depend on the schedule (the rule of do_intersect_many and distance_many).
                PCCD::internal::with_threads(threads, [&] {
                    PCCD::internal::parallel_for_ranges(cases.size(), 1, [&](std::size_t begin, std::size_t end) {
                        for (std::size_t i = begin; i < end; ++i) {
                            try {
                                PCCD::Contact_time_options pair_options = options;
                                pair_options.distance.intersection.seed = PCCD::pair_seed(seed, first_index + i);
                                results[i] = run_case(cases[i], screw, pair_options);
                            } catch (...) {
                                errors[i] = std::current_exception();
                            }
                        }
                    });
                });
            }
            // The error of the first pair that failed, in input order (what a loop would raise).
            for (std::size_t i = 0; i < errors.size(); ++i) {
                if (!errors[i]) continue;
                try {
                    std::rethrow_exception(errors[i]);
                } catch (const PCCD::Invalid_input& e) {
                    throw py::value_error("pairs[" + std::to_string(i) + "]: " + e.what());
                }
            }
            std::vector<Contact_time_held> out;
            out.reserve(results.size());
            for (PCCD::Contact_time_result& r : results) out.push_back(Contact_time_held{std::move(r)});
            return out;
        },
        py::arg("pairs"), py::kw_only(), py::arg("motion") = "linear", py::arg("tolerance") = 0.0,
        py::arg("time_accuracy") = py::none(), py::arg("near_step") = PCCD::Contact_time_options{}.near_step,
        py::arg("max_steps") = PCCD::Contact_time_options{}.max_steps,
        py::arg("seed") = PCCD::Intersection_options{}.seed, py::arg("threads") = py::none(),
        py::arg("first_index") = 0, time_of_contact_many_doc.c_str());
}

} // namespace pccd_python
