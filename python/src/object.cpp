// python/src/object.cpp -- pccd.Object: a PCCD::Point_cloud_object<> built from an (N, 3) numpy
// array read in place (PCCD copies the points into its own store, nothing else does), with its
// preprocessing options as keyword arguments, save() / load() (and pccd.load for a file of either
// kind), and read-only properties; the
// arrays it hands out are read-only views of the object's own data (doc/manual/python.md,
// "Objects").
#include "pccd_python.h"

#include <pybind11/stl.h>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/object_file_info.h>
#include <PCCD/sharp_feature_options.h>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <ranges>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace pccd_python {

namespace {

/// Reads row i of a Row_array: the point map of the constructor (PCCD's ReadablePointMap).
struct Row_map {
    const Row_array* rows;
    friend Eigen::Vector3d get(const Row_map& m, std::size_t i)
    {
        return Eigen::Vector3d(m.rows->at(i, 0), m.rows->at(i, 1), m.rows->at(i, 2));
    }
};

template <class T>
T option_value(const py::handle& value, const std::string& key, const std::string& who)
{
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(who + "(): option " + key + " has the wrong type (" +
                             std::string(py::str(py::type::handle_of(value).attr("__name__"))) + ")");
    }
}

/// The options the keyword arguments name; an unknown name raises TypeError, a value PCCD rejects
/// raises ValueError when the object is built.
/// The bounding volume named `name` ('box_and_slab', 'box', 'sphere'); `where` names the call in the error.
PCCD::Bounding_volume volume_of(const std::string& name, const std::string& where)
{
    if (const auto v = PCCD::bounding_volume_from_string(name)) return *v;
    throw py::value_error(where + ": volume must be 'box_and_slab', 'box' or 'sphere', not '" + name + "'");
}

/// The options of Object() (`who` "Object") or LeanObject() (`who` "LeanObject", which has no
/// proximity graph: `geodesic_only` names the keywords it refuses).
PCCD::Point_cloud_object_options object_options(const py::kwargs& kwargs, const std::string& who)
{
    static const std::vector<std::string> geodesic_only{"graph", "sig_r", "knn_k"};
    using Setter = std::function<void(PCCD::Point_cloud_object_options&, const py::handle&, const std::string&, const std::string&)>;
    static const std::map<std::string, Setter> setters{
        {"graph",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) {
             const auto name = option_value<std::string>(v, k, who);
             if (name == "sphere_of_influence") o.graph = PCCD::Graph_kind::sphere_of_influence;
             else if (name == "knn") o.graph = PCCD::Graph_kind::knn;
             else throw py::value_error(who + "(): graph must be 'sphere_of_influence' or 'knn', not '" + name + "'");
         }},
        {"sig_r", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.sphere_of_influence.r = option_value<unsigned>(v, k, who); }},
        {"knn_k", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.knn.k = option_value<unsigned>(v, k, who); }},
        {"eta", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.bandwidth.eta = option_value<double>(v, k, who); }},
        {"theta_eps", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.bandwidth.theta_eps = option_value<double>(v, k, who); }},
        {"bandwidth", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.bandwidth.bandwidth = option_value<std::optional<double>>(v, k, who); }},
        {"noise_factor", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.bandwidth.noise_factor = option_value<double>(v, k, who); }},
        {"surface_fit",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) {
             const auto name = option_value<std::string>(v, k, who);
             const std::optional<PCCD::Surface_fit> fit = PCCD::surface_fit_from_string(name);
             if (!fit) throw py::value_error(who + "(): surface_fit must be 'sphere', 'plane' or 'imls', not '" + name + "'");
             o.surface_fit = *fit;
         }},
        {"normal_bandwidth",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.normal_bandwidth = option_value<double>(v, k, who); }},
        {"normal_residual_scale",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) {
             o.normal_residual_scale = option_value<std::optional<double>>(v, k, who);
         }},
        {"domain", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.domain.enabled = option_value<bool>(v, k, who); }},
        {"domain_factor", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.domain.factor = option_value<double>(v, k, who); }},
        {"remove_outliers", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.outliers.remove = option_value<bool>(v, k, who); }},
        {"outlier_ratio", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.outliers.ratio = option_value<double>(v, k, who); }},
        {"sampling_radius_samples",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.sampling_radius.samples = option_value<std::size_t>(v, k, who); }},
        {"sampling_radius_seed",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.sampling_radius.seed = option_value<std::uint64_t>(v, k, who); }},
        {"leaf_size", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.hierarchy.leaf_size = option_value<std::size_t>(v, k, who); }},
        {"volume", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.hierarchy.volume = volume_of(option_value<std::string>(v, k, who), who + "()"); }},
        {"spatial_order", [](auto& o, const py::handle& v, const std::string& k, const std::string& who) { o.spatial_order = option_value<bool>(v, k, who); }},
        // Applied before every other keyword (below), so that those override its fields in any order.
        {"sharp_features", [](auto&, const py::handle& v, const std::string& k, const std::string& who) { (void)option_value<bool>(v, k, who); }},
        {"threads",
         [](auto& o, const py::handle& v, const std::string& k, const std::string& who) {
             o.threads = option_value<std::optional<unsigned>>(v, k, who);
             if (o.threads && *o.threads > PCCD::Batch_options::max_threads)
                 throw py::value_error(who + "(): threads " + std::to_string(*o.threads) + " exceeds the limit " +
                                       std::to_string(PCCD::Batch_options::max_threads) + " (None: all available)");
         }},
    };
    const bool lean = who == "LeanObject";
    const auto refused = [&](const std::string& name) {
        return lean && std::find(geodesic_only.begin(), geodesic_only.end(), name) != geodesic_only.end();
    };
    PCCD::Point_cloud_object_options options;
    if (kwargs.contains("sharp_features") && option_value<bool>(kwargs["sharp_features"], "sharp_features", who))
        options = PCCD::sharp_feature_options(options);
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::str(key);
        const auto setter = setters.find(name);
        if (setter == setters.end() || refused(name)) {
            std::string known;
            for (const auto& [k, s] : setters)
                if (!refused(k)) known += (known.empty() ? "" : ", ") + k;
            throw py::type_error(who + "() got an unexpected keyword argument '" + name + "'" +
                                 (refused(name) ? " (a proximity graph option: the lean object has no graph)" : "") +
                                 " (options: " + known + ")");
        }
        setter->second(options, value, name, who);
    }
    return options;
}

