// python/src/world.cpp -- pccd.World, a PCCD::Collision_world over pccd.Object instances, and
// pccd.WorldHandle, the name of one instance: insertion, moves (one pose or an (n, 3, 4) array of
// poses in one call), erasure, collision filters and excluded pairs, and the world's queries (all
// intersecting pairs, the instances one instance or a query object touches, within a distance, in a
// box), each run with the GIL released (doc/manual/world.md).
#include "pccd_python.h"

#include <PCCD/Error.h>
#include <PCCD/World/Collision_world.h>
#include <PCCD/World/World_handle.h>
#include <PCCD/World/World_options.h>
#include <PCCD/World/World_results.h>

#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pccd_python {

namespace {

using Handle = PCCD::World_handle;
using Pose = PCCD::Rigid_transform_3<double>;

/// A new float64 array of shape (3,).
py::array_t<double> vector_array(const Eigen::Vector3d& v)
{
    py::array_t<double> a(3);
    auto out = a.mutable_unchecked<1>();
    for (int k = 0; k < 3; ++k) out(k) = v(k);
    return a;
}

/// The 3x4 [R | t] of a pose as a new float64 array.
py::array_t<double> pose_array(const Pose& pose)
{
    py::array_t<double> a({py::ssize_t(3), py::ssize_t(4)});
    auto out = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < 3; ++i) {
        for (py::ssize_t j = 0; j < 3; ++j) out(i, j) = pose.rotation()(i, j);
        out(i, 3) = pose.translation()(i);
    }
    return a;
}

/// A group or mask argument: an int in [0, 2**32).
std::uint32_t filter_bits(const py::handle& value, const char* function, const char* name)
{
    if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
        throw py::type_error(std::string(function) + "(): " + name + " must be an int, not " +
                             std::string(py::str(py::type::handle_of(value).attr("__name__"))));
    const py::int_ v = py::reinterpret_borrow<py::int_>(value);
    if (v < py::int_(0) || v > py::int_(0xFFFFFFFFull))
        throw py::value_error(std::string(function) + "(): " + name + " = " + std::string(py::str(static_cast<const py::handle&>(v))) +
                              " must be in [0, 2**32) (a 32-bit set of collision groups)");
    return v.cast<std::uint32_t>();
}

/// A handle argument: TypeError for anything but a pccd.WorldHandle.
Handle handle_argument(const py::handle& value, const char* function, const char* name)
{
    if (!py::isinstance<Handle>(value))
        throw py::type_error(std::string(function) + "(): " + name + " must be a pccd.WorldHandle, not " +
                             std::string(py::str(py::type::handle_of(value).attr("__name__"))));
    return value.cast<Handle>();
}

/// pccd.World. The C++ world holds its objects by std::shared_ptr<const Object>, while pccd.Object
/// instances live in Python objects (pybind11's default holder). The choice made here: the wrapper
/// keeps, for every slot of the world, a reference to the Python object inserted there
/// (`m_objects`, indexed like the world's slots, released when the instance is erased), and hands
/// the C++ world a non-owning std::shared_ptr that aliases the Object inside that Python object.
/// So an object lives at least as long as an instance uses it, nothing is copied or allocated per
/// instance besides one Python reference, no reference is ever dropped without the GIL (erase and
/// the world's destruction run under it, unlike a shared_ptr deleter that could run on a worker
/// thread), and World.object(h) returns the very Python object inserted. (pccd.Object copies would
/// share their data too, but not their identity.) The world is destroyed before m_objects (member
/// order), so it never holds a pointer to a released object.
///
/// The queries release the GIL; a mutex then keeps another Python thread from changing the world
/// (or querying it: intersecting_pairs updates the cache) meanwhile. It is taken after the
/// arguments are converted, and waited for without the GIL.
class World {
public:
    using Cpp_world = PCCD::Collision_world<Object>;

    World(const PCCD::World_options& options, const PCCD::Interpolation_search& policy) : m_world(options, policy) {}

    Cpp_world& world() { return m_world; }
    const Cpp_world& world() const { return m_world; }

    std::unique_lock<std::mutex> lock()
    {
        std::unique_lock<std::mutex> l(m_mutex, std::try_to_lock);
        if (!l.owns_lock()) {
            py::gil_scoped_release release;
            l.lock();
        }
        return l;
    }

