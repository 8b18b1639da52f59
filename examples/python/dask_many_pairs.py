"""Many object pairs on a Dask cluster: collision checks past one machine with pccd.

The objects are preprocessed once, here, and saved (Object.save); the files' bytes are sent to
every worker once (Client.scatter with broadcast), and each worker process loads each object once
(Object.load) and keeps it. The pairs -- names of objects and 3x4 poses -- are cut into chunks;
each chunk is one task that answers its pairs with pccd.do_intersect_many (first_index = the
chunk's start, so pair i is seeded as pair i of the whole batch), and the results are gathered in
input order. They equal, bit for bit, one pccd.do_intersect_many call over all the pairs.

    build/pccd-python examples/python/dask_many_pairs.py --pairs 2000
starts a LocalCluster of 2 worker processes on this machine (127.0.0.1). On a real cluster, start
`dask scheduler` on one machine and `dask worker tcp://SCHEDULER:8786 --nthreads 1` on each of the
others (each with numpy, dask.distributed and pccd importable), then pass
`--scheduler tcp://SCHEDULER:8786`. doc/manual/python.md, "Scaling out", says more.
"""
import argparse
import hashlib
import os
import pathlib
import sys
import tempfile
import time

import numpy as np

import pccd

# --- the objects and the pairs ---------------------------------------------------------------------


def unit_cube(points):
    low, high = points.min(axis=0), points.max(axis=0)
    return (points - (low + high) / 2) / ((high - low).max() / 2)


def procedural_clouds(seed=1):
    """A sphere (2000 points) and a torus (3000 points) from a seeded generator."""
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(2000, 3))
    sphere = 0.5 * v / np.linalg.norm(v, axis=1, keepdims=True)
    u, w = rng.uniform(0, 2 * np.pi, 3000), rng.uniform(0, 2 * np.pi, 3000)
    torus = np.column_stack([(0.7 + 0.3 * np.cos(w)) * np.cos(u), (0.7 + 0.3 * np.cos(w)) * np.sin(u), 0.3 * np.sin(w)])
    return {"sphere": sphere, "torus": torus}


def scanned_clouds(meshes):
    """libcgal-demo's bunny and elephant, each scaled into [-1, 1]^3."""
    return {name: unit_cube(pccd.read_points(pathlib.Path(meshes) / f"{name}.off")[0])
            for name in ("bunny00", "elephant")}


def save_objects(clouds, work):
    """Preprocesses each cloud once and saves it; returns {name: file}."""
    files = {}
    for name, points in clouds.items():
        files[name] = pathlib.Path(work) / f"{name}.pccd"
        pccd.Object(points).save(files[name])
    return files


def random_rotation(rng):
    q = rng.normal(size=4)
    a, b, c, d = q / np.linalg.norm(q)
    return np.array([[a*a + b*b - c*c - d*d, 2*(b*c - a*d), 2*(b*d + a*c)],
                     [2*(b*c + a*d), a*a - b*b + c*c - d*d, 2*(c*d - a*b)],
                     [2*(b*d - a*c), 2*(c*d + a*b), a*a - b*b - c*c + d*d]])


def make_pairs(names, count, seed=2, reach=2.0):
    """`count` pairs (name_a, pose_a, name_b, pose_b): random objects, orientations and distances
    0 ... reach, so that some touch and some do not."""
    rng = np.random.default_rng(seed)
    pairs = []
    for _ in range(count):
        a, b = rng.choice(names), rng.choice(names)
        direction = rng.normal(size=3)
        offset = rng.uniform(0, reach) * direction / np.linalg.norm(direction)
        pose_a = np.hstack([random_rotation(rng), np.zeros((3, 1))])
        pose_b = np.hstack([random_rotation(rng), offset.reshape(3, 1)])
        pairs.append((str(a), pose_a, str(b), pose_b))
    return pairs


# --- what runs on the workers --------------------------------------------------------------------------

_loaded = {}  # per worker process: digest -> pccd.Object


def _object(digest, blob):
    if digest not in _loaded:
        with tempfile.TemporaryDirectory() as scratch:
            path = pathlib.Path(scratch) / "object.pccd"
            path.write_bytes(blob)
            _loaded[digest] = pccd.Object.load(path)
    return _loaded[digest]


def answer_chunk(first_index, chunk, blobs, seed, mode):
    """Answers pairs first_index, first_index + 1, ... of the batch; returns plain values."""
    objects = {name: _object(digest, blob) for name, (digest, blob) in blobs.items()}
    pairs = [(objects[a], pose_a, objects[b], pose_b) for a, pose_a, b, pose_b in chunk]
    query = pccd.do_intersect_many if mode == "first" else pccd.intersection_points_many
    results = query(pairs, threads=1, first_index=first_index, seed=seed)
    return [(r.intersects, r.status, r.counters, r.points) for r in results]


