"""Continuous collision in the Python module: pccd.time_of_contact and time_of_contact_many against
independent truths -- two sampled unit spheres meeting along a line and along a screw, whose first
contact times are known in closed form -- and against the C++ calls (`pccd contact-time --json`
on the same files, which calls PCCD::time_of_contact on objects preprocessed from them, bit for
bit); the batch against the single calls for 1 and 2 threads; every bad argument a clear
ValueError or TypeError."""

import json
import math
import subprocess
import threading
import time

import numpy as np
import pytest

import pccd
from conftest import pose, sphere_points, torus_points

SPACING = math.sqrt(4 * math.pi / 2000)  # the unit sphere's mean spacing at 2000 points, about 0.08


def at(x=0.0, y=0.0, z=0.0):
    return pose(translation=(x, y, z))


STILL = (None, None)
THROUGH = (at(4.0), at(-4.0))  # a path of length 8: one spacing is 0.01 of time


@pytest.fixture(scope="module")
def ball():
    return pccd.Object(sphere_points(2000, radius=1.0))


# --- analytic truth: two unit spheres ---------------------------------------------------------------

def test_spheres_meeting_along_a_line(ball):
    """B from x = 4 to x = -4 through A at rest: the spheres touch when their centres are 2 apart,
    at t = 0.25; the contact point is near (1, 0, 0) and B leaves A along +x."""
    r = pccd.time_of_contact(ball, STILL, ball, THROUGH)
    assert r.status == "contact" and bool(r)
    assert abs(r.t - 0.25) * 8 <= SPACING, r
    assert r.t_low <= r.t == r.t_high
    assert (r.t_high - r.t_low) * 8 <= 0.25 * ball.sampling_radius + 1e-12  # the default time accuracy or finer
    assert r.point.shape == (3,) and r.point.dtype == np.float64
    assert abs(r.point[0] - 1.0) <= SPACING
    assert r.normal[0] > math.cos(math.radians(20)) and np.linalg.norm(r.normal) == pytest.approx(1, abs=1e-9)
    assert list(r.counters) == ["advancement_steps", "near_checks", "bisection_steps", "node_pairs", "f_evaluations"]
    assert r.counters is r.counters  # built once
    assert 0 < r.counters["advancement_steps"] < 60
    assert math.isfinite(r.query_us) and r.query_us > 0
    assert "contact at t = 0.2" in repr(r)
    # The surfaces do intersect at t.
    assert pccd.do_intersect(ball, None, ball, at(4.0 - 8.0 * r.t)).intersects


def test_a_tolerance_makes_contact_earlier(ball):
    r = pccd.time_of_contact(ball, STILL, ball, THROUGH, tolerance=0.4)
    assert r.status == "contact"
    assert abs(r.t - (4.0 - 2.4) / 8.0) * 8 <= SPACING


def test_passing_at_a_gap_is_no_contact(ball):
    past = (at(4.0, 2.5), at(-4.0, 2.5))
    r = pccd.time_of_contact(ball, STILL, ball, past)
    assert r.status == "no_contact" and not r
    assert math.isnan(r.t) and r.t_low == 1.0 and math.isnan(r.t_high)
    assert np.isnan(r.point).all() and np.isnan(r.normal).all()
    assert repr(r) == "<pccd.ContactTimeResult: no_contact>"
    # Within 0.6 of each other they are: contact with that tolerance.
    assert pccd.time_of_contact(ball, STILL, ball, past, tolerance=0.6).status == "contact"


def test_starting_in_contact_is_t_0(ball):
    r = pccd.time_of_contact(ball, STILL, ball, (at(1.5), at(5.0)))
    assert r.status == "contact" and r.t == 0.0 and r.t_low == 0.0


def test_a_screw_motion(ball):
    """B screws a quarter turn about z from (3, 0, 0) to (0, 3, 0) towards A resting at (0, 3, 0):
    contact when the centres are 2 apart, at t = asin(7/9) / (pi / 2); moved linearly between the
    same poses B cuts the corner and meets A at t = 1 - 2 / (3 sqrt 2)."""
    fixed = (at(0, 3), at(0, 3))
    turn = (at(3), pose((0, 0, 1), math.pi / 2, (0, 3, 0)))
    screwed = pccd.time_of_contact(ball, fixed, ball, turn, motion="screw")
    assert screwed.status == "contact"
    assert abs(screwed.t - math.asin(7 / 9) / (math.pi / 2)) * (3 * math.pi / 2) <= SPACING
    linear = pccd.time_of_contact(ball, fixed, ball, turn)
    assert abs(linear.t - (1 - 2 / (3 * math.sqrt(2)))) * 3 * math.sqrt(2) <= SPACING


