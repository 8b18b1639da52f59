"""`pip install --no-build-isolation` of the source tree, offline, into a virtual environment with
the system's site packages (Debian's setuptools, pybind11 and numpy), then the installed module
(with its type stubs) runs the quickstart from outside the source tree. A few minutes: the
extension is compiled from scratch (setup.py)."""

import os
import shutil
import subprocess
import sys

import pytest

from conftest import sphere_points


def test_pip_install_then_quickstart(source_dir, tmp):
    work = tmp / "pip"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    # A copy of what the package needs, so that setuptools' scratch files stay out of the sources.
    src = work / "src"
    src.mkdir()
    for name in ("setup.py", "pyproject.toml"):
        shutil.copy2(source_dir / name, src / name)
    shutil.copytree(source_dir / "include", src / "include")
    shutil.copytree(source_dir / "python", src / "python", ignore=shutil.ignore_patterns("__pycache__"))
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    venv = work / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True, env=env, timeout=300)
    python = venv / "bin" / "python"
    done = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation", "--no-index", str(src)],
                          env=env, cwd=work, capture_output=True, text=True, timeout=1500)
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-4000:]
    check = ("import pathlib, pccd, pccd._pccd as m; "
             "p = pathlib.Path(m.__file__); "
             "assert (p.with_name('_pccd.pyi')).is_file() and (p.with_name('py.typed')).is_file(); "
             "print(p)")
    done = subprocess.run([str(python), "-c", check], env=env, cwd=work, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert str(venv) in done.stdout, done.stdout  # the installed module, not the build tree's
    # The quickstart, run from outside the source tree: on libcgal-demo's scans when present,
    # else on two procedural clouds written here.
    data = os.environ.get("PCCD_DATA_DIR", "")
    arguments = []
    if not data:
        import pccd
        pccd.write_points(work / "a.xyz", sphere_points(1500))
        pccd.write_points(work / "b.xyz", sphere_points(1500, seed=5))
        arguments = [str(work / "a.xyz"), str(work / "b.xyz")]
    done = subprocess.run([str(python), str(source_dir / "examples" / "python" / "quickstart.py"), "--out", str(work),
                           *arguments], env=env, cwd=work, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "intersecting" in done.stdout and (work / "curve.ply").is_file()
