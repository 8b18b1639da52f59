"""examples/python/quickstart.py on libcgal-demo's bunny and elephant (the README's Python
example): it runs, prints both answers, and the curve it saves is the one intersection_points
returns for the same scans and pose."""

import subprocess
import sys

import numpy as np

import pccd


def unit_cube(points):
    low, high = points.min(axis=0), points.max(axis=0)
    return (points - (low + high) / 2) / ((high - low).max() / 2)


def test_quickstart_runs_and_saves_the_curve(source_dir, bunny_file, tmp):
    script = source_dir / "examples" / "python" / "quickstart.py"
    done = subprocess.run([sys.executable, str(script), "--out", str(tmp)], cwd=tmp, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "B at x = 0.5: intersecting" in done.stdout
    assert "B at x = 3.0: separate" in done.stdout
    curve, _ = pccd.read_points(tmp / "curve.ply")
    a = pccd.Object(unit_cube(pccd.read_points(bunny_file)[0]))
    b = pccd.Object(unit_cube(pccd.read_points(bunny_file.parent / "elephant.off")[0]))
    turn = np.array([[0.0, -1.0, 0.0, 0.5], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])
    expected = pccd.intersection_points(a, None, b, turn, seed=7)
    assert len(expected.points) > 10
    assert np.array_equal(curve, expected.points)
