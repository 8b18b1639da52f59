"""pccd.Object from an Open3D point cloud (Debian's python3-open3d): the same object as from its
points as an array, its normals taken as hints; and examples/python/open3d_distance.py runs. ctest
lists the file as skipped, saying why, when Open3D was not found at configure time."""

import os
import subprocess
import sys

import numpy as np
import pytest

import pccd
from conftest import sphere_points

try:
    import open3d as o3d
except ImportError:  # ctest registers this file as skipped when Open3D was absent at configure time
    pytest.fail("Open3D was found at configure time but does not import now (Debian: python3-open3d)",
                pytrace=False)


def test_object_from_an_open3d_point_cloud():
    points = sphere_points(1200)
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    assert not cloud.has_normals()
    from_cloud = pccd.Object(cloud)
    from_array = pccd.Object(points)
    assert not from_cloud.normals_given
    assert np.array_equal(from_cloud.points, from_array.points)
    assert np.array_equal(from_cloud.normals, from_array.normals)
    # With normals: taken as hints (inward normals flip the orientation).
    cloud.normals = o3d.utility.Vector3dVector(-points / np.linalg.norm(points, axis=1, keepdims=True))
    with_normals = pccd.Object(cloud)
    assert with_normals.normals_given
    inward = np.einsum("ij,ij->i", with_normals.normals, with_normals.points)
    assert (inward < 0).mean() > 0.99
    # Explicit normals win over the cloud's.
    assert pccd.Object(cloud, None).normals_given  # None: the cloud's normals
    outward = pccd.Object(cloud, points)
    assert (np.einsum("ij,ij->i", outward.normals, outward.points) > 0).mean() > 0.99
    # The Vector3dVector itself exposes the buffer protocol.
    assert np.array_equal(pccd.Object(cloud.points).points, from_array.points)


def test_an_empty_open3d_cloud_is_a_valueerror():
    with pytest.raises(ValueError, match="empty|two points|at least"):
        pccd.Object(o3d.geometry.PointCloud())


def test_the_open3d_example_runs(source_dir, bunny_file):
    script = source_dir / "examples" / "python" / "open3d_distance.py"
    done = subprocess.run([sys.executable, str(script), "--meshes", str(bunny_file.parent), "--shifts", "0.5", "3"],
                          capture_output=True, text=True, timeout=600, env=dict(os.environ))
    assert done.returncode == 0, done.stdout + done.stderr
    rows = [line.split() for line in done.stdout.splitlines()[2:]]
    assert [row[1] for row in rows] == ["intersecting", "separate"], done.stdout
    assert float(rows[0][3]) < float(rows[1][3])  # Open3D's smallest distance grows with the shift
