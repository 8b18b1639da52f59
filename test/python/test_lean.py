"""pccd.LeanObject, the lean object (Euclidean kernel, no geodesic map) in the Python module: built
from the same arguments as pccd.Object; every single-pair query, the batches and time_of_contact
take it, alone or beside an Object, and answer against independent truths -- sampled spheres at
known poses, whose gaps, penetration and first contact times are known in closed form; the mixed
batches equal the single calls seeded by pair_seed; it needs a fraction of an Object's memory; it is
saved and loaded bit for bit; bad arguments get a clear TypeError or ValueError."""

import math

import numpy as np
import pytest

import pccd
from conftest import pose, same_result, sphere_points, torus_points

RADIUS = 0.5  # sphere_points' default radius


def at(x=0.0, y=0.0, z=0.0):
    return pose(translation=(x, y, z))


@pytest.fixture(scope="module")
def balls():
    """The same 1500 points on a sphere of radius 0.5 as an Object and as a LeanObject."""
    points = sphere_points(1500)
    return pccd.Object(points), pccd.LeanObject(points)


@pytest.fixture(scope="module")
def torus():
    return pccd.LeanObject(torus_points(2000))


def kinds(balls):
    """The four (a, b) pairs of kinds."""
    geodesic, lean = balls
    return [(geodesic, geodesic), (geodesic, lean), (lean, geodesic), (lean, lean)]


def test_a_lean_object_is_built_from_the_same_arguments(balls):
    geodesic, lean = balls
    assert isinstance(lean, pccd.LeanObject) and not isinstance(lean, pccd.Object)
    assert lean.kernel == "euclidean" and geodesic.kernel == "geodesic"
    assert len(lean) == lean.size == lean.input_points == 1500
    assert lean.sampling_radius == pytest.approx(geodesic.sampling_radius)  # the same points, the same r(P)
    assert lean.points.shape == (1500, 3) and not lean.points.flags.writeable
    assert np.array_equal(np.sort(lean.input_indices), np.arange(1500))
    assert np.allclose(lean.points, sphere_points(1500)[lean.input_indices])
    # Oriented outward: the unit sphere's normal at p is p / |p|.
    outward = np.einsum("ij,ij->i", lean.normals, lean.points / RADIUS)
    assert np.all(outward > 0.9)
    assert lean.surface_fit == "sphere" and lean.leaf_size == 8 and lean.volume == "box_and_slab"
    assert set(lean.timings) == set(geodesic.timings)
    assert "<pccd.LeanObject: 1500 points" in repr(lean)
    # Options as for Object, the sharp-feature preset included.
    sharp = pccd.LeanObject(sphere_points(1500), sharp_features=True, leaf_size=10)
    assert sharp.surface_fit == "imls" and sharp.theta_eps == pytest.approx(3e-5) and sharp.leaf_size == 10
    # Normals given as hints orient the surface as they say (inward here).
    inward = pccd.LeanObject(sphere_points(1500), normals=-sphere_points(1500))
    assert inward.normals_given
    assert np.all(np.einsum("ij,ij->i", inward.normals, inward.points) < 0)


def test_a_lean_object_holds_a_fraction_of_the_memory(balls):
    _, lean = balls
    # Points, kd-tree, input indices, normals, domain radii and hierarchy: about 150 B per point
    # (an Object adds the proximity graph and geodesic map, 700-870 B per point).
    assert 80 <= lean.memory_bytes / lean.size <= 250


@pytest.mark.parametrize("gap", [0.1, 0.5])
def test_every_mix_of_kinds_measures_the_gap_of_two_spheres(balls, gap):
    for a, b in kinds(balls):
        d = pccd.distance(a, None, b, at(2 * RADIUS + gap), seed=3)
        assert d.status == "separate", (a.kernel, b.kernel)
        assert d.distance == pytest.approx(gap, rel=0.03), (a.kernel, b.kernel, d)
        assert d.lower_bound <= d.distance <= d.upper_bound
        assert np.linalg.norm(d.point_a - d.point_b) == pytest.approx(d.distance, rel=1e-9)
        w = pccd.within_distance(a, None, b, at(2 * RADIUS + gap), gap + 0.05)
        assert w.within and w.status == "separate"
        assert not pccd.within_distance(a, None, b, at(2 * RADIUS + gap), gap - 0.05).within


