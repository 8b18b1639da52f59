"""The proximity queries of the Python module: pccd.distance, within_distance, contacts and
distance_many, against independent truths -- two sampled spheres at known poses, whose gap and
penetration depth are known analytically -- and against the C++ calls (`pccd distance --json`
on the same files, which calls PCCD::distance on objects preprocessed from them); the batch
against the single calls for 1 and 2 threads; every bad argument a clear ValueError or TypeError."""

import json
import math
import subprocess

import numpy as np
import pytest

import pccd
from conftest import pose, rotation, sphere_points, torus_points

RADIUS = 0.5  # sphere_points' radius


def shifted(x, axis=(0, 0, 1), angle=0.0):
    """B's pose: turned by `angle` about `axis` (a sphere about its centre: the same surface) and
    moved by x along the x axis."""
    return pose(axis, angle, (x, 0.0, 0.0))


@pytest.fixture(scope="module")
def ball():
    return pccd.Object(sphere_points(1500))


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


# --- analytic truth: two spheres of radius 0.5 -----------------------------------------------------

@pytest.mark.parametrize("gap", [0.1, 0.25, 0.5, 1.0])
def test_the_distance_of_two_spheres_is_their_gap(ball, gap):
    centre_b = np.array([2 * RADIUS + gap, 0.0, 0.0])
    d = pccd.distance(ball, None, ball, shifted(centre_b[0], (1, 2, 3), 0.7), seed=3)
    assert d.status == "separate"
    assert not d.intersecting
    assert d.distance == pytest.approx(gap, rel=0.03), d
    assert d.lower_bound <= d.distance <= d.upper_bound
    assert d.lower_bound >= 0
    # The witnesses lie on the spheres, on the segment between the centres, and are d apart.
    for p, c in ((d.point_a, np.zeros(3)), (d.point_b, centre_b)):
        assert p.shape == (3,) and p.dtype == np.float64
        assert np.linalg.norm(p - c) == pytest.approx(RADIUS, rel=0.02)
    assert np.linalg.norm(d.point_a - d.point_b) == pytest.approx(d.distance, rel=1e-9, abs=1e-12)
    assert np.dot(unit(d.point_a), [1, 0, 0]) > 0.99
    assert np.dot(unit(d.point_b - centre_b), [-1, 0, 0]) > 0.99
    # Outward normals: A's towards B, B's towards A; contact_normal from point_a to point_b.
    assert np.dot(d.normal_a, [1, 0, 0]) > 0.98 and np.linalg.norm(d.normal_a) == pytest.approx(1, abs=1e-9)
    assert np.dot(d.normal_b, [-1, 0, 0]) > 0.98 and np.linalg.norm(d.normal_b) == pytest.approx(1, abs=1e-9)
    assert np.allclose(d.contact_normal, unit(d.point_b - d.point_a), atol=1e-9)
    # Not asked for: the penetration fields are NaN, never a made-up 0.
    assert math.isnan(d.depth) and math.isnan(d.depth_a) and math.isnan(d.depth_b)
    assert d.intersection_points.shape == (0, 3)
    assert math.isfinite(d.query_us) and d.query_us > 0


def test_the_distance_does_not_depend_on_which_object_moves(ball):
    """B 0.4 beyond A along a slanted direction, or A moved the other way: the same gap."""
    direction = unit((1.0, -2.0, 0.5))
    centre = (2 * RADIUS + 0.4) * direction
    one = pccd.distance(ball, None, ball, np.hstack([np.eye(3), centre.reshape(3, 1)]))
    other = pccd.distance(ball, np.hstack([rotation((0, 1, 0), 1.0), -centre.reshape(3, 1)]), ball, None)
    for d in (one, other):
        assert d.distance == pytest.approx(0.4, rel=0.03)
    assert np.dot(unit(one.point_b - one.point_a), direction) > 0.99
    assert np.dot(unit(other.point_b - other.point_a), direction) > 0.99  # A moved by -centre: still towards B


def test_a_4x4_pose_answers_as_its_3x4_form(ball):
    p = shifted(1.3, (0, 1, 1), 0.4)
    three = pccd.distance(ball, None, ball, p, seed=9)
    four = pccd.distance(ball, None, ball, np.vstack([p, [0, 0, 0, 1]]), seed=9)
    assert same_distance(three, four)


