"""examples/python/dask_many_pairs.py on a LocalCluster of 2 worker processes: its results,
gathered from the workers, equal one pccd.do_intersect_many (intersection_points_many) call over
the same pairs, bit for bit; examples/python/proximity.py prints the exact gaps and depths of its
two spheres; examples/python/contact_time.py the exact first contact times of its spheres;
examples/python/lean_scan.py the exact clearances of a sphere over a floor held as a LeanObject."""

import os
import subprocess
import sys

import numpy as np

import pccd


def run_example(source_dir, tmp, *arguments):
    script = source_dir / "examples" / "python" / "dask_many_pairs.py"
    out = tmp / "results.npz"
    done = subprocess.run([sys.executable, str(script), "--procedural", "--workers", "2", "--work", str(tmp),
                           "--out", str(out), *arguments],
                          capture_output=True, text=True, timeout=600, env=dict(os.environ))
    assert done.returncode == 0, done.stdout + done.stderr
    assert "on 2 workers" in done.stdout, done.stdout
    return np.load(out)


def check_against_batch(saved):
    objects = [pccd.Object.load(f) for f in saved["files"]]
    pairs = [(objects[a], pa, objects[b], pb)
             for a, pa, b, pb in zip(saved["index_a"], saved["pose_a"], saved["index_b"], saved["pose_b"])]
    query = pccd.do_intersect_many if str(saved["mode"]) == "first" else pccd.intersection_points_many
    truth = query(pairs, threads=2, seed=int(saved["seed"]))
    assert 0 < sum(r.intersects for r in truth) < len(truth)
    names = [str(n) for n in saved["counter_names"]]
    offsets = np.concatenate([[0], np.cumsum(saved["point_counts"])])
    for i, r in enumerate(truth):
        assert bool(saved["intersects"][i]) == r.intersects, i
        assert str(saved["status"][i]) == r.status, i
        assert dict(zip(names, saved["counters"][i].tolist())) == r.counters, i
        assert np.array_equal(saved["points"][offsets[i]:offsets[i + 1]], r.points), i


def test_dask_example_equals_do_intersect_many(source_dir, tmp):
    saved = run_example(source_dir, tmp, "--pairs", "150", "--chunk", "16")
    assert len(saved["intersects"]) == 150 and int(saved["workers"]) == 2
    check_against_batch(saved)


def test_dask_example_equals_intersection_points_many(source_dir, tmp):
    saved = run_example(source_dir, tmp, "--pairs", "40", "--chunk", "7", "--mode", "all", "--seed", "5")
    assert saved["points"].shape[0] > 100
    check_against_batch(saved)


def test_readme_quotes_the_quickstart(source_dir):
    """The README's Python example is examples/python/quickstart.py, verbatim."""
    quickstart = (source_dir / "examples" / "python" / "quickstart.py").read_text().rstrip("\n")
    assert "```python\n" + quickstart + "\n```" in (source_dir / "README.md").read_text()


def test_proximity_example_prints_the_exact_gaps_and_depths(source_dir):
    """examples/python/proximity.py: its distances are the spheres' exact gaps (within 3 %, or 0.002
    for the smallest), its depths the exact ones within 10 %, and its batch equals the single calls."""
    script = source_dir / "examples" / "python" / "proximity.py"
    done = subprocess.run([sys.executable, str(script), "--threads", "2"], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    rows = [line.split() for line in done.stdout.splitlines() if line[:5].strip().replace(".", "").isdigit()]
    assert len(rows) == 6, done.stdout
    separate = intersecting = 0
    for row in rows:
        x, gap, distance = float(row[0]), float(row[1]), float(row[2])
        if gap > 0:
            separate += 1
            assert abs(distance - gap) <= max(0.03 * gap, 0.002), row
        else:
            intersecting += 1
            assert distance == 0, row
            depth, exact = float(row[-2]), float(row[-1])
            assert abs(depth - exact) <= 0.1 * exact, row
        assert row[5] == str(gap < 0.1), row  # within the default margin 0.1
    assert separate == 4 and intersecting == 2
    assert "2 threads, the same answers as the single calls" in done.stdout
    assert "contacts at x = 0.75: intersecting" in done.stdout


def test_contact_time_example_prints_the_exact_contact_times(source_dir):
    """examples/python/contact_time.py: its contact times are the exact ones within a spacing of the
    path (0.012 of time), the pass at a gap is no contact, the batch equals the single calls, and
    the discrete poses miss the grazing contact that time_of_contact finds."""
    script = source_dir / "examples" / "python" / "contact_time.py"
    done = subprocess.run([sys.executable, str(script), "--threads", "2"], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    rows = [line.split() for line in done.stdout.splitlines() if line[:4].strip().replace(".", "").isdigit()]
    assert len(rows) == 4, done.stdout
    for row in rows:
        if float(row[0]) < 2:
            assert row[1] == "contact", row
            assert abs(float(row[2]) - float(row[3])) <= 0.012, row
        else:
            assert row[1] == "no_contact", row
    assert "the same answers as the single calls" in done.stdout
    assert "6 discrete poses see contact 0 times; time_of_contact: contact" in done.stdout


def test_lean_scan_example_prints_the_exact_clearances(source_dir):
    """examples/python/lean_scan.py: a sphere (an Object) over a 200,000-point floor (a LeanObject):
    every clearance is the exact gap within 0.001 (a quarter of the floor's spacing of about 0.0045),
    the first pose below the 0.03 margin is the one at gap 0.02, and the lean floor holds at most 250
    bytes per point."""
    script = source_dir / "examples" / "python" / "lean_scan.py"
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "euclidean kernel" in done.stdout and "geodesic kernel" in done.stdout, done.stdout
    per_point = float(done.stdout.split(" bytes per point")[0].split()[-1])
    assert 80 <= per_point <= 250, done.stdout
    rows = [line.split() for line in done.stdout.splitlines() if line[:7].strip().replace(".", "").isdigit()]
    assert len(rows) == 7, done.stdout
    for height, gap, clearance, status in rows:
        assert abs(float(clearance) - float(gap)) <= 0.001, (height, gap, clearance)
        assert status == ("below_margin" if float(gap) < 0.03 else "clear"), (height, status)
    assert "first pose below the margin 0.03: 4" in done.stdout
