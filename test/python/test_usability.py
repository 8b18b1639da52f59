"""What a new user meets first: paths of every kind, clear messages for degenerate clouds, the
time budget's 0 as on the command line, query times and cheap counters, a docstring that says
what closest_estimate is, Open3D-like inputs, the pccd info layout, the Dask script's default
chunk, and scripts that write into a directory of their choosing."""

import os
import pathlib
import re
import subprocess
import sys
import timeit

import numpy as np
import pytest

import pccd
from conftest import pose, sphere_points

TOUCHING = pose((1, 1, 0), 0.4, (0.9, 0.0, 0.0))
NEAR_MISS = pose((0, 0, 1), 0.0, (1.51, 0.0, 0.0))  # the sphere 0.01 beyond the torus


# --- paths -------------------------------------------------------------------------------------------

def test_paths_may_be_str_bytes_or_pathlike(tmp):
    p = sphere_points(50)
    pccd.write_points(os.fsencode(tmp / "a.xyz"), p)
    for path in (str(tmp / "a.xyz"), os.fsencode(tmp / "a.xyz"), tmp / "a.xyz"):
        q, _ = pccd.read_points(path)
        assert np.array_equal(q, p)
    sphere = pccd.Object(p)
    sphere.save(os.fsencode(tmp / "a.pccd"))
    assert pccd.Object.load(os.fsencode(tmp / "a.pccd")).size == sphere.size


def test_a_missing_bytes_path_is_named_as_given(tmp):
    with pytest.raises(OSError) as error:
        pccd.read_points(os.fsencode(tmp / "kitten.xyz"))
    message = str(error.value)
    assert str(tmp / "kitten.xyz") in message
    assert "b'" not in message and "'.xyz''" not in message


@pytest.mark.parametrize("function", [pccd.read_points, pccd.Object.load])
@pytest.mark.parametrize("bad", [None, 3, 2.5, ["a.xyz"]])
def test_a_path_that_is_not_one_is_a_typeerror(function, bad):
    with pytest.raises(TypeError, match="str, bytes or os.PathLike"):
        function(bad)


def test_a_directory_is_named_as_such(tmp):
    (tmp / "scans.ply").mkdir()
    for directory in (tmp, tmp / "scans.ply"):
        with pytest.raises(OSError, match="is a directory"):
            pccd.read_points(directory)


# --- degenerate clouds ---------------------------------------------------------------------------------

def test_identical_points_say_why_the_sampling_radius_is_0():
    for points in (np.zeros((2, 3)), np.ones((50, 3))):
        with pytest.raises(ValueError) as error:
            pccd.Object(points)
        message = str(error.value)
        assert "sampling radius is 0" in message
        assert "coincide" in message and "duplicate" in message


# --- queries: the time budget, the query time, the counters --------------------------------------------

def test_max_time_us_0_means_no_budget_as_on_the_command_line(shapes):
    sphere, torus = shapes
    for p in (TOUCHING, NEAR_MISS):
        unlimited = pccd.do_intersect(sphere, p, torus, None, seed=3)
        zero = pccd.do_intersect(sphere, p, torus, None, seed=3, max_time_us=0)
        assert zero.status == unlimited.status and zero.counters == unlimited.counters
    [batch] = pccd.do_intersect_many([(sphere, TOUCHING, torus, None)], max_time_us=0.0)
    assert batch.intersects
    with pytest.raises(ValueError, match="max_time_us"):
        pccd.do_intersect(sphere, TOUCHING, torus, None, max_time_us=-1.0)


def test_a_result_carries_its_query_time(shapes):
    sphere, torus = shapes
    for query in (pccd.do_intersect, pccd.intersection_points):
        r = query(sphere, TOUCHING, torus, None)
        assert isinstance(r.query_us, float) and 0 < r.query_us < 60e6
    slow = pccd.intersection_points(sphere, TOUCHING, torus, None, point_spacing=0.002)
    fast = pccd.do_intersect(sphere, pose((0, 0, 1), 0, (5, 0, 0)), torus, None)
    assert slow.query_us > fast.query_us
    for r in pccd.do_intersect_many([(sphere, TOUCHING, torus, None)] * 3, threads=2):
        assert np.isnan(r.query_us)  # timed as a whole


def test_counters_are_built_once(shapes):
    sphere, torus = shapes
    r = pccd.do_intersect(sphere, TOUCHING, torus, None)
    assert r.counters is r.counters
    names = list(r.counters)
    assert names[0] == "f_evaluations" and len(names) == len(set(names)) == 15
    per_access = min(timeit.repeat(lambda: r.counters, number=20000, repeat=5)) / 20000
    assert per_access < 0.3e-6, per_access  # a cached attribute, not a dict built each time


