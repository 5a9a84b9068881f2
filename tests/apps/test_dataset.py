#!/usr/bin/env python3
"""`swell dataset`: bad sweeps and arguments refused with their place and exit
code 2; a sweep rendered serially, in two shards, and killed half way and
started again gives the same bytes, and the restart renders only what was not
done; and, with --dask, the same sweep on a 2-worker Dask LocalCluster
(scripts/dataset-dask.py), again killed half way and resumed.

usage: test_dataset.py SWELL_EXECUTABLE DASK_RUNNER WORK_DIR [--dask]
"""
import filecmp
import os
import re
import shutil
import signal
import subprocess
import sys
import time

swell, runner, work = sys.argv[1], sys.argv[2], sys.argv[3]
dask = "--dask" in sys.argv[4:]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []

SCENE = """[waves.wind]
speed_mps = 8.0

[[objects]]
path = "builtin:buoy"
position_m = [4.0, 0.0, -30.0]
"""
with open(os.path.join(work, "base.toml"), "w") as f:
    f.write(SCENE)


def sweep_text(count, extra=""):
    return f"""scene = "base.toml"
count = {count}
seed = 11
size = [64, 48]
time_s = [0.0, 100.0]
{extra}
[vary]
"waves.wind.speed_mps" = [4.0, 14.0]
"camera.roll_deg" = [-15.0, 15.0]
"objects[0].yaw_deg" = [0.0, 360.0]
"sun.elevation_deg" = {{ one_of = [20.0, 45.0] }}
"""


def write(name, text):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def run(*args):
    return subprocess.run([swell, "dataset", *args], capture_output=True, text=True, timeout=600)


def check(name, result, code, *needles):
    if result.returncode != code or any(n not in result.stderr for n in needles):
        failures.append(f"{name}: exit {result.returncode} (expected {code}), stderr: {result.stderr.strip()!r}, "
                        f"expected to contain {needles}")


def same_tree(a, b, name):
    def files(root):
        return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)
    fa, fb = files(a), files(b)
    if fa != fb:
        failures.append(f"{name}: different files: {sorted(set(fa) ^ set(fb))[:6]}")
        return
    for f in fa:
        if not filecmp.cmp(os.path.join(a, f), os.path.join(b, f), shallow=False):
            failures.append(f"{name}: {f} differs")


def done(out):
    folder = os.path.join(out, "samples")
    return sorted(f for f in os.listdir(folder) if f.endswith(".json")) if os.path.isdir(folder) else []


def kill_when(process, out, at_least):
    """SIGKILLs the process group once at_least samples are done."""
    deadline = time.monotonic() + 300
    while len(done(out)) < at_least and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()
    return len(done(out))


# --- Bad input: exit 2, and the place.
good = write("good.toml", sweep_text(4))
BAD = [
    ("empty_range", sweep_text(4).replace("[-15.0, 15.0]", "[15.0, -15.0]"), "9:", "empty range"),
    ("empty_one_of", sweep_text(4).replace("[20.0, 45.0]", "[]"), "11:", "one_of is empty"),
    ("unknown_top_key", sweep_text(4, 'cuont = 3\n'), "6:1", "did you mean 'count'"),
    ("unknown_key", sweep_text(4).replace('"camera.roll_deg"', '"camera.rol_deg"'), "9:", "did you mean \"camera.roll_deg\""),
    ("out_of_range", sweep_text(4).replace("[4.0, 14.0]", "[4.0, 400.0]"), "8:", "outside its range"),
    ("wrong_type", sweep_text(4).replace("[0.0, 360.0]", '["a", "b"]'), "10:", "a number"),
    ("no_such_item", sweep_text(4).replace("objects[0]", "objects[3]"), "10:", "1 item(s)"),
    ("no_count", sweep_text(4).replace("count = 4\n", ""), "", "count"),
    ("no_scene", sweep_text(4).replace('scene = "base.toml"', 'scene = "nowhere.toml"'), "1:", "scene"),
]
for name, text, place, message in BAD:
    path = write(f"bad_{name}.toml", text)
    check(name, run(path, "--out", os.path.join(work, f"out_{name}")), 2, f"bad_{name}.toml:{place}", message)
    if os.path.exists(os.path.join(work, f"out_{name}")):
        failures.append(f"{name}: a refused sweep created its output folder")
for shard in ["3/2", "0/2", "1/0", "a/b", "2"]:
    check(f"shard {shard}", run(good, "--out", os.path.join(work, "out_shard"), "--shard", shard), 2, "--shard")
a_file = write("a_file", "not a folder")
check("out is a file", run(good, "--out", a_file), 2, "--out")
first = run(good, "--out", os.path.join(work, "taken"), "--dry-run")
check("dry run", first, 0, "4 samples to render")
other = write("other.toml", sweep_text(5))
check("another sweep's folder", run(other, "--out", os.path.join(work, "taken")), 2, "another sweep")

# --- The same bytes serially, in two shards, and killed and started again.
count = 12
sweep = write("sweep.toml", sweep_text(count))
serial = os.path.join(work, "serial")
check("serial", run(sweep, "--out", serial), 0, f"{count} samples to render, 0 done already")
if not os.path.exists(os.path.join(serial, "coco.json")):
    failures.append("serial: no coco.json")
sharded = os.path.join(work, "sharded")
check("shard 1/2", run(sweep, "--out", sharded, "--shard", "1/2"), 0, "6 samples to render")
if os.path.exists(os.path.join(sharded, "coco.json")):
    failures.append("shard 1/2 wrote coco.json before every sample was done")
check("shard 2/2", run(sweep, "--out", sharded, "--shard", "2/2"), 0, "6 samples to render")
same_tree(serial, sharded, "two shards")

resumed = os.path.join(work, "resumed")
process = subprocess.Popen([swell, "dataset", sweep, "--out", resumed], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, start_new_session=True)
finished = kill_when(process, resumed, 4)
if finished >= count:
    failures.append("killed: the run finished before it was killed")
again = run(sweep, "--out", resumed)
check("restart", again, 0, f"{count - finished} samples to render, {finished} done already")
same_tree(serial, resumed, "killed and started again")

# --- Dask: 200 samples on a 2-worker LocalCluster, killed half way, resumed.
if dask:
    count = 200
    sweep = write("sweep200.toml", sweep_text(count))
    serial = os.path.join(work, "serial200")
    check("serial 200", run(sweep, "--out", serial), 0, f"{count} samples to render")
    cluster = os.path.join(work, "dask200")
    command = [sys.executable, runner, sweep, "--out", cluster, "--workers", "2", "--swell", swell]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    finished = kill_when(process, cluster, count // 2)
    result = subprocess.run(command, capture_output=True, text=True, timeout=900)
    summary = re.search(r"(\d+) samples rendered .* (\d+) done before", result.stdout)
    if result.returncode != 0 or not summary:
        failures.append(f"dask resume: exit {result.returncode}: {result.stdout} {result.stderr[-2000:]}")
    elif (int(summary.group(1)), int(summary.group(2))) != (count - finished, finished):
        failures.append(f"dask resume rendered {summary.group(1)} and found {summary.group(2)} done; "
                        f"{finished} were done when it was killed")
    same_tree(serial, cluster, "dask, killed and resumed")
    print(result.stdout.strip())

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
