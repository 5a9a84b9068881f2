#!/usr/bin/env python3
"""The fleet sweep (examples/fleet-sweep.toml; issue 46, item 6, "a sweep over
the fleet writes COCO with every class"): `swell dataset` renders it, and
coco.json has a category for each of the fleet's classes, each with at
least one annotation, and each sample's JSON names them as its objects'
classes; a fleet key on a model outside the fleet is refused (exit 2, its
place, nothing written).

usage: test_fleet_sweep.py SWELL_EXECUTABLE SOURCE_DIR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

swell, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []

FLEET = ["sailing_yacht", "rib", "fishing_trawler", "tug", "container_ship", "tanker", "kayak",
         "lateral_port_buoy", "lateral_starboard_buoy", "cardinal_north_buoy"]

out = os.path.join(work, "data")
run = subprocess.run([swell, "dataset", os.path.join(source, "examples", "fleet-sweep.toml"), "--out", out],
                     capture_output=True, text=True, timeout=900)
if run.returncode != 0:
    failures.append("swell dataset exited %d: %s" % (run.returncode, run.stderr[-2000:]))
else:
    with open(os.path.join(out, "coco.json")) as f:
        coco = json.load(f)
    names = {c["id"]: c["name"] for c in coco["categories"]}
    counts = {name: 0 for name in names.values()}
    for a in coco["annotations"]:
        counts[names[a["category_id"]]] += 1
    for cls in FLEET:
        if cls not in counts:
            failures.append("no COCO category %s (categories: %s)" % (cls, sorted(counts)))
        elif counts[cls] == 0:
            failures.append("COCO category %s has no annotation" % cls)
    print("annotations per class:", json.dumps(counts, sort_keys=True))
    with open(os.path.join(out, "samples", "000000.json")) as f:
        sample = json.load(f)
    seen = {o.get("class_name", o.get("class")) for o in sample["objects"]}
    for cls in FLEET:
        if cls not in seen:
            failures.append("sample 0's JSON has no object of class %s (%s)" % (cls, sorted(map(str, seen))))

# A fleet key on the built-in workboat: refused at its place, nothing made.
bad_folder = os.path.join(work, "bad")
os.makedirs(bad_folder)
with open(os.path.join(bad_folder, "scene.toml"), "w") as f:
    f.write('[[objects]]\npath = "builtin:boat"\nlength_m = 9.0\n')
with open(os.path.join(bad_folder, "sweep.toml"), "w") as f:
    f.write('scene = "scene.toml"\ncount = 1\nsize = [64, 48]\n')
bad_out = os.path.join(work, "bad-out")
run = subprocess.run([swell, "dataset", os.path.join(bad_folder, "sweep.toml"), "--out", bad_out],
                     capture_output=True, text=True, timeout=120)
if run.returncode != 2 or "scene.toml:3:12" not in run.stderr or "length_m" not in run.stderr:
    failures.append("a fleet key on builtin:boat: exit %d, %r" % (run.returncode, run.stderr))
if os.path.exists(bad_out):
    failures.append("a refused sweep made %s" % bad_out)

for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
