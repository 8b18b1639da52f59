"""How far apart, how deep, and where in contact: the proximity queries of PCCD from Python.

Two sampled spheres of radius 0.5 (procedural, seeded: no data files needed); B approaches A
along x. For each pose the script prints the exact gap between the spheres next to
pccd.distance's answer (with its honest interval [lower_bound, upper_bound]), whether
pccd.within_distance finds them closer than the margin, and for intersecting poses the
penetration depth (penetration=True) next to the exact one. It then answers all poses at once
with pccd.distance_many on several threads, checks that the batch gives the single calls'
answers, and lists the contact regions (pccd.contacts) of the deepest pose.

    build/pccd-python examples/python/proximity.py [--points N] [--margin M] [--threads T]
"""
import argparse
import math

import numpy as np

import pccd


def sphere_points(n, radius, seed):
    """n points on a sphere about the origin, from a seeded generator."""
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return radius * v / np.linalg.norm(v, axis=1, keepdims=True)


def moved(x):
    """The pose of B: moved by x along the x axis (3x4 [R | t])."""
    return np.array([[1.0, 0.0, 0.0, x], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])


def main():
    parser = argparse.ArgumentParser(description="Distances, clearance and contacts of two posed spheres")
    parser.add_argument("--points", type=int, default=2000, help="points per sphere (default 2000)")
    parser.add_argument("--margin", type=float, default=0.1, help="the clearance asked of within_distance (default 0.1)")
    parser.add_argument("--threads", type=int, default=2, help="threads of distance_many (default 2)")
    args = parser.parse_args()

    radius = 0.5
    a = pccd.Object(sphere_points(args.points, radius, seed=1))
    b = pccd.Object(sphere_points(args.points, radius, seed=2))
    print(f"A, B: spheres of radius {radius}, {a.size} and {b.size} points, sampling radii "
          f"{a.sampling_radius:.4f}, {b.sampling_radius:.4f}")

    centres = [2.0, 1.5, 1.2, 1.05, 0.9, 0.75]
    print(f"{'x':>5} {'exact gap':>10} {'distance':>10} {'[lower_bound, upper_bound]':>27} "
          f"{'within ' + str(args.margin):>11} {'depth':>7} {'exact':>6}")
    for x in centres:
        gap = x - 2 * radius
        d = pccd.distance(a, None, b, moved(x), penetration=True)
        near = pccd.within_distance(a, None, b, moved(x), args.margin)
        depth = exact = ""
        if d.intersecting:  # the deepest point of A inside B is A's (0.5, 0, 0), x - 0.5 from B's centre
            depth, exact = f"{d.depth:.4f}", f"{radius - abs(x - radius):.4f}"
        interval = f"[{d.lower_bound:.4f}, {d.upper_bound:.4f}]"
        print(f"{x:5.2f} {gap:10.4f} {d.distance:10.4f} {interval:>27} {str(near.within):>11} {depth:>7} {exact:>6}")

    pairs = [(a, None, b, moved(x)) for x in centres]
    batch = pccd.distance_many(pairs, threads=args.threads, seed=5)
    singles = [pccd.distance(*pair, seed=pccd.pair_seed(5, i)) for i, pair in enumerate(pairs)]
    same = all(x.status == y.status and (x.distance == y.distance or math.isnan(x.distance) and math.isnan(y.distance))
               and x.counters == y.counters for x, y in zip(batch, singles))
    print(f"distance_many: {len(pairs)} pairs on {args.threads} threads, "
          f"{'the same answers as' if same else 'DIFFERENT answers from'} the single calls")

    touching = pccd.contacts(a, None, b, moved(centres[-1]))
    print(f"contacts at x = {centres[-1]}: {touching.status}, {touching.regions} region(s)")
    for c in touching.contacts:
        print(f"  depth {c.depth:.4f} at {np.round(c.position, 3)}, B leaves along {np.round(c.normal, 3)}")
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())