    Handle insert(const py::object& object, const Pose& pose, const PCCD::Collision_filter& filter)
    {
        const Object& o = object.cast<const Object&>();
        const std::shared_ptr<const Object> alias(std::shared_ptr<const Object>(), &o); // non-owning, see the class
        const auto l = lock();
        const Handle h = m_world.insert(alias, pose, filter);
        if (m_objects.size() <= h.index) m_objects.resize(std::size_t(h.index) + 1);
        m_objects[h.index] = object;
        return h;
    }

    void erase(Handle h)
    {
        py::object released; // dropped after the lock, under the GIL
        {
            const auto l = lock();
            m_world.erase(h);
            released = std::move(m_objects[h.index]);
        }
    }

    py::object object(Handle h)
    {
        const auto l = lock();
        m_world.object(h); // throws Invalid_input for a stale handle
        return m_objects[h.index];
    }

private:
    std::vector<py::object> m_objects;
    std::mutex m_mutex;
    Cpp_world m_world;
};

py::list handle_list(const std::vector<Handle>& handles)
{
    py::list out;
    for (const Handle& h : handles) out.append(py::cast(h));
    return out;
}

py::list hit_list(const std::vector<PCCD::World_hit>& hits, bool details)
{
    py::list out;
    for (const PCCD::World_hit& hit : hits) {
        if (details)
            out.append(py::make_tuple(hit.handle, PCCD::to_string(hit.status), vector_array(hit.point)));
        else
            out.append(py::cast(hit.handle));
    }
    return out;
}

py::list proximity_list(const std::vector<PCCD::World_proximity>& near)
{
    py::list out;
    for (const PCCD::World_proximity& p : near) out.append(py::make_tuple(p.handle, clearance_result(p.clearance)));
    return out;
}

double margin_argument(double margin, const char* function)
{
    if (!(std::isfinite(margin) && margin >= 0.0))
        throw py::value_error(std::string(function) + "(): margin " + std::string(py::str(py::float_(margin))) +
                              " must be finite and >= 0 (world units)");
    return margin;
}

Eigen::Vector3d corner_argument(const py::handle& value, const char* name)
{
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    py::array any = py::array::ensure(value);
    const char kind = any ? any.dtype().kind() : 'O';
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw py::value_error(std::string("World.overlapping(): ") + name + " must be 3 numbers");
    const Array a = Array::ensure(any);
    if (a.ndim() != 1 || a.shape(0) != 3)
        throw py::value_error(std::string("World.overlapping(): ") + name + " must have shape (3,)");
    return Eigen::Vector3d(a.data()[0], a.data()[1], a.data()[2]);
}

const char* world_doc = R"doc(A collision world: many posed instances of pccd.Object, with a broad phase (a dynamic
AABB tree over the instances' world boxes), a narrow phase (do_intersect) run in parallel, and a
cache of the answers of pairs that did not move (PCCD::Collision_world, doc/manual/world.md).

World(*, threads=None, cache=True, **options)

One Object may be inserted any number of times, at different poses: instances share it.

Parameters
----------
threads : int, optional
    Worker threads of the narrow phase, 1 to 4096; None (default): all available. The answers do
    not depend on it.
cache : bool, optional
    Keep the answer of every candidate pair and reuse it while neither instance moved (default
    True). The answers do not depend on it.
**options
    The narrow phase's options: the keyword arguments of pccd.do_intersect (seed, epsilon,
    max_f_evaluations, traversal, samples, ...; method must be 'isearch').

Notes
-----
Pair (a, b) with a.index < b.index is answered exactly as
``pccd.do_intersect(world.object(a), world.pose(a), world.object(b), world.pose(b), **options,
seed=pccd.pair_seed(seed, pccd.world_pair_key(a.index, b.index)))``, so intersecting_pairs() equals
that brute force over all pairs the filters allow. The queries release the GIL.

Examples
--------
>>> world = pccd.World(threads=2)
>>> a = world.insert(bunny, None)
>>> b = world.insert(bunny, turn)
>>> world.intersecting_pairs()
[(WorldHandle(index=0, generation=0), WorldHandle(index=1, generation=0))]
)doc";

} // namespace

