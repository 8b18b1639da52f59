#!/usr/bin/env python3
"""The include graph of include/PCCD keeps the library's stages in order (doc/design.md, "Stages").

Every header belongs to one stage; a header may include headers of its own stage and of earlier
stages only, and the units (the folders directly under include/PCCD, and the headers at its top)
include each other in no cycle. Prints each violation and exits 1 if there is any.
Usage: check_layers.py <include/PCCD>
"""
import pathlib
import re
import sys

# The stages in order, each a list of paths under include/PCCD: a folder (ending in "/"), a file,
# or a file-name prefix (ending in "*").
STAGES = [
    ("ground", ["Error.h", "version.h", "Point_traits.h", "Identity_point_map.h", "Eigen_kernel.h",
                "concepts/", "internal/", "Random.h", "Rigid_transform_3.h", "Kd_tree.h", "IO/",
                "Point_cloud.h", "sampling_radius_options.h", "sampling_radius.h", "Similarity_3.h",
                "sample_triangle_mesh.h"]),
    ("proximity graphs", ["Proximity_graph/"]),
    ("geodesics", ["Geodesic/"]),
    ("surface", ["Surface/"]),
    ("hierarchy", ["Hierarchy/"]),
    ("object", ["Point_cloud_object*", "Euclidean_point_cloud_object*", "make_point_cloud_object.h", "object_file_info.h",
                "sharp_feature_options.h"]),
    ("intersection", ["Intersection/"]),
    ("proximity", ["Proximity/"]),
    ("continuous", ["Continuous/"]),
    ("world", ["World/"]),
    ("kinetic", ["Kinetic/"]),
    ("exact", ["Exact/"]),
    ("umbrella", ["PCCD.h"]),
]


def stage_of(path):
    for index, (_, patterns) in enumerate(STAGES):
        for p in patterns:
            if p.endswith("/") and path.startswith(p):
                return index
            if p.endswith("*") and path.startswith(p[:-1]) and "/" not in path:
                return index
            if path == p:
                return index
    return None


def unit_of(path):
    return path.split("/")[0] + "/" if "/" in path else path


def main(root):
    root = pathlib.Path(root)
    problems = []
    edges = {}
    headers = sorted(root.rglob("*.h"))
    if not headers:
        print(f"no headers under {root}")
        return 1
    for header in headers:
        path = header.relative_to(root).as_posix()
        stage = stage_of(path)
        if stage is None:
            problems.append(f"{path}: belongs to no stage (add it to STAGES and doc/design.md)")
            continue
        for target in re.findall(r"^\s*#\s*include\s*<PCCD/([^>]+)>", header.read_text(), re.M):
            to = stage_of(target)
            if to is not None and to > stage:
                problems.append(f"{path} ({STAGES[stage][0]}) includes {target} ({STAGES[to][0]}), a later stage")
            if unit_of(target) != unit_of(path):
                edges.setdefault(unit_of(path), set()).add(unit_of(target))
    # Cycles between units: Tarjan's strongly connected components.
    index, low, on_stack, stack, order = {}, {}, set(), [], [0]

    def connect(v):
        index[v] = low[v] = order[0]
        order[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                problems.append("include cycle between " + ", ".join(sorted(component)))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            connect(v)
    for p in problems:
        print(p)
    print(f"{len(headers)} headers, {sum(len(e) for e in edges.values())} include edges between units, "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "include/PCCD"))
