"""Same answers and counters as the C++ calls: the Python module and the pccd tool (`pccd collide
--json`, which calls PCCD::do_intersect / intersection_points on objects preprocessed from the same
file) agree exactly, on procedural clouds written to files, for both leaf intersectors, both modes,
several poses and seeds, with and without normals in the file."""

import json
import subprocess

import numpy as np
import pytest

import pccd
from conftest import pose, sphere_points, torus_points

POSES = [
    pose((1, 1, 0), 0.4, (0.9, 0.0, 0.0)),  # across the torus tube
    pose((0, 1, 0), 1.1, (0.0, 0.0, 0.55)),  # resting on the hole
    pose((0, 0, 1), 0.0, (2.5, 0.0, 0.0)),  # apart
]


def run_cli(cli, file_a, file_b, pose_b, method, mode, seed, out=None):
    numbers = " ".join(repr(float(x)) for x in np.asarray(pose_b).reshape(-1))
    command = [str(cli), "collide", str(file_a), str(file_b), f"--transform-b={numbers}", "--method", method,
               "--mode", mode, "--seed", str(seed), "--json"]
    if out is not None:
        command += ["--out", str(out)]
    done = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def check_agreement(cli, tmp, file_a, file_b, a, b, seed_base):
    for k, p in enumerate(POSES):
        for method in ("isearch", "rst"):
            for mode in ("first", "all"):
                seed = seed_base + k
                curve = tmp / f"curve_{k}_{method}_{mode}.ply"
                expected = run_cli(cli, file_a, file_b, p, method, mode, seed, curve)
                query = pccd.do_intersect if mode == "first" else pccd.intersection_points
                got = query(a, None, b, p, method=method, seed=seed)
                where = f"pose {k}, {method}, {mode}"
                assert got.intersects == expected["intersects"], where
                assert got.status == expected["status"], where
                assert len(got.points) == expected["points"], where
                for name, value in got.counters.items():
                    assert value == expected[name], f"{where}: {name}"
                if got.intersects:
                    assert got.points[0].tolist() == expected["first_point"], where
                    written, _ = pccd.read_points(curve)  # 17 digits: the C++ points exactly
                    assert np.array_equal(got.points, written), where


def test_same_answers_as_the_cli(cli, tmp):
    file_a, file_b = tmp / "torus.xyz", tmp / "sphere.xyz"
    pccd.write_points(file_a, torus_points(3000))
    pccd.write_points(file_b, sphere_points(2000))
    a = pccd.Object(pccd.read_points(file_a)[0])
    b = pccd.Object(pccd.read_points(file_b)[0])
    check_agreement(cli, tmp, file_a, file_b, a, b, 100)


def test_same_answers_as_the_cli_with_normals(cli, tmp):
    """Normals in the file are hints in both (here pointing inwards: the orientation follows)."""
    points = sphere_points(2000, radius=0.6, seed=5)
    file_a, file_b = tmp / "torus.xyz", tmp / "sphere_normals.xyz"
    pccd.write_points(file_a, torus_points(3000, seed=6))
    pccd.write_points(file_b, points, -points)
    p, n = pccd.read_points(file_b)
    assert n is not None
    a = pccd.Object(pccd.read_points(file_a)[0])
    b = pccd.Object(p, normals=n)
    assert np.all(np.einsum("ij,ij->i", b.normals, p[b.input_indices]) < 0)
    check_agreement(cli, tmp, file_a, file_b, a, b, 200)


def test_cli_and_module_report_the_same_file_errors(cli, tmp):
    (tmp / "bad.off").write_text("OFF\n3 0 0\n0 0 0\n1 1\n")
    done = subprocess.run([str(cli), "collide", str(tmp / "bad.off"), str(tmp / "bad.off")],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1
    message = done.stderr.strip().removeprefix("pccd: error: ")
    with pytest.raises(OSError) as error:
        pccd.read_points(tmp / "bad.off")
    assert str(error.value) == message
