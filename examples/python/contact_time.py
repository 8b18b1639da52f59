"""When do two moving point clouds first touch: continuous collision detection of PCCD from Python.

Two sampled unit spheres (procedural, seeded: no data files needed). A rests at the origin; B
travels from x = 4 to x = -4 at heights y = 0, 1, 1.9 and 2.5 above the line through A's centre.
For each path the script prints pccd.time_of_contact's first contact time next to the exact one
(the centres are 2 apart when x = sqrt(4 - y^2)), with its bracket [t_low, t_high], the contact
point and normal, or no_contact for the path that passes by. Then the same paths as screw motions
(a quarter turn about the z axis through A's centre, B rolling around A), all paths at once with
pccd.time_of_contact_many on several threads (the same answers as the single calls), and the
discrete view: poses at 6 equally spaced times all miss the touch that time_of_contact finds.

    build/pccd-python examples/python/contact_time.py [--points N] [--threads T]
"""
import argparse
import math

import numpy as np

import pccd


def sphere_points(n, seed):
    """n points on the unit sphere about the origin, from a seeded generator."""
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def at(x, y=0.0, z=0.0, angle=0.0):
    """A 3x4 pose [R | t]: turned by `angle` about z, then moved to (x, y, z)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0, x], [s, c, 0.0, y], [0.0, 0.0, 1.0, z]])


def main():
    parser = argparse.ArgumentParser(description="First contact times of a sphere moving past another")
    parser.add_argument("--points", type=int, default=2000, help="points per sphere (default 2000)")
    parser.add_argument("--threads", type=int, default=2, help="threads of time_of_contact_many (default 2)")
    args = parser.parse_args()

    a = pccd.Object(sphere_points(args.points, seed=1))
    b = pccd.Object(sphere_points(args.points, seed=2))
    print(f"A, B: unit spheres, {a.size} and {b.size} points, sampling radii {a.sampling_radius:.4f}, "
          f"{b.sampling_radius:.4f}")

    still = (None, None)  # A at rest at the identity
    print("B from x = 4 to x = -4 at height y (linear motion):")
    print(f"{'y':>4} {'status':>10} {'t':>7} {'exact':>7} {'[t_low, t_high]':>18} {'point':>22} {'normal':>22}")
    heights = [0.0, 1.0, 1.9, 2.5]
    motions = [(at(4.0, y), at(-4.0, y)) for y in heights]
    for y, motion_b in zip(heights, motions):
        r = pccd.time_of_contact(a, still, b, motion_b)
        exact = (4.0 - math.sqrt(4.0 - y * y)) / 8.0 if y < 2.0 else math.nan
        if r:
            bracket = f"[{r.t_low:.4f}, {r.t_high:.4f}]"
            point = np.array2string(np.round(r.point, 2) + 0.0, precision=2)
            normal = np.array2string(np.round(r.normal, 2) + 0.0, precision=2)
            print(f"{y:4.1f} {r.status:>10} {r.t:7.4f} {exact:7.4f} {bracket:>18} {point:>22} {normal:>22}")
        else:
            print(f"{y:4.1f} {r.status:>10} {'-':>7} {'-':>7} {'-':>18} {'-':>22} {'-':>22}")

    # A screw: B turns a quarter about the z axis through A's centre, from (3, 0, 0) to (0, 3, 0),
    # against a third sphere resting at (0, 3, 0): first contact when the angle reaches 2 asin(1/3).
    fixed = (at(0.0, 3.0), at(0.0, 3.0))
    turn = (at(3.0), at(0.0, 3.0, angle=math.pi / 2))
    screwed = pccd.time_of_contact(a, fixed, b, turn, motion="screw")
    straight = pccd.time_of_contact(a, fixed, b, turn)
    print(f"screw motion: {screwed.status} at t = {screwed.t:.4f} (exact {math.asin(7 / 9) / (math.pi / 2):.4f}); "
          f"linear between the same poses: t = {straight.t:.4f} (exact {1 - 2 / (3 * math.sqrt(2)):.4f})")

    pairs = [(a, still, b, m) for m in motions]
    batch = pccd.time_of_contact_many(pairs, threads=args.threads, seed=5)
    singles = [pccd.time_of_contact(*pair, seed=pccd.pair_seed(5, i)) for i, pair in enumerate(pairs)]
    same = all(x.status == y.status and (x.t == y.t or (math.isnan(x.t) and math.isnan(y.t)))
               and x.counters == y.counters for x, y in zip(batch, singles))
    print(f"time_of_contact_many on {args.threads} threads: {[r.status for r in batch]}, "
          f"{'the same answers as the single calls' if same else 'DIFFERENT from the single calls'}")

    # Grazing at y = 1.9: the spheres overlap only while |x| < sqrt(4 - 1.9^2) = 0.62, a stretch of
    # 0.16 in time; poses at 6 equally spaced times (steps of 0.2, t = 0.4 and 0.6 at x = 0.8 and
    # -0.8) all fall outside it.
    grazing = motions[2]
    seen = [pccd.do_intersect(a, None, b, at(4.0 - 8.0 * k / 5, 1.9)).intersects for k in range(6)]
    r = pccd.time_of_contact(a, still, b, grazing)
    print(f"grazing at y = 1.9: 6 discrete poses see contact {sum(seen)} times; time_of_contact: {r.status} "
          f"at t = {r.t:.4f}")


if __name__ == "__main__":
    main()
