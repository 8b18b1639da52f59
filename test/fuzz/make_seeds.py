#!/usr/bin/env python3
"""Writes the hand-made seed inputs of PCCD's fuzz targets (test/fuzz/) into <out>/<target>/.

    python3 test/fuzz/make_seeds.py <out> [--object FILE]

The seeds are small valid files of every variant the readers accept, plus broken ones near the
edge of each check. --object: an object file written by Point_cloud_object::save (of a small
cloud); it becomes the fuzz_load_object seeds, with their mode byte (see fuzz_load_object.cpp),
together with its embedded geodesic section. The fuzz_do_intersect seeds (queries on small
spheres, patches, degenerate clouds, bad poses and refused options) need no argument. The fuzzing
campaign merges these seeds with what the fuzzers find into test/fuzz/corpus/
(doc/reliability.md, "Fuzzing")."""
import argparse
import os
import struct

TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply_header(fmt, vertex_props, faces=None, extra=""):
    h = f"ply\nformat {fmt} 1.0\ncomment seed\nelement vertex 4\n"
    h += "".join(f"property {t} {n}\n" for t, n in vertex_props)
    if faces:
        h += f"element face 4\nproperty list {faces} vertex_indices\n"
    return h + extra + "end_header\n"


def ply_seeds():
    xyz = [("float", "x"), ("float", "y"), ("float", "z")]
    normals = [("float", "nx"), ("float", "ny"), ("float", "nz")]
    s = {}
    body = "".join(f"{x} {y} {z}\n" for x, y, z in TETRA)
    faces = "".join(f"3 {a} {b} {c}\n" for a, b, c in FACES)
    s["ascii_points"] = ply_header("ascii", xyz) + body
    s["ascii_normals"] = ply_header("ascii", xyz + normals) + "".join(f"{x} {y} {z} 0 0 1\n" for x, y, z in TETRA)
    s["ascii_mesh"] = ply_header("ascii", xyz, "uchar int") + body + faces
    s["ascii_mesh_colors"] = (ply_header("ascii", xyz + [("uchar", "red"), ("uchar", "green"), ("uchar", "blue")],
                                         "uchar int")
                              + "".join(f"{x} {y} {z} 255 0 10\n" for x, y, z in TETRA) + faces)
    s["ascii_quad_double"] = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                              "property double z\nelement face 1\nproperty list uchar uint vertex_index\n"
                              "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    s["ascii_extra_element"] = (ply_header("ascii", xyz, "uchar int", "element edge 1\nproperty int vertex1\n"
                                           "property int vertex2\n") + body + faces + "0 1\n")
    # Broken.
    s["bad_magic"] = "plx\nformat ascii 1.0\nend_header\n"
    s["no_end_header"] = ply_header("ascii", xyz).replace("end_header\n", "") + body
    s["negative_count"] = s["ascii_points"].replace("element vertex 4", "element vertex -4")
    s["truncated_ascii"] = s["ascii_mesh"][:-10]
    s["nan_coordinate"] = s["ascii_points"].replace("1 0 0\n", "nan 0 0\n")
    s["index_out_of_range"] = s["ascii_mesh"].replace("3 1 2 3\n", "3 1 2 4\n")
    s["int_coordinates"] = ply_header("ascii", [("int", "x"), ("int", "y"), ("int", "z")]) + body
    s["partial_normals"] = ply_header("ascii", xyz + normals[:2]) + "".join(f"{x} {y} {z} 0 1\n" for x, y, z in TETRA)

    out = {k: v.encode() for k, v in s.items()}
    for name, fmt, order in (("binary_le", "binary_little_endian", "<"), ("binary_be", "binary_big_endian", ">")):
        vb = b"".join(struct.pack(order + "fff", *p) for p in TETRA)
        fb = b"".join(struct.pack(order + "Biii", 3, *f) for f in FACES)
        out[name + "_mesh"] = ply_header(fmt, xyz, "uchar int").encode() + vb + fb
        out[name + "_points_double"] = (ply_header(fmt, [("double", "x"), ("double", "y"), ("double", "z")]).encode()
                                        + b"".join(struct.pack(order + "ddd", *p) for p in TETRA))
    out["binary_truncated"] = out["binary_le_mesh"][:-7]
    out["binary_trailing"] = out["binary_le_mesh"] + b"\0\0"
    out["binary_huge_count"] = out["binary_le_mesh"].replace(b"element face 4", b"element face 400000000")
    out["binary_nan"] = out["binary_le_points_double"][:-8] + struct.pack("<d", float("nan"))
    return out


