// python/src/pccd_python.h -- what the translation units of the Python module `pccd` share: the
// object type it wraps, the conversions between numpy arrays and PCCD's types (points, poses), and
// the functions that add each part of the module. The module is described in doc/manual/python.md.
#pragma once

#include <PCCD/Intersection/Interpolation_search.h>
#include <PCCD/Intersection/Intersection_options.h>
#include <PCCD/Euclidean_point_cloud_object.h>
#include <PCCD/Point_cloud_object.h>
#include <PCCD/Proximity/Distance_result.h>
#include <PCCD/Rigid_transform_3.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace pccd_python {

namespace py = pybind11;

/// The preprocessed object of pccd.Object (copies share the data).
using Object = PCCD::Point_cloud_object<>;
/// The lean object of pccd.LeanObject (the Euclidean kernel, no geodesic map).
using Lean_object = PCCD::Euclidean_point_cloud_object<>;

/// The C++ object of a pccd.Object or pccd.LeanObject, and which of the two it is (what a query
/// keeps of its Python arguments while the GIL is released; the Python object keeps it alive).
struct Any_object {
    const void* object = nullptr;
    bool lean = false;
};

/// The C++ object `value` holds. Raises TypeError "<where>: <requirement>, not <type>" for
/// anything but a pccd.Object or a pccd.LeanObject.
inline Any_object any_object(py::handle value, const std::string& where, const std::string& requirement)
{
    if (py::isinstance<Object>(value)) return {&value.cast<const Object&>(), false};
    if (py::isinstance<Lean_object>(value)) return {&value.cast<const Lean_object&>(), true};
    throw py::type_error(where + ": " + requirement + ", not " +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))));
}

/// Calls `f(a, b)` with the two objects as const references to their C++ types.
template <class F>
decltype(auto) visit_objects(const Any_object& a, const Any_object& b, F&& f)
{
    const auto geodesic = [](const Any_object& o) -> const Object& { return *static_cast<const Object*>(o.object); };
    const auto lean = [](const Any_object& o) -> const Lean_object& { return *static_cast<const Lean_object*>(o.object); };
    if (!a.lean && !b.lean) return f(geodesic(a), geodesic(b));
    if (!a.lean) return f(geodesic(a), lean(b));
    if (!b.lean) return f(lean(a), geodesic(b));
    return f(lean(a), lean(b));
}

/// The two objects of a query, `f(a, b)` with each one's C++ type. Raises TypeError
/// "<function>(): <name> must be a pccd.Object or a pccd.LeanObject, not <type>" (a first) for
/// anything else.
template <class F>
decltype(auto) with_objects(py::handle a, const char* name_a, py::handle b, const char* name_b, const char* function, F&& f)
{
    const std::string where = std::string(function) + "()";
    const char* requirement = " must be a pccd.Object or a pccd.LeanObject";
    const Any_object object_a = any_object(a, where, name_a + std::string(requirement));
    const Any_object object_b = any_object(b, where, name_b + std::string(requirement));
    return visit_objects(object_a, object_b, f);
}

/// An (N, 3) array argument read in place: float32 or float64 rows at any strides. Other numeric
/// dtypes are converted to float64 first (the only copy), which `keep` then holds.
struct Row_array {
    py::array keep;
    const char* data = nullptr;
    std::size_t rows = 0;
    py::ssize_t row_stride = 0;
    py::ssize_t column_stride = 0;
    bool single = false; // float32

    double at(std::size_t i, int j) const
    {
        const char* p = data + py::ssize_t(i) * row_stride + j * column_stride;
        if (single) {
            float v;
            std::memcpy(&v, p, sizeof v);
            return double(v);
        }
        double v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
};

/// `value` as an (N, 3) array of numbers; `name` is the argument's name in the ValueError raised
/// for anything else (another shape, strings, objects, booleans, complex numbers).
Row_array row_array(py::handle value, const char* name);

/// A pose argument: a 3x4 [R | t] or 4x4 homogeneous array-like (last row 0 0 0 1), or None for
/// the identity. Raises ValueError (PCCD::Invalid_input) naming `name` when it is not rigid (the
/// rule of Rigid_transform_3: R^T R - I within its default tolerance, det R > 0; the last row of a
/// 4x4 within the same tolerance of 0 0 0 1).
PCCD::Rigid_transform_3<double> pose_argument(py::handle value, const char* name);

/// A stack of poses: an (n, 3, 4) or (n, 4, 4) array read row by row, each checked as one pose
/// argument is (rigid within Rigid_transform_3's tolerance; a 4x4's last row 0 0 0 1). ValueError
/// "<function>(): <name>[i]: ..." naming the first bad pose, or the shape.
std::vector<PCCD::Rigid_transform_3<double>> pose_stack(py::handle value, const char* function, const char* name);

/// pccd.orthonormalize(pose): (the pose with the nearest rotation, in the shape given, and the
/// largest change of an entry), PCCD::orthonormalize on a 3x4 or 4x4 array.
py::tuple orthonormalize_pose(py::handle value);

/// A path argument (str, bytes or os.PathLike) as a str, decoded as os.fsdecode does; TypeError
/// naming `function` and `name` for None or anything else.
std::string path_argument(py::handle value, const char* function, const char* name);

/// A read-only (N, 3) float64 view of the 3 x N column-major matrix `m`, kept alive by `owner`.
py::array matrix_view(const Eigen::Matrix3Xd& m, py::handle owner);

void add_io(py::module_& m);
void add_object(py::module_& m);
void add_queries(py::module_& m);
void add_proximity(py::module_& m);
void add_continuous(py::module_& m);
void add_world(py::module_& m);

/// The narrow phase of a pccd.World: do_intersect's keyword arguments (the same names, defaults
/// and checks as pccd.do_intersect) read into Intersection_options and the interpolation search's
/// parameters. method='rst' raises ValueError (a world answers with the interpolation search).
struct World_narrow_phase {
    PCCD::Intersection_options options;
    PCCD::Interpolation_search isearch;
};
World_narrow_phase world_narrow_phase(const py::kwargs& kwargs, const char* function);

/// A pccd.ClearanceResult (proximity.cpp) holding `r`, for World.within_distance.
py::object clearance_result(const PCCD::Clearance_result& r);

/// Reads one keyword argument of a query into `field`: TypeError naming the function, the key and
/// the value when it has the wrong type (the options' own checks then raise ValueError).
template <class T>
void read_argument(T& field, const py::handle& value, const char* function, std::string_view key)
{
    try {
        field = value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(std::string(function) + "(): " + std::string(key) + " cannot be " +
                             std::string(py::str(py::repr(value))));
    }
}

} // namespace pccd_python