def test_intersecting_spheres_are_at_distance_0_and_their_penetration_is_measured(ball):
    # B's centre 0.75 from A's: A's point (0.5, 0, 0) lies 0.25 from B's centre, 0.25 deep inside B;
    # no point of either sphere is deeper inside the other (by symmetry depth_a = depth_b = 0.25).
    plain = pccd.distance(ball, None, ball, shifted(0.75), seed=4)
    assert plain.status == "intersecting" and plain.intersecting
    assert plain.distance == 0 and plain.lower_bound == 0 and plain.upper_bound == 0
    assert math.isnan(plain.depth)
    assert plain.intersection_points.shape[0] >= 1
    p = plain.intersection_points[0]  # on both spheres: the circle x = 0.375
    assert np.linalg.norm(p) == pytest.approx(RADIUS, rel=0.02)
    assert np.linalg.norm(p - [0.75, 0, 0]) == pytest.approx(RADIUS, rel=0.02)

    deep = pccd.distance(ball, None, ball, shifted(0.75), penetration=True, seed=4)
    assert deep.status == "intersecting" and deep.distance == 0
    assert deep.depth == pytest.approx(0.25, rel=0.05), deep
    assert deep.depth_a == pytest.approx(0.25, rel=0.05)
    assert deep.depth_b == pytest.approx(0.25, rel=0.05)
    assert deep.depth == max(deep.depth_a, deep.depth_b)
    # B must move along +x to leave A.
    assert np.dot(deep.contact_normal, [1, 0, 0]) > 0.95
    assert np.linalg.norm(deep.contact_normal) == pytest.approx(1, abs=1e-9)


def test_beyond_max_distance_only_farther_than_is_reported(ball):
    d = pccd.distance(ball, None, ball, shifted(2.0), max_distance=0.5)  # gap 1
    assert d.status == "separate"
    assert d.distance == math.inf
    assert d.lower_bound >= 0.5  # the limit itself is an honest lower bound
    assert np.isnan(d.point_a).all() and np.isnan(d.point_b).all()
    near = pccd.distance(ball, None, ball, shifted(2.0), max_distance=2.0)
    assert near.distance == pytest.approx(1.0, rel=0.03)


def test_a_node_pair_budget_gives_an_honest_interval_that_narrows(ball):
    gap = 0.5
    widths = []
    for budget in (1, 4, 16, 10**6):
        r = pccd.distance(ball, None, ball, shifted(2 * RADIUS + gap), max_node_pairs=budget)
        assert r.status == "separate"
        assert r.lower_bound <= gap * 1.03 and r.upper_bound >= gap * 0.97, (budget, r)
        widths.append(r.upper_bound - r.lower_bound)
    assert widths[-1] <= widths[0]
    assert math.isfinite(widths[-1])


def test_the_certified_lower_bound_is_below_the_gap_and_the_premise_bound(ball):
    # certified_lower_bound: point pairs minus the points' domain radii (a certificate whatever
    # the fit) instead of minus r(P) + 2 sigma; the same distance and witnesses otherwise
    for gap in (0.1, 0.5):
        plain = pccd.distance(ball, None, ball, shifted(2 * RADIUS + gap))
        certified = pccd.distance(ball, None, ball, shifted(2 * RADIUS + gap), certified_lower_bound=True)
        assert certified.status == plain.status == "separate"
        assert 0.0 <= certified.lower_bound <= plain.lower_bound + 1e-12
        assert certified.lower_bound <= gap
        assert certified.distance == pytest.approx(plain.distance, abs=1e-3)
        clear = pccd.within_distance(ball, None, ball, shifted(2 * RADIUS + gap), 0.5 * gap, certified_lower_bound=True)
        assert not clear.within and clear.lower_bound <= gap
    with pytest.raises(TypeError):
        pccd.distance(ball, None, ball, shifted(2.0), certified_lower_bound="yes")