/// The points and normals of a constructor call, read in place.
struct Input {
    py::object cloud_points, cloud_normals; // arrays made from an Open3D cloud, kept alive
    Row_array points;
    std::optional<Row_array> normals;
};

/// Reads the constructor's `points` and `normals`: (N, 3) arrays, or an Open3D point cloud
/// (open3d.geometry.PointCloud, or anything alike: its `points`, and its `normals` when it has
/// some and none are given; duck-typed, so Open3D is not needed here).
Input read_input(py::handle points, py::handle normals)
{
    Input in;
    if (!py::isinstance<py::array>(points) && py::hasattr(points, "points") && py::hasattr(points, "has_normals")) {
        static const py::object& asarray = *new py::object(py::module_::import("numpy").attr("asarray")); // never released
        const py::object cloud = py::reinterpret_borrow<py::object>(points);
        in.cloud_points = asarray(cloud.attr("points"));
        points = in.cloud_points;
        if (normals.is_none() && py::bool_(cloud.attr("has_normals")())) {
            in.cloud_normals = asarray(cloud.attr("normals"));
            normals = in.cloud_normals;
        }
    }
    in.points = row_array(points, "points");
    if (!normals.is_none()) {
        in.normals = row_array(normals, "normals");
        if (in.normals->rows != in.points.rows)
            throw py::value_error("normals: " + std::to_string(in.normals->rows) + " normals for " +
                                  std::to_string(in.points.rows) + " points (need one per point, or None)");
    }
    return in;
}

/// Normals as hints: the constructor with a normal map.
Object build(py::handle points, py::handle normals, const py::kwargs& kwargs)
{
    const PCCD::Point_cloud_object_options options = object_options(kwargs, "Object");
    const Input in = read_input(points, normals);
    const auto items = std::views::iota(std::size_t(0), in.points.rows);
    py::gil_scoped_release release;
    if (in.normals) return Object(items, Row_map{&in.points}, Row_map{&*in.normals}, options);
    return Object(items, Row_map{&in.points}, options);
}

