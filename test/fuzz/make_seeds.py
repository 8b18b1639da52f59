#!/usr/bin/env python3
"""Writes the hand-made seed inputs of PCCD's fuzz targets (test/fuzz/) into <out>/<target>/.

    python3 test/fuzz/make_seeds.py <out> [--object FILE]

The seeds are small valid files of every variant the readers accept, plus broken ones near the
edge of each check. --object: an object file written by Point_cloud_object::save (of a small
cloud); it becomes the fuzz_load_object seeds, with their mode byte (see fuzz_load_object.cpp),
together with its embedded geodesic section. The fuzzing campaign merges these seeds with what the
fuzzers find into test/fuzz/corpus/ (doc/reliability_fuzzing.md)."""
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out")
    parser.add_argument("--object")
    args = parser.parse_args()
    targets = {"fuzz_read_ply": ply_seeds(), "fuzz_read_off": off_seeds(), "fuzz_read_xyz": xyz_seeds()}
    if args.object:
        targets["fuzz_load_object"] = object_seeds(args.object)
    for target, seeds in targets.items():
        os.makedirs(os.path.join(args.out, target), exist_ok=True)
        for name, content in seeds.items():
            with open(os.path.join(args.out, target, "seed_" + name), "wb") as f:
                f.write(content)


if __name__ == "__main__":
    main()
