"""PCCD next to Open3D's point distances, on a pair of scans.

For the bunny and the elephant (libcgal-demo's scans, each scaled into [-1, 1]^3) in a few poses,
prints PCCD's answer (do_intersect on the implicit surfaces, with its query time) and Open3D's
compute_point_cloud_distance: for each point of B, the distance to the nearest point of A; the
table shows the smallest and the share of B's points within one sampling radius of A.

Point distances alone cannot tell two surfaces that cross from two that pass within a point
spacing of each other; PCCD's implicit surfaces decide that, and find the points where they cross.
The objects are built straight from Open3D's point clouds (pccd.Object takes one as it is).

    build/pccd-python examples/python/open3d_distance.py [--meshes DIR] [--shifts 0.5 1 1.5 3]

Needs Open3D (Debian: python3-open3d).
"""
import argparse
import os
import pathlib
import time

import numpy as np
import open3d as o3d

import pccd


def unit_cube(points):
    low, high = points.min(axis=0), points.max(axis=0)
    return (points - (low + high) / 2) / ((high - low).max() / 2)


def main():
    default = os.environ.get("PCCD_DATA_DIR") or pathlib.Path(__file__).resolve().parents[2] / "build/cgal-data/data/meshes"
    parser = argparse.ArgumentParser(description="PCCD's answer next to Open3D's point distances")
    parser.add_argument("--meshes", default=default, help="directory holding bunny00.off and elephant.off")
    parser.add_argument("--shifts", type=float, nargs="+", default=[0.5, 1.0, 1.5, 3.0],
                        help="x offsets of the elephant (default 0.5 1 1.5 3)")
    args = parser.parse_args()
    meshes = pathlib.Path(args.meshes)
    clouds = []
    for name in ("bunny00.off", "elephant.off"):
        cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(unit_cube(pccd.read_points(meshes / name)[0])))
        clouds.append(cloud)
    a, b = (pccd.Object(cloud) for cloud in clouds)  # Open3D point clouds as they are
    print(f"A: {a.size} points, B: {b.size} points, sampling radii {a.sampling_radius:.4f}, {b.sampling_radius:.4f}")
    print(f"{'shift':>6} {'PCCD':>13} {'PCCD us':>9} {'Open3D min':>11} {'within r':>9} {'Open3D us':>10}")
    radius = max(a.sampling_radius, b.sampling_radius)
    for shift in args.shifts:
        pose = np.array([[0.0, -1.0, 0.0, shift], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])
        result = pccd.do_intersect(a, None, b, pose, seed=7)
        moved = o3d.geometry.PointCloud(clouds[1])
        moved.transform(np.vstack([pose, [0.0, 0.0, 0.0, 1.0]]))
        start = time.perf_counter()
        distances = np.asarray(moved.compute_point_cloud_distance(clouds[0]))
        open3d_us = (time.perf_counter() - start) * 1e6
        print(f"{shift:6.2f} {result.status:>13} {result.query_us:9.0f} {distances.min():11.4f} "
              f"{(distances <= radius).mean():9.1%} {open3d_us:10.0f}")


if __name__ == "__main__":
    main()