/// The lean object from the same arguments (the points, and the normals as hints, through
/// PCCD::Point_data: one copy of each, freed once the object holds its own).
Lean_object build_lean(py::handle points, py::handle normals, const py::kwargs& kwargs)
{
    const PCCD::Point_cloud_object_options options = object_options(kwargs, "LeanObject");
    const Input in = read_input(points, normals);
    PCCD::Point_data data;
    data.points.reserve(in.points.rows);
    for (std::size_t i = 0; i < in.points.rows; ++i) data.points.push_back(get(Row_map{&in.points}, i));
    if (in.normals) {
        data.normals.reserve(in.normals->rows);
        for (std::size_t i = 0; i < in.normals->rows; ++i) data.normals.push_back(get(Row_map{&*in.normals}, i));
    }
    py::gil_scoped_release release;
    return Lean_object(data, options);
}

py::dict timings_dict(const PCCD::Preprocessing_times& t)
{
    py::dict d;
    d["kd_tree"] = t.kd_tree;
    d["outliers"] = t.outliers;
    d["graph"] = t.graph;
    d["sampling_radius"] = t.sampling_radius;
    d["cpsp"] = t.cpsp;
    d["normals"] = t.normals;
    d["hierarchy"] = t.hierarchy;
    return d;
}

const char* object_doc = R"doc(A preprocessed point cloud: everything a collision query needs, built once.

Object(points, normals=None, **options)

Building an object runs PCCD's preprocessing: kd-tree, removal of isolated outliers, proximity
graph, sampling radius r(P), kernel bandwidth, geodesic (CPSP) map, oriented normals, domain of
the implicit surface and the bounding-volume hierarchy. Queries (``pccd.do_intersect`` and the
others) then pose it by rigid transforms without rebuilding anything. The object is immutable;
any number of queries may use it at once, from any thread.

Parameters
----------
points : array_like or open3d.geometry.PointCloud
    (N, 3) array of float32 or float64 numbers (N >= 2), read in place; other numeric dtypes are
    converted to float64 first. Anything numpy converts (lists, objects exposing ``__array__``)
    is accepted, and so is an Open3D point cloud: its points, and its normals when it has some
    and `normals` is not given.
normals : array_like, optional
    (N, 3) array, one normal per point, used as hints that orient the surface's normals (a zero or
    non-finite row counts as missing for its point).
**options
    Preprocessing options, each with PCCD's default:

    graph : {'sphere_of_influence', 'knn'}
        Proximity graph (default 'sphere_of_influence', the r-SIG).
    sig_r : int
        r of the r-SIG (default 3).
    knn_k : int
        k of the k-NN graph (default 8).
    eta : float
        Support radius in units of r(P) (default 3).
    theta_eps : float
        Kernel weights below it are ignored (default 0.01).
    bandwidth : float
        A kernel bandwidth h given by the user, finite and > 0; None (default) chooses it from
        eta and r(P).
    noise_factor : float
        Noise-aware support: the support radius is at least noise_factor times the noise
        estimate (default 15; 0 disables it).
    surface_fit : {'sphere', 'plane', 'imls'}
        Local shape of the surface fit (default 'sphere'); 'imls' keeps sharp edges (with
        normal_residual_scale=0.25 and theta_eps=3e-5 for parts with sharp edges).
    sharp_features : bool
        True: the sharp-feature options for CAD parts in one keyword (surface_fit='imls',
        theta_eps=3e-5, normal_residual_scale=0.25; C++ PCCD::sharp_feature_options()), applied
        before the other keywords, which override its fields. Default False.
    normal_bandwidth : float
        Refit the oriented normals with this fraction of the kernel, in (0, 1] (default 1: no
        refit).
    normal_residual_scale : float
        Refit the oriented normals robustly: neighbours farther than about this many kernel
        bandwidths from a point's plane lose their weight, so normals keep to their face at
        sharp edges; finite and > 0, None (default): no robust refit.
    domain : bool
        Restrict the surface to a domain around the points (default True).
    domain_factor : float
        Domain radius in units of the local spacing (default 1).
    remove_outliers : bool
        Leave isolated points out of the surface (default True).
    outlier_ratio : float
        Local spacing ratio that makes a point an outlier (default 4).
    sampling_radius_samples : int
        Monte-Carlo samples of r(P) (default 10000).
    sampling_radius_seed : int
        Seed of those samples (default 1).
    leaf_size : int
        Largest number of points in a hierarchy leaf (default 8).
    volume : str
        Bounding volume of the hierarchy's node tests: 'box_and_slab' (default, measured fastest),
        'box' or 'sphere'. The answers do not depend on it.
    spatial_order : bool
        Store the points in a spatial (Morton) order, near in memory when near in space (default
        True; ``input_indices`` maps them back to the points given).
    threads : int
        Worker threads of the preprocessing, 1 to 4096; None (default) uses all. The result does
        not depend on it.