def off_seeds():
    verts = "".join(f"{x} {y} {z}\n" for x, y, z in TETRA)
    faces = "".join(f"3 {a} {b} {c}\n" for a, b, c in FACES)
    s = {}
    s["off_mesh"] = "OFF\n4 4 6\n" + verts + faces
    s["off_points"] = "OFF\n4 0 0\n" + verts
    s["off_comments"] = "# seed\nOFF # keyword\n4 4 6 # counts\n# vertices\n" + verts + "\n" + faces + "# end\n"
    s["off_header_lines"] = "OFF\n4\n4\n6\n" + verts.replace(" ", "\t") + faces
    s["off_crlf_no_newline"] = ("OFF\n4 4 6\n" + verts + faces).replace("\n", "\r\n").rstrip()
    s["noff"] = "NOFF\n4 4 0\n" + "".join(f"{x} {y} {z} 0 0 1\n" for x, y, z in TETRA) + faces
    s["coff"] = ("COFF\n4 4 0\n" + "".join(f"{x} {y} {z} 255 0 0 255\n" for x, y, z in TETRA)
                 + "".join(f"3 {a} {b} {c} 0.5 0.5 0.5\n" for a, b, c in FACES))
    s["cnoff_index_colors"] = ("CNOFF\n4 4 0\n" + "".join(f"{x} {y} {z} 1 0 0 7\n" for x, y, z in TETRA)
                               + "".join(f"3 {a} {b} {c} 3\n" for a, b, c in FACES))
    s["off_quad"] = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"
    s["off_exponents"] = "OFF\n4 1 0\n1e-320 0 0\n1.5E+3 -0 +2\n.5 5. 0\n-1e300 1 1\n3 0 1 2\n"
    # Broken.
    s["bad_keyword"] = "OFX\n4 4 6\n" + verts + faces
    s["binary_off"] = "OFF BINARY\n4 4 6\n"
    s["missing_count"] = "OFF\n4 4\n"
    s["negative_count"] = "OFF\n-4 4 6\n" + verts + faces
    s["huge_count"] = "OFF\n2147483647 1 0\n0 0 0\n3 0 0 0\n"
    s["truncated"] = "OFF\n4 4 6\n" + verts + faces[:-8]
    s["extra_data"] = "OFF\n4 4 6\n" + verts + faces + "1 2 3\n"
    s["bad_number"] = "OFF\n4 0 0\n" + verts.replace("1 0 0", "1 0x1 0")
    s["inf_coordinate"] = "OFF\n4 0 0\n" + verts.replace("1 0 0", "inf 0 0")
    s["overflow"] = "OFF\n4 0 0\n" + verts.replace("1 0 0", "1e400 0 0")
    s["face_out_of_range"] = "OFF\n4 1 0\n" + verts + "3 0 1 9\n"
    s["face_too_small"] = "OFF\n4 1 0\n" + verts + "2 0 1\n"
    s["bad_color"] = "COFF\n4 0 0\n" + "".join(f"{x} {y} {z} 300 0 0\n" for x, y, z in TETRA)
    s["inconsistent_colors"] = "COFF\n4 0 0\n" + verts.replace("1 0 0\n", "1 0 0 1 0 0\n", 1)
    s["skel"] = "SKEL\n4 0\n" + verts
    return {k: v.encode() for k, v in s.items()}


def xyz_seeds():
    pts = "".join(f"{x} {y} {z}\n" for x, y, z in TETRA)
    s = {}
    s["points"] = pts
    s["normals"] = "".join(f"{x} {y} {z} 0 0 1\n" for x, y, z in TETRA)
    s["count_line"] = "4\n" + pts
    s["comments_blank"] = "# seed\n\n" + pts.replace("\n", " # c\n", 2) + "\t\n"
    s["crlf_tabs_no_newline"] = pts.replace(" ", "\t").replace("\n", "\r\n").rstrip()
    s["exponents"] = "1e-320 +0 -0\n1.5E+3 .5 5.\n-1e300 1 1\n"
    # Broken.
    s["count_too_large"] = "5\n" + pts
    s["count_too_small"] = "3\n" + pts
    s["negative_count"] = "-4\n" + pts
    s["two_numbers"] = "0 0\n"
    s["mixed_normals"] = pts + "1 1 1 0 0 1\n"
    s["nan"] = pts + "nan 0 0\n"
    s["overflow"] = pts + "1e999 0 0\n"
    s["hex"] = "0x1 0 0\n"
    s["only_comments"] = "# nothing\n#\n"
    s["ply_magic"] = "ply\nformat ascii 1.0\n"
    return {k: v.encode() for k, v in s.items()}


