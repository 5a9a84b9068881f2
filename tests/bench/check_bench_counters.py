#!/usr/bin/env python3
"""Runs `swell bench` twice on a small frame and checks that it succeeds and
that everything it counts is identical between the runs: the pipeline
statistics and samples passed of every pass of every measured frame, their
totals (real and floor), the water LOD figures, and Swell's own GPU work of
every frame (dispatches, barriers, mipmaps, bytes written, draw calls), and
the boxes the views' culling tested.
Timings vary and are only checked for being there, the simulation's CPU time
(second line, and its parts in the JSON) among them. The second run adds --terms: only it may print the
shading terms' table and the reflection lookups; both print frames per second
on their first line. It adds --labels too: only it prints the label pass's rows
("labels", "frame + labels" and the optical flow's "flow" in the table of
times, "labels" in the counters) and writes them in the JSON, with a label pass in every measured
frame that drew something; and --motion-vectors: only it prints their row
("motion vectors", the pass that draws a host's motion vectors in the frame
drawn again as a host's) and writes their draws and triangles in the JSON.
The colour frames' counters stay those of the first run: the motion
vectors cost the frame nothing where they are not asked for.

Usage: check_bench_counters.py SWELL_EXECUTABLE OUTPUT_DIR
"""
import json
import os
import re
import subprocess
import sys

ARGS = ["bench", "--size", "160x90", "--frames", "3", "--warmup", "1"]


def run(swell, json_path, terms):
    command = [swell, *ARGS, "--json", json_path, *(["--terms", "--labels", "--motion-vectors"] if terms else [])]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"FAIL: {' '.join(command)} exited {result.returncode}\n{result.stdout}\n{result.stderr}")
    if "Time per pass" not in result.stdout or "goals" not in result.stdout:
        sys.exit(f"FAIL: no table on stdout:\n{result.stdout}")
    if not re.match(r"[0-9.]+ frames per second \(median frame ", result.stdout):
        sys.exit(f"FAIL: stdout does not start with the frames per second:\n{result.stdout}")
    second = result.stdout.splitlines()[1]
    if not re.match(r"simulation CPU [0-9.]+ ms a frame \(median; p95 [0-9.]+\)", second):
        sys.exit(f"FAIL: the second line is not the simulation's CPU time:\n{result.stdout}")
    if "Swell's GPU work a frame" not in result.stdout:
        sys.exit(f"FAIL: no table of Swell's GPU work:\n{result.stdout}")
    for table in ("Water shading terms", "Reflection lookup"):
        if (table in result.stdout) != terms:
            sys.exit(f"FAIL: '{table}' {'missing with' if terms else 'printed without'} --terms:\n{result.stdout}")
    labels = terms
    rows = [re.match(r"\s+(labels|frame \+ labels|flow)\s+[0-9.]+ ", line) for line in result.stdout.splitlines()]
    rows = [m.group(1) for m in rows if m]
    # "labels" twice (times, counters), "frame + labels" and "flow" once, only with --labels.
    if sorted(rows) != (["flow", "frame + labels", "labels", "labels"] if labels else []):
        sys.exit(f"FAIL: the label pass's rows {rows} {'with' if labels else 'without'} --labels:\n{result.stdout}")
    # The progress counts frames of the path: warm-up and measured, then the floor's.
    motion = [line for line in result.stdout.splitlines() if re.match(r"\s+motion vectors\s+[0-9.]+ ", line)]
    if len(motion) != (1 if terms else 0):
        sys.exit(f"FAIL: the motion vectors' row {motion} {'with' if terms else 'without'} --motion-vectors:\n"
                 f"{result.stdout}")
    frames, warmup = ARGS[ARGS.index("--frames") + 1], ARGS[ARGS.index("--warmup") + 1]
    path_frames = int(frames) + int(warmup)
    if f" {path_frames}/{path_frames} " not in result.stderr:
        sys.exit(f"FAIL: the progress does not end at {path_frames}/{path_frames} frames:\n{result.stderr}")
    with open(json_path, encoding="utf-8") as f:
        results = json.load(f)
    if (len(results["water_terms"]) > 0) != terms or (len(results["reflection_modes"]) > 0) != terms:
        sys.exit(f"FAIL: JSON water_terms {results['water_terms']!r}, reflection modes {results['reflection_modes']!r} "
                 f"{'with' if terms else 'without'} --terms")
    if (results["labels"] is not None) != labels:
        sys.exit(f"FAIL: JSON labels {results['labels']!r} {'with' if labels else 'without'} --labels")
    if labels:
        totals = results["labels"]["counters_total"]
        sample = results["labels"]["labelled_sample"]
        if (totals["samples_passed"] <= 0 or not results["labels"]["wall_ms"]["median"] > 0.0
                or not sample["wall_ms"]["median"] >= results["labels"]["wall_ms"]["median"]
                or (results["pipeline_statistics"] and totals["fragment_shader_invocations"] <= 0)):
            sys.exit(f"FAIL: the label pass drew nothing, or its sample costs less than itself: {results['labels']!r}")
        flow = results["labels"]["flow"]
        if flow is None or not flow["cpu_ms"]["median"] > 0.0:
            sys.exit(f"FAIL: no optical flow's time with --labels: {results['labels']!r}")
        if any("labels" not in f for f in results["measured_frames"]):
            sys.exit("FAIL: a measured frame without its label pass in the JSON")
    vectors = results["motion_vectors"]
    if (vectors is not None) != terms or (terms and not (vectors["draws"] >= 3 and vectors["triangles"] > 0
                                                        and vectors["wall_ms"]["median"] > 0.0)):
        sys.exit(f"FAIL: JSON motion_vectors {vectors!r} {'with' if terms else 'without'} --motion-vectors")
    if not results["frames_per_second"] > 0.0:
        sys.exit(f"FAIL: frames_per_second {results['frames_per_second']!r}")
    cpu = results["simulation_cpu_ms"]
    # The calling thread's parts, and the bodies' worker's own time (none
    # where no body steps ahead, as in the default scene).
    if (set(cpu) != {"total", "model", "bodies", "queries", "views", "bodies_ahead_worker"}
            or not cpu["total"]["median"] > 0.0 or not cpu["bodies_ahead_worker"]["median"] >= 0.0):
        sys.exit(f"FAIL: simulation_cpu_ms {cpu!r}")
    return results


