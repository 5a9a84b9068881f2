#!/usr/bin/python3
"""Renders a sweep's labelled samples on Dask distributed (docs/DATASETS.md).

It needs Python 3.11 or later with Dask distributed: Debian's
python3-distributed (scripts/install-deps.sh installs it) for Debian's
/usr/bin/python3, which this file names; run it with another Python that
has Dask (`python3.12 scripts/dataset-dask.py ...`) to use that one.

The sweep is cut into shards, and each shard is one task: `swell dataset SWEEP
--out DIR --shard K/N` on a worker. Shards are resumable (a sample whose JSON
is there is done), so a task that fails is retried, a run that is stopped is
started again with the same command, and neither renders a done sample again.
The output is byte-identical to a serial `swell dataset SWEEP --out DIR`.

  scripts/dataset-dask.py sweep.toml --out data/            # a LocalCluster here
  scripts/dataset-dask.py sweep.toml --out /shared/data --scheduler tcp://head:8786

The swell executable is --swell, else $SWELL, else `swell` on PATH, else the
build tree's (build/apps/swell/swell beside this script, or in
$SWELL_BUILD_DIR). With a scheduler, every worker needs it and the output
folder at the same paths (a shared file system).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def stop(message):
    """Exit 2 with a message: what is missing and how to get it."""
    sys.stderr.write(f"dataset-dask.py: {message}\n")
    sys.exit(2)


if sys.version_info < (3, 11):
    stop(f"needs Python 3.11 or later (for tomllib); this is {sys.version.split()[0]} at {sys.executable}: "
         f"run it with /usr/bin/python3 on Debian 12")
import tomllib  # noqa: E402


def import_dask():
    """dask.distributed's Client and LocalCluster, or a message naming what is missing."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError as error:
        missing = error.name or "dask.distributed"
        package = "python3-distributed" if missing.split(".")[0] in ("dask", "distributed") else f"python3-{missing}"
        stop(f"needs Dask distributed, whose import failed in this Python ({sys.executable}): "
             f"No module named '{missing}'. On Debian: `apt-get install {package}` "
             f"(scripts/install-deps.sh installs python3-distributed) and run the script with /usr/bin/python3; "
             f"with another Python: `{sys.executable} -m pip install distributed`")
    return Client, LocalCluster


def find_swell(given):
    """The swell executable: --swell, $SWELL, swell on PATH, or the build tree's."""
    build = os.environ.get("SWELL_BUILD_DIR", os.path.join(HERE, "..", "build"))
    candidates = [given] if given else [os.environ["SWELL"]] if os.environ.get("SWELL") else \
        ["swell", os.path.join(build, "apps", "swell", "swell")]
    for candidate in candidates:
        found = shutil.which(candidate)
        if found:
            return os.path.abspath(found)
    if given or os.environ.get("SWELL"):
        source = "--swell" if given else "$SWELL"
        stop(f"the swell executable {candidates[0]!r} ({source}) is missing or not executable; build it "
             f"(scripts/build.sh builds build/apps/swell/swell) or name another with --swell PATH or SWELL=PATH")
    stop(f"no swell executable: none on PATH, nor the build tree's {os.path.normpath(candidates[-1])}; build it "
         f"with scripts/build.sh, or name it with --swell PATH or SWELL=PATH")


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
    parser.add_argument("--swell", help="the swell executable (default: $SWELL, swell on PATH, or the build "
                                            "tree's build/apps/swell/swell)")
    args = parser.parse_args()

    Client, LocalCluster = import_dask()
    swell = find_swell(args.swell)
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