def test_within_distance_answers_against_the_gap(ball):
    far = shifted(1.5)  # gap 0.5
    yes = pccd.within_distance(ball, None, ball, far, 0.6)
    assert yes.within and bool(yes) and yes.status == "separate" and yes.margin == 0.6
    assert np.linalg.norm(yes.point_a - yes.point_b) < 0.6
    assert yes.lower_bound <= 0.5 * 1.03
    no = pccd.within_distance(ball, None, ball, far, 0.4)
    assert not no.within and not bool(no) and no.status == "separate" and no.margin == 0.4
    assert no.lower_bound <= 0.5 * 1.03  # honest: never above the true gap
    assert np.isnan(no.point_a).all()
    touching = pccd.within_distance(ball, None, ball, shifted(0.75), 0.0)
    assert touching.within and touching.status == "intersecting"
    assert isinstance(yes.counters, dict) and yes.counters is yes.counters
    assert math.isfinite(yes.query_us)


def test_contacts_of_intersecting_spheres(ball):
    r = pccd.contacts(ball, None, ball, shifted(0.75), seed=2)
    assert r.status == "intersecting"
    assert 1 <= len(r.contacts) == len(r) <= 8 and r.regions >= len(r.contacts)
    c = r.contacts[0]
    assert isinstance(c, pccd.Contact)
    assert c.depth == pytest.approx(0.25, rel=0.1)
    assert np.dot(c.normal, [1, 0, 0]) > 0.9
    assert c.position.shape == (3,) and abs(c.position[0] - 0.375) < 0.15
    assert c.points_inside >= 1
    depths = [k.depth for k in r.contacts]
    assert depths == sorted(depths, reverse=True)  # deepest first
    one = pccd.contacts(ball, None, ball, shifted(0.75), seed=2, max_contacts=1)
    assert len(one.contacts) == 1
    apart = pccd.contacts(ball, None, ball, shifted(1.5))
    assert apart.status == "separate" and apart.contacts == [] and apart.regions == 0


def test_counters_and_determinism(ball):
    p = shifted(1.2, (1, 0, 0), 0.3)
    first = pccd.distance(ball, None, ball, p, seed=12)
    again = pccd.distance(ball, None, ball, p, seed=12)
    assert same_distance(first, again)
    counters = first.counters
    assert counters is first.counters  # built once
    for name in ("node_pairs", "leaf_pairs", "point_pairs", "f_evaluations", "refinement_steps",
                 "candidates_refined", "inside_tests", "intersection_f_evaluations"):
        assert name in counters and isinstance(counters[name], int), name
    assert counters["point_pairs"] > 0


# --- the batch ---------------------------------------------------------------------------------------

def batch_pairs(ball, torus):
    pairs = []
    for k in range(12):
        x = 0.6 + 0.15 * k
        other = ball if k % 2 == 0 else torus
        pairs.append((ball, None, other, shifted(x, (1, 1, k), 0.2 * k)))
    pairs.append((torus, shifted(0.3), ball, np.vstack([shifted(-1.9), [0, 0, 0, 1]])))
    return pairs


def test_distance_many_equals_the_single_calls_for_any_thread_count(ball):
    torus = pccd.Object(torus_points(1500))
    pairs = batch_pairs(ball, torus)
    one = pccd.distance_many(pairs, threads=1, seed=21)
    two = pccd.distance_many(pairs, threads=2, seed=21)
    default = pccd.distance_many(pairs, seed=21)
    assert len(one) == len(two) == len(default) == len(pairs)
    statuses = {r.status for r in one}
    assert statuses == {"intersecting", "separate"}, statuses
    for i, (a, b, c) in enumerate(zip(one, two, default)):
        single = pccd.distance(*pairs[i], seed=pccd.pair_seed(21, i))
        assert same_distance(a, single), i
        assert same_distance(a, b), i
        assert same_distance(a, c), i
        assert math.isnan(a.query_us)
    # Chunks seeded by first_index give the whole batch's answers.
    tail = pccd.distance_many(pairs[5:], threads=2, seed=21, first_index=5)
    assert all(same_distance(x, y) for x, y in zip(tail, one[5:]))
    # The options reach every pair.
    limited = pccd.distance_many(pairs, threads=2, seed=21, max_distance=0.05)
    assert any(r.distance == math.inf for r in limited)
    for r, full in zip(limited, one):
        assert r.status == full.status
        if full.lower_bound > 0.1:
            assert r.distance == math.inf and r.lower_bound >= 0.05


