"""pccd.World (PCCD::Collision_world) against brute force: on seeded random scenes of shared
sphere and torus objects, after moves (one pose, and an (n, 3, 4) array in one call), insertions
and erasures, intersecting_pairs() equals pccd.do_intersect over every pair the filters allow,
seeded by the documented rule pair_seed(seed, world_pair_key(a.index, b.index)), status and point
bit for bit; the answers do not depend on the threads or the cache; the one-instance, query-object,
distance and box queries equal their brute force; the objects stay alive while an instance uses
them; every bad argument raises a clear ValueError or TypeError."""

import gc
import pickle
import sys
import threading

import numpy as np
import pytest

import pccd
from conftest import sphere_points, torus_points


@pytest.fixture(scope="module")
def objects():
    """Three shared objects: spheres of radius 0.5 and 0.3, a torus of outer radius 1."""
    return [pccd.Object(sphere_points(800)), pccd.Object(0.6 * sphere_points(500, seed=3)),
            pccd.Object(torus_points(1000))]


def random_pose(rng, side):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q @ np.diag(np.sign(np.diag(r)))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return np.hstack([q, rng.uniform(0, side, size=(3, 1))])


def side_for(n):
    return np.cbrt(2.5 * n)


def allowed(world, a, b):
    ga, ma = world.filter(a)
    gb, mb = world.filter(b)
    return (ga & mb) != 0 and (gb & ma) != 0 and not world.excluded(a, b)


class Tracked:
    """A pccd.World and, beside it, the object and the pose array given for each live handle: the
    brute force poses the objects with the arrays given, as the world did. (World.pose returns the
    pose as stored: Rigid_transform_3 takes the nearest rotation, so a pose read back may differ
    from the one given in the last bits, and so may an answer computed with it.)"""

    def __init__(self, world):
        self.world = world
        self.given = {}

    def insert(self, obj, pose, *filter_bits):
        h = self.world.insert(obj, pose, *filter_bits)
        self.given[h] = (obj, pose)
        return h

    def set_pose(self, h, pose):
        self.world.set_pose(h, pose)
        self.given[h] = (self.given[h][0], pose)

    def set_poses(self, handles, poses):
        self.world.set_poses(handles, poses)
        for h, p in zip(handles, poses):
            self.given[h] = (self.given[h][0], p)

    def erase(self, h):
        self.world.erase(h)
        del self.given[h]

    def object(self, h):
        return self.given[h][0]

    def pose(self, h):
        return self.given[h][1]


def brute_force(tracked, **options):
    """(a, b, status, point) of every allowed pair that do_intersect does not find separate, in
    (a.index, b.index) order, each answered with the world's pair seed."""
    world = tracked.world
    assert sorted(tracked.given) == world.handles()
    out = []
    handles = world.handles()
    for i, a in enumerate(handles):
        for b in handles[i + 1:]:
            if not allowed(world, a, b):
                continue
            seed = pccd.pair_seed(world.seed, pccd.world_pair_key(a.index, b.index))
            r = pccd.do_intersect(tracked.object(a), tracked.pose(a), tracked.object(b), tracked.pose(b), **options,
                                  seed=seed)
            if r.status != "separate":
                point = r.points[0] if len(r.points) else np.full(3, np.nan)
                out.append((a, b, r.status, point))
    return out


def same_pairs(x, y):
    return len(x) == len(y) and all(
        p[0] == q[0] and p[1] == q[1] and p[2] == q[2] and np.array_equal(p[3], q[3], equal_nan=True)
        for p, q in zip(x, y))


def fill(world, objects, rng, n, side, **insert_options):
    return [world.insert(objects[int(rng.integers(len(objects)))], random_pose(rng, side), **insert_options)
            for _ in range(n)]


def test_pairs_equal_brute_force_after_moves_insertions_and_erasures(objects):
    rng = np.random.default_rng(2026)
    n = 40
    side = side_for(n)
    tracked = Tracked(pccd.World(threads=2))
    world = tracked.world
    fill(tracked, objects, rng, n, side)
    total = 0
    for step in range(4):
        pairs = world.intersecting_pairs(details=True)
        assert same_pairs(pairs, brute_force(tracked)), f"step {step}"
        assert [p[:2] for p in pairs] == world.intersecting_pairs()
        assert all(a.index < b.index for a, b, _, _ in pairs)
        total += len(pairs)
        handles = world.handles()
        # About a quarter moves in one set_poses call, one more by set_pose.
        moving = [h for h in handles if rng.uniform() < 0.25]
        tracked.set_poses(moving, np.stack([random_pose(rng, side) for _ in moving]))
        tracked.set_pose(handles[0], random_pose(rng, side))
        for h in rng.choice(len(handles), size=4, replace=False):
            tracked.erase(handles[int(h)])
        added = fill(tracked, objects, rng, 4, side)
        assert all(h in world for h in added)
        assert len(world) == n
    assert total >= n  # the scenes do collide
    # Early stop: the first pairs of the full answer.
    everything = world.intersecting_pairs()
    assert world.intersecting_pairs(limit=1) == everything[:1]
    assert world.intersecting_pairs(limit=3, details=True)[2][:2] == everything[2]
    assert world.intersecting_pairs(limit=10 ** 6) == everything
    # Erased slots are reused with a new generation: the old handles are stale.
    assert any(h.generation > 0 for h in world.handles())


