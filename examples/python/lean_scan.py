"""A large scan as a pccd.LeanObject beside a small part as a pccd.Object: the clearance of the part
moved along a path over the scan.

The "scan" is a square floor of side 2 sampled by --scan-points points (procedural and seeded: no
data files needed) with a little noise; the part is a sphere of radius 0.1 (--part-points points)
lowered towards the floor. The floor becomes the lean object (the Euclidean kernel, no geodesic
map: a fifth of the memory, what 10^6-10^7-point scans need), the part the default Object (the
geodesic kernel, better on small parts with sharp edges). pccd.clearance answers the path on
several threads; the script prints each pose's clearance next to the exact gap (height of the
centre minus the radius), the first pose below the margin, and both objects' memory per point.

    build/pccd-python examples/python/lean_scan.py [--scan-points N] [--part-points N] [--margin M]
"""
import argparse

import numpy as np

import pccd


def floor_points(n, seed, noise):
    """n points uniformly on the square [-1, 1]^2 at z = 0, with Gaussian noise of `noise` in z."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-1.0, 1.0, size=(n, 2))
    return np.column_stack([xy, rng.normal(0.0, noise, size=n)])


def sphere_points(n, radius, seed):
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return radius * v / np.linalg.norm(v, axis=1, keepdims=True)


def at_height(z):
    return np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, z]])


def main():
    parser = argparse.ArgumentParser(description="Clearance of a part over a large scan held as a lean object")
    parser.add_argument("--scan-points", type=int, default=200000, help="points of the floor (default 200000)")
    parser.add_argument("--part-points", type=int, default=3000, help="points of the sphere (default 3000)")
    parser.add_argument("--margin", type=float, default=0.03, help="the safety margin (default 0.03)")
    args = parser.parse_args()

    radius = 0.1
    spacing = 2.0 / np.sqrt(args.scan_points)
    scan = pccd.LeanObject(floor_points(args.scan_points, seed=1, noise=0.05 * spacing))
    part = pccd.Object(sphere_points(args.part_points, radius, seed=2))
    print(f"scan: {scan.size} points, {scan.kernel} kernel, {scan.memory_bytes / scan.size:.0f} bytes per point")
    print(f"part: {part.size} points, {part.kernel} kernel")

    heights = [0.5, 0.3, 0.2, 0.15, 0.12, 0.11, 0.105]
    profile = pccd.clearance(part, scan, np.stack([at_height(z) for z in heights]), args.margin)
    print(f"{'height':>7} {'exact gap':>10} {'clearance':>10} {'status':>13}")
    for z, c, s in zip(heights, profile.clearance, profile.status):
        print(f"{z:7.3f} {z - radius:10.4f} {c:10.4f} {s:>13}")
    print(f"first pose below the margin {args.margin}: {profile.first_below_margin}")


if __name__ == "__main__":
    main()
