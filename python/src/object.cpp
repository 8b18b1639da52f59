// python/src/object.cpp -- pccd.Object: a PCCD::Point_cloud_object<> built from an (N, 3) numpy
// array read in place (PCCD copies the points into its own store, nothing else does), with its
// preprocessing options as keyword arguments, save() / load(), and read-only properties; the
// arrays it hands out are read-only views of the object's own data (doc/manual/python.md,
// "Objects").
#include "pccd_python.h"

#include <pybind11/stl.h>

#include <PCCD/Error.h>
#include <PCCD/Intersection/do_intersect_many.h>
#include <PCCD/sharp_feature_options.h>

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <ranges>
#include <string>
#include <utility>

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
T option_value(const py::handle& value, const std::string& key)
{
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error("Object(): option " + key + " has the wrong type (" +
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

PCCD::Point_cloud_object_options object_options(const py::kwargs& kwargs)
{
    using Setter = std::function<void(PCCD::Point_cloud_object_options&, const py::handle&, const std::string&)>;
    static const std::map<std::string, Setter> setters{
        {"graph",
         [](auto& o, const py::handle& v, const std::string& k) {
             const auto name = option_value<std::string>(v, k);
             if (name == "sphere_of_influence") o.graph = PCCD::Graph_kind::sphere_of_influence;
             else if (name == "knn") o.graph = PCCD::Graph_kind::knn;
             else throw py::value_error("Object(): graph must be 'sphere_of_influence' or 'knn', not '" + name + "'");
         }},
        {"sig_r", [](auto& o, const py::handle& v, const std::string& k) { o.sphere_of_influence.r = option_value<unsigned>(v, k); }},
        {"knn_k", [](auto& o, const py::handle& v, const std::string& k) { o.knn.k = option_value<unsigned>(v, k); }},
        {"eta", [](auto& o, const py::handle& v, const std::string& k) { o.bandwidth.eta = option_value<double>(v, k); }},
        {"theta_eps", [](auto& o, const py::handle& v, const std::string& k) { o.bandwidth.theta_eps = option_value<double>(v, k); }},
        {"bandwidth", [](auto& o, const py::handle& v, const std::string& k) { o.bandwidth.bandwidth = option_value<std::optional<double>>(v, k); }},
        {"noise_factor", [](auto& o, const py::handle& v, const std::string& k) { o.bandwidth.noise_factor = option_value<double>(v, k); }},
        {"surface_fit",
         [](auto& o, const py::handle& v, const std::string& k) {
             const auto name = option_value<std::string>(v, k);
             if (name == "sphere") o.surface_fit = PCCD::Surface_fit::sphere;
             else if (name == "plane") o.surface_fit = PCCD::Surface_fit::plane;
             else if (name == "imls") o.surface_fit = PCCD::Surface_fit::imls;
             else throw py::value_error("Object(): surface_fit must be 'sphere', 'plane' or 'imls', not '" + name + "'");
         }},
        {"normal_bandwidth",
         [](auto& o, const py::handle& v, const std::string& k) { o.normal_bandwidth = option_value<double>(v, k); }},
        {"normal_residual_scale",
         [](auto& o, const py::handle& v, const std::string& k) {
             o.normal_residual_scale = option_value<std::optional<double>>(v, k);
         }},
        {"domain", [](auto& o, const py::handle& v, const std::string& k) { o.domain.enabled = option_value<bool>(v, k); }},
        {"domain_factor", [](auto& o, const py::handle& v, const std::string& k) { o.domain.factor = option_value<double>(v, k); }},
        {"remove_outliers", [](auto& o, const py::handle& v, const std::string& k) { o.outliers.remove = option_value<bool>(v, k); }},
        {"outlier_ratio", [](auto& o, const py::handle& v, const std::string& k) { o.outliers.ratio = option_value<double>(v, k); }},
        {"sampling_radius_samples",
         [](auto& o, const py::handle& v, const std::string& k) { o.sampling_radius.samples = option_value<std::size_t>(v, k); }},
        {"sampling_radius_seed",
         [](auto& o, const py::handle& v, const std::string& k) { o.sampling_radius.seed = option_value<std::uint64_t>(v, k); }},
        {"leaf_size", [](auto& o, const py::handle& v, const std::string& k) { o.hierarchy.leaf_size = option_value<std::size_t>(v, k); }},
        {"volume", [](auto& o, const py::handle& v, const std::string& k) { o.hierarchy.volume = volume_of(option_value<std::string>(v, k), "Object()"); }},
        {"spatial_order", [](auto& o, const py::handle& v, const std::string& k) { o.spatial_order = option_value<bool>(v, k); }},
        // Applied before every other keyword (below), so that those override its fields in any order.
        {"sharp_features", [](auto&, const py::handle& v, const std::string& k) { (void)option_value<bool>(v, k); }},
        {"threads",
         [](auto& o, const py::handle& v, const std::string& k) {
             o.threads = option_value<std::optional<unsigned>>(v, k);
             if (o.threads && *o.threads > PCCD::Batch_options::max_threads)
                 throw py::value_error("Object(): threads " + std::to_string(*o.threads) + " exceeds the limit " +
                                       std::to_string(PCCD::Batch_options::max_threads) + " (None: all available)");
         }},
    };
    PCCD::Point_cloud_object_options options;
    if (kwargs.contains("sharp_features") && option_value<bool>(kwargs["sharp_features"], "sharp_features"))
        options = PCCD::sharp_feature_options(options);
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::str(key);
        const auto setter = setters.find(name);
        if (setter == setters.end()) {
            std::string known;
            for (const auto& [k, s] : setters) known += (known.empty() ? "" : ", ") + k;
            throw py::type_error("Object() got an unexpected keyword argument '" + name + "' (options: " + known + ")");
        }
        setter->second(options, value, name);
    }
    return options;
}

/// Normals as hints: the constructor with a normal map.
Object build(py::handle points, py::handle normals, const py::kwargs& kwargs)
{
    const PCCD::Point_cloud_object_options options = object_options(kwargs);
    // An Open3D point cloud (open3d.geometry.PointCloud), or anything alike: its `points`, and its
    // `normals` when it has some and none are given. Duck-typed, so Open3D is not needed here.
    py::object cloud_points, cloud_normals;
    if (!py::isinstance<py::array>(points) && py::hasattr(points, "points") && py::hasattr(points, "has_normals")) {
        static const py::object& asarray = *new py::object(py::module_::import("numpy").attr("asarray")); // never released
        const py::object cloud = py::reinterpret_borrow<py::object>(points);
        cloud_points = asarray(cloud.attr("points"));
        points = cloud_points;
        if (normals.is_none() && py::bool_(cloud.attr("has_normals")())) {
            cloud_normals = asarray(cloud.attr("normals"));
            normals = cloud_normals;
        }
    }
    const Row_array p = row_array(points, "points");
    std::optional<Row_array> n;
    if (!normals.is_none()) {
        n = row_array(normals, "normals");
        if (n->rows != p.rows)
            throw py::value_error("normals: " + std::to_string(n->rows) + " normals for " + std::to_string(p.rows) +
                                  " points (need one per point, or None)");
    }
    const auto items = std::views::iota(std::size_t(0), p.rows);
    py::gil_scoped_release release;
    if (n) return Object(items, Row_map{&p}, Row_map{&*n}, options);
    return Object(items, Row_map{&p}, options);
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

} // namespace

void add_object(py::module_& m)
{
    py::class_<Object>(m, "Object", object_doc)
        .def(py::init([](const py::object& points, const py::object& normals, const py::kwargs& kwargs) {
                 return build(points, normals, kwargs);
             }),
             py::arg("points"), py::arg("normals") = py::none())
        .def(
            "save",
            [](const Object& self, const py::object& path) {
                const std::string file = path_argument(path, "Object.save", "path");
                py::gil_scoped_release release;
                self.save(file);
            },
            py::arg("path"), R"doc(Write the object to a binary file (replaced if it exists).

The file holds the points, normals, parameters, timings, graph and geodesic map, with a
checksum; ``Object.load`` reads it back bit for bit (the kd-tree is rebuilt, the hierarchy from its
stored layout).

Parameters
----------
path : str or os.PathLike
    The file to write.

Raises
------
OSError
    The file cannot be written.
)doc")
        .def_static(
            "load",
            [](const py::object& path, std::optional<std::size_t> leaf_size, std::optional<std::string> volume) {
                const std::string file = path_argument(path, "Object.load", "path");
                std::optional<PCCD::Point_cloud_hierarchy_options> hierarchy;
                if (leaf_size || volume) {
                    hierarchy.emplace();
                    if (leaf_size) hierarchy->leaf_size = *leaf_size;
                    if (volume) hierarchy->volume = volume_of(*volume, "Object.load()");
                }
                py::gil_scoped_release release;
                return hierarchy ? Object::load(file, *hierarchy) : Object::load(file);
            },
            py::arg("path"), py::kw_only(), py::arg("leaf_size") = py::none(), py::arg("volume") = py::none(),
            R"doc(Read an object written by ``Object.save``.

Parameters
----------
path : str or os.PathLike
    The file to read.
leaf_size : int, optional
    Largest number of points in a hierarchy leaf.
volume : str, optional
    'box_and_slab', 'box' or 'sphere'. With neither given (default), the hierarchy the file stores
    is rebuilt from its layout. Giving either asks for a hierarchy with the values given and the
    defaults (8, 'box_and_slab') for the other: the stored one when they are the file's, otherwise
    a new build.

Returns
-------
Object
    The object, answering every query exactly as the one that was saved.

Raises
------
OSError
    The file is missing, not a PCCD object file, of another format version, truncated,
    corrupted (checksum) or inconsistent; the message names the file and the problem.
)doc")
        .def_property_readonly("size", &Object::size, "int: Number of points of the surface (outliers removed).")
        .def_property_readonly("volume", [](const Object& o) { return std::string(PCCD::to_string(o.hierarchy().volume())); },
                               "str: The bounding volume of the hierarchy ('box_and_slab', 'box' or 'sphere').")
        .def_property_readonly("input_points", [](const Object& o) { return o.scan().input_points; },
                               "int: Number of points given (before the removal of outliers).")
        .def_property_readonly(
            "points", [](const py::object& self) { return matrix_view(self.cast<const Object&>().cloud().coordinates(), self); },
            "numpy.ndarray: (size, 3) read-only float64 view of the surface's points (outliers removed, in "
            "spatial order unless spatial_order=False; see input_indices).")
        .def_property_readonly(
            "input_indices",
            [](const Object& o) {
                const auto& indices = o.input_indices();
                return py::array_t<std::uint32_t>(py::ssize_t(indices.size()), indices.data());
            },
            "numpy.ndarray: For each row of points (and normals), its index among the points given.")
        .def_property_readonly(
            "normals", [](const py::object& self) { return matrix_view(self.cast<const Object&>().normals(), self); },
            "numpy.ndarray: (size, 3) read-only float64 view of the oriented unit normals (zero rows: "
            "undetermined).")
        .def_property_readonly(
            "outliers",
            [](const Object& o) {
                const auto& indices = o.scan().outliers;
                return py::array_t<std::uint32_t>(py::ssize_t(indices.size()), indices.data());
            },
            "numpy.ndarray: Indices (into the points given, ascending) of the outliers left out.")
        .def_property_readonly("sampling_radius", &Object::sampling_radius,
                               "float: The sampling radius r(P) (length unit of the points).")
        .def_property_readonly("bandwidth", &Object::bandwidth, "float: The kernel bandwidth h.")
        .def_property_readonly("support_radius", [](const Object& o) { return o.weight().support_radius(); },
                               "float: The kernel's support radius R = h sqrt(-ln theta_eps).")
        .def_property_readonly("theta_eps", &Object::theta_eps, "float: The kernel's weight threshold.")
        .def_property_readonly("surface_fit", [](const Object& o) { return std::string(PCCD::to_string(o.surface().fit())); },
                               "str: The surface's local fit: 'sphere', 'plane' or 'imls'.")
        .def_property_readonly("leaf_size", [](const Object& o) { return o.hierarchy().leaf_size(); },
                               "int: The hierarchy's largest number of points in a leaf.")
        .def_property_readonly("eta", &Object::eta, "float: R / r(P).")
        .def_property_readonly("noise_estimate", &Object::noise_estimate, "float: The estimated noise level sigma.")
        .def_property_readonly("normals_given", &Object::normals_given, "bool: Whether normals were given as hints.")
        .def_property_readonly("unoriented", [](const Object& o) { return o.orientation().unoriented; },
                               "int: Number of points whose normal is undetermined.")
        .def_property_readonly("timings", [](const Object& o) { return timings_dict(o.timings()); },
                               "dict: Wall-clock milliseconds of each preprocessing stage.")
        .def("__len__", &Object::size)
        .def("__repr__", [](const Object& o) {
            return "<pccd.Object: " + std::to_string(o.size()) + " points, sampling_radius " +
                   std::string(py::str(py::float_(o.sampling_radius()))) + ">";
        });
}

} // namespace pccd_python
