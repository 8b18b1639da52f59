"""Shared fixtures of the pytest suite of the Python module pccd.

ctest runs each file with PYTHONPATH pointing at the built package and these variables set:
PCCD_SOURCE_DIR (the source tree), PCCD_DATA_DIR (libcgal-demo's meshes, empty when absent) and
PCCD_CLI (the built pccd tool, when built); scratch files go to build/test/python/tmp. A fixture
whose resource is missing fails the test: the files that need one are registered as skipped by
ctest when it was not found at configure time, so a test never passes without what it checks.
"""

import os
import pathlib

import numpy as np
import pytest

import pccd


def _required_env(name, what):
    value = os.environ.get(name, "")
    if not value:
        pytest.fail(f"{name} is not set: {what} (run the tests through ctest)")
    return value


@pytest.fixture(scope="session")
def source_dir():
    return pathlib.Path(_required_env("PCCD_SOURCE_DIR", "the PCCD source tree"))


@pytest.fixture(scope="session")
def cli():
    path = pathlib.Path(_required_env("PCCD_CLI", "the pccd tool"))
    if not path.is_file():
        pytest.fail(f"the pccd tool {path} does not exist (build it: cmake --build build --target pccd)")
    return path


@pytest.fixture(scope="session")
def bunny_file():
    path = pathlib.Path(_required_env("PCCD_DATA_DIR", "libcgal-demo's meshes")) / "bunny00.off"
    if not path.is_file():
        pytest.fail(f"{path} is missing (libcgal-demo's meshes were found at configure time)")
    return path


@pytest.fixture
def tmp(tmp_path):
    return tmp_path


def sphere_points(n, radius=0.5, seed=1):
    """n points on a sphere, from a seeded numpy generator (the same on every run)."""
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(n, 3))
    return radius * v / np.linalg.norm(v, axis=1, keepdims=True)


def torus_points(n, major=0.7, minor=0.3, seed=2):
    """n points on a torus about z, area-uniform (rejection on the angle about the tube)."""
    rng = np.random.default_rng(seed)
    points = []
    while len(points) < n:
        u, v, w = rng.uniform(0, 2 * np.pi), rng.uniform(0, 2 * np.pi), rng.uniform(0, 1)
        if w <= (major + minor * np.cos(v)) / (major + minor):
            r = major + minor * np.cos(v)
            points.append((r * np.cos(u), r * np.sin(u), minor * np.sin(v)))
    return np.array(points)


def rotation(axis, angle):
    """The rotation matrix about `axis` by `angle` (Rodrigues)."""
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def pose(axis=(0, 0, 1), angle=0.0, translation=(0, 0, 0)):
    """A 3x4 pose [R | t]."""
    return np.hstack([rotation(axis, angle), np.asarray(translation, dtype=float).reshape(3, 1)])


@pytest.fixture(scope="session")
def shapes():
    """A sphere (1500 points) and a torus (2000 points), preprocessed once for the session."""
    return pccd.Object(sphere_points(1500)), pccd.Object(torus_points(2000))


def same_result(x, y):
    """Whether two pccd.Result objects are identical, points bit for bit."""
    return (
        x.intersects == y.intersects
        and x.status == y.status
        and x.counters == y.counters
        and x.kinds == y.kinds
        and np.array_equal(x.points, y.points)
        and np.array_equal(x.f_values, y.f_values, equal_nan=True)
        and np.array_equal(np.array([x.closest_estimate]), np.array([y.closest_estimate]), equal_nan=True)
    )