def object_seeds(path):
    data = open(path, "rb").read()
    n = struct.unpack_from("<Q", data, 16)[0]
    at = 8 + 4 + 4 + 8 + 3 * 8 + 1 + 3 * 8 + 5 * 8 + 6 * 8 * n
    g = struct.unpack_from("<Q", data, at)[0]
    geodesic = data[at + 8: at + 8 + g]
    return {
        "object": b"\x00" + data,
        "object_repair": b"\x02" + data,
        "object_truncated": b"\x00" + data[:-9],
        "geodesic": b"\x01" + geodesic,
        "geodesic_repair": b"\x03" + geodesic,
        "geodesic_bad_magic": b"\x01" + b"PCCDGEX" + geodesic[7:],
        "object_bad_version": b"\x02" + data[:8] + b"\x02" + data[9:],
    }


def do_intersect_query(rst=False, all_points=False, symmetric=True, object_boxes=False, refinement=2,
                       epsilon=None, budget=None, spacing=None, knn=False, random_partners=False, samples=None,
                       seed=7, refinement_samples=16, min_samples=20, max_samples=60, partners=4,
                       rst_max=300, leaf_size=16, radius_samples=60):
    """The query part of a fuzz_do_intersect input (layout: fuzz_do_intersect.cpp). epsilon and
    spacing: None (unset), an int (a selector byte, 2^(s/8 - 16)) or a float (raw double)."""
    def value(v):
        if v is None or isinstance(v, int):
            return struct.pack("<Bd", v or 0, 0.0)
        return struct.pack("<Bd", 255, v)
    flags = (rst | all_points << 1 | symmetric << 2 | object_boxes << 3 | refinement << 4
             | (epsilon is not None) << 6 | (budget is not None) << 7)
    more = (spacing is not None) | knn << 1 | random_partners << 2 | (samples is not None) << 3
    return (bytes([flags, more]) + struct.pack("<Q", seed) + value(epsilon) + struct.pack("<H", budget or 0)
            + value(spacing) + bytes([refinement_samples, min_samples, max_samples, samples or 0, partners])
            + struct.pack("<H", rst_max) + bytes([leaf_size, radius_samples]))


def sphere_cloud(n, centre=(0, 0, 0), radius_byte=48, jitter=0, bad=None):
    """Kind 3: radius 0.25 + radius_byte / 64 (48: 1.0), centre in sixteenths; bad = (index, axis,
    which) corrupts one point (which: NaN, inf, -inf, 1e300, max)."""
    kind = 3 | (8 if bad else 0)
    out = bytes([kind, n]) + struct.pack("<bbbB", *centre, radius_byte)
    out += bytes([(jitter * (i % 3 - 1)) & 0xFF for i in range(n)])
    return out + (bytes(bad) if bad else b"")


def patch_cloud(n, spacing_byte=12, heights=0):
    return bytes([4, n, spacing_byte]) + bytes([(heights * (i % 5 - 2)) & 0xFF for i in range(n)])


def pose(tx=0, ty=0, tz=0, quaternion=(0, 0, 0, 0), kind=0, perturb=None):
    """Quaternion pose; translation in 1/4096 (scale byte 8); kind 2 adds perturb (k, 9 int8)."""
    out = bytes([kind]) + struct.pack("<hhhhBhhh", *quaternion, 8, tx, ty, tz)
    if kind == 2:
        out += bytes([perturb[0]]) + struct.pack("<9b", *perturb[1])
    return out