Raises
------
ValueError
    `points` or `normals` is not an (N, 3) array of numbers, holds NaN or infinite values, has
    fewer than two points, or an option value is invalid (PCCD's message names it).
TypeError
    An unknown option name, or an option value of the wrong type.

See Also
--------
Object.load : read an object written by `save`.
do_intersect, intersection_points, do_intersect_many

Examples
--------
>>> points, normals = pccd.read_points("bunny00.off")
>>> bunny = pccd.Object(points)
>>> bunny.input_points
37706
)doc";

/// The members pccd.Object and pccd.LeanObject share (both model PCCD's CollisionObject).
template <class T>
void add_shared_members(py::class_<T>& c, const char* name)
{
    c.def_property_readonly("size", &T::size, "int: Number of points of the surface (outliers removed).")
        .def_property_readonly("volume", [](const T& o) { return std::string(PCCD::to_string(o.hierarchy().volume())); },
                               "str: The bounding volume of the hierarchy ('box_and_slab', 'box' or 'sphere').")
        .def_property_readonly("input_points", [](const T& o) { return o.scan().input_points; },
                               "int: Number of points given (before the removal of outliers).")
        .def_property_readonly(
            "points", [](const py::object& self) { return matrix_view(self.cast<const T&>().cloud().coordinates(), self); },
            "numpy.ndarray: (size, 3) read-only float64 view of the surface's points (outliers removed, in "
            "spatial order unless spatial_order=False; see input_indices).")
        .def_property_readonly(
            "input_indices",
            [](const T& o) {
                const auto& indices = o.input_indices();
                return py::array_t<std::uint32_t>(py::ssize_t(indices.size()), indices.data());
            },
            "numpy.ndarray: For each row of points (and normals), its index among the points given.")
        .def_property_readonly(
            "normals", [](const py::object& self) { return matrix_view(self.cast<const T&>().normals(), self); },
            "numpy.ndarray: (size, 3) read-only float64 view of the oriented unit normals (zero rows: "
            "undetermined).")
        .def_property_readonly(
            "outliers",
            [](const T& o) {
                const auto& indices = o.scan().outliers;
                return py::array_t<std::uint32_t>(py::ssize_t(indices.size()), indices.data());
            },
            "numpy.ndarray: Indices (into the points given, ascending) of the outliers left out.")
        .def_property_readonly("sampling_radius", &T::sampling_radius,
                               "float: The sampling radius r(P) (length unit of the points).")
        .def_property_readonly("bandwidth", &T::bandwidth, "float: The kernel bandwidth h.")
        .def_property_readonly("support_radius", [](const T& o) { return o.weight().support_radius(); },
                               "float: The kernel's support radius R = h sqrt(-ln theta_eps).")
        .def_property_readonly("theta_eps", [](const T& o) { return o.weight().threshold(); }, "float: The kernel's weight threshold.")
        .def_property_readonly("surface_fit", [](const T& o) { return std::string(PCCD::to_string(o.surface().fit())); },
                               "str: The surface's local fit: 'sphere', 'plane' or 'imls'.")
        .def_property_readonly("leaf_size", [](const T& o) { return o.hierarchy().leaf_size(); },
                               "int: The hierarchy's largest number of points in a leaf.")
        .def_property_readonly("eta", &T::eta, "float: R / r(P).")
        .def_property_readonly("noise_estimate", &T::noise_estimate, "float: The estimated noise level sigma.")
        .def_property_readonly("normals_given", &T::normals_given, "bool: Whether normals were given as hints.")
        .def_property_readonly("unoriented", [](const T& o) { return o.orientation().unoriented; },
                               "int: Number of points whose normal is undetermined.")
        .def_property_readonly("timings", [](const T& o) { return timings_dict(o.timings()); },
                               "dict: Wall-clock milliseconds of each preprocessing stage.")
        .def("__len__", &T::size)
        .def("__repr__", [name](const T& o) {
            return "<pccd." + std::string(name) + ": " + std::to_string(o.size()) + " points, sampling_radius " +
                   std::string(py::str(py::float_(o.sampling_radius()))) + ">";
        });
    c.def_property_readonly("kernel", [](const T&) { return std::string(PCCD::GeodesicCollisionObject<T> ? "geodesic" : "euclidean"); },
                            "str: The surface's kernel: 'geodesic' (pccd.Object) or 'euclidean' (pccd.LeanObject).");
}