def test_the_answers_do_not_depend_on_threads_or_cache(objects):
    rng = np.random.default_rng(7)
    n = 30
    side = side_for(n)
    poses = [random_pose(rng, side) for _ in range(n)]
    worlds = [pccd.World(threads=1), pccd.World(threads=2, cache=False), pccd.World()]
    for w in worlds:
        for i, p in enumerate(poses):
            w.insert(objects[i % 3], p)
    first = [w.intersecting_pairs(details=True) for w in worlds]
    assert all(same_pairs(first[0], f) for f in first[1:])
    queried = worlds[0].counters["narrow_phase_queries"]
    assert worlds[0].counters["cached_pairs"] == 0 and queried > 0
    # Nothing moved: the cached world answers from its cache; the uncached one asks again.
    assert same_pairs(worlds[0].intersecting_pairs(details=True), first[0])
    assert worlds[0].counters["narrow_phase_queries"] == 0
    assert worlds[0].counters["cached_pairs"] == queried
    assert same_pairs(worlds[1].intersecting_pairs(details=True), first[0])
    assert worlds[1].counters["cached_pairs"] == 0
    assert worlds[0].cache and not worlds[1].cache and worlds[0].threads == 1 and worlds[2].threads is None


def test_intersection_options_are_do_intersects(objects):
    rng = np.random.default_rng(11)
    tracked = Tracked(pccd.World(seed=99, traversal="flat", samples=150))
    fill(tracked, objects, rng, 20, side_for(20))
    assert tracked.world.seed == 99
    assert same_pairs(tracked.world.intersecting_pairs(details=True), brute_force(tracked, traversal="flat", samples=150))


def test_filters_and_excluded_pairs(objects):
    rng = np.random.default_rng(13)
    n = 36
    tracked = Tracked(pccd.World())
    world = tracked.world
    handles = []
    for i in range(n):
        group = 1 << (i % 3)
        mask = 0xFFFFFFFF & ~2 if group == 4 else 0xFFFFFFFF  # group 4 ignores group 2
        handles.append(tracked.insert(objects[i % 3], random_pose(rng, side_for(n)), group, mask))
    pairs = world.intersecting_pairs()
    assert len(pairs) >= 4
    assert same_pairs(world.intersecting_pairs(details=True), brute_force(tracked))
    world.exclude_pair(*pairs[0])
    world.exclude_pair(pairs[1][1], pairs[1][0])
    assert world.excluded(pairs[1][0], pairs[1][1])
    fewer = world.intersecting_pairs()
    assert fewer == [p for p in pairs if p not in pairs[:2]]
    assert same_pairs(world.intersecting_pairs(details=True), brute_force(tracked))
    world.include_pair(*pairs[0])
    world.set_filter(pairs[2][0], 0)  # group 0 collides with nothing
    assert world.filter(pairs[2][0]) == (0, 0xFFFFFFFF)
    assert same_pairs(world.intersecting_pairs(details=True), brute_force(tracked))
    assert pairs[0] in world.intersecting_pairs() and pairs[2] not in world.intersecting_pairs()


def test_one_instance_and_query_object_queries(objects):
    rng = np.random.default_rng(17)
    n = 30
    side = side_for(n)
    tracked = Tracked(pccd.World())
    world = tracked.world
    handles = fill(tracked, objects, rng, n, side)
    pairs = world.intersecting_pairs()
    for h in handles[:10]:
        assert world.intersecting(h) == [b if a == h else a for a, b in pairs if h in (a, b)]
    query = objects[2]
    for _ in range(3):
        pose = random_pose(rng, side)
        truth = []
        for h in world.handles():
            r = pccd.do_intersect(query, pose, tracked.object(h), tracked.pose(h),
                                  seed=pccd.pair_seed(world.seed, h.index))
            if r.status != "separate":
                truth.append((h, r.status, r.points[0] if len(r.points) else np.full(3, np.nan)))
        hits = world.intersecting_object(query, pose, details=True)
        assert len(hits) == len(truth)
        assert all(x[0] == y[0] and x[1] == y[1] and np.array_equal(x[2], y[2], equal_nan=True)
                   for x, y in zip(hits, truth))
        assert world.intersecting_object(query, pose) == [t[0] for t in truth]
        assert world.intersecting_object(query, pose, 1, 0) == []  # mask 0: no instance agrees


