#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_sweep into fuzz/corpus/sweep/ and its
dictionary fuzz/sweep.dict.

The fuzz target's folder holds base.toml (a floating boat under way and a
buoy, under the wind's waves), so the sweeps here name it: valid_* ones vary
every kind of key (numbers, whole numbers, vectors, choices and flags as
one_of, an item of a list, the sun's angles, the lens and the field of view,
time ranges), invalid_* ones make each mistake docs/DATASETS.md lists, and
paths out of the folder. Files that once crashed the target (crash-*) are
kept in the same folder and are not written here.
"""
import pathlib
import re

root = pathlib.Path(__file__).resolve().parent.parent
out = root / "fuzz" / "corpus" / "sweep"
out.mkdir(parents=True, exist_ok=True)

HEAD = 'scene = "base.toml"\ncount = 4\nseed = 11\nsize = [64, 48]\ntime_s = [0.0, 100.0]\n'
seeds = {
    "valid_documented.toml": HEAD + """labels = true
[vary]
"waves.wind.speed_mps" = [8.0, 20.0]
"waves.wind.direction_deg" = [0.0, 360.0]
"waves.wind.seed" = [1, 1000]
"camera.position_m" = [[-20.0, 2.0, -20.0], [20.0, 30.0, 20.0]]
"camera.roll_deg" = [-15.0, 15.0]
"camera.pitch_deg" = [-12.0, 2.0]
"objects[0].yaw_deg" = [0.0, 360.0]
"objects[1].position_m" = [[-40.0, 0.0, -120.0], [40.0, 0.0, -30.0]]
"fog.end_m" = [800.0, 5000.0]
"reflection.mode" = { one_of = ["raymarch", "fixed"] }
"sun.elevation_deg" = [5.0, 60.0]
"sun.azimuth_deg" = [0.0, 360.0]
""",
    "valid_lens.toml": HEAD + '[vary]\n"camera.fov_y_deg" = [40.0, 90.0]\n"camera.distortion_k1" = [-0.1, 0.1]\n'
                       '"camera.distortion_p2" = { one_of = [0.0, 0.001] }\n',
    "valid_mount.toml": HEAD + '[vary]\n"camera.mount_object" = [-1, 1]\n"camera.mount_offset_m" = [0.0, 0.0, 0.0]\n',
    "valid_flags.toml": HEAD + '[vary]\n"terrain" = { one_of = [true, false] }\n"wake.enabled" = false\n'
                        '"wake.cells" = [32, 1021]\n',
    "valid_waves.toml": HEAD + '[vary]\n"waves.depth_m" = [1e-310, 30.0]\n"waves.model" = { one_of = ["gerstner", "spectral"] }\n',
    "valid_time_once.toml": 'scene = "base.toml"\ncount = 1\ntime_s = 3600.0\nlabels = false\n',
    "valid_preset.toml": 'scene = "storm"\ncount = 2\n',
    "valid_history.toml": HEAD.replace("[0.0, 100.0]", "[100000.0, 1000000.0]") + '[vary]\n"history_start_s" = [-60.0, 0.0]\n',
    "invalid_escape.toml": HEAD.replace('"base.toml"', '"../../../../etc/passwd"'),
    "invalid_absolute.toml": HEAD.replace('"base.toml"', '"/dev/zero"'),
    "invalid_empty_scene.toml": HEAD.replace('"base.toml"', '""'),
    "invalid_folder_scene.toml": HEAD.replace('"base.toml"', '"."'),
    "invalid_weights.toml": HEAD + '[vary]\n"reflection.mode" = { one_of = ["fixed"], weights = [2] }\n',
    "invalid_empty_range.toml": HEAD + '[vary]\n"camera.roll_deg" = [15.0, -15.0]\n',
    "invalid_out_of_range.toml": HEAD + '[vary]\n"waves.wind.speed_mps" = [4.0, 400.0]\n',
    "invalid_unknown.toml": HEAD + 'cuont = 3\n[vary]\n"camera.rol_deg" = [0.0, 1.0]\n',
    "invalid_no_item.toml": HEAD + '[vary]\n"objects[9].yaw_deg" = [0.0, 1.0]\n',
    "invalid_mount.toml": HEAD + '[vary]\n"camera.mount_object" = [0, 5]\n',
    "invalid_types.toml": 'scene = 3\ncount = "many"\nsize = [1e9, -1]\ntime_s = [nan, inf]\nlabels = 1\nvary = 2\n',
    "invalid_syntax.toml": 'scene = "base.toml"\ncount = [\n',
}
for name, text in seeds.items():
    (out / name).write_text(text)

# The dictionary: the sweep's own keys, and every scene key quoted as a vary key.
keys = set()
for line in (root / "docs" / "SCENE.md").read_text().splitlines():
    m = re.match(r"\| `\[\[?([a-z_.]+)\]?\]` \| `([a-z_0-9]+)` \|", line)
    if m:
        keys.add(f"{m.group(1)}.{m.group(2)}")
    m = re.match(r"\| top level \| `([a-z_0-9]+)` \|", line)
    if m:
        keys.add(m.group(1))
tokens = ["scene", "count", "seed", "size", "time_s", "labels", "[vary]", "one_of", "{ one_of = [", "] }", "[", "]",
          "=", ",", "\\\"", "true", "false", "inf", "nan", "-1", "1e308", "5e-324", "1000000", "../", "/",
          "sun.elevation_deg", "sun.azimuth_deg", "objects[0].", "objects[1].", "camera.path[0]."]
with open(root / "fuzz" / "sweep.dict", "w") as f:
    f.write("# Sweep keys and values for fuzz_sweep (written by make_sweep_corpus.py).\n")
    for t in tokens:
        f.write(f'"{t}"\n')
    for k in sorted(keys):
        f.write(f'"\\"{k.replace("objects.", "objects[0].")}\\""\n')
print(f"{len(seeds)} seeds, {len(tokens) + len(keys)} dictionary entries")
