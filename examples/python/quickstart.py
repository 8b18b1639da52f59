"""Two scans, one collision query, one intersection curve: the Python quickstart of PCCD.

Run from the source tree after building, with the interpreter the module was built for:
    build/pccd-python examples/python/quickstart.py [--out DIR] [SCAN_A SCAN_B]
(or python3 after `pip install`). Without scans it takes libcgal-demo's bunny and elephant from
$PCCD_DATA_DIR or build/cgal-data, each scaled into [-1, 1]^3. The curve goes to DIR/curve.ply,
by default into a new temporary directory.
"""
import argparse
import os
import pathlib
import tempfile

import numpy as np

import pccd

meshes = pathlib.Path(os.environ.get("PCCD_DATA_DIR") or pathlib.Path(__file__).resolve().parents[2] / "build/cgal-data/data/meshes")
parser = argparse.ArgumentParser(description="Collide two scans with pccd and save their intersection curve.")
parser.add_argument("scans", nargs="*", default=[meshes / "bunny00.off", meshes / "elephant.off"])
parser.add_argument("--out", help="directory of curve.ply (default: a new temporary directory)")
args = parser.parse_args()


def unit_cube(points):
    """Centre the bounding box at the origin and scale it into [-1, 1]^3."""
    low, high = points.min(axis=0), points.max(axis=0)
    return (points - (low + high) / 2) / ((high - low).max() / 2)


a = pccd.Object(unit_cube(pccd.read_points(args.scans[0])[0]))  # preprocessed once
b = pccd.Object(unit_cube(pccd.read_points(args.scans[1])[0]))
print(f"A: {a.size} points, B: {b.size} points, sampling radii {a.sampling_radius:.4f}, {b.sampling_radius:.4f}")

turn = np.array([[0.0, -1.0, 0.0, 0.5],  # B turned 90 degrees about z and moved 0.5 along x
                 [1.0, 0.0, 0.0, 0.0],
                 [0.0, 0.0, 1.0, 0.0]])
for pose_b in (turn, turn + [[0, 0, 0, 2.5], [0, 0, 0, 0], [0, 0, 0, 0]]):
    hit = pccd.do_intersect(a, None, b, pose_b, seed=7)
    print(f"B at x = {pose_b[0, 3]}: {hit.status}, {hit.counters['f_evaluations']} f evaluations")

curve = pccd.intersection_points(a, None, b, turn, seed=7)
print(f"{len(curve.points)} points on the intersection curves, e.g. {curve.points[0]}")
out = pathlib.Path(args.out or tempfile.mkdtemp(prefix="pccd-quickstart-")) / "curve.ply"
out.parent.mkdir(parents=True, exist_ok=True)
pccd.write_points(out, curve.points)
print("wrote", out)
