"""A collision world from Python (doc/manual/world.md): a sphere and a torus, preprocessed once and
shared by 60 instances at random poses, moved for a few steps with one set_poses call per step (an
(n, 3, 4) array); each step prints the intersecting pairs found and how many narrow-phase queries
the cache saved. At the end, every reported pair is checked against pccd.do_intersect with the
documented pair seed, and a stale handle shows its error.

    python3 examples/python/world.py [--instances 60] [--steps 5] [--seed 1]
"""

import argparse

import numpy as np

import pccd


def sphere(n, radius, rng):
    v = rng.normal(size=(n, 3))
    return radius * v / np.linalg.norm(v, axis=1, keepdims=True)


def torus(n, major, minor, rng):
    u, v = rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n)
    r = major + minor * np.cos(v)
    return np.column_stack([r * np.cos(u), r * np.sin(u), minor * np.sin(v)])


def random_poses(rng, count, side):
    """`count` rigid poses: uniform rotations (QR of a Gaussian matrix), translations in [0, side]^3."""
    q, r = np.linalg.qr(rng.normal(size=(count, 3, 3)))
    q = q * np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :]
    q[np.linalg.det(q) < 0, :, 0] *= -1
    return np.concatenate([q, rng.uniform(0, side, size=(count, 3, 1))], axis=2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--instances", type=int, default=60)
    parser.add_argument("--steps", type=int, default=5)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    objects = [pccd.Object(sphere(1500, 0.5, rng)), pccd.Object(torus(2500, 0.7, 0.3, rng))]
    side = np.cbrt(8.0 * args.instances)

    world = pccd.World(threads=2)
    poses = random_poses(rng, args.instances, side)
    handles = [world.insert(objects[i % 2], poses[i]) for i in range(args.instances)]
    for step in range(args.steps):
        pairs = world.intersecting_pairs()
        c = world.counters
        print(f"step {step}: {len(pairs)} intersecting pairs; {c['narrow_phase_queries']} narrow-phase queries, "
              f"{c['cached_pairs']} answers from the cache")
        # A fifth of the instances move, in one call.
        moving = rng.choice(args.instances, size=args.instances // 5, replace=False)
        new = random_poses(rng, len(moving), side)
        world.set_poses([handles[i] for i in moving], new)
        poses[moving] = new

    pairs = world.intersecting_pairs(details=True)
    for a, b, status, point in pairs:
        seed = pccd.pair_seed(world.seed, pccd.world_pair_key(a.index, b.index))
        alone = pccd.do_intersect(world.object(a), poses[a.index], world.object(b), poses[b.index], seed=seed)
        assert alone.status == status and np.array_equal(alone.points[0], point)
    print(f"{len(pairs)} pairs, each equal to do_intersect with its pair seed; "
          f"{world.memory_bytes() // len(world)} bytes per instance")
    world.erase(handles[0])
    try:
        world.set_pose(handles[0], None)
    except ValueError as error:
        print(error)


if __name__ == "__main__":
    main()
