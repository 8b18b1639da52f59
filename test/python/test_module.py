"""The Python module pccd on procedural clouds: arrays in and out, errors, properties, save and
load, poses, batch queries against the single ones, and the GIL released during a batch."""

import threading
import time

import numpy as np
import pytest

import pccd
from conftest import pose, same_result, sphere_points

TOUCHING = pose((1, 1, 0), 0.4, (0.9, 0.0, 0.0))  # the sphere (radius 0.5) across the torus tube
APART = pose((0, 0, 1), 0.0, (3.0, 0.0, 0.0))


# --- read_points / write_points -----------------------------------------------------------------

def test_write_then_read_points_is_exact(tmp):
    p = sphere_points(100)
    n = p / np.linalg.norm(p, axis=1, keepdims=True)
    for name in ("a.xyz", "a.ply", "a.off"):
        pccd.write_points(tmp / name, p, n if name != "a.off" else None)
        q, m = pccd.read_points(tmp / name)
        assert q.dtype == np.float64 and q.shape == (100, 3)
        assert np.array_equal(q, p), name
        if name == "a.off":
            assert m is None
        else:
            assert np.array_equal(m, n), name


def test_file_errors_are_oserror_with_pccd_message(tmp):
    with pytest.raises(OSError, match="missing.xyz"):
        pccd.read_points(tmp / "missing.xyz")
    (tmp / "bad.xyz").write_text("1 2 3\n4 five 6\n")
    with pytest.raises(OSError, match="bad.xyz.*line 2"):
        pccd.read_points(tmp / "bad.xyz")
    with pytest.raises(OSError, match="extension"):
        pccd.write_points(tmp / "points.txt", sphere_points(10))
    with pytest.raises(OSError):
        pccd.Object.load(tmp / "missing.pccd")
    (tmp / "garbage.pccd").write_bytes(b"not a PCCD object file" * 10)
    with pytest.raises(OSError, match="garbage.pccd"):
        pccd.Object.load(tmp / "garbage.pccd")


def test_write_points_rejects_bad_arrays(tmp):
    with pytest.raises(ValueError, match="shape"):
        pccd.write_points(tmp / "a.xyz", np.zeros((4, 2)))
    with pytest.raises(ValueError, match="NaN"):
        pccd.write_points(tmp / "a.xyz", np.array([[0.0, np.nan, 0.0]]))
    with pytest.raises(ValueError, match="one per point"):
        pccd.write_points(tmp / "a.xyz", np.zeros((4, 3)), np.zeros((3, 3)))


# --- Object: bad arrays and options ---------------------------------------------------------------

@pytest.mark.parametrize(
    "points, message",
    [
        (np.zeros((10, 2)), r"shape \(N, 3\), got \(10, 2\)"),
        (np.zeros(30), r"got \(30,\)"),
        (np.zeros((2, 5, 3)), r"got \(2, 5, 3\)"),
        (np.zeros((0, 3)), "empty|no point"),
        (np.array([["a", "b", "c"]] * 5), "real numbers"),
        (np.ones((5, 3), dtype=bool), "real numbers"),
        (np.ones((5, 3), dtype=complex), "real numbers"),
        (None, "not None"),
        ([[0, 0], [1, 1, 1]], "(N, 3)"),
    ],
)
def test_object_rejects_bad_points(points, message):
    with pytest.raises(ValueError, match=message):
        pccd.Object(points)


def test_object_rejects_non_finite_points_naming_them():
    p = sphere_points(200)
    p[17, 1] = np.nan
    with pytest.raises(ValueError, match="17"):
        pccd.Object(p)
    p[17, 1] = np.inf
    with pytest.raises(ValueError, match="17"):
        pccd.Object(p)