def test_a_budget_of_one_step_is_undecided(ball):
    r = pccd.time_of_contact(ball, STILL, ball, THROUGH, max_steps=1)
    assert r.status == "undecided" and not r
    assert math.isnan(r.t) and r.t_low == 0.0 and math.isnan(r.t_high)
    assert "undecided" in repr(r)


def same_result(x, y):
    """Two ContactTimeResults are identical: every field bit for bit (NaN where NaN), the counters."""
    def same(u, v):
        return np.array_equal(np.asarray(u), np.asarray(v), equal_nan=True)
    return (x.status == y.status and same(x.t, y.t) and same(x.t_low, y.t_low) and same(x.t_high, y.t_high)
            and same(x.point, y.point) and same(x.normal, y.normal) and x.counters == y.counters)


def test_the_forms_of_a_motion_give_the_same_answer(ball):
    """(3x4, 3x4), (4x4, 4x4), a (2, 3, 4) array and lists; None for (identity, identity)."""
    four = tuple(np.vstack([p, [0, 0, 0, 1]]) for p in THROUGH)
    reference = pccd.time_of_contact(ball, STILL, ball, THROUGH, seed=4)
    for motion_b in (four, np.stack(THROUGH), [p.tolist() for p in THROUGH]):
        assert same_result(pccd.time_of_contact(ball, STILL, ball, motion_b, seed=4), reference)
    assert same_result(pccd.time_of_contact(ball, None, ball, THROUGH, seed=4), reference)
    assert same_result(pccd.time_of_contact(ball, (at(), at()), ball, THROUGH, seed=4), reference)


# --- the batch ----------------------------------------------------------------------------------

def test_the_batch_equals_the_single_calls(ball):
    torus = pccd.Object(torus_points(2000))
    pairs = [(ball, STILL, ball, THROUGH),
             (torus, (at(), pose((0, 0, 1), 1.0, (0.1, 0, 0))), ball, (at(0.2, 3.0), at(0.0, -3.0))),
             (ball, STILL, torus, (at(4.0, 2.5), at(-4.0, 2.5))),
             (torus, STILL, ball, THROUGH, (0.0, 0.0, 0.0), (0.0, 0.5, 0.0))]
    seed = 11
    single = [pccd.time_of_contact(*p[:4], **({"centre_a": p[4], "centre_b": p[5]} if len(p) == 6 else {}),
                                   seed=pccd.pair_seed(seed, i)) for i, p in enumerate(pairs)]
    assert {r.status for r in single} == {"contact", "no_contact"}
    for threads in (1, 2, None):
        batch = pccd.time_of_contact_many(pairs, seed=seed, threads=threads)
        assert len(batch) == len(pairs)
        for got, expected in zip(batch, single):
            assert same_result(got, expected)
            assert math.isnan(got.query_us)
    # A chunk of the batch, seeded as its place in the whole.
    chunk = pccd.time_of_contact_many(pairs[2:], seed=seed, first_index=2, threads=2)
    assert all(same_result(x, y) for x, y in zip(chunk, single[2:]))
    screws = pccd.time_of_contact_many([p[:4] for p in pairs], motion="screw", tolerance=0.1, threads=2)
    for i, got in enumerate(screws):
        expected = pccd.time_of_contact(*pairs[i][:4], motion="screw", tolerance=0.1, seed=pccd.pair_seed(24301, i))
        assert same_result(got, expected)
    assert pccd.time_of_contact_many([]) == []


@pytest.mark.parametrize("batch", [False, True])
def test_the_queries_release_the_gil(ball, batch):
    """While one query (or a batch) runs, Python code on another thread keeps running. The query:
    B passing A at a gap of 0.1 with near sub-steps of 0.005 sampling radii (about 8,000 contact
    checks; 0.07 s on the project's machine), or, should that take less than 0.05 s, with
    sub-steps five or twenty-five times shorter."""
    passing = (ball, STILL, ball, (at(4.0, 2.1), at(-4.0, 2.1)))
    candidates = [(passing, dict(near_step=step)) for step in (0.005, 0.001, 0.0002)]
    for arguments, options in candidates:
        start = time.perf_counter()
        pccd.time_of_contact(*arguments, **options)
        if time.perf_counter() - start > 0.05:
            break

    def query():
        if batch:
            pccd.time_of_contact_many([arguments] * 3, threads=1, **options)
        else:
            pccd.time_of_contact(*arguments, **options)

    start = time.perf_counter()
    query()
    duration = time.perf_counter() - start
    assert duration > 0.025, "the queries are too short to observe"
    window = {}

    def run():
        window["start"] = time.perf_counter()
        query()
        window["end"] = time.perf_counter()

    worker = threading.Thread(target=run)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    middle = [t for t in ticks if window["start"] + 0.25 * duration < t < window["end"] - 0.25 * duration]
    assert len(middle) > 100, f"{len(middle)} ticks while the queries ran: the GIL was held"


