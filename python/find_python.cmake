# Finds what the Python module pccd needs and sets PCCD_PYTHON_AVAILABLE: an interpreter that
# imports numpy (Python_EXECUTABLE when given; otherwise the first of `python3` on PATH and
# /usr/bin/python3 that does, so that Debian's python3-numpy is found even when another python3
# comes first on PATH), its development files, and pybind11 (Debian: pybind11-dev). Included by
# the top-level CMakeLists.txt before the option PCCD_BUILD_PYTHON, whose default it gives.
set(PCCD_PYTHON_AVAILABLE OFF)
if(NOT Python_EXECUTABLE)
  find_program(_pccd_python_on_path NAMES python3 NO_CACHE)
  foreach(_pccd_candidate IN ITEMS "${_pccd_python_on_path}" /usr/bin/python3)
    if(_pccd_candidate AND EXISTS "${_pccd_candidate}")
      execute_process(COMMAND "${_pccd_candidate}" -c "import numpy" RESULT_VARIABLE _pccd_numpy_result
                      OUTPUT_QUIET ERROR_QUIET)
      if(_pccd_numpy_result EQUAL 0)
        set(Python_EXECUTABLE "${_pccd_candidate}" CACHE FILEPATH "The Python interpreter of the pccd module")
        break()
      endif()
    endif()
  endforeach()
endif()
if(Python_EXECUTABLE)
  find_package(Python 3.8 COMPONENTS Interpreter Development.Module QUIET)
  if(Python_FOUND)
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 2.6 CONFIG QUIET)
    if(pybind11_FOUND)
      set(PCCD_PYTHON_AVAILABLE ON)
    endif()
  endif()
endif()
if(NOT PCCD_PYTHON_AVAILABLE)
  message(STATUS "PCCD: the Python module is not built (it needs pybind11-dev, python3-dev and python3-numpy)")
endif()
