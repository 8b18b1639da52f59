"""pccd.clearance: an object moved along a path of poses past a scene, against independent truths --
a sampled sphere of radius 0.5 passing another one, whose surface gap at each pose is known
analytically -- and against the C++ calls (`pccd clearance --json` on the same files, which calls
PCCD::clearance on objects preprocessed from them); the samples equal the single distance calls
with their seeds, for 1 and 2 threads; every bad argument a clear ValueError or TypeError."""

import json
import math
import subprocess

import numpy as np
import pytest

import pccd
from conftest import pose, sphere_points

RADIUS = 0.5  # sphere_points' radius
# distance()'s accuracy on these clouds: test_distance.py checks the gap within 3 % of up to 1 (the
# C++ tests state half a mean spacing, about 0.023 for 1500 points on this sphere).
ACCURACY = 0.025


@pytest.fixture(scope="module")
def ball():
    return pccd.Object(sphere_points(1500))


def along_x(xs, turn=True):
    """The moving sphere's centre at (x, 0, 0) for each x, turned about a tilted axis (a sphere does
    not care), as an (n, 3, 4) array."""
    return np.array([pose((1, 2, 3), 0.3 * k if turn else 0.0, (x, 0.0, 0.0)) for k, x in enumerate(xs)])


XS = [2.0 - 0.1 * k for k in range(10)]  # centres 2.0 ... 1.1 apart: gaps 1.0 ... 0.1
GAPS = [x - 2 * RADIUS for x in XS]
MARGIN = 0.35  # between the gaps 0.4 (pose 6) and 0.3 (pose 7), 0.05 from each: beyond the accuracy


def test_the_first_pose_below_the_margin_is_the_analytic_one(ball):
    p = pccd.clearance(ball, ball, along_x(XS), MARGIN)
    assert len(p) == len(XS)
    assert p.margin == MARGIN and p.max_distance is None
    assert p.status == ["clear"] * 7 + ["below_margin"] * 3
    assert p.first_below_margin == 7 == next(i for i, g in enumerate(GAPS) if g < MARGIN)
    for name in ("clearance", "lower_bound", "upper_bound", "depth"):
        values = getattr(p, name)
        assert values.shape == (len(XS),) and values.dtype == np.float64, name
    assert np.all(np.abs(p.clearance - np.array(GAPS)) <= ACCURACY), p.clearance - np.array(GAPS)
    assert np.all(p.lower_bound <= p.clearance) and np.all(p.clearance <= p.upper_bound)
    assert np.all(np.isnan(p.depth))
    # The witnesses: on the scene sphere facing +x, on the object's facing -x, their distance the clearance.
    assert p.point_object.shape == p.point_scene.shape == (len(XS), 3)
    assert np.allclose(np.linalg.norm(p.point_object - p.point_scene, axis=1), p.clearance, rtol=1e-9)
    assert np.all(p.point_scene[:, 0] > 0.45) and np.all(np.abs(np.linalg.norm(p.point_scene, axis=1) - RADIUS) < 0.01)
    assert p.first_point_object.tolist() == p.point_object[7].tolist()
    assert p.first_point_scene.tolist() == p.point_scene[7].tolist()
    # The minimum: the last pose, gap 0.1.
    assert p.minimum == 9 and abs(p.minimum_clearance - 0.1) <= ACCURACY
    assert p.first_undecided is None and not p.all_clear
    c = p.counters
    assert (c["clear"], c["below_margin"], c["intersecting"], c["beyond_cap"], c["undecided"]) == (7, 3, 0, 0, 0)
    assert c["work"]["node_pairs"] > 0 and c["work"]["intersection_node_pairs"] >= len(XS)
    assert p.counters is c  # built once
    assert p.query_us > 0
    assert "first below 7" in repr(p)


def test_intersecting_poses_and_the_cap(ball):
    xs = [3.0, 2.5, 1.6, 0.8]  # gaps 2, 1.5, 0.6, overlapping by 0.2
    p = pccd.clearance(ball, ball, along_x(xs), 0.1, max_distance=1.0, penetration=True)
    assert p.status == ["beyond_cap", "beyond_cap", "clear", "intersecting"]
    assert p.max_distance == 1.0
    assert p.clearance[0] == math.inf and p.lower_bound[0] >= 1.0 and np.isnan(p.point_object[0]).all()
    assert p.clearance[3] == 0.0 and abs(p.depth[3] - 0.2) <= 2 * ACCURACY
    assert p.first_below_margin == 3 and p.minimum == 3 and p.minimum_clearance == 0.0
    # every pose beyond the cap: nothing below the margin, no minimum
    far = pccd.clearance(ball, ball, along_x(xs[:2]), 0.1, max_distance=1.0)
    assert far.all_clear and far.minimum is None and far.minimum_clearance == math.inf


