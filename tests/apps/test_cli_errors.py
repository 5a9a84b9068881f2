#!/usr/bin/env python3
"""Feeds the swell executable malformed scene files and argument lists.

Each case must exit with its documented code (2: bad input, 0: fine) and say
where the problem is; none may crash (a signal, or exit codes other than 0/1/2).
usage: test_cli_errors.py SWELL_EXECUTABLE WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

swell, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)

# (name, scene text, expected "line:column" or "" for file-level errors, substring of the message)
SCENES = [
    ("syntax", "[fog\nstart_m = 1\n", "1:", "TOML"),
    ("unknown_key", "[fog]\nstrat_m = 10.0\n", "2:1", "start_m"),
    ("wrong_type", "[fog]\nstart_m = \"far\"\n", "2:", "fog.start_m"),
    ("negative_fog_end", "[fog]\nend_m = -5.0\n", "2:", "fog.end_m"),
    ("fog_order", "[fog]\nstart_m = 500.0\nend_m = 100.0\n", "3:", "fog.end_m"),
    ("nan", "[sun]\nintensity = nan\n", "2:", "sun.intensity"),
    ("infinite", "[water]\nshininess = inf\n", "2:", "water.shininess"),
    ("huge_grid", "[grid]\nresolution = 100000000\n", "2:", "grid.resolution"),
    ("negative_radius", "[grid]\nradius_m = -1.0\n", "2:", "grid.radius_m"),
    ("zero_wavelength", "[[waves.list]]\ndirection = [1.0, 0.0]\nwavelength_m = 0.0\namplitude_m = 0.1\n", "3:", "wavelength_m"),
    ("negative_amplitude", "[[waves.list]]\ndirection = [1.0, 0.0]\nwavelength_m = 5.0\namplitude_m = -0.1\n", "4:", "amplitude_m"),
    ("zero_direction", "[[waves.list]]\ndirection = [0.0, 0.0]\nwavelength_m = 5.0\namplitude_m = 0.1\n", "2:", "direction"),
    ("steepness_above_one", "[[waves.list]]\ndirection = [1.0, 0.0]\nwavelength_m = 5.0\namplitude_m = 0.1\nsteepness = 3.0\n", "5:", "steepness"),
    ("wind_too_fast", "[waves.wind]\nspeed_mps = 400.0\n", "2:", "speed_mps"),
    ("too_many_waves", "".join("[[waves.list]]\ndirection = [1.0, 0.0]\nwavelength_m = 5.0\namplitude_m = 0.01\n" for _ in range(65)), "257:", "waves.list"),
    ("bad_reflection_mode", "[reflection]\nmode = \"mirror\"\n", "2:", "reflection.mode"),
    ("bad_debug_view", "debug_view = \"xray\"\n", "1:", "debug_view"),
    ("bad_antialiasing", "antialiasing = \"8x\"\n", "1:", "antialiasing"),
    ("missing_model", "[[objects]]\npath = \"no/such/model.glb\"\n", "2:", "no/such/model.glb"),
    ("unknown_builtin", "[[objects]]\npath = \"builtin:submarine\"\n", "2:", "builtin:submarine"),
    ("camera_path_unsorted", "[[camera.path]]\ntime_s = 5.0\n[[camera.path]]\ntime_s = 1.0\n", "4:", "camera.path"),
    ("fov_out_of_range", "[camera]\nfov_y_deg = 179.5\n", "2:", "fov_y_deg"),
    ("deep_nesting", "a = " + "[" * 200 + "]" * 200 + "\n", "1:", "nest"),
    ("binary_garbage", None, "", "UTF-8"),
    ("sky_faces_count", "[sky]\nfaces = [\"a.png\"]\n", "2:", "sky.faces"),
    ("body_sinks", "[[objects]]\npath = \"builtin:boat\"\nfloats = true\ndensity_kg_per_m3 = 5000.0\n", "2:", "sinks"),
    ("body_mass_twice", "[[objects]]\npath = \"builtin:boat\"\nfloats = true\nmass_kg = 900.0\ndensity_kg_per_m3 = 200.0\n",
     "5:", "gives both mass_kg"),
    ("hull_node_of_builtin", "[[objects]]\npath = \"builtin:boat\"\nhull_node = \"Hull\"\n", "3:", "hull_node"),
    # Bodies within the documented ranges that the fixed step cannot follow:
    # refused at the object, naming the key (they once crashed on a NaN index).
    ("body_gram_hull", "[[objects]]\npath = \"builtin:boat\"\nfloats = true\nmass_kg = 0.001\n", "2:8",
     "objects[0].mass_kg = 0.001"),
    ("body_least_density", "[[objects]]\npath = \"builtin:boat\"\nfloats = true\ndensity_kg_per_m3 = 5e-324\n", "2:8",
     "objects[0].density_kg_per_m3"),
    ("wake_too_coarse", "[wake]\ncell_size_m = 50.0\n", "2:", "wake.cell_size_m"),
    # The sun placed by date, time and place: each mistake names its key.
    ("sun_date_without_time", "[sun]\ntime = 2003-10-17\nlatitude_deg = 39.7\nlongitude_deg = -105.2\n", "2:8",
     "sun.time must be a date and time with its UTC offset"),
    ("sun_time_without_offset", "[sun]\ntime = 2003-10-17T12:30:30\nlatitude_deg = 39.7\nlongitude_deg = -105.2\n",
     "2:8", "sun.time has no UTC offset"),
    ("sun_latitude_out_of_range", "[sun]\ntime = 2003-10-17T12:30:30-07:00\nlatitude_deg = 95.0\nlongitude_deg = 0.0\n",
     "3:16", "sun.latitude_deg = 95 is out of range"),
    # A lens that folds the image: one rule (docs/SCENE.md, "The lens"), at
    # the first coefficient's line, naming the coefficients set (issue 48).
    ("lens_tangential_fold", "[camera]\nfov_y_deg = 120.0\ndistortion_p1 = 0.1\ndistortion_p2 = 0.1\n", "3:",
     "camera.distortion_p1 = 0.1 and camera.distortion_p2 = 0.1: no ray reaches"),
    ("lens_radial_fold_150", "[camera]\nfov_y_deg = 150.0\ndistortion_k1 = -1.0\ndistortion_k2 = -1.0\n"
     "distortion_k3 = -1.0\n", "3:", "camera.distortion_k3 = -1"),
    ("clouds_coverage", "[sky.clouds]\ncoverage = 0.5\n", "2:1", "did you mean 'sky.clouds.cover'"),
    # An object's class key, empty (issue 46): at its place, nothing written.
    ("object_class_empty", "[[objects]]\npath = \"builtin:buoy\"\nclass = \"\"\n", "3:9", "objects[0].class is empty"),
    # The sun by its angles, as sweeps vary it: both keys, and not with another form.
    ("sun_elevation_alone", "[sun]\nelevation_deg = 20.0\n", "2:", "sun.azimuth_deg is missing"),
    ("sun_elevation_misspelt", "[sun]\nelevation = 20.0\nazimuth_deg = 0.0\n", "2:1",
     "did you mean 'sun.elevation_deg'"),
    ("sun_direction_and_time",
     "[sun]\ndirection = [0.0, 1.0, 0.0]\ntime = 2003-10-17T12:30:30-07:00\nlatitude_deg = 39.7\nlongitude_deg = 0.0\n",
     "3:8", "exclude each other"),
]

# Scenes that must render (exit 0): every documented table, bodies at the
# ranges' edges that simulate, a wake. A short time keeps them quick under
# the sanitizers.
GOOD_SCENES = [
    ("wake_table", "[wake]\nenabled = true\ncells = 64\ncell_size_m = 2.0\n"
     "[[objects]]\npath = \"builtin:boat\"\nfloats = true\ndensity_kg_per_m3 = 250.0\n"
     "velocity_m_per_s = [0.0, 0.0, -4.0]\n"),
    ("body_high_centre_of_mass", "[[objects]]\npath = \"builtin:boat\"\nfloats = true\ndensity_kg_per_m3 = 300.0\n"
     "center_of_mass_offset_m = [0.0, 1000.0, 0.0]\n"),
    ("body_as_dense_as_water", "[[objects]]\npath = \"builtin:buoy\"\nfloats = true\ndensity_kg_per_m3 = 1025.0\n"),
    ("body_keys_not_floating", "[[objects]]\npath = \"builtin:buoy\"\nmass_kg = 100.0\n"),
    ("floating_rock", "[[objects]]\npath = \"builtin:rock\"\nfloats = true\ndensity_kg_per_m3 = 600.0\n"),
    # A body under way in water of a denormal depth: drawn (its wake once turned NaN).
    ("depth_denormal_under_way", "[waves]\ndepth_m = 1e-310\n[wake]\ncells = 64\n"
     "[[objects]]\npath = \"builtin:boat\"\nfloats = true\ndensity_kg_per_m3 = 250.0\n"
     "velocity_m_per_s = [0.0, 0.0, -4.0]\n"),
    ("sun_placed", "[sun]\ntime = 2003-10-17T12:30:30-07:00\nlatitude_deg = 39.742476\nlongitude_deg = -105.1786\n"
     "[sky]\nmodel = \"physical\"\n"),
]

# (name, arguments, expected exit code, substring of stderr)
ARGUMENTS = [
    ("no_output", ["render"], 2, "--output"),
    ("bad_size", ["render", "-o", "x.png", "--size", "big"], 2, "--size"),
    ("zero_size", ["render", "-o", "x.png", "--size", "0x10"], 2, "--size"),
    ("huge_size", ["render", "-o", "x.png", "--size", "99999x99999"], 2, "--size"),
    ("negative_time", ["render", "-o", "x.png", "--time", "-3"], 2, "--time"),
    ("nan_time", ["render", "-o", "x.png", "--time", "nan"], 2, "--time"),
    ("bad_fps", ["render", "-o", "x.png", "--duration", "1", "--fps", "0"], 2, "--fps"),
    ("bad_extension", ["render", "-o", "x.jpg"], 2, ".png or .mp4"),
    ("mp4_without_duration", ["render", "-o", "x.mp4"], 2, "--duration"),
    ("missing_scene", ["render", "nowhere.toml", "-o", "x.png"], 2, "nowhere.toml"),
    ("scene_is_a_folder", ["render", work, "-o", "x.png"], 2, work),
    ("unknown_subcommand", ["paint"], 2, "paint"),
    # A mistyped subcommand: every subcommand listed, and the nearest one.
    ("mistyped_subcommand", ["rendr"], 2, "the subcommands are view, render, bench and dataset"),
    ("mistyped_subcommand_nearest", ["rendr"], 2, "did you mean `swell render`?"),
    ("mistyped_dataset", ["datset"], 2, "did you mean `swell dataset`?"),
    ("unknown_option", ["render", "-o", "x.png", "--colour", "red"], 2, "--colour"),
    ("bench_bad_frames", ["bench", "--frames", "0"], 2, "--frames"),
    ("range_in_words", ["render", "-o", "x.png", "--time", "-3"], 2, "must be a number from 0 to 1e+09, got '-3'"),
    # A scene file without a subcommand: the commands that take it.
    ("scene_without_subcommand", ["evening.toml"], 2, "swell view evening.toml"),
    # Neither a file nor a preset: the presets are listed.
    ("unknown_preset", ["render", "no-such-sea", "-o", "x.png"], 2, "calm, cloud-shadows, coast, fleet, fog, gale-under-way, harbour, paper, storm"),
    # The render scale: 0.1..2, a finite number, on every subcommand that draws.
    *[(f"render_scale_{v}", ["render", "-o", "x.png", "--scale", v], 2, "--scale")
      for v in ("0", "-1", "5", "abc", "nan", "0.05")],
    *[(f"view_scale_{v}", ["view", "--scale", v], 2, "--scale") for v in ("0", "-1", "5", "abc")],
    ("bench_scale_zero", ["bench", "--scale", "0"], 2, "--scale"),
    # The viewer's temporal resolve and dynamic resolution.
    ("view_bad_temporal", ["view", "--temporal", "sometimes"], 2, "--temporal"),
    *[(f"view_frame_target_{v}", ["view", "--frame-target", v], 2, "--frame-target") for v in ("-5", "abc", "20000")],
    ("bad_antialiasing", ["render", "-o", "x.png", "--antialiasing", "8x"], 2, "--antialiasing"),
    ("view_bad_antialiasing", ["view", "--antialiasing", "on"], 2, "--antialiasing"),
    ("bodies_far_in_time", ["render", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes",
                                                   "under-way.toml"), "-o", "x.png", "--time", "5000"], 2, "--time"),
    # Within the bodies' hour but past the wake's 10 minutes.
    ("wake_far_in_time", ["render", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes",
                                                 "under-way.toml"), "-o", "x.png", "--time", "900"], 2, "wake"),
]

failures = []
count = 0

# Reports of AddressSanitizer and UndefinedBehaviorSanitizer, when swell is
# such a build (.ci/sanitize): a hostile input that corrupts memory without
# crashing must still fail its case.
SANITIZER_REPORTS = ("ERROR: AddressSanitizer", "runtime error:", "ERROR: LeakSanitizer")


def run(args):
    # A hang (a FIFO opened the blocking way) fails as a timeout, far past
    # the second or so any case takes.
    try:
        r = subprocess.run([swell] + args, cwd=work, capture_output=True, text=True, timeout=300,
                           env=dict(os.environ, DISPLAY=""), errors="replace")
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(args, -1, "", "timed out: swell hung")
    for report in SANITIZER_REPORTS:
        if report in r.stderr:
            failures.append(f"{args}: sanitizer report: {r.stderr.strip()[:600]!r}")
    return r


for name, text, place, needle in SCENES:
    count += 1
    path = os.path.join(work, name + ".toml")
    with open(path, "wb") as f:
        f.write(bytes(range(256)) * 8 if text is None else text.encode())
    r = run(["render", path, "-o", os.path.join(work, name + ".png"), "--size", "32x32"])
    prefix = path + ":" + place
    if r.returncode != 2 or prefix not in r.stderr or needle not in r.stderr:
        failures.append(f"scene {name}: exit {r.returncode}, stderr: {r.stderr.strip()[:300]!r} "
                        f"(wanted exit 2 with {prefix!r} and {needle!r})")
    if os.path.exists(os.path.join(work, name + ".png")):
        failures.append(f"scene {name}: a bad scene still wrote an image")

for name, text in GOOD_SCENES:
    count += 1
    path = os.path.join(work, name + ".toml")
    with open(path, "w") as f:
        f.write("[waves.wind]\nspeed_mps = 9.0\n" + text)
    out = os.path.join(work, name + ".png")
    r = run(["render", path, "-o", out, "--size", "32x32", "--time", "10"])
    if r.returncode != 0 or not os.path.exists(out):
        failures.append(f"good scene {name}: exit {r.returncode}, stderr: {r.stderr.strip()[:300]!r} (wanted exit 0)")

for name, args, code, needle in ARGUMENTS:
    count += 1
    r = run(args)
    if r.returncode != code or needle not in r.stderr + r.stdout:
        failures.append(f"arguments {name} {args}: exit {r.returncode}, output: {(r.stderr + r.stdout).strip()[:300]!r} "
                        f"(wanted exit {code} with {needle!r})")

# Scenes whose model is a broken glTF: the scene loads (the file exists), the
# renderer's loader refuses the model, and the error names the model's file.
# valid_triangle.glb of the fuzz corpus cut short, and a .gltf whose buffer
# claims more bytes than its file has.
corpus = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "fuzz", "corpus", "gltf")
with open(os.path.join(corpus, "valid_triangle.glb"), "rb") as f:
    glb = f.read()
MODELS = [
    ("truncated_glb", "truncated.glb", glb[: len(glb) // 2]),
    ("lying_buffer", "lying.gltf", b'{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4096, "uri": "short.bin"}],'
     b' "bufferViews": [{"buffer": 0, "byteLength": 4096}], "accessors": [{"bufferView": 0, "componentType": 5126,'
     b' "count": 3, "type": "VEC3"}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],'
     b' "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}'),
]
with open(os.path.join(work, "short.bin"), "wb") as f:
    f.write(bytes(36))
for name, model, data in MODELS:
    count += 1
    with open(os.path.join(work, model), "wb") as f:
        f.write(data)
    scene = os.path.join(work, name + ".toml")
    with open(scene, "w") as f:
        f.write(f'[[objects]]\npath = "builtin:buoy"\n[[objects]]\n  path = "{model}"\n')
    r = run(["render", scene, "-o", os.path.join(work, name + ".png"), "--size", "32x32"])
    # The scene key that named the model, at its place, then the model's file.
    wanted = f"{scene}:4:10: objects[1].path: {os.path.join(work, model)}"
    if r.returncode != 2 or wanted not in r.stderr:
        failures.append(f"model {name}: exit {r.returncode}, stderr: {r.stderr.strip()[:300]!r} "
                        f"(wanted exit 2 with {wanted!r})")

# Special files where a file is read: the scene itself, a model, a sky face.
# Each must be refused naming the file (exit 2), never opened the blocking
# way: a FIFO would hang, /dev/zero never end.
special = os.path.join(work, "special")
shutil.rmtree(special, ignore_errors=True)
os.makedirs(special)
os.mkfifo(os.path.join(special, "fifo.toml"))
os.mkfifo(os.path.join(special, "fifo.glb"))
os.mkfifo(os.path.join(special, "fifo.png"))
os.symlink("/dev/zero", os.path.join(special, "zero.toml"))
os.symlink(os.path.join(special, "missing.toml"), os.path.join(special, "dangling.toml"))
os.symlink(os.path.join(special, "loop2.toml"), os.path.join(special, "loop.toml"))
os.symlink(os.path.join(special, "loop.toml"), os.path.join(special, "loop2.toml"))
with open(os.path.join(special, "fifo_model.toml"), "w") as f:
    f.write('[[objects]]\npath = "fifo.glb"\n')
with open(os.path.join(special, "fifo_face.toml"), "w") as f:
    f.write('[sky]\nfaces = ["fifo.png", "fifo.png", "fifo.png", "fifo.png", "fifo.png", "fifo.png"]\n')
SPECIAL = [
    ("fifo.toml", "", "FIFO"),
    ("zero.toml", "", "character device"),
    ("dangling.toml", "", "symbolic link to a file that does not exist"),
    ("loop.toml", "", "loop"),
    ("fifo_model.toml", ":2:8: objects[0].path", "FIFO"),
    ("fifo_face.toml", ":2:10: sky.faces[0]", "FIFO"),
]
for scene, place, needle in SPECIAL:
    count += 1
    path = os.path.join(special, scene)
    r = run(["render", path, "-o", os.path.join(special, "out.png"), "--size", "32x32"])
    if r.returncode != 2 or path + place not in r.stderr or needle not in r.stderr:
        failures.append(f"special {scene}: exit {r.returncode}, stderr: {r.stderr.strip()[:300]!r} "
                        f"(wanted exit 2 with {path + place!r} and {needle!r})")

# And a good one, so the cases above fail for their own reasons.
count += 1
r = run(["render", "-o", "good.png", "--size", "48x27"])
if r.returncode != 0 or not os.path.exists(os.path.join(work, "good.png")):
    failures.append(f"the default scene did not render: {r.returncode} {r.stderr[:300]!r}")

# A refused lens, or a history past the bound, makes no output folder: the
# whole request is checked first. And the lens refused names no coefficient
# it does not set.
lens = os.path.join(work, "lens_tangential_fold.toml")
for name, args in [("lens", [lens]), ("history", [os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                               "scenes", "under-way.toml"), "--time", "5000"])]:
    count += 1
    folder = os.path.join(work, "not_made_" + name)
    shutil.rmtree(folder, ignore_errors=True)
    r = run(["render", *args, "-o", os.path.join(folder, "deeper", "x.png"), "--size", "64x36"])
    if r.returncode != 2 or os.path.exists(folder) or "distortion_k1" in r.stderr:
        failures.append(f"{name} refused after making its folder: exit {r.returncode}, {r.stderr.strip()[:300]!r}")

# A render scale draws smaller (or larger) but writes the size asked for.
def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


for scale, antialiasing in (("0.5", "off"), ("0.1", "fxaa"), ("2", "msaa4")):
    count += 1
    out = os.path.join(work, f"scaled_{scale}.png")
    r = run(["render", "-o", out, "--size", "48x27", "--scale", scale, "--antialiasing", antialiasing])
    if r.returncode != 0 or not os.path.exists(out) or png_size(out) != (48, 27):
        failures.append(f"--scale {scale} --antialiasing {antialiasing}: exit {r.returncode}, "
                        f"size {png_size(out) if os.path.exists(out) else None}, {r.stderr[:300]!r}")

# The help names types and ranges in words (SECONDS:0..3600), not CLI11's
# validator names, and says as many renders a frame for `bench --terms` as
# docs/PERFORMANCE.md does.
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
for command in ("view", "render", "bench"):
    count += 1
    r = run([command, "--help"])
    noise = [n for n in ("FINITE", " AND ", "FLOAT", "INT in", "TEXT:") if n in r.stdout]
    if r.returncode != 0 or noise:
        failures.append(f"{command} --help: exit {r.returncode}, validator noise {noise}: {r.stdout[:600]!r}")
    if command == "render" and ("--time SECONDS:0..1e+09" not in r.stdout or "--duration SECONDS:0..3600" not in r.stdout):
        failures.append(f"render --help does not show --time's and --duration's ranges: {r.stdout[:900]!r}")
    if command == "bench":
        renders = re.search(r"(\d+) renders a measured frame", r.stdout.replace("\n", " "))
        with open(os.path.join(root, "docs", "PERFORMANCE.md"), encoding="utf-8") as f:
            docs = f.read()
        if not renders or f"{renders.group(1)} renders a measured frame" not in docs:
            failures.append(f"bench --help and docs/PERFORMANCE.md disagree on --terms' renders a frame: {r.stdout[:900]!r}")

# A preset by its name, from a folder without such a file.
count += 1
r = run(["render", "calm", "-o", "preset.png", "--size", "32x18"])
if r.returncode != 0 or not os.path.exists(os.path.join(work, "preset.png")):
    failures.append(f"the preset 'calm' by name: exit {r.returncode}, {r.stderr[:300]!r}")

# A sequence's progress gives the time left (stderr is not a terminal here: plain lines).
count += 1
r = run(["render", "-o", "sequence.png", "--duration", "0.3", "--fps", "10", "--size", "32x18"])
if r.returncode != 0 or "rendering frames: 1/3" not in r.stderr or "left" not in r.stderr:
    failures.append(f"a sequence's progress: exit {r.returncode}, no time left in {r.stderr[:400]!r}")

for f in failures:
    print("FAIL", f)
print(f"{count - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