const char* lean_object_doc = R"doc(The lean object for large scans: the Euclidean kernel, about a fifth of an Object's memory.

LeanObject(points, normals=None, **options)

The same preprocessing as ``Object`` but for the geodesic map: the implicit surface weighs the
neighbours by their straight-line distance instead of their distance along the surface, so the
object keeps only the points, kd-tree, normals, domain radii and hierarchy (about 150-170 bytes per
point against 700-870 for an Object; 1.65 GB at 10^7 points). Every query that takes an Object
takes a LeanObject, and a mix of the two (a part as an Object beside a large scan as a
LeanObject), the batch functions' pair lists included; ``pccd.World`` holds Objects only.

What it gives up: the Euclidean kernel bleeds across gaps thinner than twice the support radius
(two faces of a thin wall, fingers that nearly touch), where the geodesic kernel keeps them apart,
and it rounds sharp edges a little more. ``save``/``load`` keep it in a file of its own kind (about
150 bytes per point; loading rebuilds the kd-tree and the hierarchy from the file, far faster than
the preprocessing). Use it from about 10^6 points, where the geodesic map dominates the memory and
walls are many spacings thick.

Parameters
----------
points : array_like or open3d.geometry.PointCloud
    As for ``Object``.
normals : array_like, optional
    As for ``Object``.
**options
    The options of ``Object`` but for the proximity graph's (graph, sig_r, knn_k), which raise
    TypeError here.

Raises
------
ValueError, TypeError
    As for ``Object``.

Examples
--------
>>> scan = pccd.LeanObject(points)        # e.g. 10^7 points of a terrestrial scan
>>> part = pccd.Object(part_points)       # a small part: the geodesic kernel
>>> pccd.distance(part, pose, scan, None).distance
)doc";

/// The hierarchy a load asks for: none (the stored one) unless `leaf_size` or `volume` is given,
/// then those with the defaults for the other.
std::optional<PCCD::Point_cloud_hierarchy_options> loaded_hierarchy(std::optional<std::size_t> leaf_size,
                                                                    const std::optional<std::string>& volume,
                                                                    const std::string& where)
{
    std::optional<PCCD::Point_cloud_hierarchy_options> hierarchy;
    if (leaf_size || volume) {
        hierarchy.emplace();
        if (leaf_size) hierarchy->leaf_size = *leaf_size;
        if (volume) hierarchy->volume = volume_of(*volume, where);
    }
    return hierarchy;
}

/// pccd.load(path): the object a file of either kind holds, as its kind (PCCD::object_file_info).
py::object load_any(const py::object& path, std::optional<std::size_t> leaf_size, const std::optional<std::string>& volume)
{
    const std::string file = path_argument(path, "load", "path");
    const auto hierarchy = loaded_hierarchy(leaf_size, volume, "load()");
    const auto load = [&]<class T>(std::type_identity<T>) {
        std::optional<T> object;
        {
            py::gil_scoped_release release;
            object.emplace(hierarchy ? T::load(file, *hierarchy) : T::load(file));
        }
        return py::cast(std::move(*object));
    };
    switch (PCCD::object_file_info(file).kind) {
    case PCCD::Object_file_kind::geodesic: return load(std::type_identity<Object>{});
    case PCCD::Object_file_kind::euclidean: return load(std::type_identity<Lean_object>{});
    case PCCD::Object_file_kind::none: break;
    }
    throw PCCD::File_error(file, "not a PCCD object file (Object.save or LeanObject.save); a point file is read with "
                                 "pccd.read_points and preprocessed by pccd.Object or pccd.LeanObject");
}

const char* any_load_doc = R"doc(Read an object file of either kind: an ``Object`` or a ``LeanObject``, as the file holds.

The kind is read from the file's first bytes (its magic), not from its name: a file written by
``Object.save`` loads as an ``Object``, one written by ``LeanObject.save`` (or by
``pccd prepare``) as a ``LeanObject``.

Parameters
----------
path : str or os.PathLike
    The file to read.
