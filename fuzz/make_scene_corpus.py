#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_scene into fuzz/corpus/scene/.

The presets in scenes/ are copied as valid_<name>.toml; the rest are small
variations, each reaching one part of the parser: every section, listed
waves, a camera path, sky faces and model paths (the fuzz target's folder
holds model.gltf and model.glb), inline tables, and invalid_* files for the
errors (bad syntax, unknown keys, out-of-range and non-finite values, broken
cross-field rules, nesting past the limits). Files that once crashed the
parser (crash-*) are kept in the same folder and are not written here.
"""
import pathlib
import shutil

root = pathlib.Path(__file__).resolve().parent.parent
out = root / "fuzz" / "corpus" / "scene"
out.mkdir(parents=True, exist_ok=True)

for preset in sorted((root / "scenes").glob("*.toml")):
    shutil.copy(preset, out / f"valid_{preset.name}")

seeds = {
    "valid_empty.toml": "",
    "valid_listed_waves.toml": """[waves]
depth_m = 30.0
[[waves.list]]
direction = [1.0, 0.5]
wavelength_m = 40.0
amplitude_m = 0.4
steepness = 0.7
phase_rad = 1.0
[[waves.list]]
direction = [-0.2, 1.0]
wavelength_m = 7.5
amplitude_m = 0.05
""",
    "valid_inline.toml": """terrain = false
grid = { resolution = 64, radius_m = 500.0, fade_start_m = 100.0, fade_end_m = 400.0 }
reflection = { mode = "fixed", fixed_distance_m = 2.0, resolution_scale = 0.25, clip_offset_m = 0.1 }
waves.wind.speed_mps = 12.0
waves.wind.count = 8
""",
    "valid_objects.toml": """[[objects]]
path = "model.gltf"
position_m = [1.0, 2.0, 3.0]
scale = 2.5
[[objects]]
path = "model.glb"
yaw_deg = -90.0
floats = true
[[objects]]
path = "builtin:buoy"
""",
    "valid_camera_path.toml": """[camera]
position_m = [0.0, 3.0, 0.0]
yaw_deg = 10.0
pitch_deg = -4.0
fov_y_deg = 50.0
near_m = 0.5
far_m = 9000.0
[[camera.path]]
time_s = 0.0
position_m = [0.0, 3.0, 0.0]
[[camera.path]]
time_s = 5.5
position_m = [10.0, 4.0, -3.0]
yaw_deg = 20.0
pitch_deg = -10.0
""",
    "valid_sky_sun_fog_water.toml": """[sun]
direction = [0.0, 1.0, 0.0]
color = [1.0, 1.0, 1.0]
intensity = 3.0
[sky]
zenith_color = [0.1, 0.2, 0.3]
horizon_color = [0.5, 0.6, 0.7]
faces = []
[fog]
start_m = 0.0
end_m = 1e6
color = [0.0, 0.0, 0.0]
[water]
deep_color = [0.0, 0.1, 0.2]
absorption_per_m = [1.0, 0.5, 0.25]
fresnel_f0 = 0.02
shininess = 10000
specular_strength = 0.0
refraction_distortion = 1.0
""",
    "invalid_syntax.toml": "[grid\nresolution = 64\n",
    "invalid_unknown_key.toml": "[grid]\nresolutoin = 64\n",
    "invalid_type.toml": "[fog]\nstart_m = \"near\"\n",
    "invalid_nan.toml": "[fog]\nstart_m = nan\n",
    "invalid_inf.toml": "[grid]\nradius_m = inf\n",
    "invalid_negative_wavelength.toml": "[[waves.list]]\nwavelength_m = -3.0\n",
    "invalid_zero_direction.toml": "[[waves.list]]\ndirection = [0.0, 0.0]\n",
    "invalid_huge_resolution.toml": "[grid]\nresolution = 9223372036854775807\n",
    "invalid_fog_order.toml": "[fog]\nstart_m = 500.0\nend_m = 100.0\n",
    "invalid_path_order.toml": "[[camera.path]]\ntime_s = 2.0\n[[camera.path]]\ntime_s = 1.0\n",
    "invalid_missing_model.toml": "[[objects]]\npath = \"missing.glb\"\n",
    "invalid_builtin.toml": "[[objects]]\npath = \"builtin:whale\"\n",
    "invalid_deep_nesting.toml": "a = " + "[" * 40 + "]" * 40 + "\n",
    "invalid_long_key.toml": "waves." + ".".join(["x"] * 20) + " = 1\n",
    "invalid_binary.toml": "terrain = true\n\x01\x02\x7f\n",
}
for name, text in seeds.items():
    (out / name).write_text(text, encoding="utf-8")