def test_object_rejects_bad_normals_and_options():
    p = sphere_points(300)
    with pytest.raises(ValueError, match="one per point"):
        pccd.Object(p, normals=p[:10])
    with pytest.raises(ValueError, match="shape"):
        pccd.Object(p, normals=p[:, :2])
    with pytest.raises(TypeError, match="unexpected keyword argument 'etta'"):
        pccd.Object(p, etta=3.0)
    with pytest.raises(TypeError, match="eta"):
        pccd.Object(p, eta="three")
    with pytest.raises(ValueError, match="eta"):
        pccd.Object(p, eta=-1.0)
    with pytest.raises(ValueError, match="graph"):
        pccd.Object(p, graph="delaunay")
    with pytest.raises(ValueError, match="'imls'"):
        pccd.Object(p, surface_fit="rimls")
    with pytest.raises(ValueError, match="normal_bandwidth"):
        pccd.Object(p, normal_bandwidth=0.0)
    for bad in (0.0, -0.25, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="normal_residual_scale"):
            pccd.Object(p, normal_residual_scale=bad)


def test_the_imls_surface_keeps_a_sphere_and_answers_like_the_default():
    """The sharp-feature options build; on a sphere of radius 0.5 (no edges) the IMLS surface, like
    the default one, says a sphere 0.1 away is separate and one 0.1 inside intersects."""
    p = sphere_points(2000)
    sharp = pccd.Object(p, surface_fit="imls", normal_residual_scale=0.25, theta_eps=3e-5, threads=1)
    assert sharp.theta_eps == pytest.approx(3e-5)
    for gap, expected in ((0.1, False), (-0.1, True)):
        t = pose((0, 0, 1), 0.0, (1.0 + gap, 0.0, 0.0))
        assert pccd.do_intersect(sharp, None, sharp, t).intersects == expected


def test_sharp_features_sets_the_sharp_feature_options_and_other_keywords_override_them():
    """sharp_features=True is surface_fit='imls', theta_eps=3e-5, normal_residual_scale=0.25 (the
    C++ PCCD::sharp_feature_options()); an explicit keyword wins in either order; a non-bool is
    refused."""
    p = sphere_points(600)
    default = pccd.Object(p, threads=1)
    assert default.surface_fit == "sphere" and default.leaf_size == 8
    sharp = pccd.Object(p, sharp_features=True, threads=1)
    by_hand = pccd.Object(p, surface_fit="imls", theta_eps=3e-5, normal_residual_scale=0.25, threads=1)
    assert sharp.surface_fit == "imls" and sharp.theta_eps == pytest.approx(3e-5)
    assert np.array_equal(sharp.normals, by_hand.normals)
    assert sharp.bandwidth == by_hand.bandwidth
    for kwargs in ({"theta_eps": 1e-2, "sharp_features": True}, {"sharp_features": True, "theta_eps": 1e-2}):
        o = pccd.Object(p, leaf_size=10, threads=1, **kwargs)
        assert o.surface_fit == "imls" and o.theta_eps == pytest.approx(1e-2) and o.leaf_size == 10
    assert pccd.Object(p, sharp_features=False, threads=1).surface_fit == "sphere"
    with pytest.raises(TypeError, match="sharp_features"):
        pccd.Object(p, sharp_features="yes")


# --- Object: inputs read in place, properties ---------------------------------------------------

def test_float32_strided_and_integer_inputs_give_the_same_object():
    p = sphere_points(800).astype(np.float32)
    reference = pccd.Object(p.astype(np.float64), threads=1)
    wide = np.zeros((800, 6), dtype=np.float32)
    wide[:, ::2] = p  # a strided view: rows 24 bytes apart, columns 8
    for variant in (p, wide[:, ::2], np.asfortranarray(p)):
        o = pccd.Object(variant, threads=1)
        assert np.array_equal(o.points, reference.points)
        assert np.array_equal(o.normals, reference.normals)
        assert o.sampling_radius == reference.sampling_radius
    grid = np.array([[x, y, 0] for x in range(20) for y in range(20)], dtype=np.int32)
    o = pccd.Object(grid)
    assert np.array_equal(o.points, grid.astype(np.float64)[o.input_indices])
    # The points are stored in a spatial order; input_indices is a permutation of the points given.
    assert sorted(o.input_indices.tolist()) == list(range(len(grid)))
    assert not np.array_equal(o.input_indices, np.arange(len(grid)))
    unordered = pccd.Object(grid, spatial_order=False)
    assert np.array_equal(unordered.points, grid.astype(np.float64))
    assert np.array_equal(unordered.input_indices, np.arange(len(grid)))