leaf_size : int, optional
volume : str, optional
    As for ``Object.load``: with neither given (default), the stored hierarchy.

Returns
-------
Object or LeanObject
    The object, answering every query exactly as the one that was saved.

Raises
------
OSError
    The file is missing, not a PCCD object file (a point file, say), of another format version,
    truncated, corrupted (checksum) or inconsistent; the message names the file and the problem.
)doc";

/// save() and the static load() of pccd.Object and pccd.LeanObject (each reads its own kind's files).
template <class T>
void add_files(py::class_<T>& c, const std::string& name, const std::string& extra_contents)
{
    static std::deque<std::string> docs; // pybind11 keeps the pointers: the strings must live on, unmoved
    docs.push_back("Write the object to a binary file (replaced if it exists).\n\nThe file holds the points, normals, "
                   "parameters, timings, " + extra_contents + "domain radii and the hierarchy's layout, with a\n"
                   "checksum; ``" + name + ".load`` reads it back bit for bit (the kd-tree is rebuilt, the hierarchy "
                   "from its\nstored layout).\n\nParameters\n----------\npath : str or os.PathLike\n    The file to "
                   "write.\n\nRaises\n------\nOSError\n    The file cannot be written.\n");
    const char* save_doc = docs.back().c_str();
    docs.push_back("Read an object written by ``" + name + ".save``.\n\nParameters\n----------\npath : str or "
                   "os.PathLike\n    The file to read.\nleaf_size : int, optional\n    Largest number of points in a "
                   "hierarchy leaf.\nvolume : str, optional\n    'box_and_slab', 'box' or 'sphere'. With neither given "
                   "(default), the hierarchy the file stores\n    is rebuilt from its layout. Giving either asks for a "
                   "hierarchy with the values given and the\n    defaults (8, 'box_and_slab') for the other: the stored "
                   "one when they are the file's, otherwise\n    a new build.\n\nReturns\n-------\n" + name +
                   "\n    The object, answering every query exactly as the one that was saved.\n\nRaises\n------\n"
                   "OSError\n    The file is missing, not a PCCD " + (name == "Object" ? "object" : "lean object") +
                   " file (the other kind's file is named as such), of\n    another format version, truncated, "
                   "corrupted (checksum) or inconsistent; the message names\n    the file and the problem.\n");
    const char* load_doc = docs.back().c_str();
    c.def(
         "save",
         [name](const T& self, const py::object& path) {
             const std::string file = path_argument(path, (name + ".save").c_str(), "path");
             py::gil_scoped_release release;
             self.save(file);
         },
         py::arg("path"), save_doc)
        .def_static(
            "load",
            [name](const py::object& path, std::optional<std::size_t> leaf_size, std::optional<std::string> volume) {
                const std::string file = path_argument(path, (name + ".load").c_str(), "path");
                const auto hierarchy = loaded_hierarchy(leaf_size, volume, name + ".load()");
                py::gil_scoped_release release;
                return hierarchy ? T::load(file, *hierarchy) : T::load(file);
            },
            py::arg("path"), py::kw_only(), py::arg("leaf_size") = py::none(), py::arg("volume") = py::none(), load_doc);
}

} // namespace

void add_object(py::module_& m)
{
    py::class_<Object> object(m, "Object", object_doc);
    object.def(py::init([](const py::object& points, const py::object& normals, const py::kwargs& kwargs) {
                   return build(points, normals, kwargs);
               }),
               py::arg("points"), py::arg("normals") = py::none());
    add_files(object, "Object", "graph and geodesic map, ");
    add_shared_members(object, "Object");

    py::class_<Lean_object> lean(m, "LeanObject", lean_object_doc);
    lean.def(py::init([](const py::object& points, const py::object& normals, const py::kwargs& kwargs) {
                 return build_lean(points, normals, kwargs);
             }),
             py::arg("points"), py::arg("normals") = py::none());
    add_shared_members(lean, "LeanObject");
    add_files(lean, "LeanObject", "");
    lean.def_property_readonly("memory_bytes", &Lean_object::memory_bytes,
                               "int: Bytes the object holds (points, kd-tree, input indices, normals, domain radii, "
                               "hierarchy).");
    m.def("load", &load_any, py::arg("path"), py::kw_only(), py::arg("leaf_size") = py::none(),
          py::arg("volume") = py::none(), any_load_doc);
}

} // namespace pccd_python
