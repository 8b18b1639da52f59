"""Builds and installs the Python module pccd with pip (doc/manual/python.md, "pip install"):

    pip install --no-build-isolation .

compiles the extension pccd._pccd from python/src against the headers of include/ with the
packages the interpreter already has (setuptools, pybind11, numpy: Debian's python3-setuptools,
python3-pybind11, python3-numpy), so it works offline; the C++ dependencies are those of the CMake
build (.ci/debian-packages: Eigen, Boost, nanoflann, CGAL with GMP and MPFR, TBB). It is the same
module as the CMake target pccd_python; CMake remains the build of the tests.
"""
import os
import pathlib
import re

from pybind11.setup_helpers import ParallelCompile, Pybind11Extension, build_ext
from setuptools import setup

root = pathlib.Path(__file__).resolve().parent
version = re.search(r'#define PCCD_VERSION_STRING "([^"]+)"', (root / "include/PCCD/version.h").read_text()).group(1)
ParallelCompile("PCCD_PIP_JOBS", default=2).install()


def first_existing(*paths):
    return [p for p in paths if os.path.isdir(p)][:1]


extension = Pybind11Extension(
    "pccd._pccd",
    sorted(str(p.relative_to(root)) for p in (root / "python/src").glob("*.cpp")),
    include_dirs=["include", *first_existing("/usr/include/eigen3", "/usr/local/include/eigen3")],
    define_macros=[("BOOST_ALL_NO_LIB", None), ("CGAL_USE_GMPXX", "1"), ("PCCD_HAS_TBB", None), ("NDEBUG", None)],
    extra_compile_args=["-O2", "-frounding-math"],
    libraries=["tbb", "gmpxx", "mpfr", "gmp"],
    cxx_std=20,
)

setup(
    name="pccd",
    version=version,
    description="Collision detection and intersection of point clouds (Python interface of PCCD)",
    license="BSD-3-Clause",
    python_requires=">=3.9",
    install_requires=["numpy"],
    packages=["pccd"],
    package_dir={"pccd": "python/pccd"},
    package_data={"pccd": ["_pccd.pyi", "py.typed"]},
    ext_modules=[extension],
    cmdclass={"build_ext": build_ext},
    zip_safe=False,
)