def test_the_samples_are_the_single_distances_for_any_thread_count(ball):
    poses = along_x([2.3 - 0.13 * k for k in range(12)])  # from apart to overlapping
    one = pccd.clearance(ball, ball, poses, 0.2, threads=1, seed=9, first_index=3)
    two = pccd.clearance(ball, ball, poses, 0.2, threads=2, seed=9, first_index=3)
    assert set(one.status) >= {"clear", "below_margin", "intersecting"}
    assert one.status == two.status and one.counters == two.counters
    for name in ("clearance", "lower_bound", "upper_bound", "point_object", "point_scene"):
        assert np.array_equal(getattr(one, name), getattr(two, name), equal_nan=True), name
    work = {}
    for i in range(len(poses)):
        d = pccd.distance(ball, poses[i], ball, None, seed=pccd.pair_seed(9, 3 + i))
        assert d.status == ("intersecting" if one.status[i] == "intersecting" else "separate"), i
        assert d.distance == one.clearance[i] and d.lower_bound == one.lower_bound[i], i
        assert d.upper_bound == one.upper_bound[i], i
        for name, value in d.counters.items():
            work[name] = work.get(name, 0) + value
    assert work == one.counters["work"]  # the sum of the single queries' counters
    # A 4x4 stack answers as its 3x4 form.
    homogeneous = np.concatenate([poses, np.tile([[[0.0, 0.0, 0.0, 1.0]]], (len(poses), 1, 1))], axis=1)
    four = pccd.clearance(ball, ball, homogeneous, 0.2, threads=2, seed=9, first_index=3)
    assert np.array_equal(four.clearance, one.clearance)


def test_an_empty_path(ball):
    p = pccd.clearance(ball, ball, np.zeros((0, 3, 4)), 0.1)
    assert len(p) == 0 and p.status == [] and p.clearance.shape == (0,) and p.point_object.shape == (0, 3)
    assert p.first_below_margin is None and p.minimum is None and p.all_clear


@pytest.mark.parametrize("margin", [-1.0, math.nan, math.inf])
def test_a_bad_margin_is_a_valueerror(ball, margin):
    with pytest.raises(ValueError, match="margin"):
        pccd.clearance(ball, ball, along_x(XS), margin)


def test_bad_arguments(ball):
    with pytest.raises(ValueError, match="below the margin"):
        pccd.clearance(ball, ball, along_x(XS), 0.5, max_distance=0.25)
    with pytest.raises(ValueError, match="max_distance"):
        pccd.clearance(ball, ball, along_x(XS), 0.5, max_distance=-1.0)
    with pytest.raises(ValueError, match="relative_tolerance"):
        pccd.clearance(ball, ball, along_x(XS), 0.5, relative_tolerance=-1.0)
    with pytest.raises(ValueError, match="threads"):
        pccd.clearance(ball, ball, along_x(XS), 0.5, threads=0)
    with pytest.raises(ValueError, match=r"clearance\(\): poses must have shape \(n, 3, 4\) or \(n, 4, 4\), got \(3, 4\)"):
        pccd.clearance(ball, ball, pose(), 0.5)
    nan_path = along_x(XS)
    nan_path[1, 2, 3] = math.nan
    with pytest.raises(ValueError, match=r"poses\[1\]: rigid transform: translation entry \(2, 3\) is nan"):
        pccd.clearance(ball, ball, nan_path, 0.5)
    scaled = along_x(XS)
    scaled[4, :, :3] *= 2
    with pytest.raises(ValueError, match=r"poses\[4\]: rigid transform: the rotation part scales"):
        pccd.clearance(ball, ball, scaled, 0.5)
    with pytest.raises(TypeError, match="unexpected keyword argument 'margins'"):
        pccd.clearance(ball, ball, along_x(XS), 0.5, margins=1)
    with pytest.raises(TypeError):
        pccd.clearance(ball, "ball", along_x(XS), 0.5)


def test_same_answers_as_the_cli(cli, tmp):
    file = tmp / "sphere.xyz"
    pccd.write_points(file, sphere_points(1500))
    ball = pccd.Object(pccd.read_points(file)[0])
    poses = along_x(XS)
    path = tmp / "path.csv"
    path.write_text("".join(",".join(repr(float(v)) for v in p.reshape(-1)) + "\n" for p in poses))
    done = subprocess.run([str(cli), "clearance", str(file), str(file), "--path", str(path), "--margin", str(MARGIN),
                           "--max-distance", "0.8", "--seed", "7", "--json"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout)
    got = pccd.clearance(ball, ball, poses, MARGIN, max_distance=0.8, seed=7)
    assert got.status == [s["status"] for s in expected["samples"]]
    assert "beyond_cap" in got.status
    for name in ("clearance", "lower_bound", "upper_bound", "depth"):
        for i, s in enumerate(expected["samples"]):
            want = s[name]
            value = getattr(got, name)[i]
            assert (not math.isfinite(value)) if want is None else value == want, (name, i)
    for name in ("point_object", "point_scene"):
        for i, s in enumerate(expected["samples"]):
            want = s[name]
            value = getattr(got, name)[i]
            assert np.isnan(value).all() if want is None else value.tolist() == want, (name, i)
    for name in ("first_below_margin", "minimum", "first_undecided", "all_clear", "margin", "max_distance"):
        assert getattr(got, name) == expected[name], name
    assert got.minimum_clearance == expected["minimum_clearance"]
    assert got.first_point_object.tolist() == expected["first_point_object"]
    assert got.counters == expected["counters"]