def test_object_properties_are_read_only(shapes):
    sphere, torus = shapes
    assert sphere.size == len(sphere) == 1500 and sphere.input_points == 1500
    assert sphere.points.shape == (1500, 3) and sphere.normals.shape == (1500, 3)
    assert np.allclose(np.linalg.norm(sphere.points, axis=1), 0.5)
    assert np.allclose(np.abs(np.einsum("ij,ij->i", sphere.normals, sphere.points / 0.5)), 1.0, atol=0.05)
    assert 0 < sphere.sampling_radius < sphere.support_radius
    assert sphere.eta == pytest.approx(3.0)
    assert set(sphere.timings) == {"kd_tree", "outliers", "graph", "sampling_radius", "cpsp", "normals", "hierarchy"}
    assert sphere.outliers.size == 0 and not sphere.normals_given
    with pytest.raises(AttributeError):
        sphere.sampling_radius = 1.0
    with pytest.raises(ValueError):
        sphere.points[0, 0] = 1.0


def test_normals_are_hints_that_set_the_orientation():
    p = sphere_points(1000)
    inward = pccd.Object(p, normals=-p)
    outward = pccd.Object(p, normals=p)
    assert inward.normals_given
    assert np.all(np.einsum("ij,ij->i", inward.normals, p[inward.input_indices]) < 0)
    assert np.all(np.einsum("ij,ij->i", outward.normals, p[outward.input_indices]) > 0)


# --- save / load ----------------------------------------------------------------------------------

def test_save_load_round_trip(shapes, tmp):
    sphere, torus = shapes
    torus.save(tmp / "torus.pccd")
    loaded = pccd.Object.load(tmp / "torus.pccd")
    assert np.array_equal(loaded.points, torus.points)
    assert np.array_equal(loaded.normals, torus.normals)
    for name in ("size", "sampling_radius", "bandwidth", "theta_eps", "eta", "noise_estimate"):
        assert getattr(loaded, name) == getattr(torus, name), name
    for p in (TOUCHING, APART, pose((0, 1, 0), 1.0, (0.7, 0.2, 0.1))):
        for method in ("isearch", "rst"):
            assert same_result(pccd.intersection_points(sphere, p, loaded, None, method=method, seed=3),
                               pccd.intersection_points(sphere, p, torus, None, method=method, seed=3))


def test_bounding_volume_option_and_load(shapes, tmp):
    sphere, torus = shapes
    assert torus.volume == "box_and_slab"
    balls = pccd.Object(torus.points, volume="sphere", leaf_size=4)
    assert balls.volume == "sphere"
    # The answers do not depend on the volume (every test is conservative).
    for p in (TOUCHING, APART, pose((0, 1, 0), 1.0, (0.7, 0.2, 0.1))):
        assert pccd.do_intersect(sphere, p, balls, None).intersects == pccd.do_intersect(sphere, p, torus, None).intersects
    balls.save(tmp / "balls.pccd")
    assert pccd.Object.load(tmp / "balls.pccd").volume == "sphere"
    assert pccd.Object.load(tmp / "balls.pccd", volume="box").volume == "box"
    assert pccd.Object.load(tmp / "balls.pccd", leaf_size=8).volume == "box_and_slab"
    with pytest.raises(ValueError, match="volume must be"):
        pccd.Object(torus.points, volume="cube")
    with pytest.raises(ValueError, match="volume must be"):
        pccd.Object.load(tmp / "balls.pccd", volume="cube")