def test_distance_many_of_nothing():
    assert pccd.distance_many([], threads=2) == []


# --- errors ------------------------------------------------------------------------------------------

@pytest.mark.parametrize(
    "options, message",
    [
        (dict(absolute_tolerance=-0.1), "absolute_tolerance"),
        (dict(absolute_tolerance=0.0), "absolute_tolerance"),
        (dict(absolute_tolerance=math.nan), "absolute_tolerance"),
        (dict(relative_tolerance=-1.0), "relative_tolerance"),
        (dict(max_distance=-0.5), "max_distance"),
        (dict(max_distance=math.inf), "max_distance"),
        (dict(max_time_us=-3.0), "max_time_us"),
        (dict(max_f_evaluations=0), "max_f_evaluations"),
        (dict(max_node_pairs=0), "max_node_pairs"),
        (dict(max_contacts=0), "max_contacts"),
        (dict(candidates=0), "candidates"),
        (dict(traversal="sideways"), "traversal"),
    ],
)
def test_invalid_options_are_valueerrors_naming_them(ball, options, message):
    for call in (lambda: pccd.distance(ball, None, ball, shifted(2.0), **options),
                 lambda: pccd.within_distance(ball, None, ball, shifted(2.0), 0.1, **options),
                 lambda: pccd.contacts(ball, None, ball, shifted(2.0), **options),
                 lambda: pccd.distance_many([(ball, None, ball, shifted(2.0))], **options)):
        with pytest.raises(ValueError, match=message):
            call()


@pytest.mark.parametrize("margin", [-1.0, -1e-300, math.nan, math.inf])
def test_a_bad_margin_is_a_valueerror(ball, margin):
    with pytest.raises(ValueError, match="margin"):
        pccd.within_distance(ball, None, ball, shifted(2.0), margin)


def test_bad_poses_are_valueerrors_naming_them(ball):
    nan_pose = shifted(2.0)
    nan_pose[1, 3] = math.nan
    scaled = shifted(2.0)
    scaled[:, :3] *= 2
    for bad, message in ((nan_pose, r"pose_b: rigid transform: translation entry \(1, 3\) is nan"),
                         (scaled, "pose_b: rigid transform: the rotation part scales"),
                         (np.eye(3), r"pose_b must have shape \(3, 4\) or \(4, 4\)")):
        with pytest.raises(ValueError, match=message):
            pccd.distance(ball, None, ball, bad)
        with pytest.raises(ValueError, match=message):
            pccd.within_distance(ball, None, ball, bad, 0.1)
        with pytest.raises(ValueError, match=message):
            pccd.contacts(ball, None, ball, bad)
        with pytest.raises(ValueError, match=r"pairs\[1\]: " + message):
            pccd.distance_many([(ball, None, ball, None), (ball, None, ball, bad)])
    with pytest.raises(ValueError, match="pose_a"):
        pccd.distance(ball, nan_pose, ball, None)


