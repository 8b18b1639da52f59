// python/src/conversions.cpp -- numpy arrays to and from PCCD's types: (N, 3) point and normal
// arrays read in place, 3x4 / 4x4 poses checked into Rigid_transform_3, and read-only views of
// PCCD's 3 x N matrices. Every malformed array raises ValueError naming the argument
// (doc/manual/python.md, "Arrays").
#include "pccd_python.h"

#include <PCCD/Error.h>

#include <array>
#include <string>

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

PCCD::Rigid_transform_3<double> pose_argument(py::handle value, const char* name)
{
    if (value.is_none()) return {};
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
    if (a.shape(0) == 4 && !(m[12] == 0.0 && m[13] == 0.0 && m[14] == 0.0 && m[15] == 1.0))
        throw py::value_error(std::string(name) + ": the last row of a 4x4 pose must be [0, 0, 0, 1], got [" +
                              std::to_string(m[12]) + ", " + std::to_string(m[13]) + ", " + std::to_string(m[14]) +
                              ", " + std::to_string(m[15]) + "]");
    std::array<double, 12> entries;
    for (int k = 0; k < 12; ++k) entries[std::size_t(k)] = m[k];
    try {
        return PCCD::Rigid_transform_3<double>(entries);
    } catch (const PCCD::Invalid_input& e) {
        throw PCCD::Invalid_input(std::string(name) + ": " + e.what());
    }
}

py::array matrix_view(const Eigen::Matrix3Xd& m, py::handle owner)
{
    const auto d = py::ssize_t(sizeof(double));
    py::array view(py::dtype::of<double>(), {py::ssize_t(m.cols()), py::ssize_t(3)}, {3 * d, d}, m.data(), owner);
    py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return view;
}

} // namespace pccd_python
