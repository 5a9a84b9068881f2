#!/usr/bin/env python3
"""A rig of cameras on one platform ([[camera.rig]], docs/LABELS.md "Rigs and
the platform"; issue 46, item 3), through the swell executable:

- a stereo pair 0.6 m apart over calm water, written by `swell render
  --labels`: each water pixel of the left image is matched, in the same row
  of the right image, to the pixel whose range label puts the same point of
  the sea under it (the two images' own ranges, put back along their rays
  by their written calibrations); the disparity of the match equals
  f B / z from the WRITTEN calibration (fx, the baseline from the two rig
  blocks' platform_from_camera, z the point's depth in the left camera)
  within 0.1 px;
- a rig with two cameras of one name is refused at its line:column with
  exit 2 and nothing written, by `swell render` and by `swell dataset`;
- a sweep of 2-frame clips with the rig writes each camera's files
  (NNNNNN_FFFFF.CAM.*), their platform and rig blocks, and a COCO image per
  camera.

usage: test_rig.py SWELL_EXECUTABLE WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np

swell, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []

SIZE = (320, 240)
BASELINE_M = 0.6
STEREO = f"""terrain = false

[[waves.list]]                 # calm water: one wave of no height
direction = [1.0, 0.0]
wavelength_m = 20.0
amplitude_m = 0.0

[camera]                       # the platform
position_m = [3.0, 4.0, -2.0]
yaw_deg = 25.0
pitch_deg = -25.0
fov_y_deg = 50.0

[[camera.rig]]
name = "left"
position_m = [{-BASELINE_M / 2}, 0.0, 0.0]

[[camera.rig]]
name = "right"
position_m = [{BASELINE_M / 2}, 0.0, 0.0]
"""


def write(name, text):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def run(*args):
    return subprocess.run([swell, *args], capture_output=True, text=True, timeout=600)


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def points_of(calibration, range_m):
    """World points (H, W, 3) where each pixel centre's ray meets at its range."""
    h, w = range_m.shape
    x, y = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
    ray = np.stack([(x - calibration["cx_px"]) / calibration["fx_px"],
                    (y - calibration["cy_px"]) / calibration["fy_px"], np.ones_like(x)], axis=-1)
    ray /= np.linalg.norm(ray, axis=-1, keepdims=True)
    world_from_camera = np.array(calibration["world_from_camera"])
    return (ray * range_m[..., None].astype(np.float64)) @ world_from_camera[:3, :3].T + world_from_camera[:3, 3]