def ship_objects(client, files):
    """Sends each saved object's bytes to every worker once: {name: (digest, future)}."""
    blobs = {}
    for name, path in files.items():
        data = pathlib.Path(path).read_bytes()
        blobs[name] = (hashlib.sha256(data).hexdigest(), client.scatter(data, broadcast=True, hash=False))
    return blobs


def run_on_cluster(client, blobs, pairs, seed=24301, chunk=50, mode="first"):
    """The answers to `pairs` (see make_pairs) on the cluster of `client`, in input order, as
    (intersects, status, counters, points) tuples; `blobs` from ship_objects()."""
    futures = [client.submit(answer_chunk, start, pairs[start:start + chunk], blobs, seed, mode, pure=False)
               for start in range(0, len(pairs), chunk)]
    results = []
    for part in client.gather(futures):
        results.extend(part)
    return results


# --- the command -----------------------------------------------------------------------------------------


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=4000, help="number of object pairs (default 4000)")
    parser.add_argument("--chunk", type=int, default=1000,
                        help="pairs per task (default 1000: at least a tenth of a second of queries per task, "
                             "as doc/manual/python.md advises)")
    parser.add_argument("--mode", choices=("first", "all"), default="first",
                        help="first: do_intersect (default); all: intersection_points")
    parser.add_argument("--seed", type=int, default=24301, help="seed of the batch (default 24301)")
    parser.add_argument("--workers", type=int, default=2, help="worker processes of the LocalCluster (default 2)")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: start a LocalCluster)")
    parser.add_argument("--meshes", default=os.environ.get("PCCD_DATA_DIR", ""),
                        help="libcgal-demo's meshes directory (bunny00.off, elephant.off); default $PCCD_DATA_DIR")
    parser.add_argument("--procedural", action="store_true", help="a sphere and a torus instead of the scans")
    parser.add_argument("--work", help="where to save the objects (default: a temporary directory)")
    parser.add_argument("--out", help="write the pairs and results to this .npz file")
    args = parser.parse_args(argv)
    if args.work:
        pathlib.Path(args.work).mkdir(parents=True, exist_ok=True)
        return run(args, args.work)
    with tempfile.TemporaryDirectory(prefix="pccd_dask_") as work:
        return run(args, work)


def run(args, work):
    from dask.distributed import Client, LocalCluster

    scanned = not args.procedural and args.meshes and (pathlib.Path(args.meshes) / "bunny00.off").is_file()
    clouds = scanned_clouds(args.meshes) if scanned else procedural_clouds()
    print("objects:", ", ".join(f"{n} ({len(p)} points)" for n, p in clouds.items()),
          "" if scanned else "(procedural: pass --meshes for libcgal-demo's scans)")
    start = time.perf_counter()
    files = save_objects(clouds, work)
    print(f"preprocessed and saved in {time.perf_counter() - start:.2f} s to {work}")
    pairs = make_pairs(sorted(files), args.pairs)

    if args.scheduler:
        cluster, client = None, Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None)
        client = Client(cluster)
    try:
        workers = len(client.scheduler_info()["workers"])
        blobs = ship_objects(client, files)
        # Warm-up: every worker loads the objects before the clock starts.
        run_on_cluster(client, blobs, pairs[:2 * workers], args.seed, 1, args.mode)
        start = time.perf_counter()
        results = run_on_cluster(client, blobs, pairs, args.seed, args.chunk, args.mode)
        seconds = time.perf_counter() - start
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    hits = sum(r[0] for r in results)
    print(f"{len(pairs)} pairs on {workers} workers in {seconds:.3f} s: {len(pairs) / seconds:.0f} queries/s, "
          f"{hits} intersecting")

    if args.out:
        names = sorted(files)
        np.savez(args.out,
                 names=np.array(names), files=np.array([str(files[n]) for n in names]),
                 index_a=np.array([names.index(p[0]) for p in pairs]), pose_a=np.array([p[1] for p in pairs]),
                 index_b=np.array([names.index(p[2]) for p in pairs]), pose_b=np.array([p[3] for p in pairs]),
                 seed=args.seed, mode=args.mode,
                 intersects=np.array([r[0] for r in results]), status=np.array([r[1] for r in results]),
                 counters=np.array([[r[2][k] for k in sorted(r[2])] for r in results]),
                 counter_names=np.array(sorted(results[0][2])) if results else np.array([]),
                 point_counts=np.array([len(r[3]) for r in results]),
                 points=np.concatenate([r[3] for r in results]) if results else np.zeros((0, 3)),
                 seconds=seconds, workers=workers)
        print("wrote", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