# --- queries ----------------------------------------------------------------------------------------

def test_answers_and_result(shapes):
    sphere, torus = shapes
    hit = pccd.do_intersect(sphere, TOUCHING, torus, None)
    assert hit.intersects and bool(hit) and hit.status == "intersecting"
    assert hit.points.shape == (1, 3) and hit.kinds == ["refined"]
    assert set(hit.counters) == {
        "f_evaluations", "brackets_tried", "partner_candidates", "brackets_found", "search_steps",
        "bisection_steps", "samples", "candidate_points", "refinement_samples", "node_pairs", "leaf_pairs",
        "candidates_rejected", "pending_node_pairs", "certification_passes", "unverified_crossings"}
    assert hit.counters["f_evaluations"] > 0
    miss = pccd.do_intersect(sphere, APART, torus, None, method="rst")
    assert not miss.intersects and miss.status == "separate" and miss.points.shape == (0, 3)
    curve = pccd.intersection_points(sphere, TOUCHING, torus, None)
    assert curve.points.shape[0] > 10 and curve.f_values.shape == (curve.points.shape[0], 2)
    assert np.all(np.abs(curve.f_values) < 0.05 * min(sphere.sampling_radius, torus.sampling_radius))
    budget = pccd.intersection_points(sphere, pose((0, 0, 1), 0, (1.25, 0, 0)), torus, None, max_f_evaluations=3)
    assert budget.counters["f_evaluations"] <= 3 + 2  # one bracket or step may finish past the budget
    assert budget.status in ("undecided", "intersecting")
    # The hierarchy traversals: the flat (published) walk agrees; an exhausted time budget is undecided.
    assert pccd.do_intersect(sphere, TOUCHING, torus, None, traversal="flat").intersects
    assert pccd.do_intersect(sphere, TOUCHING, torus, None, traversal="depth_first").intersects
    assert pccd.do_intersect(sphere, TOUCHING, torus, None, max_time_us=1e-3).status == "undecided"
    with pytest.raises(ValueError, match="traversal"):
        pccd.do_intersect(sphere, TOUCHING, torus, None, traversal="breadth")
    # "Separate" is earned: the same answer as C++'s certify_separation; False is the policy alone.
    certified = pccd.do_intersect(sphere, APART, torus, None)
    assert certified.status == "separate" and certified.counters["unverified_crossings"] == 0
    alone = pccd.do_intersect(sphere, APART, torus, None, certify_separation=False)
    assert alone.status == "separate" and alone.counters["certification_passes"] == 0
    with pytest.raises(TypeError, match="certify_separation"):
        pccd.do_intersect(sphere, APART, torus, None, certify_separation="yes")
    with pytest.raises(ValueError, match="max_time_us"):
        pccd.do_intersect(sphere, TOUCHING, torus, None, max_time_us=-1.0)


def test_same_seed_same_answer_other_seed_other_work(shapes):
    sphere, torus = shapes
    a = pccd.intersection_points(sphere, TOUCHING, torus, None, seed=5)
    b = pccd.intersection_points(sphere, TOUCHING, torus, None, seed=5)
    c = pccd.intersection_points(sphere, TOUCHING, torus, None, seed=6)
    assert same_result(a, b)
    assert not same_result(a, c)


def test_poses_3x4_4x4_lists_and_none_agree(shapes):
    sphere, torus = shapes
    p4 = np.vstack([TOUCHING, [0, 0, 0, 1]])
    reference = pccd.intersection_points(sphere, TOUCHING, torus, None)
    for p in (p4, TOUCHING.tolist(), np.asfortranarray(TOUCHING), TOUCHING[:, [0, 1, 2, 3]]):
        assert same_result(pccd.intersection_points(sphere, p, torus, np.eye(4)), reference)
    assert same_result(pccd.intersection_points(sphere, TOUCHING, torus, np.eye(3, 4)), reference)


