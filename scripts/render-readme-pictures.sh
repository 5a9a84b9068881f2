#!/usr/bin/env bash
# Renders the README's pictures into docs/images/ with the built swell, as the
# README says: 960x540 at 20 s. Deliberate only: look at every picture zoomed
# in (reflections, edges, the horizon) before committing them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
swell=${SWELL_BUILD_DIR:-$root/build}/apps/swell/swell
out=$root/docs/images
size=(--size 960x540 --time 20)
[[ -x $swell ]] || { echo "render-readme-pictures: no $swell; build first (scripts/build.sh)" >&2; exit 1; }

"$swell" render -o "$out/default.png" "${size[@]}"
"$swell" render "$root/scenes/sunset.toml" -o "$out/sunset.png" "${size[@]}"
"$swell" render "$root/scenes/storm.toml" -o "$out/storm.png" "${size[@]}"
"$swell" render "$root/scenes/trade-wind.toml" -o "$out/trade-wind.png" "${size[@]}"
"$swell" render "$out/calm-mirror.toml" -o "$out/calm-mirror.png" "${size[@]}"
"$swell" render "$root/scenes/underwater.toml" -o "$out/underwater.png" "${size[@]}"
"$swell" render "$out/caustics.toml" -o "$out/caustics.png" "${size[@]}"
"$swell" render "$out/shafts.toml" -o "$out/shafts.png" "${size[@]}"
"$swell" render "$root/scenes/under-way.toml" -o "$out/under-way.png" "${size[@]}"
"$swell" render "$root/scenes/coast.toml" -o "$out/coast.png" "${size[@]}"
"$swell" render "$root/scenes/harbour.toml" -o "$out/harbour.png" "${size[@]}"

# The low grazing camera: the trade wind preset with its camera at 1.2 m.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
sed 's/^position_m = \[0\.0, 8\.0, 0\.0\]/position_m = [0.0, 1.2, 0.0]/' "$root/scenes/trade-wind.toml" >"$scratch/grazing.toml"
grep -q '^position_m = \[0.0, 1.2, 0.0\]' "$scratch/grazing.toml" ||
  { echo "render-readme-pictures: scenes/trade-wind.toml's camera line changed; update this script" >&2; exit 1; }
"$swell" render "$scratch/grazing.toml" -o "$out/grazing.png" "${size[@]}"

# The storm from 300 m up, looking 50 degrees down: whitecaps without tiling.
sed 's/^position_m = \[0\.0, 10\.0, 0\.0\]/position_m = [0.0, 300.0, 0.0]/; s/^pitch_deg = -8\.0/pitch_deg = -50.0/' \
  "$root/scenes/storm.toml" >"$scratch/storm-from-above.toml"
grep -q '^position_m = \[0.0, 300.0, 0.0\]' "$scratch/storm-from-above.toml" ||
  { echo "render-readme-pictures: scenes/storm.toml's camera line changed; update this script" >&2; exit 1; }
"$swell" render "$scratch/storm-from-above.toml" -o "$out/storm-from-above.png" "${size[@]}"

# A whitecap close up: the trade wind preset at 0 s, its camera (the
# [camera] table, the file's end) replaced by one 3.5 m up and about 6 m
# from a crest breaking then (found on the CPU twin's foam replay): its
# dense fresh foam, the lace and flecks of the older foam, the bubbles
# glowing through the water under them.
sed '/^\[camera\]/,$d' "$root/scenes/trade-wind.toml" >"$scratch/whitecap.toml"
grep -q '^\[waves\.wind\]' "$scratch/whitecap.toml" && ! grep -q '^\[camera' "$scratch/whitecap.toml" ||
  { echo "render-readme-pictures: scenes/trade-wind.toml's layout changed; update this script" >&2; exit 1; }
printf '%s\n' '[camera]' 'position_m = [3.0, 3.5, -1.0]' 'yaw_deg = 0.0' 'pitch_deg = -30.0' 'fov_y_deg = 60.0' \
  'far_m = 30000.0' >>"$scratch/whitecap.toml"
"$swell" render "$scratch/whitecap.toml" -o "$out/whitecap.png" "${size[@]}"

# The wake from above, against the sun: the under-way preset at 30 s with its
# camera (the [camera] table and its path, the file's end) replaced.
sed '/^\[camera\]/,$d' "$root/scenes/under-way.toml" >"$scratch/wake.toml"
grep -q '^\[\[objects\]\]' "$scratch/wake.toml" && ! grep -q '^\[camera' "$scratch/wake.toml" ||
  { echo "render-readme-pictures: scenes/under-way.toml's layout changed; update this script" >&2; exit 1; }
printf '%s\n' '[camera]' 'position_m = [22.0, 32.0, -78.0]' 'yaw_deg = -22.0' 'pitch_deg = -33.0' 'far_m = 30000.0' \
  >>"$scratch/wake.toml"
"$swell" render "$scratch/wake.toml" -o "$out/under-way-wake.png" --size 960x540 --time 30

# A labelled frame (docs/LABELS.md): the under-way preset with its ground
# truth, drawn into four panels by docs/images/labelled-frame.py.
"$swell" render "$root/scenes/under-way.toml" -o "$scratch/labelled.png" --size 480x270 --time 20 --labels
python3 "$root/docs/images/labelled-frame.py" "$scratch/labelled.png" "$out/labelled-frame.png"

# The example host's picture: the build installed into a scratch prefix, the
# example (an outside project) built against it, one frame headless.
cmake --install "${SWELL_BUILD_DIR:-$root/build}" --prefix "$scratch/prefix" >/dev/null
cmake -S "$root/examples/host" -B "$scratch/host" -G Ninja -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$scratch/host" >/dev/null
"$scratch/host/swell_host_example" --headless "$out/host-example.png" "${size[@]}"
git -C "$root" status --short docs/images