def test_wrong_types_and_unknown_keywords_are_typeerrors(ball):
    with pytest.raises(TypeError, match="unexpected keyword argument 'tolerance'"):
        pccd.distance(ball, None, ball, None, tolerance=0.1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'threads'"):
        pccd.distance(ball, None, ball, None, threads=2)
    with pytest.raises(TypeError, match="penetration cannot be"):
        pccd.distance(ball, None, ball, None, penetration="yes")
    with pytest.raises(TypeError):
        pccd.distance(ball, None, "ball", None)
    with pytest.raises(TypeError, match="pccd.Object"):
        pccd.distance_many([(ball, None, 3, None)])
    with pytest.raises(ValueError, match=r"pairs\[0\] must be a tuple"):
        pccd.distance_many([(ball, None, ball)])
    with pytest.raises(ValueError, match="threads"):
        pccd.distance_many([(ball, None, ball, None)], threads=0)


# --- the same answers as the C++ calls (pccd distance --json) ------------------------------------

def same_distance(x, y):
    """Two DistanceResults are identical: every field bit for bit (NaN where NaN), the counters."""
    def same(u, v):
        return np.array_equal(np.asarray(u), np.asarray(v), equal_nan=True)
    return (x.status == y.status and same(x.distance, y.distance) and same(x.lower_bound, y.lower_bound)
            and same(x.upper_bound, y.upper_bound) and same(x.point_a, y.point_a) and same(x.point_b, y.point_b)
            and same(x.normal_a, y.normal_a) and same(x.normal_b, y.normal_b) and same(x.depth, y.depth)
            and same(x.depth_a, y.depth_a) and same(x.depth_b, y.depth_b)
            and same(x.contact_normal, y.contact_normal)
            and same(x.intersection_points, y.intersection_points) and x.counters == y.counters)


def cli_json(cli, file_a, file_b, pose_b, *options):
    numbers = " ".join(repr(float(v)) for v in np.asarray(pose_b).reshape(-1))
    done = subprocess.run([str(cli), "distance", str(file_a), str(file_b), f"--transform-b={numbers}", "--json",
                           *options], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def json_number(value):
    """The JSON's number: null is a value the query did not compute (NaN) or an infinity."""
    return math.nan if value is None else value


def check_number(got, expected, name):
    if expected is None:
        assert not math.isfinite(got), f"{name}: {got}, the CLI printed null"
    else:
        assert got == expected, f"{name}: {got} != {expected}"


def check_vector(got, expected, name):
    if expected is None:
        assert np.isnan(got).all(), f"{name}: {got}, the CLI printed null"
    else:
        assert got.tolist() == expected, f"{name}: {got} != {expected}"


POSES = [
    pose((1, 1, 0), 0.4, (2.2, 0.0, 0.0)),   # apart, gap about 0.7
    pose((0, 1, 0), 1.1, (0.0, 0.3, 1.15)),  # apart, above
    pose((0, 0, 1), 0.5, (0.9, 0.0, 0.0)),   # across the torus tube
]


def test_same_answers_as_the_cli(cli, tmp):
    file_a, file_b = tmp / "torus.xyz", tmp / "sphere.xyz"
    pccd.write_points(file_a, torus_points(2000))
    pccd.write_points(file_b, sphere_points(1500))
    a = pccd.Object(pccd.read_points(file_a)[0])
    b = pccd.Object(pccd.read_points(file_b)[0])
    statuses = set()
    for k, p in enumerate(POSES):
        for options in ((), ("--penetration",), ("--max-distance", "0.3")):
            seed = 40 + k
            expected = cli_json(cli, file_a, file_b, p, "--seed", str(seed), *options)
            kwargs = dict(seed=seed)
            if "--penetration" in options:
                kwargs["penetration"] = True
            if "--max-distance" in options:
                kwargs["max_distance"] = 0.3
            got = pccd.distance(a, None, b, p, **kwargs)
            where = f"pose {k}, {options}"
            assert got.status == expected["status"], where
            statuses.add(got.status)
            for name in ("distance", "lower_bound", "upper_bound", "depth", "depth_a", "depth_b"):
                check_number(getattr(got, name), expected[name], f"{where}: {name}")
            for name in ("point_a", "point_b", "normal_a", "normal_b", "contact_normal"):
                check_vector(getattr(got, name), expected[name], f"{where}: {name}")
            assert got.counters == expected["counters"], where
            assert got.intersection_points.tolist() == expected["intersection_points"], where
        margin = 0.5
        expected = cli_json(cli, file_a, file_b, p, "--seed", str(seed), "--margin", str(margin))
        got = pccd.within_distance(a, None, b, p, margin, seed=seed)
        assert got.within == expected["within"] and got.status == expected["status"]
        for name in ("lower_bound", "upper_bound"):
            check_number(getattr(got, name), expected[name], f"pose {k}, margin: {name}")
        for name in ("point_a", "point_b"):
            check_vector(getattr(got, name), expected[name], f"pose {k}, margin: {name}")
        assert got.counters == expected["counters"]
    assert statuses == {"intersecting", "separate"}