def test_within_distance_and_overlapping_equal_brute_force(objects):
    rng = np.random.default_rng(19)
    n = 20
    side = side_for(n)
    tracked = Tracked(pccd.World())
    world = tracked.world
    handles = fill(tracked, objects, rng, n, side)
    for h in handles[:4]:
        near = world.within_distance(h, 0.3)
        truth = [o for o in world.handles() if o != h and
                 pccd.within_distance(tracked.object(h), tracked.pose(h), tracked.object(o), tracked.pose(o), 0.3).within]
        assert [x for x, _ in near] == truth
        assert all(c.within and c.margin == 0.3 for _, c in near)
    pose = random_pose(rng, side)
    near = world.within_distance_object(objects[0], pose, 0.5)
    assert [x for x, _ in near] == [o for o in world.handles() if pccd.within_distance(
        objects[0], pose, tracked.object(o), tracked.pose(o), 0.5).within]
    lo, hi = np.full(3, 0.3 * side), np.full(3, 0.7 * side)
    truth = []
    for h in world.handles():
        p = tracked.pose(h)
        points = tracked.object(h).points @ p[:, :3].T + p[:, 3]
        if np.any(np.all((points >= lo) & (points <= hi), axis=1)):
            truth.append(h)
    assert world.overlapping(lo, hi) == truth and truth


def test_the_world_keeps_its_objects_alive(objects):
    world = pccd.World()
    temporary = pccd.Object(sphere_points(600, seed=5))
    count = sys.getrefcount(temporary)
    a = world.insert(temporary, None)
    b = world.insert(temporary, np.hstack([np.eye(3), [[0.5], [0.0], [0.0]]]))
    assert sys.getrefcount(temporary) == count + 2
    del temporary
    gc.collect()
    assert world.intersecting_pairs() == [(a, b)]
    kept = world.object(a)
    assert kept is world.object(b) and len(kept) == 600
    count = sys.getrefcount(kept)
    world.erase(a)
    assert sys.getrefcount(kept) == count - 1
    assert world.intersecting_pairs() == []


