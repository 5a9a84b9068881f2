#!/usr/bin/env python3
"""`swell dataset`: bad sweeps and arguments refused with their place and exit
code 2; a sweep rendered serially, in two shards, and killed half way and
started again gives the same bytes, and the restart renders only what was not
done; a sweep of clips, each frame with its labels and flow; and, with
--dask, the same sweep on a 2-worker Dask LocalCluster
(scripts/dataset-dask.py), again killed half way and resumed.

usage: test_dataset.py SWELL_EXECUTABLE DASK_RUNNER WORK_DIR [--dask]
"""
import filecmp
import json
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


# --- Dask (--dask: its own test, swell_dataset_dask; swell_dataset runs
# every check below without it): a sweep on a 2-worker LocalCluster, killed
# half way and resumed, gives the serial run's bytes and renders only what
# was not done. 40 samples: the runner cuts them into 8 shards (4 a worker)
# of 5, so the kill falls with some shards done, some part done and some not
# begun, which is what the resume has to sort out (the 200 it had before
# took two minutes of the suite to show the same).
def finish():
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if dask:
    count = 40
    sweep = write(f"sweep{count}.toml", sweep_text(count))
    serial = os.path.join(work, f"serial{count}")
    check(f"serial {count}", run(sweep, "--out", serial), 0, f"{count} samples to render")
    cluster = os.path.join(work, f"dask{count}")
    command = [sys.executable, runner, sweep, "--out", cluster, "--workers", "2", "--swell", swell]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    finished = kill_when(process, cluster, count // 2)
    if finished >= count:
        failures.append("dask: the run finished before it was killed")
    result = subprocess.run(command, capture_output=True, text=True, timeout=900)
    summary = re.search(r"(\d+) samples rendered .* (\d+) done before", result.stdout)
    if result.returncode != 0 or not summary:
        failures.append(f"dask resume: exit {result.returncode}: {result.stdout} {result.stderr[-2000:]}")
    elif (int(summary.group(1)), int(summary.group(2))) != (count - finished, finished):
        failures.append(f"dask resume rendered {summary.group(1)} and found {summary.group(2)} done; "
                        f"{finished} were done when it was killed")
    same_tree(serial, cluster, "dask, killed and resumed")
    print(result.stdout.strip())
    finish()


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
# Issue 48: the sweep's base scene, named at the sweep's `scene` line when it
# cannot be read at all (a device, a FIFO, a folder, nothing) or lies out of
# the sweep's folder; an object's index past the base scene's; a table's
# stray key; a lens that folds, at the varied key's line or the base scene's;
# a history past the bound, at time_s. None makes a folder.
os.makedirs(os.path.join(work, "a_folder"), exist_ok=True)
fifo = os.path.join(work, "a_fifo")
if not os.path.exists(fifo):
    os.mkfifo(fifo)
with open(os.path.join(work, "folding.toml"), "w") as f:
    f.write(SCENE + "\n[camera]\nfov_y_deg = 120.0\ndistortion_p1 = 0.1\ndistortion_p2 = 0.1\n")
with open(os.path.join(work, "floating.toml"), "w") as f:
    f.write(SCENE.replace('position_m = [4.0, 0.0, -30.0]', 'position_m = [4.0, 0.0, -30.0]\nfloats = true\n'
                          'density_kg_per_m3 = 400.0'))
def with_scene(scene, extra_vary=""):
    return sweep_text(4).replace('scene = "base.toml"', f'scene = "{scene}"') + extra_vary
BAD += [
    ("scene_dev_zero", with_scene("/dev/zero"), "1:9", "outside the sweep file's folder"),
    ("scene_passwd", with_scene("../../../../etc/passwd"), "1:9", "outside the sweep file's folder"),
    ("scene_empty", with_scene(""), "1:9", "name the base scene"),
    ("scene_folder", with_scene("a_folder"), "1:9", "is a folder, not a scene file"),
    ("scene_fifo", with_scene("a_fifo"), "1:9", "FIFO"),
    ("mount_past_objects", sweep_text(4) + '"camera.mount_object" = [0, 5]\n', "12:", "1 object(s)"),
    ("one_of_weights", sweep_text(4).replace("[20.0, 45.0] }", "[20.0, 45.0], weights = [1, 3] }"), "11:",
     "unknown key 'weights'"),
    ("lens_varied", sweep_text(4) + '"camera.fov_y_deg" = 120.0\n"camera.distortion_p1" = [0.09, 0.1]\n'
     '"camera.distortion_p2" = 0.1\n', "13:", "camera.distortion_p1 = 0.09"),
    # A fisheye whose theta_d stops growing inside the field: at its first
    # coefficient's line, before anything is made.
    ("fisheye_varied", sweep_text(4) + '"camera.fov_y_deg" = 100.0\n"camera.lens" = "kannala_brandt"\n'
     '"camera.fisheye_k1" = [-0.35, -0.34]\n', "14:", "theta_d stops growing"),
    ("history", sweep_text(4).replace('time_s = [0.0, 100.0]', 'time_s = [100000.0, 200000.0]')
     .replace('"base.toml"', '"floating.toml"'), "5:", "history_start_s"),
    # Issue 46: a clip of 0 frames or 10^9, a frame rate of 0.
    ("clip_no_frames", sweep_text(4, "[clip]\nframes = 0\nfps = 10\n"), "7:10", "clip.frames"),
    ("clip_billion", sweep_text(4, "[clip]\nframes = 1000000000\nfps = 10\n"), "7:10", "clip.frames"),
    ("clip_no_rate", sweep_text(4, "[clip]\nframes = 3\nfps = 0\n"), "8:7", "clip.fps"),
]
# A lens that folds in the base scene: at the scene file's line.
BAD_IN_SCENE = [("lens_in_scene", with_scene("folding.toml"), "folding.toml:10:", "camera.distortion_p1 = 0.1 and")]

for name, text, place, message in BAD:
    path = write(f"bad_{name}.toml", text)
    check(name, run(path, "--out", os.path.join(work, f"out_{name}")), 2, f"bad_{name}.toml:{place}", message)
    if os.path.exists(os.path.join(work, f"out_{name}")):
        failures.append(f"{name}: a refused sweep created its output folder")
for name, text, place, message in BAD_IN_SCENE:
    path = write(f"bad_{name}.toml", text)
    check(name, run(path, "--out", os.path.join(work, f"out_{name}")), 2, place, message)
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
check("empty out", run(good, "--out", ""), 2, "--out")
manifest_folder = os.path.join(work, "manifest_folder")
os.makedirs(os.path.join(manifest_folder, "manifest.json"), exist_ok=True)
check("manifest is a folder", run(good, "--out", manifest_folder), 2, "--out")
if os.path.exists(os.path.join(manifest_folder, "samples")):
    failures.append("manifest is a folder: samples/ was made before the folder was refused")

def check_rate(name, result, out, written):
    """The run's last report: the samples it wrote, over its wall time and its
    cores, and over its CPU time; each figure the quotient of the others as
    printed (their rounding allowed), not a bound on the time."""
    found = re.search(r"swell: (\d+) samples rendered in ([0-9.]+) s on (\d+) cores: ([0-9.]+) samples per second "
                      r"per core \(samples / wall time / cores\); ([0-9.]+) s of CPU: ([0-9.]+) samples per CPU second",
                      result.stderr)
    if not found:
        failures.append(f"{name}: no samples per second per core at the end: {result.stderr.strip()[-600:]!r}")
        return
    samples, wall, cores, rate, cpu, cpu_rate = (float(g) for g in found.groups())
    if samples != written or len(done(out)) < written or cores < 1 or wall <= 0.0 or cpu <= 0.0:
        failures.append(f"{name}: reported {found.group(0)!r} for {written} samples written "
                        f"({len(done(out))} in the folder)")
        return
    low, high = samples / ((wall + 0.005) * cores) - 5e-5, samples / (max(wall - 0.005, 1e-9) * cores) + 5e-5
    cpu_low, cpu_high = samples / (cpu + 0.005) - 5e-5, samples / max(cpu - 0.005, 1e-9) + 5e-5
    if not low <= rate <= high or not cpu_low <= cpu_rate <= cpu_high:
        failures.append(f"{name}: {found.group(0)!r}: the rates are not the samples over the times "
                        f"({low:.4f}..{high:.4f} per core, {cpu_low:.4f}..{cpu_high:.4f} per CPU second)")


# --- The same bytes serially, in two shards, and killed and started again.
count = 12
sweep = write("sweep.toml", sweep_text(count))
serial = os.path.join(work, "serial")
serial_run = run(sweep, "--out", serial)
check("serial", serial_run, 0, f"{count} samples to render, 0 done already")
check_rate("serial", serial_run, serial, count)
if not os.path.exists(os.path.join(serial, "coco.json")):
    failures.append("serial: no coco.json")
else:
    # Each annotation's amodal RLE decodes to its object's amodal mask and holds its visible one.
    def decoded(rle):
        height, width = rle["size"]
        flat, value = [], False
        for run_length in rle["counts"]:
            flat += [value] * run_length
            value = not value
        return [[flat[x * height + y] for x in range(width)] for y in range(height)]

    with open(os.path.join(serial, "coco.json")) as f:
        coco = json.load(f)
    checked = 0
    for a in coco["annotations"]:
        name = os.path.join(serial, "samples", f"{a['image_id']:06d}")
        with open(name + ".json") as f:
            objects = json.load(f)["objects"]
        k = [o["instance"] for o in objects].index(a["instance"])
        with open(name + ".amodal.npy", "rb") as f:
            raw = f.read()
        header = 10 + raw[8] + 256 * raw[9]
        h, w = a["amodal_segmentation"]["size"]
        mask = raw[header + k * h * w: header + (k + 1) * h * w]
        amodal, visible = decoded(a["amodal_segmentation"]), decoded(a["segmentation"])
        if any(amodal[y][x] != (mask[y * w + x] == 1) or (visible[y][x] and not amodal[y][x])
               for y in range(h) for x in range(w)):
            failures.append(f"serial: annotation {a['id']}'s amodal_segmentation is not its amodal mask "
                            "or does not hold its segmentation")
        if a["amodal_area"] != objects[k]["amodal_pixels"]:
            failures.append(f"serial: annotation {a['id']}'s amodal_area is not its object's amodal_pixels")
        checked += 1
    if checked == 0:
        failures.append("serial: coco.json has no annotation to check the amodal masks on")
sharded = os.path.join(work, "sharded")
first_shard = run(sweep, "--out", sharded, "--shard", "1/2")
check("shard 1/2", first_shard, 0, "6 samples to render")
check_rate("shard 1/2", first_shard, sharded, 6)
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

# --- Broken samples are found on resume, said, and rendered again (issue 48):
# a JSON cut short, a JSON emptied, a PNG emptied, an array deleted, an array
# cut in half. coco.json goes while a sample is not whole.
def samples_file(out, i, suffix):
    return os.path.join(out, "samples", f"{i:06d}{suffix}")


broken = os.path.join(work, "broken")
shutil.copytree(serial, broken)
with open(samples_file(broken, 3, ".json"), "r+") as f:
    f.truncate(len(f.read()) // 2)
open(samples_file(broken, 5, ".json"), "w").close()
open(samples_file(broken, 6, ".png"), "w").close()
os.remove(samples_file(broken, 7, ".range.npy"))
with open(samples_file(broken, 8, ".normal.npy"), "r+b") as f:
    f.truncate(len(f.read()) // 2)
first_half = run(sweep, "--out", broken, "--shard", "1/2")  # 0, 2, ..., 10: only 6 and 8 are its
check("broken, shard 1/2", first_half, 0, "sample 6 is not whole", "sample 8 is not whole", "2 samples to render, 4 done")
if os.path.exists(os.path.join(broken, "coco.json")):
    failures.append("broken: coco.json stayed while samples 3, 5 and 7 were not whole")
second_half = run(sweep, "--out", broken, "--shard", "2/2")
check("broken, shard 2/2", second_half, 0, "sample 3 is not whole", "sample 5 is not whole",
      "3 samples to render, 3 done")
if "json.exception" in first_half.stderr + second_half.stderr:
    failures.append("broken: a raw JSON exception was printed")
same_tree(serial, broken, "broken samples rendered again")


def partial_samples(out):
    """Samples with some of their files but not their JSON, and temporary files."""
    folder = os.path.join(out, "samples")
    names = os.listdir(folder) if os.path.isdir(folder) else []
    stems = {n.split(".")[0] for n in names if not n.startswith(".")}
    return sorted([s for s in stems if f"{s}.json" not in names] + [n for n in names if n.endswith(".tmp")])


def writing(out):
    """A sample whose files are being written: its PNG (the first written) there, its JSON (the last) not."""
    folder = os.path.join(out, "samples")
    try:
        names = set(os.listdir(folder))
    except FileNotFoundError:
        return False
    return any(n.endswith(".png") and not n.endswith(".labels.png") and n[:-4] + ".json" not in names for n in names)


def stop_run(out, stop, when):
    """Starts the sweep into `out` and sends `stop` to it: while a sample's
    files are being written (when = "writing"), or that many seconds after
    its next sample is done; True when it was still running then."""
    process = subprocess.Popen([swell, "dataset", sweep, "--out", out], stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, start_new_session=True)
    before = len(done(out))
    deadline = time.monotonic() + 300
    if when == "writing":
        while not writing(out) and process.poll() is None and time.monotonic() < deadline:
            pass
    else:
        while len(done(out)) <= before and process.poll() is None and time.monotonic() < deadline:
            time.sleep(0.002)
        time.sleep(when)
    running = process.poll() is None
    if running:
        os.killpg(process.pid, stop)
    process.wait()
    return running


MOMENTS = ["writing", 0.0, "writing", 0.01, "writing", 0.03, "writing", 0.06, "writing", 0.1, "writing"]

# --- SIGTERM (and Ctrl-C's SIGINT) while a sample's files are being written,
# and at moments after: the sample is finished or not begun, never half
# there, and the process ends; started again, the same bytes.
termed = os.path.join(work, "termed")
stopped = 0
for when, stop in zip(MOMENTS, [signal.SIGTERM, signal.SIGINT] * 6):
    stopped += stop_run(termed, stop, when)
    if partial_samples(termed):
        failures.append(f"{signal.Signals(stop).name} ({when}) left part of a sample: {partial_samples(termed)}")
if stopped < 6:
    failures.append(f"only {stopped} of the runs were stopped: the stops no longer fall inside a run")
check("restart after SIGTERM", run(sweep, "--out", termed), 0, "done already")
same_tree(serial, termed, "stopped and started again")

# --- Killed again and again, while a sample's files are written and at
# moments after: every restart cleans up after the kill, and the last gives
# the same bytes as a run never killed.
killed = os.path.join(work, "killed")
kills = sum(stop_run(killed, signal.SIGKILL, when) for when in MOMENTS)
if kills < 6:
    failures.append(f"only {kills} of the runs were killed: the kills no longer fall inside a run")
check("restart after kills", run(sweep, "--out", killed), 0, "done already")
same_tree(serial, killed, "killed again and again")
print(f"stopped {stopped} runs, killed {kills}")

# --- The values a sample records are the ones drawn: an azimuth swept over
# [0, 360] stays there (it was written as atan2's -180..180); no labels.
azimuth = write("azimuth.toml", 'scene = "base.toml"\ncount = 6\nsize = [16, 16]\nlabels = false\n'
                '[vary]\n"sun.azimuth_deg" = [0.0, 360.0]\n')
azimuth_out = os.path.join(work, "azimuth")
check("azimuth", run(azimuth, "--out", azimuth_out), 0, "6 samples to render")
values = []
for i in range(6):
    with open(samples_file(azimuth_out, i, ".json")) as f:
        values.append(json.load(f)["varied"]["sun.azimuth_deg"])
if not all(0.0 <= v <= 360.0 for v in values) or max(values) < 180.0:
    failures.append(f"azimuth: varied values {values} are not the [0, 360] drawn")
if sorted(os.listdir(os.path.join(azimuth_out, "samples")))[:2] != ["000000.json", "000000.png"]:
    failures.append("azimuth: a sample without labels is its PNG and JSON")

# --- Clips (issue 46, item 1): each sample 3 frames at 10 frames a second,
# the camera on the floating buoy: every frame's files and its flow; its
# JSON's frame, time and flow interval; the same instance ids in every
# frame; the buoy and the camera riding it moving; COCO listing each frame;
# a frame's file deleted: that sample alone rendered again, the same bytes.
clip_sweep = write("clip.toml", sweep_text(2, "[clip]\nframes = 3\nfps = 10\n").replace('"base.toml"', '"floating.toml"')
                   + '"camera.mount_object" = 0\n"camera.mount_offset_m" = { one_of = [[0.0, 2.0, 4.0]] }\n')
clip_out = os.path.join(work, "clip")
check("clip", run(clip_sweep, "--out", clip_out), 0, "2 samples to render")
clip_frames = {}
for i in range(2):
    for k in range(3):
        stem = os.path.join(clip_out, "samples", f"{i:06d}_{k:05d}")
        missing = [x for x in [".png", ".json", ".range.npy", ".instance.npy", ".flow.npy", ".flow_valid.npy"]
                   if not os.path.isfile(stem + x)]
        if missing:
            failures.append(f"clip: sample {i} frame {k} lacks {missing}")
            continue
        with open(stem + ".json") as f:
            clip_frames[i, k] = json.load(f)
for i in range(2):
    frames = [clip_frames.get((i, k)) for k in range(3)]
    if None in frames:
        continue
    times = [f["time_s"] for f in frames]
    if [f["frame"] for f in frames] != [0, 1, 2] or any(abs(t - (times[0] + k / 10.0)) > 1e-9 for k, t in enumerate(times)):
        failures.append(f"clip: sample {i}'s frames {[f['frame'] for f in frames]} at {times}, not 0.1 s apart")
    if any(f["flow"]["interval_s"] != 0.1 for f in frames):
        failures.append(f"clip: sample {i}'s flow intervals {[f['flow'] for f in frames]}")
    if len({tuple((o["instance"], o["class"]) for o in f["objects"]) for f in frames}) != 1:
        failures.append(f"clip: sample {i}'s instance ids change along the clip")
    poses = [f["objects"][0]["pose"]["position_m"] for f in frames]
    cameras = [f["camera"]["camera_from_world"] for f in frames]
    if poses[0] == poses[2] or cameras[0] == cameras[2]:
        failures.append(f"clip: sample {i}'s buoy ({poses}) or the camera on it does not move")
if not os.path.isfile(os.path.join(clip_out, "coco.json")):
    failures.append("clip: no coco.json: a sample not done after its run")
else:
    with open(os.path.join(clip_out, "coco.json")) as f:
        clip_coco = json.load(f)
    names = [(im["file_name"], im["sample"], im["frame"]) for im in clip_coco["images"]]
    if names != [(f"samples/{i:06d}_{k:05d}.png", i, k) for i in range(2) for k in range(3)]:
        failures.append(f"clip: COCO's images {names}")
with open(os.path.join(clip_out, "manifest.json")) as f:
    if json.load(f).get("clip", {}).get("frames") != 3:
        failures.append("clip: the manifest does not say the clip's frames")
clip_again = os.path.join(work, "clip_again")
shutil.copytree(clip_out, clip_again)
os.remove(os.path.join(clip_again, "samples", "000001_00001.flow_valid.npy"))
check("clip resumed", run(clip_sweep, "--out", clip_again), 0, "sample 1 is not whole",
      "1 samples to render, 1 done already")
same_tree(clip_out, clip_again, "a clip's frame deleted and rendered again")

finish()
