"""Poses as users write them: one tolerance rule for the library, the pccd tool and the module
(R^T R - I within 1e-5 per entry, det R > 0; a 4x4 pose's last row within 1e-5 of 0 0 0 1), so a
rotation printed with 6 decimals is always accepted; error messages with the values in full; and
the opt-in pccd.orthonormalize (nearest rotation by SVD) that says how far it moved the matrix."""

import re
import subprocess

import numpy as np
import pytest

import pccd
from conftest import pose, rotation, sphere_points

TOLERANCE = 1e-5


def random_rotations(count, seed):
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(count, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], axis=-1),
        np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], axis=-1),
        np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=1)


def printed(matrix, decimals):
    """The matrix as a program printing it with %.{decimals}f writes it, read back."""
    return np.array([[float(f"{v:.{decimals}f}") for v in row] for row in matrix])


def test_rotations_printed_with_6_decimals_are_accepted(shapes):
    sphere, torus = shapes
    rotations = random_rotations(200, seed=32)
    refused_by_the_former_rule = 0
    for r in rotations:
        six = printed(r, 6)
        off = np.abs(six.T @ six - np.eye(3)).max()
        assert off < 1.8e-6  # the bound the documented rule rests on
        refused_by_the_former_rule += off > 1e-6
        result = pccd.do_intersect(sphere, None, torus, np.hstack([six, [[3.0], [0.0], [0.0]]]), seed=1)
        assert result.status == "separate"
    assert refused_by_the_former_rule > 10  # about 40 of 200 were refused with a tolerance of 1e-6


def test_a_4x4_last_row_within_the_tolerance_is_accepted(shapes):
    sphere, torus = shapes
    p = np.vstack([pose((0, 0, 1), 0.3, (3, 0, 0)), [0.0, 0.0, 0.0, 1.0 + 1e-12]])
    assert pccd.do_intersect(sphere, None, torus, p).status == "separate"
    p[3, 3] = 1.00001234567  # 6 digits would print 1.000012
    with pytest.raises(ValueError, match=r"last row .*within 1e-05.*got \[0, 0, 0, 1.00001234567\]"):
        pccd.do_intersect(sphere, None, torus, p)
    p[3] = [1e-4, 0.0, 0.0, 1.0]
    with pytest.raises(ValueError, match=r"got \[1e-04, 0, 0, 1\]"):
        pccd.do_intersect(sphere, None, torus, p)


def test_refusals_print_the_values_in_full(shapes):
    sphere, torus = shapes
    r = np.eye(3)
    r[1, 1] = 1.0000123456789
    with pytest.raises(ValueError) as error:
        pccd.do_intersect(sphere, None, torus, np.hstack([r, np.zeros((3, 1))]))
    message = str(error.value)
    assert "column 1 has length 1.0000123456789," in message
    assert "tolerance 1e-05" in message
    assert "has length 1, not 1" not in message
    assert "pccd.orthonormalize" in message  # says what to do about it


def test_orthonormalize_returns_the_nearest_rotation_and_how_far_it_moved():
    r = rotation((1, -2, 0.5), 0.7)
    three = printed(r, 3)
    fixed, moved = pccd.orthonormalize(np.hstack([three, [[1.0], [2.0], [3.0]]]))
    assert fixed.shape == (3, 4) and fixed.dtype == np.float64
    q = fixed[:, :3]
    assert np.abs(q.T @ q - np.eye(3)).max() < 2e-15
    assert abs(np.linalg.det(q) - 1) < 2e-15
    assert np.array_equal(fixed[:, 3], [1.0, 2.0, 3.0])
    assert moved == pytest.approx(np.abs(q - three).max(), rel=1e-12)
    assert 0 < moved < 1e-3
    # The nearest rotation (Frobenius): numpy's SVD agrees.
    u, _, vt = np.linalg.svd(three)
    assert np.abs(q - u @ vt).max() < 1e-14
    # 4x4 in, 4x4 out; an exact rotation does not move.
    fixed4, moved4 = pccd.orthonormalize(np.vstack([np.hstack([r, np.zeros((3, 1))]), [0, 0, 0, 1]]))
    assert fixed4.shape == (4, 4) and np.array_equal(fixed4[3], [0, 0, 0, 1])
    assert moved4 < 1e-15
    # The repaired pose is accepted by the queries.
    sphere = pccd.Object(sphere_points(400))
    assert pccd.do_intersect(sphere, None, sphere, fixed).intersects in (True, False)
    with pytest.raises(ValueError):
        pccd.do_intersect(sphere, None, sphere, np.hstack([three, [[1.0], [2.0], [3.0]]]))


@pytest.mark.parametrize(
    "bad, error, message",
    [
        (np.hstack([np.diag([1.0, 1.0, -1.0]), np.zeros((3, 1))]), ValueError, "reflection"),
        (np.hstack([np.diag([1.0, 1.0, 0.0]), np.zeros((3, 1))]), ValueError, "singular"),
        (np.hstack([np.eye(3), [[np.nan], [0], [0]]]), ValueError, r"entry \(0, 3\) is nan"),
        (np.eye(3), ValueError, "shape"),
        (None, TypeError, "None"),
    ],
)
def test_orthonormalize_refuses_what_has_no_nearest_rotation(bad, error, message):
    with pytest.raises(error, match=message):
        pccd.orthonormalize(bad)


def numbers(matrix):
    return [f"{v:.6f}" for v in np.asarray(matrix).ravel()]


def test_the_cli_applies_the_same_rule(cli, tmp):
    pccd.write_points(tmp / "sphere.xyz", sphere_points(600))
    rotations = random_rotations(40, seed=7)
    for r in rotations:
        six = printed(r, 6)
        if np.abs(six.T @ six - np.eye(3)).max() > 1e-6:
            break
    else:
        pytest.fail("no rotation in the sample needed the new tolerance")
    arguments = numbers(np.hstack([six, [[3.0], [0.0], [0.0]]]))
    done = subprocess.run([str(cli), "collide", "sphere.xyz", "sphere.xyz", "--transform-b", *arguments],
                          cwd=tmp, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "separate" in done.stdout
    # Off by more than the tolerance: refused, with full digits and the way out.
    three = numbers(np.hstack([printed(rotations[0], 2), [[3.0], [0.0], [0.0]]]))
    done = subprocess.run([str(cli), "collide", "sphere.xyz", "sphere.xyz", "--transform-b", *three],
                          cwd=tmp, capture_output=True, text=True, timeout=300)
    assert done.returncode != 0
    assert "--transform-b: rigid transform" in done.stderr and "--orthonormalize" in done.stderr, done.stderr
    assert re.search(r"tolerance 1e-05", done.stderr), done.stderr
    done = subprocess.run([str(cli), "collide", "sphere.xyz", "sphere.xyz", "--orthonormalize", "--transform-b", *three],
                          cwd=tmp, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    moved = re.search(r"--transform-b: orthonormalized, the rotation moved by (\S+)", done.stderr)
    assert moved, done.stderr
    expected = pccd.orthonormalize(np.hstack([printed(rotations[0], 2), [[3.0], [0.0], [0.0]]]))[1]
    assert float(moved.group(1)) == expected