def deterministic(results):
    """The parts of a result file that must not change from run to run."""
    return {
        "size": results["size"],
        "pass_size": results["pass_size"],
        "surface": results["surface"],
        "grid_cells": results["grid_cells"],
        "frames": results["frames"],
        "totals": {name: (p["counters_total"], p["floor_counters_total"]) for name, p in results["passes"].items()},
        "measured_frames": [
            {
                "time_s": f["time_s"],
                "camera": f["camera"],
                "counters": {name: p["counters"] for name, p in f["passes"].items()},
                "gpu_work": f["gpu_work"],
                "culling": f["culling"],
            }
            for f in results["measured_frames"]
        ],
        "lod": results["lod"],
    }


def differences(a, b, path=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if key not in a or key not in b:
                yield f"{path}/{key}: only in run {'2' if key not in a else '1'}"
            else:
                yield from differences(a[key], b[key], f"{path}/{key}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            yield from differences(x, y, f"{path}[{i}]")
    elif a != b:
        yield f"{path}: {a!r} != {b!r}"


def main():
    swell, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    first = run(swell, os.path.join(out_dir, "bench_run1.json"), terms=False)
    second = run(swell, os.path.join(out_dir, "bench_run2.json"), terms=True)

    problems = list(differences(deterministic(first), deterministic(second)))

    # The counters mean what they say.
    passes = first["passes"]
    for name in ("reflection", "refraction", "main", "water"):
        if name not in passes:
            problems.append(f"pass '{name}' missing")
    if "water" in passes and "main" in passes:
        water, main_pass = passes["water"]["counters_total"], passes["main"]["counters_total"]
        if main_pass["samples_passed"] <= 0:
            problems.append("main pass passed no samples")
        if first["pipeline_statistics"]:
            # Culling leaves out the grid tiles outside the view, never adds any.
            triangles = 2 * first["grid_cells"] ** 2
            if not 0 < water["primitives_submitted"] < first["frames"] * triangles:
                problems.append(f"water primitives submitted {water['primitives_submitted']}, "
                                f"expected some but fewer than {first['frames']} frames x {triangles} triangles")
            for key, value in water.items():
                if value > main_pass[key]:
                    problems.append(f"water {key} {value} exceeds main's {main_pass[key]}, which includes it")
    for lod in first["lod"]:
        if not 0 < lod["triangles"] < 2 * first["grid_cells"] ** 2 or not 0.0 <= lod["in_frustum_share"] <= 1.0:
            problems.append(f"implausible LOD sample {lod}")
        # The LOD figures describe the triangles that frame really drew.
        # The grid is the visibility pass's when the water is drawn in two
        # (the shading pass draws a point per tile).
        frame_passes = first["measured_frames"][lod["frame"]]["passes"]
        frame = frame_passes.get("water visibility", frame_passes.get("water", {}))
        drawn = frame.get("counters", {}).get("primitives_submitted")
        if first["pipeline_statistics"] and drawn != lod["triangles"]:
            problems.append(f"LOD sample of frame {lod['frame']} counts {lod['triangles']} triangles, "
                            f"the frame drew {drawn}")
    for f in first["measured_frames"]:
        # The default scene's waves (Gerstner) dispatch nothing; every view draws.
        work = f["gpu_work"]
        if work["views"]["draw_calls"] <= 0 or work["simulation"]["dispatches"] != 0:
            problems.append(f"implausible GPU work of frame {f['index']}: {work}")
        # The views' culling tests every block of the grid at least,
        # whatever it then keeps.
        if not f["culling"]["boxes_tested"] > 0:
            problems.append(f"no box tested by the culling of frame {f['index']}: {f['culling']}")
    for name, p in passes.items():
        if not p["wall_ms"]["median"] > 0.0 or not p["floor_wall_ms"]["median"] > 0.0:
            problems.append(f"pass '{name}' has no wall time")

    if problems:
        print("FAIL:\n  " + "\n  ".join(problems))
        return 1
    print(f"OK: {len(first['measured_frames'])} frames, counters identical in two runs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
