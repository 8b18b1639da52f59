// python/src/module.cpp -- the extension module pccd._pccd: adds the parts (I/O, Object,
// intersection queries, proximity queries, collision worlds) and maps PCCD's exceptions to Python's:
// PCCD::File_error -> OSError, PCCD::Invalid_input and PCCD::Precondition_failure -> ValueError,
// PCCD::Assertion_failure -> RuntimeError, each with PCCD's message (doc/manual/python.md,
// "Errors").
#include "pccd_python.h"

#include <PCCD/Error.h>
#include <PCCD/version.h>

#include <exception>

PYBIND11_MODULE(_pccd, m)
{
    namespace py = pybind11;
    m.doc() = "Compiled part of the pccd package (see help(pccd)).";
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const PCCD::File_error& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        } catch (const PCCD::Invalid_input& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const PCCD::Precondition_failure& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const PCCD::Assertion_failure& e) {
            PyErr_SetString(PyExc_RuntimeError, e.what());
        }
    });
    m.attr("__version__") = PCCD_VERSION_STRING;
    pccd_python::add_io(m);
    pccd_python::add_object(m);
    pccd_python::add_queries(m);
    pccd_python::add_proximity(m);
    pccd_python::add_world(m);
    pccd_python::add_continuous(m);
}