def stereo_disparity():
    scene = write("stereo.toml", STEREO)
    out = os.path.join(work, "stereo", "pair.png")
    r = run("render", scene, "-o", out, "--size", f"{SIZE[0]}x{SIZE[1]}", "--labels")
    check(r.returncode == 0, f"stereo render exited {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        return
    folder = os.path.dirname(out)
    check(not os.path.exists(out), "a rig writes no image of the platform itself (pair.png)")
    frames = {}
    for name in ("left", "right"):
        for suffix in ("png", "json", "range.npy", "semantic.npy", "flow.npy", "kitti.txt"):
            check(os.path.exists(os.path.join(folder, f"pair.{name}.{suffix}")), f"pair.{name}.{suffix} missing")
        with open(os.path.join(folder, f"pair.{name}.json")) as f:
            frames[name] = json.load(f)
        frames[name]["range"] = np.load(os.path.join(folder, f"pair.{name}.range.npy"))
        frames[name]["semantic"] = np.load(os.path.join(folder, f"pair.{name}.semantic.npy"))
    left, right = frames["left"], frames["right"]
    check(left["rig"]["cameras"] == ["left", "right"] and left["rig"]["camera"] == "left", "left's rig block")
    check(left["platform"]["time_s"] == right["platform"]["time_s"] == left["time_s"] == right["time_s"],
          "both cameras at one time")
    # The written calibration: the focal length, and the baseline between the
    # two cameras' centres on the platform.
    f_px = left["camera"]["fx_px"]
    centre = {n: np.array(frames[n]["rig"]["platform_from_camera"])[:3, 3] for n in ("left", "right")}
    baseline_m = np.linalg.norm(centre["right"] - centre["left"])
    check(abs(baseline_m - BASELINE_M) < 1e-9, f"written baseline {baseline_m} m, the rig's {BASELINE_M} m")
    left_points = points_of(left["camera"], left["range"])
    right_points = points_of(right["camera"], right["range"])
    camera_from_world = np.array(left["camera"]["camera_from_world"])
    right_x = np.array(right["camera"]["world_from_camera"])[:3, 0]  # the right camera's x axis in the world
    water = 2
    errors, matched = [], 0
    h, w = left["range"].shape
    for j in range(0, h, 3):
        row_ok = (right["semantic"][j] == water) & np.isfinite(right["range"][j])
        for i in range(0, w, 3):
            if left["semantic"][j, i] != water or not np.isfinite(left["range"][j, i]):
                continue
            p = left_points[j, i]
            # Along the right image's row, where the sea's point crosses p
            # (across the baseline): between two water pixels, interpolated.
            offset = (right_points[j] - p) @ right_x
            cross = np.nonzero(row_ok[:-1] & row_ok[1:] & (offset[:-1] <= 0.0) & (offset[1:] > 0.0))[0]
            if len(cross) != 1:
                continue
            k = cross[0]
            u_right = k + 0.5 + offset[k] / (offset[k] - offset[k + 1])
            z_m = (camera_from_world @ np.append(p, 1.0))[2]
            disparity = (i + 0.5) - u_right
            errors.append(disparity - f_px * baseline_m / z_m)
            matched += 1
    errors = np.abs(np.array(errors))
    check(matched > 2000, f"only {matched} water pixels matched")
    if matched:
        print(f"stereo: {matched} water pixels matched; |disparity - f B / z| median {np.median(errors):.2e} px, "
              f"largest {errors.max():.2e} px (f {f_px:.2f} px, B {baseline_m:.3f} m)")
        check(errors.max() < 0.1, f"disparity off f B / z by up to {errors.max():.4f} px (bound 0.1)")


DUPLICATE = """[camera]
fov_y_deg = 50.0
[[camera.rig]]
name = "left"
[[camera.rig]]
name = "left"
position_m = [0.5, 0.0, 0.0]
"""


def duplicate_names():
    scene = write("twice.toml", DUPLICATE)
    out = os.path.join(work, "twice-render", "frame.png")
    r = run("render", scene, "-o", out, "--size", "64x48", "--labels")
    check(r.returncode == 2, f"render of a rig with one name twice exited {r.returncode}")
    check(f"{scene}:6:8" in r.stderr and "camera.rig[0].name has that name too" in r.stderr,
          f"render names the place: {r.stderr.strip()}")
    check(not os.path.exists(os.path.dirname(out)), "render of a refused rig made its folder")
    sweep = write("twice-sweep.toml", 'scene = "twice.toml"\ncount = 2\nseed = 1\nsize = [64, 48]\n')
    data = os.path.join(work, "twice-data")
    r = run("dataset", sweep, "--out", data)
    check(r.returncode == 2, f"dataset of a rig with one name twice exited {r.returncode}")
    check(":6:8" in r.stderr and "camera.rig[0].name has that name too" in r.stderr,
          f"dataset names the place: {r.stderr.strip()}")
    check(not os.path.exists(data), "dataset of a refused rig made its folder")


def clip_sweep():
    write("rig-base.toml", STEREO.replace("amplitude_m = 0.0", "amplitude_m = 0.3"))
    sweep = write("rig-sweep.toml", 'scene = "rig-base.toml"\ncount = 1\nseed = 3\nsize = [64, 48]\n'
                                    'time_s = 5.0\n[clip]\nframes = 2\nfps = 10.0\n'
                                    '[vary]\n"camera.rig[1].position_m" = [[0.2, 0.0, 0.0], [0.4, 0.0, 0.0]]\n')
    data = os.path.join(work, "rig-data")
    r = run("dataset", sweep, "--out", data)
    check(r.returncode == 0, f"rig sweep exited {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        return
    for frame in range(2):
        for name in ("left", "right"):
            stem = os.path.join(data, "samples", f"000000_{frame:05d}.{name}")
            for suffix in ("png", "range.npy", "flow.npy", "amodal.npy", "json"):
                check(os.path.exists(f"{stem}.{suffix}"), f"{stem}.{suffix} missing")
            if os.path.exists(stem + ".json"):
                with open(stem + ".json") as f:
                    j = json.load(f)
                check(j["rig"]["camera"] == name and j["frame"] == frame, f"{stem}.json's rig and frame")
                check(abs(j["platform"]["time_s"] - (5.0 + frame / 10.0)) < 1e-12, f"{stem}.json's platform time")
                check(abs(np.linalg.norm(j["platform"]["imu"]["specific_force_mps2"]) - 9.80665) < 1e-9,
                      "a fixed platform's IMU reads g")
                # The increments since the clip's frame before: none for its
                # first; over 0.1 s at rest, g times 0.1 s and no turn.
                increment = j["platform"]["imu"]["increment"]
                if frame == 0:
                    check(increment is None, f"{stem}.json: a clip's first frame has no increment")
                else:
                    check(increment is not None and abs(increment["from_s"] - 5.0) < 1e-12
                          and abs(increment["to_s"] - 5.1) < 1e-12, f"{stem}.json's increment's interval")
                    if increment is not None:
                        check(abs(np.linalg.norm(increment["delta_velocity_mps"]) - 0.980665) < 1e-9,
                              f"{stem}.json: at rest the delta velocity is g dt")
                        check(np.linalg.norm(increment["delta_angle_rad"]) < 1e-12,
                              f"{stem}.json: at rest no delta angle")
    with open(os.path.join(data, "coco.json")) as f:
        coco = json.load(f)
    check(len(coco["images"]) == 4 and {i["camera"] for i in coco["images"]} == {"left", "right"},
          "coco.json has an image per camera per frame")
    # Run again: everything is done, nothing rendered.
    r = run("dataset", sweep, "--out", data)
    check(r.returncode == 0 and "0 samples to render, 1 done already" in r.stderr,
          f"the rig's sample is done: {r.stderr.strip()}")


def render_sequence():
    # `swell render --duration --labels`: each frame after the first carries
    # the IMU's increments since the frame before (at rest: g dt, no turn).
    scene = write("rig-sequence.toml", STEREO)
    out = os.path.join(work, "rig-sequence", "seq.png")
    r = run("render", scene, "-o", out, "--size", "64x48", "--labels", "--time", "5", "--duration", "0.2",
            "--fps", "10")
    check(r.returncode == 0, f"rig sequence render exited {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        return
    for frame in range(2):
        for name in ("left", "right"):
            path = os.path.join(work, "rig-sequence", f"seq_{frame:05d}.{name}.json")
            check(os.path.exists(path), f"{path} missing")
            if not os.path.exists(path):
                continue
            with open(path) as f:
                increment = json.load(f)["platform"]["imu"]["increment"]
            if frame == 0:
                check(increment is None, f"{path}: the sequence's first frame has no increment")
            else:
                check(increment is not None and abs(increment["to_s"] - increment["from_s"] - 0.1) < 1e-12
                      and abs(np.linalg.norm(increment["delta_velocity_mps"]) - 0.980665) < 1e-9,
                      f"{path}: the increment over 0.1 s at rest is g dt: {increment}")


stereo_disparity()
duplicate_names()
clip_sweep()
render_sequence()
if failures:
    print(f"{len(failures)} failure(s)")
    sys.exit(1)
print("rig: all checks passed")
