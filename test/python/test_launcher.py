"""build/pccd-python runs the interpreter the module was built for, with the built package on
PYTHONPATH: the quickstart runs through it even when another python3 (here one that cannot import
numpy) comes first on PATH, where `PYTHONPATH=build/python python3 ...` fails."""

import os
import pathlib
import subprocess

import pccd
from conftest import sphere_points


def test_the_launcher_ignores_another_python3_first_on_path(source_dir, tmp):
    launcher = pathlib.Path(pccd.__file__).resolve().parents[2] / "pccd-python"
    assert launcher.is_file() and os.access(launcher, os.X_OK), f"{launcher} is missing"
    fake = tmp / "bin"
    fake.mkdir()
    (fake / "python3").write_text("#!/bin/sh\necho \"ModuleNotFoundError: No module named 'numpy'\" >&2\nexit 1\n")
    (fake / "python3").chmod(0o755)
    env = dict(os.environ, PATH=f"{fake}:{os.environ['PATH']}")
    env.pop("PYTHONPATH", None)
    # The trap is real: the python3 first on PATH fails.
    assert subprocess.run(["python3", "-c", "import numpy"], env=env, capture_output=True).returncode != 0
    pccd.write_points(tmp / "a.xyz", sphere_points(1500))
    pccd.write_points(tmp / "b.xyz", sphere_points(1500, seed=5))
    done = subprocess.run([str(launcher), str(source_dir / "examples" / "python" / "quickstart.py"), "--out", str(tmp),
                           str(tmp / "a.xyz"), str(tmp / "b.xyz")],
                          env=env, cwd=tmp, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert (tmp / "curve.ply").is_file()
