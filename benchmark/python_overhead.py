"""Cost of the Python interface on the scanned bunny (libcgal-demo's bunny00.off, 37,706 points).

1. Per-query overhead: the median time of one pccd.do_intersect call from Python against the
   median time of the same C++ query (PCCD::do_intersect, timed alone by `pccd collide --cases`,
   which answers every row of a CSV of poses with the objects preprocessed from the same file), on
   two poses: one apart (the hierarchy rejects at the root: the query is almost all overhead) and
   one overlapping (first hit). The objects, poses and seed are the same, so the answers and
   counters are the same (checked).
2. Batch throughput (queries/s) of pccd.do_intersect_many with 1 and 2 threads, and of the same
   pairs on a dask.distributed LocalCluster of 2 worker processes (examples/python/
   dask_many_pairs.py), for random poses of two bunnies scaled into [-1, 1]^3 at distances 0 ... 2.

    build/pccd-python benchmark/python_overhead.py --pccd build/tools/pccd \
        --bunny build/cgal-data/data/meshes/bunny00.off

Prints a Markdown table of medians (and the load average, since other jobs may share the cores).
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import pccd

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "examples" / "python"))
import dask_many_pairs  # noqa: E402  (the example's pairs, shipping and chunked runs)


def turn(dx):
    """B turned 90 degrees about z and moved by dx along x, a 3x4 pose."""
    return np.array([[0.0, -1.0, 0.0, dx], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])


def python_median_us(a, pose, rounds, calls):
    """Median over `rounds` of the mean time of `calls` consecutive pccd.do_intersect calls (short
    rounds, so that a round the scheduler preempts is an outlier the median ignores)."""
    samples = []
    for _ in range(rounds):
        start = time.perf_counter_ns()
        for _ in range(calls):
            pccd.do_intersect(a, None, a, pose)
        samples.append((time.perf_counter_ns() - start) / calls / 1000.0)
    return statistics.median(samples)


def cpp_median_us(pccd_tool, bunny, pose, count, work):
    """Median query_us of `count` identical rows answered by `pccd collide --cases`, and the
    f_evaluations of the first."""
    cases = pathlib.Path(work) / "cases.csv"
    row = " ".join(repr(float(x)) for x in np.hstack([np.eye(3), np.zeros((3, 1))]).reshape(-1))
    row += " " + " ".join(repr(float(x)) for x in pose.reshape(-1))
    cases.write_text("\n".join([row] * count) + "\n")
    done = subprocess.run([str(pccd_tool), "collide", str(bunny), str(bunny), "--cases", str(cases)],
                          capture_output=True, text=True, check=True)
    rows = [line.split(",") for line in done.stdout.splitlines()[1:]]
    return statistics.median(float(r[3]) for r in rows), int(rows[0][2]), rows[0][1] == "1"


def throughput(run, pairs, repeats):
    """Median queries/s over `repeats` runs of run(pairs), and the median CPU share of this
    process during a run (CPU seconds of all its threads / wall seconds: 2 would be two busy
    cores; below 1 the cores were shared with other jobs)."""
    rates, shares = [], []
    for _ in range(repeats):
        start, cpu = time.perf_counter(), time.process_time()
        run(pairs)
        wall = time.perf_counter() - start
        rates.append(len(pairs) / wall)
        shares.append((time.process_time() - cpu) / wall)
    return statistics.median(rates), statistics.median(shares)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pccd", required=True, help="the built pccd tool (build/tools/pccd)")
    parser.add_argument("--bunny", required=True, help="bunny00.off of libcgal-demo")
    parser.add_argument("--pairs", type=int, default=2000, help="pairs of the throughput runs (default 2000)")
    parser.add_argument("--repeats", type=int, default=3, help="runs per throughput figure (default 3)")
    parser.add_argument("--json", help="also write the figures to this file")
    args = parser.parse_args()
    figures = {"load_average_before": os.getloadavg()}

    # 1. Per-query overhead, raw bunny coordinates, as the tool reads them.
    points, _ = pccd.read_points(args.bunny)
    bunny = pccd.Object(points)
    extent = np.ptp(bunny.points, axis=0)
    poses = {"apart": turn(3.0 * extent[0]), "overlapping": turn(0.5 * extent[0])}
    with tempfile.TemporaryDirectory() as work:
        for name, pose in poses.items():
            result = pccd.do_intersect(bunny, None, bunny, pose)
            cpp_us, cpp_evaluations, cpp_hit = cpp_median_us(args.pccd, args.bunny, pose, 20001, work)
            assert (cpp_evaluations, cpp_hit) == (result.counters["f_evaluations"], result.intersects), name
            py_us = python_median_us(bunny, pose, 2001, 20 if name == "apart" else 5)
            figures[f"query_{name}"] = {"cpp_us": cpp_us, "python_us": py_us, "overhead_us": py_us - cpp_us,
                                        "intersects": result.intersects,
                                        "f_evaluations": result.counters["f_evaluations"]}

    # 2. Throughput: bunny pairs in [-1, 1]^3, random orientations, distances 0 ... 2.
    with tempfile.TemporaryDirectory() as work:
        files = dask_many_pairs.save_objects({"bunny00": dask_many_pairs.unit_cube(points)}, work)
        unit = pccd.Object.load(files["bunny00"])
        named = dask_many_pairs.make_pairs(["bunny00"], args.pairs, seed=3)
        pairs = [(unit, pa, unit, pb) for _, pa, _, pb in named]
        reference = pccd.do_intersect_many(pairs, threads=1)
        figures["pairs"] = len(pairs)
        figures["pairs_intersecting"] = sum(r.intersects for r in reference)
        for threads in (1, 2):
            figures[f"batch_threads_{threads}_qps"] = throughput(
                lambda p: pccd.do_intersect_many(p, threads=threads), pairs, args.repeats)

        from dask.distributed import Client, LocalCluster
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=None) as cluster, Client(cluster) as client:
            blobs = dask_many_pairs.ship_objects(client, files)
            dask_many_pairs.run_on_cluster(client, blobs, named[:4], chunk=1)  # every worker loads the bunny
            answers = dask_many_pairs.run_on_cluster(client, blobs, named, chunk=100)
            assert [a[2] for a in answers] == [r.counters for r in reference]
            figures["dask_2_workers_qps"] = throughput(
                lambda p: dask_many_pairs.run_on_cluster(client, blobs, p, chunk=100), named, args.repeats)
            figures["dask_2_workers_chunk_10_qps"] = throughput(
                lambda p: dask_many_pairs.run_on_cluster(client, blobs, p, chunk=10), named, args.repeats)
    figures["load_average_after"] = os.getloadavg()

    print("| measure | C++ | Python | overhead |")
    print("|---|---:|---:|---:|")
    for name in poses:
        f = figures[f"query_{name}"]
        print(f"| one do_intersect, {name} ({f['f_evaluations']} f evaluations) | {f['cpp_us']:.2f} µs | "
              f"{f['python_us']:.2f} µs | {f['overhead_us']:.2f} µs |")
    print()
    print(f"| batch of {figures['pairs']} bunny pairs ({figures['pairs_intersecting']} intersecting) | queries/s "
          "| CPU share of this process |")
    print("|---|---:|---:|")
    rows = [("do_intersect_many, 1 thread", "batch_threads_1_qps"), ("do_intersect_many, 2 threads", "batch_threads_2_qps"),
            ("Dask LocalCluster, 2 worker processes, chunks of 100 pairs", "dask_2_workers_qps"),
            ("Dask LocalCluster, 2 worker processes, chunks of 10 pairs", "dask_2_workers_chunk_10_qps")]
    for label, key in rows:
        rate, share = figures[key]
        shown = "— (the work runs in the workers)" if key.startswith("dask") else f"{share:.2f}"
        print(f"| {label} | {rate:.0f} | {shown} |")
    print(f"\nload average before {figures['load_average_before']}, after {figures['load_average_after']}")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(figures, indent=2))


if __name__ == "__main__":
    main()