void add_world(py::module_& m)
{
    py::class_<Handle>(m, "WorldHandle", R"doc(The name of one instance of a pccd.World: a slot index and the slot's generation.

Erasing an instance makes its handle stale (the world raises ValueError for it); a later instance
in the same slot gets a new generation. Immutable, hashable, ordered by (index, generation).

WorldHandle(index, generation=0)
)doc")
        .def(py::init([](std::uint32_t index, std::uint32_t generation) { return Handle{index, generation}; }),
             py::arg("index"), py::arg("generation") = 0)
        .def_readonly("index", &Handle::index, "int: The slot index.")
        .def_readonly("generation", &Handle::generation, "int: The slot's generation.")
        .def("__eq__", [](const Handle& a, const py::object& b) { return py::isinstance<Handle>(b) && a == b.cast<Handle>(); })
        .def("__ne__", [](const Handle& a, const py::object& b) { return !(py::isinstance<Handle>(b) && a == b.cast<Handle>()); })
        .def("__lt__", [](const Handle& a, const Handle& b) { return a < b; })
        .def("__le__", [](const Handle& a, const Handle& b) { return a <= b; })
        .def("__gt__", [](const Handle& a, const Handle& b) { return a > b; })
        .def("__ge__", [](const Handle& a, const Handle& b) { return a >= b; })
        .def("__hash__", [](const Handle& h) { return py::hash(py::make_tuple(h.index, h.generation)); })
        .def("__repr__", [](const Handle& h) {
            return "WorldHandle(index=" + std::to_string(h.index) + ", generation=" + std::to_string(h.generation) + ")";
        })
        .def(py::pickle([](const Handle& h) { return py::make_tuple(h.index, h.generation); },
                        [](const py::tuple& t) { return Handle{t[0].cast<std::uint32_t>(), t[1].cast<std::uint32_t>()}; }));

    m.def("world_pair_key", &PCCD::world_pair_key, py::arg("i"), py::arg("j"),
          R"doc(The key of the unordered pair of world instances with slot indices i and j: (min << 32) | max.

Pair (a, b) of a pccd.World is answered with ``seed=pair_seed(seed, world_pair_key(a.index,
b.index))``.

Parameters
----------
i, j : int
    Slot indices (WorldHandle.index), 0 <= i, j < 2**32.

Returns
-------
int
)doc");

    py::class_<World>(m, "World", world_doc)
        .def(py::init([](std::optional<unsigned> threads, bool cache, const py::kwargs& kwargs) {
                 const World_narrow_phase narrow = world_narrow_phase(kwargs, "World");
                 PCCD::World_options options;
                 options.intersection = narrow.options;
                 options.threads = threads;
                 options.cache_results = cache;
                 return std::make_unique<World>(options, narrow.isearch);
             }),
             py::kw_only(), py::arg("threads") = py::none(), py::arg("cache") = true)
        .def(
            "insert",
            [](World& w, const py::object& object, const py::object& pose, const py::object& group,
               const py::object& mask) {
                if (!py::isinstance<Object>(object))
                    throw py::type_error("World.insert(): object must be a pccd.Object, not " +
                                         std::string(py::str(py::type::handle_of(object).attr("__name__"))) +
                                         (py::isinstance<Lean_object>(object)
                                              ? " (a World holds pccd.Object instances only; C++ worlds of lean objects: "
                                                "PCCD::Collision_world<PCCD::Euclidean_point_cloud_object<>>)"
                                              : ""));
                const Pose p = pose_argument(pose, "pose");
                const PCCD::Collision_filter filter{filter_bits(group, "World.insert", "group"),
                                                    filter_bits(mask, "World.insert", "mask")};
                return w.insert(object, p, filter);
            },
            py::arg("object"), py::arg("pose"), py::arg("group") = 1, py::arg("mask") = 0xFFFFFFFFull,
            R"doc(Add an instance of `object` at `pose`; return its handle.

Parameters
----------
object : Object
    The object (shared: the world keeps a reference, any number of instances may use it).
pose : array_like or None
    3x4 [R | t] or 4x4 rigid transform, None for the identity.
group, mask : int, optional
    The collision filter: instances a and b are tested only if ``a.group & b.mask`` and
    ``b.group & a.mask`` are both non-zero (default group 1, mask 0xFFFFFFFF: everything collides).

Returns
-------
WorldHandle

Raises
------
ValueError
    A pose that is not rigid (NaN, scaling, shear, reflection, wrong shape), group or mask outside
    [0, 2**32).
TypeError
    `object` is not a pccd.Object.
)doc")
        .def(
            "set_pose",
            [](World& w, const py::object& h, const py::object& pose) {
                const Handle handle = handle_argument(h, "World.set_pose", "handle");
                const Pose p = pose_argument(pose, "pose");
                const auto l = w.lock();
                w.world().set_pose(handle, p);
            },
            py::arg("handle"), py::arg("pose"),
            "Move instance `handle` to `pose` (3x4, 4x4 or None). ValueError for a stale handle or a bad pose.")
        .def(
            "set_poses",
            [](World& w, const py::sequence& handles, const py::object& poses) {
                std::vector<Handle> list;
                list.reserve(py::len(handles));
                for (std::size_t i = 0; i < py::len(handles); ++i)
                    list.push_back(handle_argument(handles[i], "World.set_poses", ("handles[" + std::to_string(i) + "]").c_str()));
                const std::vector<Pose> p = pose_stack(poses, "World.set_poses", "poses");
                if (p.size() != list.size())
                    throw py::value_error("World.set_poses(): " + std::to_string(list.size()) + " handles but " +
                                          std::to_string(p.size()) + " poses");
                const auto l = w.lock();
                w.world().set_poses(list, p);
            },
            py::arg("handles"), py::arg("poses"),
            R"doc(Move many instances in one call: instance handles[i] to poses[i].

Parameters
----------
handles : sequence of WorldHandle
poses : numpy.ndarray
    (n, 3, 4) or (n, 4, 4) array (read in one pass, no Python object per pose).

Raises
------
ValueError
    A shape or length mismatch, a pose that is not rigid (the message names poses[i]) or a stale
    handle. Everything is checked before any instance moves.
)doc")
        .def("erase", [](World& w, const py::object& h) { w.erase(handle_argument(h, "World.erase", "handle")); },
             py::arg("handle"), "Remove instance `handle`; its handle becomes stale. ValueError for a stale handle "
                                "(e.g. erasing twice).")
        .def("__len__", [](World& w) {
            const auto l = w.lock();
            return w.world().size();
        })
        .def("__contains__", [](World& w, const py::object& h) {
            if (!py::isinstance<Handle>(h)) return false;
            const auto l = w.lock();
            return w.world().contains(h.cast<Handle>());
        })
        .def(
            "handles",
            [](World& w) {
                std::vector<Handle> handles;
                {
                    const auto l = w.lock();
                    handles = w.world().handles();
                }
                return handle_list(handles);
            },
            "list of WorldHandle: every live instance, in increasing index order.")
        .def("object", [](World& w, const py::object& h) { return w.object(handle_argument(h, "World.object", "handle")); },
             py::arg("handle"), "Object: the object instance `handle` uses (the one inserted).")
        .def(
            "pose",
            [](World& w, const py::object& h) {
                const Handle handle = handle_argument(h, "World.pose", "handle");
                const auto l = w.lock();
                return pose_array(w.world().pose(handle));
            },
            py::arg("handle"), "numpy.ndarray: the (3, 4) pose [R | t] of instance `handle`.")
        .def(
            "box",
            [](World& w, const py::object& h) {
                const Handle handle = handle_argument(h, "World.box", "handle");
                const auto l = w.lock();
                const Eigen::AlignedBox3d& b = w.world().box(handle);
                return py::make_tuple(vector_array(b.min()), vector_array(b.max()));
            },
            py::arg("handle"), "(numpy.ndarray, numpy.ndarray): the world box (min, max) the broad phase files "
                               "instance `handle` under.")
        .def(
            "filter",
            [](World& w, const py::object& h) {
                const Handle handle = handle_argument(h, "World.filter", "handle");
                const auto l = w.lock();
                const PCCD::Collision_filter& f = w.world().filter(handle);
                return py::make_tuple(f.group, f.mask);
            },
            py::arg("handle"), "(int, int): the (group, mask) of instance `handle`.")
        .def(
            "set_filter",
            [](World& w, const py::object& h, const py::object& group, const py::object& mask) {
                const Handle handle = handle_argument(h, "World.set_filter", "handle");
                const PCCD::Collision_filter filter{filter_bits(group, "World.set_filter", "group"),
                                                    filter_bits(mask, "World.set_filter", "mask")};
                const auto l = w.lock();
                w.world().set_filter(handle, filter);
            },
            py::arg("handle"), py::arg("group"), py::arg("mask") = 0xFFFFFFFFull,
            "Set the collision filter (group, mask) of instance `handle` (see insert).")
        .def(
            "exclude_pair",
            [](World& w, const py::object& a, const py::object& b) {
                const Handle ha = handle_argument(a, "World.exclude_pair", "a");
                const Handle hb = handle_argument(b, "World.exclude_pair", "b");
                const auto l = w.lock();
                w.world().exclude_pair(ha, hb);
            },
            py::arg("a"), py::arg("b"),
            "Never test the pair (a, b) (forgotten when either is erased). ValueError for stale handles or a == b.")
        .def(
            "include_pair",
            [](World& w, const py::object& a, const py::object& b) {
                const Handle ha = handle_argument(a, "World.include_pair", "a");
                const Handle hb = handle_argument(b, "World.include_pair", "b");
                const auto l = w.lock();
                w.world().include_pair(ha, hb);
            },
            py::arg("a"), py::arg("b"), "Test the pair (a, b) again after exclude_pair.")
        .def(
            "excluded",
            [](World& w, const py::object& a, const py::object& b) {
                const Handle ha = handle_argument(a, "World.excluded", "a");
                const Handle hb = handle_argument(b, "World.excluded", "b");
                const auto l = w.lock();
                return w.world().excluded(ha, hb);
            },
            py::arg("a"), py::arg("b"), "bool: whether the pair (a, b) was excluded.")
        .def(
            "intersecting_pairs",
            [](World& w, bool details, std::optional<std::size_t> limit) {
                if (limit && *limit == 0)
                    throw py::value_error("World.intersecting_pairs(): limit must be >= 1 (None: every pair)");
                std::vector<PCCD::World_pair> pairs;
                {
                    const auto l = w.lock();
                    py::gil_scoped_release release;
                    if (limit)
                        w.world().for_each_intersecting_pair([&](const PCCD::World_pair& p) {
                            pairs.push_back(p);
                            return pairs.size() < *limit; // false: the query stops
                        });
                    else
                        pairs = w.world().intersecting_pairs();
                }
                py::list out;
                for (const PCCD::World_pair& p : pairs) {
                    if (details)
                        out.append(py::make_tuple(p.a, p.b, PCCD::to_string(p.status), vector_array(p.point)));
                    else
                        out.append(py::make_tuple(p.a, p.b));
                }
                return out;
            },
            py::kw_only(), py::arg("details") = false, py::arg("limit") = py::none(),
            R"doc(Every pair of instances whose surfaces intersect.

Parameters
----------
details : bool, optional
    False (default): tuples (a, b); True: tuples (a, b, status, point) with status 'intersecting'
    or 'undecided' (a budget of the options ran out; reported so that no contact is missed) and
    point the (3,) intersection point found (NaN when undecided).
limit : int, optional
    Stop after the first `limit` pairs (>= 1; the narrow phase answers candidate pairs in chunks
    that double, so it answers at most as many pairs beyond the stop as before it): ``limit=1``
    asks whether anything touches. None (default): every pair, in one parallel loop.

Returns
-------
list of tuple
    Sorted by (a.index, b.index), a.index < b.index; equal to brute-force do_intersect over all
    pairs the filters allow, with the pair seeds (see World), for any thread count, with or
    without the cache.

Notes
-----
Runs with the GIL released; only the pairs that moved since the last call are answered again when
the cache is on (see counters).
)doc")
        .def(
            "intersecting",
            [](World& w, const py::object& h, bool details) {
                const Handle handle = handle_argument(h, "World.intersecting", "handle");
                std::vector<PCCD::World_hit> hits;
                {
                    const auto l = w.lock();
                    py::gil_scoped_release release;
                    hits = w.world().intersecting(handle);
                }
                return hit_list(hits, details);
            },
            py::arg("handle"), py::kw_only(), py::arg("details") = false,
            R"doc(The instances instance `handle` intersects, in increasing index order: handles, or with
details=True tuples (handle, status, point). Each is answered as its pair in intersecting_pairs
(same seed); filters and excluded pairs apply. ValueError for a stale handle.
)doc")
        .def(
            "intersecting_object",
            [](World& w, const Object& object, const py::object& pose, const py::object& group, const py::object& mask,
               bool details) {
                const Pose p = pose_argument(pose, "pose");
                const PCCD::Collision_filter filter{filter_bits(group, "World.intersecting_object", "group"),
                                                    filter_bits(mask, "World.intersecting_object", "mask")};
                std::vector<PCCD::World_hit> hits;
                {
                    const auto l = w.lock();
                    py::gil_scoped_release release;
                    hits = w.world().intersecting(object, p, filter);
                }
                return hit_list(hits, details);
            },
            py::arg("object"), py::arg("pose"), py::arg("group") = 1, py::arg("mask") = 0xFFFFFFFFull, py::kw_only(),
            py::arg("details") = false,
            R"doc(The instances a query object (not in the world) at `pose` intersects, among those whose
filter agrees with (group, mask); instance i is answered with ``seed=pair_seed(seed, i)``.
Handles, or with details=True tuples (handle, status, point).
)doc")
        .def(
            "within_distance",
            [](World& w, const py::object& h, double margin) {
                const Handle handle = handle_argument(h, "World.within_distance", "handle");
                margin_argument(margin, "World.within_distance");
                std::vector<PCCD::World_proximity> near;
                {
                    const auto l = w.lock();
                    py::gil_scoped_release release;
                    near = w.world().within_distance(handle, margin);
                }
                return proximity_list(near);
            },
            py::arg("handle"), py::arg("margin"),
            R"doc(The instances whose surfaces come within `margin` of instance `handle`'s
(pccd.within_distance with default options, `handle` as a): a list of (handle, ClearanceResult),
in increasing index order. Filters and excluded pairs apply. ValueError for a stale handle or a
margin that is negative or not finite.
)doc")
        .def(
            "within_distance_object",
            [](World& w, const Object& object, const py::object& pose, double margin, const py::object& group,
               const py::object& mask) {
                const Pose p = pose_argument(pose, "pose");
                margin_argument(margin, "World.within_distance_object");
                const PCCD::Collision_filter filter{filter_bits(group, "World.within_distance_object", "group"),
                                                    filter_bits(mask, "World.within_distance_object", "mask")};
                std::vector<PCCD::World_proximity> near;
                {
                    const auto l = w.lock();
                    py::gil_scoped_release release;
                    near = w.world().within_distance(object, p, margin, filter);
                }
                return proximity_list(near);
            },
            py::arg("object"), py::arg("pose"), py::arg("margin"), py::arg("group") = 1, py::arg("mask") = 0xFFFFFFFFull,
            "within_distance for a query object at `pose`: a list of (handle, ClearanceResult).")
        .def(
            "overlapping",
            [](World& w, const py::object& box_min, const py::object& box_max) {
                const Eigen::AlignedBox3d box(corner_argument(box_min, "box_min"), corner_argument(box_max, "box_max"));
                std::vector<Handle> handles;
                {
                    const auto l = w.lock();
                    py::gil_scoped_release release;
                    handles = w.world().overlapping(box);
                }
                return handle_list(handles);
            },
            py::arg("box_min"), py::arg("box_max"),
            R"doc(The instances with a cloud point inside the axis-aligned box [box_min, box_max] (world
frame, boundary included), in increasing index order. ValueError for an empty or non-finite box.
)doc")
        .def_property_readonly(
            "counters",
            [](World& w) {
                const auto l = w.lock();
                const PCCD::World_counters& c = w.world().counters();
                py::dict d;
                d["broad_phase_pairs"] = c.broad_phase_pairs;
                d["filtered_pairs"] = c.filtered_pairs;
                d["cached_pairs"] = c.cached_pairs;
                d["narrow_phase_queries"] = c.narrow_phase_queries;
                d["reported_pairs"] = c.reported_pairs;
                return d;
            },
            "dict: what the last intersecting_pairs() did: broad_phase_pairs, filtered_pairs, cached_pairs, "
            "narrow_phase_queries, reported_pairs.")
        .def(
            "memory_bytes",
            [](World& w) {
                const auto l = w.lock();
                return w.world().memory_bytes();
            },
            "int: bytes the world holds besides the objects (slots, tree, candidate pairs, cache, excluded pairs).")
        .def_property_readonly("seed", [](const World& w) { return w.world().options().intersection.seed; },
                               "int: the seed of the narrow phase (pair seeds derive from it).")
        .def_property_readonly("threads", [](const World& w) { return w.world().options().threads; },
                               "int or None: the narrow phase's worker threads.")
        .def_property_readonly("cache", [](const World& w) { return w.world().options().cache_results; },
                               "bool: whether answers of unmoved pairs are reused.")
        .def("__repr__", [](World& w) {
            const auto l = w.lock();
            return "<pccd.World: " + std::to_string(w.world().size()) + " instance" +
                   (w.world().size() == 1 ? "" : "s") + ">";
        });
}

} // namespace pccd_python