@pytest.mark.parametrize(
    "bad, message",
    [
        (np.eye(3), r"shape \(3, 4\) or \(4, 4\), got \(3, 3\)"),
        (np.zeros(12), r"got \(12,\)"),
        (np.vstack([np.eye(3, 4), [0, 0, 1, 1]]), "last row"),
        (np.hstack([2 * np.eye(3), np.zeros((3, 1))]), "scales"),
        (np.hstack([np.diag([1.0, 1.0, -1.0]), np.zeros((3, 1))]), "reflect"),
        (np.hstack([[[1, 0.5, 0], [0, 1, 0], [0, 0, 1]], np.zeros((3, 1))]), "pose_b"),
        (np.hstack([np.eye(3), [[np.nan], [0], [0]]]), r"entry \(0, 3\) is nan"),
        ("identity", "array of numbers"),
    ],
)
def test_bad_poses_raise_valueerror(shapes, bad, message):
    sphere, torus = shapes
    with pytest.raises(ValueError, match=message):
        pccd.do_intersect(sphere, None, torus, bad)


def test_bad_query_options_raise_valueerror(shapes):
    sphere, torus = shapes
    with pytest.raises(ValueError, match="method"):
        pccd.do_intersect(sphere, None, torus, None, method="exact")
    with pytest.raises(ValueError, match="max_f_evaluations = 0"):
        pccd.do_intersect(sphere, None, torus, None, max_f_evaluations=0)
    with pytest.raises(ValueError, match="epsilon"):
        pccd.intersection_points(sphere, None, torus, None, epsilon=-1.0)
    with pytest.raises(ValueError, match="contact_core"):
        pccd.intersection_points(sphere, None, torus, None, contact_core=1.5)
    with pytest.raises(ValueError, match="samples is a parameter of method='isearch'"):
        pccd.do_intersect(sphere, None, torus, None, method="rst", samples=10)
    with pytest.raises(ValueError, match="region"):
        pccd.do_intersect(sphere, None, torus, None, region="everywhere")
    with pytest.raises(TypeError, match="seed cannot be -1"):
        pccd.do_intersect(sphere, None, torus, None, seed=-1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'sed'"):
        pccd.do_intersect(sphere, None, torus, None, sed=1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'threads'"):
        pccd.intersection_points(sphere, None, torus, None, threads=2)
    with pytest.raises(TypeError, match="max_samples cannot be 'many'"):
        pccd.do_intersect_many([], max_samples="many")
    with pytest.raises(TypeError):
        pccd.do_intersect(sphere, None, "torus", None)


# --- batch queries ------------------------------------------------------------------------------------

def batch_pairs(shapes, count=24):
    sphere, torus = shapes
    rng = np.random.default_rng(11)
    pairs = []
    for k in range(count):
        d = rng.uniform(0.0, 2.0)
        p = pose(rng.normal(size=3), rng.uniform(0, np.pi), d * np.array([1.0, 0.0, 0.0]))
        pairs.append((sphere, p, torus, None) if k % 3 else (torus, None, sphere, p))
    return pairs


def test_pair_seed_is_splitmix64():
    assert pccd.pair_seed(0, 0) == 0xE220A8397B1DCDAF  # SplitMix64's first output from state 0
    assert len({pccd.pair_seed(24301, i) for i in range(1000)}) == 1000


@pytest.mark.parametrize("method", ["isearch", "rst"])
@pytest.mark.parametrize("many, single", [(pccd.do_intersect_many, pccd.do_intersect),
                                          (pccd.intersection_points_many, pccd.intersection_points)])
def test_batch_equals_sequential_calls(shapes, method, many, single):
    pairs = batch_pairs(shapes)
    truth = [single(*pair, method=method, seed=pccd.pair_seed(77, i)) for i, pair in enumerate(pairs)]
    assert 0 < sum(r.intersects for r in truth) < len(pairs)
    for threads in (1, 2, 4):
        results = many(pairs, threads=threads, method=method, seed=77)
        assert len(results) == len(pairs)
        for i, (r, t) in enumerate(zip(results, truth)):
            assert same_result(r, t), (threads, i)
    # Chunks with first_index give the whole batch's answers.
    tail = many(pairs[10:], threads=2, first_index=10, method=method, seed=77)
    assert all(same_result(r, t) for r, t in zip(tail, truth[10:]))


def test_batch_rejects_bad_pairs(shapes):
    sphere, torus = shapes
    assert pccd.do_intersect_many([]) == []
    with pytest.raises(ValueError, match=r"pairs\[1\] must be a tuple"):
        pccd.do_intersect_many([(sphere, None, torus, None), (sphere, None, torus)])
    with pytest.raises(ValueError, match=r"pairs\[0\]: pose_b.*scales"):
        pccd.do_intersect_many([(sphere, None, torus, 2 * np.eye(4)[:3])])
    with pytest.raises(TypeError, match=r"pairs\[0\]"):
        pccd.do_intersect_many([(sphere, None, "torus", None)])
    with pytest.raises(ValueError, match="max_f_evaluations"):
        pccd.intersection_points_many([(sphere, None, torus, None)], max_f_evaluations=0)
    with pytest.raises(ValueError, match="threads 1000000 exceeds the limit 4096"):
        pccd.do_intersect_many([(sphere, None, torus, None)], threads=10**6)
    with pytest.raises(ValueError, match="threads 1000000 exceeds the limit 4096"):
        pccd.Object(sphere_points(100), threads=10**6)
    # 0 is no thread count (None, the default, uses all available threads).
    with pytest.raises(ValueError, match="threads = 0"):
        pccd.do_intersect_many([(sphere, None, torus, None)], threads=0)
    with pytest.raises(ValueError, match="threads = 0"):
        pccd.Object(sphere_points(100), threads=0)
    assert len(pccd.do_intersect_many([(sphere, None, torus, None)], threads=None)) == 1


def test_bandwidth_is_automatic_unless_given():
    """bandwidth=None (the default) is eta r(P) / sqrt(-ln theta_eps); a given one is used as it is
    and must be finite and > 0 (0 no longer means automatic)."""
    points = sphere_points(400)
    automatic = pccd.Object(points, bandwidth=None, noise_factor=0.0)  # no noise-aware widening
    assert automatic.bandwidth == pytest.approx(3.0 * automatic.sampling_radius / np.sqrt(-np.log(0.01)))
    assert pccd.Object(points, bandwidth=0.2).bandwidth == 0.2
    for h in (0.0, -1.0, float("nan")):
        with pytest.raises(ValueError, match="the given bandwidth is"):
            pccd.Object(points, bandwidth=h)


def test_batch_releases_the_gil(shapes):
    """While a batch runs, Python code on another thread keeps running."""
    sphere, torus = shapes
    pairs = [(sphere, TOUCHING, torus, None)] * 40
    start = time.perf_counter()
    pccd.intersection_points_many(pairs, threads=1)
    duration = time.perf_counter() - start
    assert duration > 0.05, "the batch is too short to observe"
    window = {}

    def run():
        window["start"] = time.perf_counter()
        pccd.intersection_points_many(pairs, threads=1)
        window["end"] = time.perf_counter()

    worker = threading.Thread(target=run)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    middle = [t for t in ticks if window["start"] + 0.25 * duration < t < window["end"] - 0.25 * duration]
    assert len(middle) > 100, f"{len(middle)} ticks while the batch ran: the GIL was held"


def test_help_reads_like_numpy():
    for f in (pccd.do_intersect, pccd.intersection_points, pccd.do_intersect_many, pccd.read_points, pccd.Object):
        doc = f.__doc__
        assert "Parameters\n----------" in doc, f
        assert "Raises\n------" in doc, f
    assert "Functions and classes" in pccd.__doc__