def do_intersect_seeds():
    one = 4096
    sphere = sphere_cloud(120)
    s = {}
    s["spheres_overlap"] = do_intersect_query() + sphere + sphere + pose() + pose(one)
    s["spheres_separate"] = do_intersect_query() + sphere + sphere + pose() + pose(3 * one)
    s["spheres_identical"] = do_intersect_query(all_points=True) + sphere + sphere + pose() + pose()
    s["spheres_overlap_all_none"] = do_intersect_query(all_points=True, refinement=0) + sphere + sphere + pose() + pose(one)
    s["spheres_overlap_all_sampling"] = (do_intersect_query(all_points=True, refinement=1, knn=True)
                                         + sphere + sphere + pose() + pose(one, one // 2))
    s["spheres_rst"] = do_intersect_query(rst=True) + sphere + sphere + pose() + pose(one)
    s["spheres_rst_all_object_boxes"] = (do_intersect_query(rst=True, all_points=True, object_boxes=True)
                                         + sphere + sphere_cloud(80, jitter=20) + pose() + pose(one))
    s["spheres_budget"] = (do_intersect_query(all_points=True, budget=37, random_partners=True)
                           + sphere + sphere + pose(quaternion=(1000, 200, 0, 3000)) + pose(one))
    s["spheres_epsilon_spacing"] = (do_intersect_query(all_points=True, epsilon=100, spacing=130, samples=40)
                                    + sphere + sphere + pose() + pose(one))
    s["patch_sphere"] = (do_intersect_query(all_points=True, symmetric=False)
                         + patch_cloud(144, heights=3) + sphere_cloud(100, centre=(9, 9, 0), radius_byte=16)
                         + pose() + pose())
    s["patch_patch_tilted"] = (do_intersect_query(rst=True) + patch_cloud(100) + patch_cloud(100)
                               + pose() + pose(one // 4, one // 4, -one // 3, (3000, 3000, 0, 0)))
    s["lattice_duplicates"] = (do_intersect_query() + bytes([2 | 16, 60, 40]) + bytes(range(0, 180))
                               + sphere + pose() + pose())
    s["segment_collinear"] = do_intersect_query() + bytes([5, 50, 1, 2, 3, 16]) + sphere + pose() + pose()
    s["raw_float"] = (do_intersect_query() + bytes([1, 4]) + struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
                      + sphere + pose() + pose())
    s["nan_point"] = do_intersect_query() + sphere_cloud(50, bad=(7, 1, 0)) + sphere + pose() + pose()
    s["huge_point"] = do_intersect_query() + sphere_cloud(50, bad=(7, 2, 3)) + sphere + pose() + pose()
    s["single_point"] = do_intersect_query() + sphere_cloud(1) + sphere + pose() + pose()
    s["pose_raw_nan"] = (do_intersect_query() + sphere + sphere + bytes([3])
                         + struct.pack("<12d", 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, float("nan"), 0) + pose())
    s["pose_raw_identity"] = (do_intersect_query() + sphere + sphere + bytes([3])
                              + struct.pack("<12d", 1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0) + pose())
    s["pose_perturbed"] = (do_intersect_query() + sphere + sphere + pose() +
                           pose(one, kind=2, perturb=(3, (1, -1, 0, 0, 2, 0, -3, 0, 1))))
    s["options_bad_epsilon"] = do_intersect_query(epsilon=-1.0) + sphere + sphere + pose() + pose(one)
    s["options_nan_spacing"] = (do_intersect_query(all_points=True, spacing=float("nan"))
                                + sphere + sphere + pose() + pose(one))
    s["options_zero_budget"] = do_intersect_query(budget=0) + sphere + sphere + pose() + pose(one)
    s["options_bad_refinement"] = (do_intersect_query(all_points=True, refinement=3)
                                   + sphere + sphere + pose() + pose(one))
    s["policy_bad_samples"] = do_intersect_query(min_samples=50, max_samples=10) + sphere + sphere + pose() + pose(one)
    s["leaf_size_zero"] = do_intersect_query(leaf_size=0) + sphere + sphere + pose() + pose(one)
    return s


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--object")
    args = parser.parse_args()
    targets = {"fuzz_read_ply": ply_seeds(), "fuzz_read_off": off_seeds(), "fuzz_read_xyz": xyz_seeds(),
               "fuzz_do_intersect": do_intersect_seeds()}
    if args.object:
        targets["fuzz_load_object"] = object_seeds(args.object)
    for target, seeds in targets.items():
        os.makedirs(os.path.join(args.out, target), exist_ok=True)
        for name, content in seeds.items():
            with open(os.path.join(args.out, target, "seed_" + name), "wb") as f:
                f.write(content)


if __name__ == "__main__":
    main()