def test_concurrent_python_threads_are_serialized(objects):
    rng = np.random.default_rng(23)
    n = 30
    side = side_for(n)
    tracked = Tracked(pccd.World(threads=2))
    world = tracked.world
    handles = fill(tracked, objects, rng, n, side)
    poses = [np.stack([random_pose(rng, side) for _ in handles]) for _ in range(5)]
    errors = []

    def mover():
        try:
            for p in poses:
                world.set_poses(handles, p)
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    def asker():
        try:
            for _ in range(5):
                world.intersecting_pairs()
        except Exception as e:  # pragma: no cover
            errors.append(e)

    threads = [threading.Thread(target=mover), threading.Thread(target=asker)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    for h, p in zip(handles, poses[-1]):
        tracked.given[h] = (tracked.given[h][0], p)
    assert same_pairs(world.intersecting_pairs(details=True), brute_force(tracked))


def test_world_handles_are_small_hashable_ordered_values():
    a, b = pccd.WorldHandle(3, 1), pccd.WorldHandle(3, 1)
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert pccd.WorldHandle(2, 5) < a < pccd.WorldHandle(3, 2) < pccd.WorldHandle(4)
    assert a != (3, 1) and repr(a) == "WorldHandle(index=3, generation=1)"
    assert pickle.loads(pickle.dumps(a)) == a
    assert (a.index, a.generation) == (3, 1)
    with pytest.raises(AttributeError):
        a.index = 4
    assert pccd.world_pair_key(7, 2) == pccd.world_pair_key(2, 7) == (2 << 32) | 7


def test_memory_and_counters(objects):
    rng = np.random.default_rng(29)
    world = pccd.World()
    empty = world.memory_bytes()
    fill(world, objects, rng, 50, side_for(50))
    world.intersecting_pairs()
    grown = world.memory_bytes() - empty
    assert 50 * 100 < grown < 50 * 2000, grown  # slots, tree nodes and the cache: ~100 bytes to ~1 KB each
    c = world.counters
    assert set(c) == {"broad_phase_pairs", "filtered_pairs", "cached_pairs", "narrow_phase_queries", "reported_pairs"}
    assert c["reported_pairs"] == len(world.intersecting_pairs())
    assert repr(world) == "<pccd.World: 50 instances>"


def test_bad_arguments_raise_clear_errors(objects):
    world = pccd.World()
    h = world.insert(objects[0], None)
    g = world.insert(objects[1], None)
    nan_pose = np.hstack([np.eye(3), [[np.nan], [0], [0]]])
    scaled = np.hstack([2 * np.eye(3), np.zeros((3, 1))])
    for bad in (nan_pose, scaled, np.eye(3), "pose"):
        with pytest.raises(ValueError, match="pose"):
            world.insert(objects[0], bad)
        with pytest.raises(ValueError, match="pose"):
            world.set_pose(h, bad)
    assert len(world) == 2
    # set_poses: shapes, lengths, one bad pose (named) -- and nothing moves then.
    before = world.pose(h)
    good = np.stack([np.hstack([np.eye(3), [[1], [2], [3]]])] * 2)
    with pytest.raises(ValueError, match=r"shape \(n, 3, 4\) or \(n, 4, 4\), got \(2, 3, 3\)"):
        world.set_poses([h, g], np.zeros((2, 3, 3)))
    with pytest.raises(ValueError, match="2 handles but 1 poses"):
        world.set_poses([h, g], good[:1])
    with pytest.raises(ValueError, match=r"poses\[1\]"):
        world.set_poses([h, g], np.stack([good[0], nan_pose]))
    assert np.array_equal(world.pose(h), before)
    with pytest.raises(TypeError, match=r"handles\[1\] must be a pccd.WorldHandle"):
        world.set_poses([h, 1], good)
    world.set_poses([h, g], good)
    assert np.array_equal(world.pose(g), good[1])
    world.set_poses([h], np.stack([np.vstack([good[0], [0, 0, 0, 1]])]))  # (n, 4, 4)
    # Stale handles: erasing twice, a reused slot, a handle never issued.
    world.erase(g)
    with pytest.raises(ValueError, match="stale"):
        world.erase(g)
    with pytest.raises(ValueError, match="stale"):
        world.set_pose(g, None)
    with pytest.raises(ValueError, match="stale"):
        world.set_poses([h, g], good)
    k = world.insert(objects[1], None)
    assert k.index == g.index and k.generation == g.generation + 1 and g not in world and k in world
    with pytest.raises(ValueError, match="stale"):
        world.intersecting(g)
    with pytest.raises(ValueError, match="never issued"):
        world.pose(pccd.WorldHandle(99))
    assert "h" not in world and pccd.WorldHandle(99) not in world
    with pytest.raises(TypeError, match="must be a pccd.WorldHandle"):
        world.erase(0)
    # Margins, boxes, filters, pairs.
    for margin in (-0.1, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="margin"):
            world.within_distance(h, margin)
        with pytest.raises(ValueError, match="margin"):
            world.within_distance_object(objects[0], None, margin)
    with pytest.raises(ValueError, match="limit must be >= 1"):
        world.intersecting_pairs(limit=0)
    with pytest.raises(ValueError, match="empty or not finite"):
        world.overlapping([1, 1, 1], [0, 0, 0])
    with pytest.raises(ValueError, match=r"shape \(3,\)"):
        world.overlapping([0, 0], [1, 1, 1])
    with pytest.raises(ValueError, match=r"group = -1 must be in \[0, 2\*\*32\)"):
        world.insert(objects[0], None, group=-1)
    with pytest.raises(ValueError, match="mask"):
        world.set_filter(h, 1, 2 ** 32)
    with pytest.raises(TypeError, match="group must be an int"):
        world.set_filter(h, 1.5)
    with pytest.raises(ValueError, match="both handles name instance"):
        world.exclude_pair(h, h)
    with pytest.raises(TypeError, match="pccd.Object"):
        world.insert(np.zeros((3, 3)), None)
    # Options.
    with pytest.raises(ValueError, match="method must be 'isearch'"):
        pccd.World(method="rst")
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        pccd.World(colour=1)
    with pytest.raises(ValueError, match="threads"):
        pccd.World(threads=0)
    with pytest.raises(ValueError, match="traversal"):
        pccd.World(traversal="sideways")


def test_the_example_runs_and_checks_its_pairs(source_dir):
    import os
    import subprocess
    done = subprocess.run([sys.executable, str(source_dir / "examples" / "python" / "world.py"), "--instances", "30",
                           "--steps", "3"], capture_output=True, text=True, timeout=600, env=dict(os.environ))
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("step 0: ") and "0 answers from the cache" in lines[0]
    assert "each equal to do_intersect with its pair seed" in lines[-2]
    assert lines[-1] == "Collision_world::set_pose: handle 0 (generation 0) is stale: that instance was erased"
