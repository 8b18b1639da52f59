// python/src/conversions.cpp -- numpy arrays to and from PCCD's types: (N, 3) point and normal
// arrays read in place, 3x4 / 4x4 poses checked into Rigid_transform_3, and read-only views of
// PCCD's 3 x N matrices. Every malformed array raises ValueError naming the argument
// (doc/manual/python.md, "Arrays").
#include "pccd_python.h"

#include <PCCD/Error.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace pccd_python {

namespace {

std::string shape_text(const py::array& a)
{
    std::string text = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
    return text + (a.ndim() == 1 ? ",)" : ")");
}

} // namespace

Row_array row_array(py::handle value, const char* name)
{
    if (value.is_none()) throw py::value_error(std::string(name) + " must be an array of shape (N, 3), not None");
    py::array a = py::array::ensure(value);
    if (!a) throw py::value_error(std::string(name) + " must be an array of shape (N, 3) (numpy could not convert it)");
    const char kind = a.dtype().kind();
    if (kind == 'i' || kind == 'u' || (kind == 'f' && a.itemsize() != 4 && a.itemsize() != 8))
        a = py::array_t<double, py::array::forcecast>::ensure(a);
    else if (kind != 'f')
        throw py::value_error(std::string(name) + " must hold real numbers (float32 or float64), not dtype " +
                              std::string(py::str(a.dtype())));
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw py::value_error(std::string(name) + " must have shape (N, 3), got " + shape_text(a));
    Row_array rows;
    rows.data = static_cast<const char*>(a.data());
    rows.rows = std::size_t(a.shape(0));
    rows.row_stride = a.strides(0);
    rows.column_stride = a.strides(1);
    rows.single = a.itemsize() == 4;
    rows.keep = std::move(a);
    return rows;
}

namespace {

/// The 12 entries of [R | t] of a pose argument, row by row (the 4x4 form's last row checked
/// against 0 0 0 1 within Rigid_transform_3's default tolerance); `rows` is 3 or 4.
std::array<double, 12> pose_entries(py::handle value, const char* name, py::ssize_t& rows)
{
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    Array a;
    if (py::isinstance<Array>(value))
        a = py::reinterpret_borrow<Array>(value);
    else {
        py::array any = py::array::ensure(value);
        const char kind = any ? any.dtype().kind() : 'O';
        if (kind != 'f' && kind != 'i' && kind != 'u')
            throw py::value_error(std::string(name) + " must be a 3x4 or 4x4 array of numbers");
        a = Array::ensure(any);
    }
    if (a.ndim() != 2 || a.shape(1) != 4 || (a.shape(0) != 3 && a.shape(0) != 4))
        throw py::value_error(std::string(name) + " must have shape (3, 4) or (4, 4), got " + shape_text(a));
    const double* m = a.data();
    rows = a.shape(0);
    if (rows == 4) {
        constexpr double tolerance = PCCD::Rigid_transform_3<double>::default_tolerance;
        const double expected[4] = {0.0, 0.0, 0.0, 1.0};
        for (int k = 0; k < 4; ++k)
            if (!(std::abs(m[12 + k] - expected[k]) <= tolerance)) {
                std::string row;
                for (int j = 0; j < 4; ++j)
                    row += (j ? ", " : "") + PCCD::Rigid_transform_3<double>::full_digits(m[12 + j]);
                throw py::value_error(std::string(name) + ": the last row of a 4x4 pose must be [0, 0, 0, 1] (within " +
                                      PCCD::Rigid_transform_3<double>::full_digits(tolerance) + "), got [" + row + "]");
            }
    }
    std::array<double, 12> entries;
    for (int k = 0; k < 12; ++k) entries[std::size_t(k)] = m[k];
    return entries;
}

} // namespace

PCCD::Rigid_transform_3<double> pose_argument(py::handle value, const char* name)
{
    if (value.is_none()) return {};
    py::ssize_t rows = 0;
    const std::array<double, 12> entries = pose_entries(value, name, rows);
    try {
        return PCCD::Rigid_transform_3<double>(entries);
    } catch (const PCCD::Invalid_input& e) {
        throw PCCD::Invalid_input(std::string(name) + ": " + e.what() +
                                  " (pccd.orthonormalize(pose) returns the nearest rigid pose and how far it is)");
    }
}

