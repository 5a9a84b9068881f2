#!/usr/bin/env python3
"""A 64x36 still of every scene at the corners of the documented limits
(issue 48): rendered in under 60 s of CPU time (so under 60 s on an idle
reference machine, docs/PERFORMANCE.md "A still's history"), or refused up
front, within a few seconds, saying why. A corner refused for its history's cost is then
rendered with the history_start_s its message says fits, which must be
drawn in time too.

Minutes of rendering: registered only with -DSWELL_LIMITS_TESTS=ON (label
`limits`); the refusals alone are quick and run by default
(tests/cpu/test_frame_request.cpp, tests/apps/test_cli_errors.py).

usage: test_still_limits.py SWELL_EXECUTABLE WORK_DIR
"""
import json
import os
import re
import resource
import shutil
import struct
import subprocess
import sys
import time

swell, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []
LIMIT_S = 60.0
REFUSED_WITHIN_S = 5.0


def cube_sphere_glb(path, n, radius_m):
    """A closed sphere of 12 n^2 triangles (a cube's faces projected), as a .glb."""
    index, positions, triangles = {}, [], []

    def vertex(p):
        if p not in index:
            index[p] = len(positions)
            length = (p[0] ** 2 + p[1] ** 2 + p[2] ** 2) ** 0.5
            positions.append(tuple(radius_m * c / length for c in p))
        return index[p]

    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for sign in (-1, 1):
            for i in range(n):
                for j in range(n):
                    def at(a, b):
                        p = [0, 0, 0]
                        p[axis], p[u], p[v] = sign * n, -n + 2 * a, -n + 2 * b
                        return vertex(tuple(p))
                    q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
                    if sign < 0:
                        q[1], q[3] = q[3], q[1]
                    triangles += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    vertices = b"".join(struct.pack("<3f", *p) for p in positions)
    indices = b"".join(struct.pack("<3I", *t) for t in triangles)
    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]
    gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "buffers": [{"byteLength": len(vertices) + len(indices)}],
            "bufferViews": [{"buffer": 0, "byteLength": len(vertices)},
                            {"buffer": 0, "byteOffset": len(vertices), "byteLength": len(indices)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
                           "min": lo, "max": hi},
                          {"bufferView": 1, "componentType": 5125, "count": 3 * len(triangles), "type": "SCALAR"}]}
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    binary = vertices + indices
    with open(path, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(binary)))
        f.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        f.write(struct.pack("<II", len(binary), 0x004E4942) + binary)
    return len(triangles)


def boats(count, under_way=True):
    text = ""
    for i in range(count):
        text += (f'\n[[objects]]\npath = "builtin:boat"\nposition_m = [{30.0 * (i % 16) - 240.0}, 0.0, '
                 f'{-30.0 * (i // 16) - 20.0}]\nfloats = true\nmass_kg = 2500.0\n'
                 f'center_of_mass_offset_m = [-0.598, -0.203, 0.0]\n')
        if under_way:
            text += "velocity_m_per_s = [0.0, 0.0, -4.0]\n"
    return text


GERSTNER_MOST = '[waves.wind]\nspeed_mps = 12.0\ncount = 64\n'
SPECTRAL = '[waves]\nmodel = "spectral"\nfoam_lifetime_s = 60.0\n\n[waves.wind]\nspeed_mps = 20.0\n'
CAMERA = '\n[camera]\nposition_m = [0.0, 6.0, 0.0]\npitch_deg = -8.0\n'

triangles = cube_sphere_glb(os.path.join(work, "hull.glb"), 408, 1.5)
assert triangles == 1997568, triangles
CORNERS = [
    ("256 boats under way, 64 waves", GERSTNER_MOST + boats(256) + CAMERA),
    ("256 boats under way, spectral", SPECTRAL + boats(256) + CAMERA),
    ("256 boats at rest, spectral", SPECTRAL + boats(256, under_way=False) + CAMERA),
    ("a 2,000,000-triangle hull", GERSTNER_MOST + '\n[[objects]]\npath = "hull.glb"\nposition_m = [0.0, 0.0, -20.0]\n'
     'floats = true\ndensity_kg_per_m3 = 500.0\nvelocity_m_per_s = [0.0, 0.0, -4.0]\n' + CAMERA),
    ("a wake of 1021 cells", GERSTNER_MOST + '\n[wake]\ncells = 1021\n' + boats(1) + CAMERA),
    ("a wake of 1024 cells, spectral", SPECTRAL + '\n[wake]\ncells = 1024\n' + boats(1) + CAMERA),
    ("a grid of 2048 vertices a side", GERSTNER_MOST + '\n[grid]\nresolution = 2048\n' + CAMERA),
    ("the longest foam", SPECTRAL + CAMERA),
    ("shallow water of a denormal depth", '[waves]\ndepth_m = 1e-310\n\n' + GERSTNER_MOST + boats(1) + CAMERA),
]


def render(path, time_s):
    """The render's result and its CPU time, s (user and system, every thread):
    what the still costs, however busy the machine is (its wall time on an
    idle one is no more; the wall time is printed too)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.monotonic()
    r = subprocess.run([swell, "render", path, "-o", path[:-5] + ".png", "--size", "64x36", "--time", str(time_s)],
                       capture_output=True, text=True, timeout=900)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu_s = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    print(f"  ({cpu_s:.1f} s of CPU, {time.monotonic() - started:.1f} s of wall time)")
    return r, cpu_s


for number, (name, text) in enumerate(CORNERS):
    path = os.path.join(work, f"corner{number}.toml")
    with open(path, "w") as f:
        f.write(text)
    for time_s in (1.0, 3600.0):
        r, seconds = render(path, time_s)
        if r.returncode == 2:
            fits = re.search(r"history_start_s = (-?[0-9.e+]+) fits", r.stderr)
            if seconds > REFUSED_WITHIN_S or not fits:
                failures.append(f"{name} at {time_s} s: refused after {seconds:.1f} s: {r.stderr.strip()[:300]}")
                continue
            print(f"{name} at {time_s} s: refused in {seconds:.1f} s ({fits.group(0)})")
            # With the start its message says fits: drawn in time.
            with open(path, "w") as f:
                f.write(f"history_start_s = {fits.group(1)}\n" + text)
            r, seconds = render(path, time_s)
            with open(path, "w") as f:
                f.write(text)
        if r.returncode != 0 and r.returncode != 2:
            failures.append(f"{name} at {time_s} s: exit {r.returncode}: {r.stderr.strip()[:300]}")
        elif r.returncode == 0 and seconds > LIMIT_S:
            failures.append(f"{name} at {time_s} s: drawn in {seconds:.1f} s of CPU, over {LIMIT_S:.0f} s")
        elif r.returncode == 2 and seconds > REFUSED_WITHIN_S:
            failures.append(f"{name} at {time_s} s: refused after {seconds:.1f} s")
        print(f"{name} at {time_s} s: exit {r.returncode} in {seconds:.1f} s")

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
