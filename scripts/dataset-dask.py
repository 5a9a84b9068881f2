#!/usr/bin/env python3
"""Renders a sweep's labelled samples on Dask distributed (docs/DATASETS.md).

The sweep is cut into shards, and each shard is one task: `swell dataset SWEEP
--out DIR --shard K/N` on a worker. Shards are resumable (a sample whose JSON
is there is done), so a task that fails is retried, a run that is stopped is
started again with the same command, and neither renders a done sample again.
The output is byte-identical to a serial `swell dataset SWEEP --out DIR`.

  scripts/dataset-dask.py sweep.toml --out data/            # a LocalCluster here
  scripts/dataset-dask.py sweep.toml --out /shared/data --scheduler tcp://head:8786

With a scheduler, every worker needs the swell executable (--swell) and the
output folder at the same path (a shared file system).
"""
import argparse
import os
import re
import subprocess
import sys
import time
import tomllib


def render_shard(swell, sweep, out, shard, shards):
    """One task: a shard's samples. Returns how many it rendered."""
    result = subprocess.run([swell, "dataset", sweep, "--out", out, "--shard", f"{shard}/{shards}"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"shard {shard}/{shards} failed (exit {result.returncode}): {result.stderr.strip()}")
    found = re.search(r"(\d+) samples to render", result.stderr)
    return int(found.group(1)) if found else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sweep", help="the sweep file (TOML)")
    parser.add_argument("--out", required=True, help="the dataset's folder")
    parser.add_argument("--scheduler", help="a Dask scheduler's address; without it, a LocalCluster here")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                        help="LocalCluster workers, one thread each (default: the machine's cores)")
    parser.add_argument("--tasks", type=int, help="shards to cut the sweep into (default: 4 per worker)")
    parser.add_argument("--retries", type=int, default=2, help="times a failed shard is tried again (default 2)")
    parser.add_argument("--swell", default="swell", help="the swell executable (default: swell on PATH)")
    args = parser.parse_args()

    swell = args.swell
    sweep = os.path.abspath(args.sweep)
    out = os.path.abspath(args.out)
    # Fail fast, here, on a bad sweep or folder: the executable checks both
    # (exit 2 with the place) and writes the manifest, rendering nothing.
    check = subprocess.run([swell, "dataset", sweep, "--out", out, "--dry-run"], capture_output=True, text=True)
    if check.returncode != 0:
        sys.stderr.write(check.stderr)
        return check.returncode
    with open(sweep, "rb") as f:
        count = tomllib.load(f)["count"]

    from dask.distributed import Client, LocalCluster  # Debian's python3-distributed

    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    cores = sum(w["nthreads"] for w in client.scheduler_info()["workers"].values())
    shards = max(1, min(count, args.tasks or 4 * cores))
    started = time.monotonic()
    futures = [client.submit(render_shard, swell, sweep, out, k, shards, retries=args.retries, pure=False)
               for k in range(1, shards + 1)]
    try:
        rendered = sum(client.gather(futures))
    finally:
        client.close()
        if cluster:
            cluster.close()
    elapsed = time.monotonic() - started
    # Every sample done: the dataset's COCO file (nothing left to render).
    final = subprocess.run([swell, "dataset", sweep, "--out", out], capture_output=True, text=True)
    if final.returncode != 0:
        sys.stderr.write(final.stderr)
        return final.returncode
    rate = rendered / elapsed / cores if rendered else 0.0
    print(f"{out}: {rendered} samples rendered in {elapsed:.1f} s on {cores} cores "
          f"({rate:.3f} samples per second per core), {count - rendered} done before")
    return 0


if __name__ == "__main__":
    sys.exit(main())
