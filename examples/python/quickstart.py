"""Two scans, one collision query, one intersection curve: the Python quickstart of PCCD.

Run from the source tree after building (PYTHONPATH=build/python) or after `cmake --install`:
    python3 examples/python/quickstart.py [SCAN_A SCAN_B]
Without arguments it takes libcgal-demo's bunny and elephant from build/cgal-data (or
$PCCD_DATA_DIR), each scaled into [-1, 1]^3.
"""
import os
import pathlib
import sys

import numpy as np

import pccd

meshes = pathlib.Path(os.environ.get("PCCD_DATA_DIR") or pathlib.Path(__file__).resolve().parents[2] / "build/cgal-data/data/meshes")
files = sys.argv[1:3] or [meshes / "bunny00.off", meshes / "elephant.off"]


def unit_cube(points):
    """Centre the bounding box at the origin and scale it into [-1, 1]^3."""
    low, high = points.min(axis=0), points.max(axis=0)
    return (points - (low + high) / 2) / ((high - low).max() / 2)


a = pccd.Object(unit_cube(pccd.read_points(files[0])[0]))  # preprocessed once
b = pccd.Object(unit_cube(pccd.read_points(files[1])[0]))
print(f"A: {a.size} points, B: {b.size} points, sampling radii {a.sampling_radius:.4f}, {b.sampling_radius:.4f}")

turn = np.array([[0.0, -1.0, 0.0, 0.5],  # B turned 90 degrees about z and moved 0.5 along x
                 [1.0, 0.0, 0.0, 0.0],
                 [0.0, 0.0, 1.0, 0.0]])
for pose_b in (turn, turn + [[0, 0, 0, 2.5], [0, 0, 0, 0], [0, 0, 0, 0]]):
    hit = pccd.do_intersect(a, None, b, pose_b, seed=7)
    print(f"B at x = {pose_b[0, 3]}: {hit.status}, {hit.counters['f_evaluations']} f evaluations")

curve = pccd.intersection_points(a, None, b, turn, seed=7)
print(f"{len(curve.points)} points on the intersection curves, e.g. {curve.points[0]}")
pccd.write_points("curve.ply", curve.points)
print("wrote curve.ply")