std::vector<PCCD::Rigid_transform_3<double>> pose_stack(py::handle value, const char* function, const char* name)
{
    using Pose = PCCD::Rigid_transform_3<double>;
    using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
    const std::string prefix = std::string(function) + "(): ";
    py::array any = py::array::ensure(value);
    const char kind = any ? any.dtype().kind() : 'O';
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw py::value_error(prefix + name + " must be an array of shape (n, 3, 4) or (n, 4, 4) of numbers");
    const Array a = Array::ensure(any);
    if (a.ndim() != 3 || a.shape(2) != 4 || (a.shape(1) != 3 && a.shape(1) != 4)) {
        std::string shape = "(";
        for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
        throw py::value_error(prefix + name + " must have shape (n, 3, 4) or (n, 4, 4), got " + shape +
                              (a.ndim() == 1 ? ",)" : ")"));
    }
    const std::size_t count = std::size_t(a.shape(0));
    const py::ssize_t rows = a.shape(1);
    const double* m = a.data();
    std::vector<Pose> poses;
    poses.reserve(count);
    for (std::size_t i = 0; i < count; ++i, m += rows * 4) {
        const std::string where = prefix + name + "[" + std::to_string(i) + "]";
        if (rows == 4) {
            constexpr double tolerance = Pose::default_tolerance;
            const double last[4] = {0.0, 0.0, 0.0, 1.0};
            for (int k = 0; k < 4; ++k)
                if (!(std::abs(m[12 + k] - last[k]) <= tolerance))
                    throw py::value_error(where + ": the last row of a 4x4 pose must be [0, 0, 0, 1]");
        }
        std::array<double, 12> entries;
        for (int k = 0; k < 12; ++k) entries[std::size_t(k)] = m[k];
        try {
            poses.emplace_back(entries);
        } catch (const PCCD::Invalid_input& e) {
            throw PCCD::Invalid_input(where + ": " + e.what());
        }
    }
    return poses;
}

py::tuple orthonormalize_pose(py::handle value)
{
    if (value.is_none()) throw py::type_error("orthonormalize(): pose must be a 3x4 or 4x4 array, not None");
    py::ssize_t rows = 0;
    const std::array<double, 12> entries = pose_entries(value, "pose", rows);
    const auto fixed = PCCD::orthonormalize(entries);
    py::array_t<double> out({rows, py::ssize_t(4)});
    auto o = out.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < 3; ++i) {
        for (py::ssize_t j = 0; j < 3; ++j) o(i, j) = fixed.transform.rotation()(i, j);
        o(i, 3) = fixed.transform.translation()(i);
    }
    if (rows == 4) {
        for (py::ssize_t j = 0; j < 3; ++j) o(3, j) = 0.0;
        o(3, 3) = 1.0;
    }
    return py::make_tuple(out, fixed.moved);
}

std::string path_argument(py::handle value, const char* function, const char* name)
{
    if (value.is_none())
        throw py::type_error(std::string(function) + "(): " + name + " must be a str, bytes or os.PathLike, not None");
    // Looked up once and never released: a static py::object would be released after the
    // interpreter has finalized.
    static const py::object& fspath = *new py::object(py::module_::import("os").attr("fspath"));
    static const py::object& fsdecode = *new py::object(py::module_::import("os").attr("fsdecode"));
    py::object path;
    try {
        path = fspath(value);
    } catch (py::error_already_set& e) {
        if (!e.matches(PyExc_TypeError)) throw;
        throw py::type_error(std::string(function) + "(): " + name + " must be a str, bytes or os.PathLike, not " +
                             std::string(py::str(py::type::handle_of(value).attr("__name__"))));
    }
    return py::str(fsdecode(path));
}

py::array matrix_view(const Eigen::Matrix3Xd& m, py::handle owner)
{
    const auto d = py::ssize_t(sizeof(double));
    py::array view(py::dtype::of<double>(), {py::ssize_t(m.cols()), py::ssize_t(3)}, {3 * d, d}, m.data(), owner);
    py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return view;
}

} // namespace pccd_python