# --- the same answers as the C++ calls (pccd contact-time --json) --------------------------------

def cli_json(cli, file_a, file_b, motion_a, motion_b, *options):
    def numbers(p):
        return " ".join(repr(float(v)) for v in np.asarray(p).reshape(-1))
    done = subprocess.run([str(cli), "contact-time", str(file_a), str(file_b), f"--from-a={numbers(motion_a[0])}",
                           f"--to-a={numbers(motion_a[1])}", f"--from-b={numbers(motion_b[0])}",
                           f"--to-b={numbers(motion_b[1])}", "--json", *options],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_same_answers_as_the_cli(cli, tmp):
    file_a, file_b = tmp / "torus.xyz", tmp / "sphere.xyz"
    pccd.write_points(file_a, torus_points(2000))
    pccd.write_points(file_b, sphere_points(1500))
    a = pccd.Object(pccd.read_points(file_a)[0])
    b = pccd.Object(pccd.read_points(file_b)[0])
    cases = [
        # the sphere (radius 0.5) through the turning torus
        (dict(), (at(), pose((0, 0, 1), 0.8, (0.1, 0, 0))), (at(3.0, 0.2), at(-3.0, 0.0))),
        (dict(motion="screw", seed=5), (at(), pose((1, 0, 0), 0.5)), (at(0, 0, 2.0), pose((0, 1, 0), 1.2, (0, 0, -2.0)))),
        (dict(centre_a=(0.2, 0.0, 0.0), centre_b=(0.0, 0.1, 0.0), tolerance=0.05, seed=7),
         (at(), pose((0, 0, 1), 1.5)), (at(0, 3.0), pose((1, 1, 0), 0.4, (0, -3.0, 0.3)))),
        (dict(tolerance=0.2), (at(), at()), (at(3.0, 1.8), at(-3.0, 1.8))),  # passes by
        (dict(max_steps=1), (at(), at()), (at(3.0), at(-3.0))),  # runs out of steps
    ]
    statuses = set()
    for k, (kwargs, motion_a, motion_b) in enumerate(cases):
        options = []
        for name, option in (("motion", "--motion"), ("tolerance", "--tolerance"), ("seed", "--seed"),
                             ("max_steps", "--max-steps")):
            if name in kwargs:
                options += [option, str(kwargs[name])]
        for name, option in (("centre_a", "--centre-a"), ("centre_b", "--centre-b")):
            if name in kwargs:
                options.append(f"{option}={','.join(repr(float(v)) for v in kwargs[name])}")
        expected = cli_json(cli, file_a, file_b, motion_a, motion_b, *options)
        got = pccd.time_of_contact(a, motion_a, b, motion_b, **kwargs)
        where = f"case {k}: {kwargs}"
        assert got.status == expected["status"], where
        statuses.add(got.status)
        for name in ("t", "t_low", "t_high"):
            value = getattr(got, name)
            if expected[name] is None:
                assert math.isnan(value), f"{where}: {name} {value}, the CLI printed null"
            else:
                assert value == expected[name], f"{where}: {name} {value} != {expected[name]}"
        for name in ("point", "normal"):
            value = getattr(got, name)
            if expected[name] is None:
                assert np.isnan(value).all(), f"{where}: {name}"
            else:
                assert value.tolist() == expected[name], f"{where}: {name}"
        assert got.counters == expected["counters"], where
    assert statuses == {"contact", "no_contact", "undecided"}, statuses


# --- errors --------------------------------------------------------------------------------------

NAN_POSE = pose(translation=(math.nan, 0, 0))
SCALED = np.hstack([2 * np.eye(3), np.zeros((3, 1))])
REFLECTED = np.hstack([np.diag([1.0, 1.0, -1.0]), np.zeros((3, 1))])


@pytest.mark.parametrize("motion_b, message", [
    ((at(), NAN_POSE), r"motion_b\[1\]: rigid transform: translation entry \(0, 3\) is nan"),
    ((SCALED, at()), r"motion_b\[0\]: rigid transform: the rotation part scales"),
    ((at(), REFLECTED), r"motion_b\[1\]: rigid transform: the rotation part is a reflection"),
    (at(), r"motion_b must be a pair .*got an array of shape \(3, 4\)"),
    ((at(),), r"motion_b must be a pair .*got a sequence of length 1"),
    ((at(), at(), at()), r"motion_b must be a pair .*length 3"),
    ("linear", r"motion_b must be a pair .*got str"),
    (3.0, r"motion_b must be a pair .*got float"),
    ((np.eye(3), at()), r"motion_b\[0\] must have shape \(3, 4\) or \(4, 4\), got \(3, 3\)"),
    ((np.zeros((2, 4)), at()), r"motion_b\[0\] must have shape"),
])
def test_a_bad_motion_is_a_value_error(ball, motion_b, message):
    with pytest.raises(ValueError, match=message):
        pccd.time_of_contact(ball, STILL, ball, motion_b)


@pytest.mark.parametrize("kwargs, message", [
    (dict(tolerance=-0.1), "tolerance -0.1 must be finite and >= 0"),
    (dict(tolerance=math.nan), "tolerance nan must be finite and >= 0"),
    (dict(tolerance=math.inf), "tolerance inf must be finite and >= 0"),
    (dict(time_accuracy=0.0), "time_accuracy 0 must be finite and > 0"),
    (dict(near_step=5.0), r"near_step 5 must be in \(0, 4\]"),
    (dict(near_step=0.0), r"near_step 0 must be in \(0, 4\]"),
    (dict(max_steps=0), "max_steps must be >= 1"),
    (dict(motion="spin"), "motion must be 'linear' or 'screw', not 'spin'"),
    (dict(motion="screw", centre_b=(0, 0, 0)), "centre_b applies to motion='linear' only"),
    (dict(centre_a=(0, 0)), r"centre_a must have shape \(3,\)"),
    (dict(centre_a=(0, math.nan, 0)), "centre_a must be finite"),
    (dict(centre_b="origin"), "centre_b must be 3 numbers"),
])
def test_a_bad_option_is_a_value_error(ball, kwargs, message):
    with pytest.raises(ValueError, match=message):
        pccd.time_of_contact(ball, STILL, ball, THROUGH, **kwargs)


def test_motions_too_fast_for_a_speed_bound_are_a_value_error(ball):
    with pytest.raises(ValueError, match="speed bound inf is not finite"):
        pccd.time_of_contact(ball, STILL, ball, (at(-1e308), at(1e308)))


def test_wrong_types_are_type_errors(ball):
    with pytest.raises(TypeError):
        pccd.time_of_contact(ball, STILL, "ball", THROUGH)
    with pytest.raises(TypeError):
        pccd.time_of_contact(ball, STILL, ball, THROUGH, tolerance="0.1")
    with pytest.raises(TypeError):
        pccd.time_of_contact(ball, STILL, ball, THROUGH, max_steps=-1)
    with pytest.raises(TypeError):
        pccd.time_of_contact(ball, STILL, ball, THROUGH, speed=2)
    with pytest.raises(TypeError):
        pccd.time_of_contact_many([(None, STILL, ball, THROUGH)])


def test_bad_batches_are_value_errors_before_any_work(ball):
    with pytest.raises(ValueError, match=r"pairs\[1\] must be a tuple"):
        pccd.time_of_contact_many([(ball, STILL, ball, THROUGH), (ball, STILL, ball)])
    with pytest.raises(ValueError, match=r"pairs\[0\]: motion_a\[1\]: rigid transform: translation entry"):
        pccd.time_of_contact_many([(ball, (at(), NAN_POSE), ball, THROUGH)])
    with pytest.raises(ValueError, match=r"pairs\[0\]: centre_a applies to motion='linear' only"):
        pccd.time_of_contact_many([(ball, STILL, ball, THROUGH, (0, 0, 0), None)], motion="screw")
    with pytest.raises(ValueError, match=r"pairs\[1\]: time_of_contact: the motions' speed bound inf"):
        pccd.time_of_contact_many([(ball, STILL, ball, THROUGH), (ball, STILL, ball, (at(-1e308), at(1e308)))],
                                  threads=2)
    with pytest.raises(ValueError, match="threads = 0 must be from 1 to 4096"):
        pccd.time_of_contact_many([(ball, STILL, ball, THROUGH)], threads=0)
    with pytest.raises(ValueError, match="tolerance -1 must be finite and >= 0"):
        pccd.time_of_contact_many([(ball, STILL, ball, THROUGH)], tolerance=-1.0)


def test_help_reads_like_numpy():
    for f in (pccd.time_of_contact, pccd.time_of_contact_many):
        doc = f.__doc__
        assert "Parameters\n----------" in doc and "Returns\n-------" in doc and "Raises\n------" in doc, f
        for name in ("motion", "tolerance", "time_accuracy", "near_step", "max_steps", "seed"):
            assert f"\n{name} : " in doc, (f, name)
    doc = pccd.ContactTimeResult.__doc__
    for name in ("status", "t", "t_low, t_high", "point", "normal", "counters", "query_us"):
        assert f"\n{name} : " in doc, name