def test_every_mix_of_kinds_finds_the_intersection_and_its_depth(balls):
    # Centres 0.8 apart: the spheres cross on a circle at x = 0.4, each 0.2 deep inside the other.
    for a, b in kinds(balls):
        r = pccd.do_intersect(a, None, b, at(0.8))
        assert r.intersects and r.status == "intersecting", (a.kernel, b.kernel)
        assert abs(r.points[0][0] - 0.4) <= 0.05
        curve = pccd.intersection_points(a, None, b, at(0.8))
        assert len(curve.points) >= 5
        assert np.all(np.abs(curve.points[:, 0] - 0.4) <= 0.05)
        assert np.all(np.abs(np.linalg.norm(curve.points[:, 1:], axis=1) - math.sqrt(0.25 - 0.16)) <= 0.05)
        d = pccd.distance(a, None, b, at(0.8), penetration=True)
        assert d.intersecting and d.depth == pytest.approx(0.2, abs=0.03), (a.kernel, b.kernel, d)
        c = pccd.contacts(a, None, b, at(0.8))
        assert c.status == "intersecting" and len(c) >= 1
        assert not pccd.do_intersect(a, None, b, at(1.5)).intersects


def test_time_of_contact_with_lean_objects(balls):
    # B from x = 3 to x = -3 through A at rest: the spheres of radius 0.5 touch at centres 1 apart,
    # t = 2 / 6; one mean spacing of 1500 points on the sphere is about 0.046.
    spacing = math.sqrt(4 * math.pi * RADIUS**2 / 1500)
    for a, b in kinds(balls):
        r = pccd.time_of_contact(a, (None, None), b, (at(3.0), at(-3.0)))
        assert r.status == "contact", (a.kernel, b.kernel)
        assert abs(r.t - 2.0 / 6.0) * 6.0 <= spacing, (a.kernel, b.kernel, r.t)
        assert pccd.time_of_contact(a, (None, None), b, (at(3.0, 2.0), at(-3.0, 2.0))).status == "no_contact"


def test_clearance_of_a_geodesic_object_beside_a_lean_scene(balls):
    geodesic, lean = balls
    path = np.stack([at(x) for x in (2.0, 1.5, 1.2, 1.05)])
    for o, s in ((geodesic, lean), (lean, geodesic), (lean, lean)):
        p = pccd.clearance(o, s, path, margin=0.1)
        assert np.allclose(p.clearance, [1.0, 0.5, 0.2, 0.05], rtol=0.05, atol=0.01), (o.kernel, s.kernel)
        assert p.first_below_margin == 3


def test_mixed_batches_equal_the_single_calls(balls, torus):
    geodesic, lean = balls
    pairs = [
        (geodesic, None, lean, at(0.8)),
        (lean, None, lean, at(0.9)),
        (lean, None, lean, at(1.3)),
        (geodesic, None, geodesic, at(0.7)),
        (lean, None, torus, at(0.6)),
        (geodesic, None, torus, at(2.0)),
    ]
    for threads in (1, 2):
        many = pccd.do_intersect_many(pairs, seed=5, first_index=7, threads=threads)
        for i, (a, pa, b, pb) in enumerate(pairs):
            assert same_result(many[i], pccd.do_intersect(a, pa, b, pb, seed=pccd.pair_seed(5, 7 + i))), i
        distances = pccd.distance_many(pairs, seed=5, threads=threads)
        for i, (a, pa, b, pb) in enumerate(pairs):
            single = pccd.distance(a, pa, b, pb, seed=pccd.pair_seed(5, i))
            assert distances[i].status == single.status
            assert np.array_equal(np.array([distances[i].distance]), np.array([single.distance]), equal_nan=True), i
    motions = [(lean, (None, None), geodesic, (at(3.0), at(-3.0))), (geodesic, (None, None), lean, (at(3.0), at(-3.0)))]
    batch = pccd.time_of_contact_many(motions, seed=2)
    for i, (a, ma, b, mb) in enumerate(motions):
        single = pccd.time_of_contact(a, ma, b, mb, seed=pccd.pair_seed(2, i))
        assert batch[i].status == single.status == "contact" and batch[i].t == single.t