def test_closest_estimate_is_documented_for_both_methods(shapes):
    sphere, torus = shapes
    doc = pccd.Result.__doc__
    assert "RST only" not in doc
    assert "both methods" in doc
    for method in ("isearch", "rst"):
        r = pccd.do_intersect(sphere, NEAR_MISS, torus, None, method=method, seed=5)
        assert r.status == "separate"
        assert np.isfinite(r.closest_estimate) and r.closest_estimate > 0, method


# --- arrays from other libraries ---------------------------------------------------------------------

class ArrayLike:
    """Anything exposing __array__, as many point cloud libraries' types do."""

    def __init__(self, points):
        self._points = points

    def __array__(self, dtype=None, copy=None):
        return self._points if dtype is None else self._points.astype(dtype)


class PointCloudLike:
    """Open3D's PointCloud interface as pccd uses it: points, normals, has_normals()."""

    def __init__(self, points, normals=None):
        self.points = points
        self.normals = normals if normals is not None else np.zeros((0, 3))

    def has_normals(self):
        return len(self.normals) > 0


def test_object_accepts_array_protocol_and_point_cloud_types():
    p = sphere_points(800)
    reference = pccd.Object(p)
    assert np.array_equal(pccd.Object(ArrayLike(p)).points, reference.points)
    assert np.array_equal(pccd.Object(PointCloudLike(ArrayLike(p))).points, reference.points)
    n = -p / np.linalg.norm(p, axis=1, keepdims=True)  # inward normals: hints that flip the orientation
    with_normals = pccd.Object(PointCloudLike(p, n))
    assert with_normals.normals_given
    assert np.array_equal(with_normals.points, reference.points)
    outward = np.einsum("ij,ij->i", reference.normals, reference.points)
    inward = np.einsum("ij,ij->i", with_normals.normals, with_normals.points)
    assert (np.sign(outward) == -np.sign(inward)).mean() > 0.99
    with pytest.raises(ValueError, match=r"shape \(N, 3\)"):
        pccd.Object(ArrayLike(np.zeros((10, 2))))


# --- the tool and the scripts ----------------------------------------------------------------------------

def test_pccd_info_separates_labels_from_values(cli, tmp):
    pccd.write_points(tmp / "sphere.xyz", sphere_points(500))
    done = subprocess.run([str(cli), "info", "sphere.xyz"], cwd=tmp, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    times = [line for line in done.stdout.splitlines() if line.startswith("time ")]
    assert any("hierarchy" in line for line in times) and any("sampling_radius" in line for line in times)
    for line in times:
        assert re.fullmatch(r"time [a-z_]+ +[0-9.e+-]+ ms", line), line


def test_dask_script_default_chunk_is_the_manuals_advice(source_dir):
    manual = (source_dir / "doc" / "manual" / "python.md").read_text()
    advised = re.search(r"chunks of about ([0-9,]+) such pairs", manual)
    assert advised, "the manual's advice on --chunk"
    chunk = int(advised.group(1).replace(",", ""))
    script = source_dir / "examples" / "python" / "dask_many_pairs.py"
    done = subprocess.run([sys.executable, str(script), "--help"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert re.search(rf"--chunk CHUNK\s+pairs per task \(default {chunk}\b", done.stdout), done.stdout


def test_quickstart_writes_into_the_directory_given_or_a_temporary_one(source_dir, tmp):
    pccd.write_points(tmp / "a.xyz", sphere_points(1500))
    pccd.write_points(tmp / "b.xyz", sphere_points(1500, radius=0.6, seed=4))
    script = source_dir / "examples" / "python" / "quickstart.py"
    work = tmp / "cwd"
    work.mkdir()
    out = tmp / "out"
    out.mkdir()
    done = subprocess.run([sys.executable, str(script), "--out", str(out), str(tmp / "a.xyz"), str(tmp / "b.xyz")],
                          cwd=work, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert (out / "curve.ply").is_file() and not list(work.iterdir())
    done = subprocess.run([sys.executable, str(script), str(tmp / "a.xyz"), str(tmp / "b.xyz")],
                          cwd=work, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert not list(work.iterdir())
    written = pathlib.Path(re.search(r"wrote (.*curve\.ply)", done.stdout).group(1))
    assert written.is_file() and written.parent.name.startswith("pccd-quickstart-")
    written.unlink()
    written.parent.rmdir()