def test_bad_arguments(balls):
    geodesic, lean = balls
    with pytest.raises(TypeError, match="proximity graph option"):
        pccd.LeanObject(sphere_points(100), graph="knn")
    with pytest.raises(TypeError, match="unexpected keyword argument 'etta'"):
        pccd.LeanObject(sphere_points(100), etta=3)
    with pytest.raises(TypeError, match="LeanObject\\(\\): option eta has the wrong type"):
        pccd.LeanObject(sphere_points(100), eta="three")
    with pytest.raises(ValueError):
        pccd.LeanObject(np.array([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0], [1.0, 0.0, 0.0]]))
    with pytest.raises(ValueError):
        pccd.LeanObject(np.zeros((5, 2)))
    with pytest.raises(TypeError, match="b must be a pccd.Object or a pccd.LeanObject, not int"):
        pccd.distance(lean, None, 3, None)
    with pytest.raises(TypeError, match="a must be a pccd.Object or a pccd.LeanObject, not str"):
        pccd.do_intersect("lean", None, lean, None)
    with pytest.raises(ValueError, match="pose_b"):
        pccd.distance(lean, None, geodesic, np.full((3, 4), np.nan))
    with pytest.raises(TypeError, match=r"pairs\[1\]: items 0 and 2 must be pccd.Object or pccd.LeanObject"):
        pccd.do_intersect_many([(lean, None, lean, None), (lean, None, 2.0, None)])
    with pytest.raises(TypeError, match=r"time_of_contact\(\): b must be a pccd.Object or a pccd.LeanObject, not int"):
        pccd.time_of_contact(lean, (None, None), 3, (None, None))
    with pytest.raises(TypeError, match=r"pairs\[0\]: items 0 and 2 must be pccd.Object or pccd.LeanObject instances"):
        pccd.time_of_contact_many([(lean, (None, None), "ball", (None, None))])
    with pytest.raises(TypeError, match="a World holds pccd.Object instances only"):
        pccd.World().insert(lean, None)
    with pytest.raises(TypeError, match="LeanObject.save"):
        lean.save(None)


def test_a_saved_lean_object_loads_back_and_answers_as_it_did(balls, tmp_path):
    geodesic, lean = balls
    path = tmp_path / "ball.pccdlean"
    lean.save(path)
    loaded = pccd.LeanObject.load(str(path))
    assert isinstance(loaded, pccd.LeanObject) and loaded.size == lean.size
    assert np.array_equal(loaded.points, lean.points) and np.array_equal(loaded.normals, lean.normals)
    assert loaded.memory_bytes == lean.memory_bytes and loaded.leaf_size == lean.leaf_size
    for x in (0.8, 1.2):
        assert same_result(pccd.do_intersect(loaded, None, geodesic, at(x), seed=4),
                           pccd.do_intersect(lean, None, geodesic, at(x), seed=4))
        assert pccd.distance(loaded, None, lean, at(x), seed=4).distance == pccd.distance(lean, None, lean, at(x), seed=4).distance
    assert pccd.LeanObject.load(path, leaf_size=4, volume="sphere").volume == "sphere"
    # Each kind reads its own files and names the other's.
    geodesic_path = tmp_path / "ball.pccdobj"
    geodesic.save(geodesic_path)
    with pytest.raises(OSError, match="load it with Point_cloud_object::load"):
        pccd.LeanObject.load(geodesic_path)
    with pytest.raises(OSError, match="load it with Euclidean_point_cloud_object::load"):
        pccd.Object.load(path)
    with pytest.raises(OSError):
        pccd.LeanObject.load(tmp_path / "missing.pccdlean")


def test_load_reads_either_kind_as_the_kind_it_holds(balls, tmp_path):
    """pccd.load: the file's magic decides the class; the object answers as the saved one."""
    geodesic, lean = balls
    lean_path, geodesic_path = tmp_path / "ball.lean", tmp_path / "ball.obj"  # names that say nothing
    lean.save(lean_path)
    geodesic.save(str(geodesic_path))
    loaded_lean, loaded_geodesic = pccd.load(lean_path), pccd.load(str(geodesic_path))
    assert type(loaded_lean) is pccd.LeanObject and loaded_lean.kernel == "euclidean"
    assert type(loaded_geodesic) is pccd.Object and loaded_geodesic.kernel == "geodesic"
    assert np.array_equal(loaded_lean.points, lean.points)
    assert np.array_equal(loaded_geodesic.points, geodesic.points)
    assert (pccd.distance(loaded_geodesic, None, loaded_lean, at(1.2), seed=4).distance ==
            pccd.distance(geodesic, None, lean, at(1.2), seed=4).distance)
    assert pccd.load(lean_path, leaf_size=4).leaf_size == 4
    # Not an object file, or not there: OSError naming the file.
    points_path = tmp_path / "points.xyz"
    pccd.write_points(points_path, lean.points[:50])
    with pytest.raises(OSError, match="points.xyz: not a PCCD object file"):
        pccd.load(points_path)
    with pytest.raises(OSError, match="missing"):
        pccd.load(tmp_path / "missing.lean")
    with pytest.raises(ValueError, match="volume"):
        pccd.load(lean_path, volume="cone")
