#!/usr/bin/env bash
# The installed swell works away from the source tree: installs the build at
# $1 into a fresh prefix outside the source tree, and from another folder
# outside it checks that swell finds its installed presets and shaders (not
# the source tree's) and renders every installed preset, and a scene that
# places an installed example model; that a preset is found by its name
# ("storm", "storm.toml") from a folder without such a file, that an unknown
# name is refused listing the presets, and that the docs are installed.
set -euo pipefail
build=$1
prefix=$(mktemp -d /tmp/swell-installed-XXXXXX)
work=$(mktemp -d /tmp/swell-outside-XXXXXX)
trap 'rm -rf "$prefix" "$work"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
cd "$work"
swell=$prefix/bin/swell
data=$prefix/share/swell

version=$("$swell" --version)
echo "$version"
grep -qx "presets: $data/scenes" <<<"$version" || { echo "swell does not use the installed presets" >&2; exit 1; }
grep -qx "shaders: $data/shaders" <<<"$version" || { echo "swell does not use the installed shaders" >&2; exit 1; }
test -f "$data/include/swell/gpu/bindings.h"   # the shaders' shared headers, for hot reload
test -f "$data/shaders/water.frag"

presets=("$data"/scenes/*.toml)
if (( ${#presets[@]} < 5 )); then
  echo "only ${#presets[@]} presets installed in $data/scenes" >&2
  exit 1
fi
# A scene of our own that places the installed example models, copied
# beside it: a scene may name only files in its own folder or below it.
cp -r "$data/models" models
cat > models.toml <<TOML
[[objects]]
path = "models/crate.glb"
position_m = [0.0, 0.0, -12.0]
floats = true

[[objects]]
path = "models/lighthouse.gltf"
position_m = [30.0, 0.0, -200.0]
TOML
for scene in "${presets[@]}" models.toml; do
  name=$(basename "$scene" .toml)
  "$swell" render "$scene" -o "frames/$name.png" --size 160x90 --time 2 >/dev/null
  python3 - "frames/$name.png" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read(32)
assert data[:8] == b"\x89PNG\r\n\x1a\n", sys.argv[1] + ": not a PNG"
assert struct.unpack(">II", data[16:24]) == (160, 90), sys.argv[1]
PY
  echo "rendered $name from the installed swell"
done

# Presets by name, from a folder that has no such file.
for name in storm storm.toml; do
  "$swell" render "$name" -o "frames/by-name.png" --size 160x90 >/dev/null
  test -f frames/by-name.png || { echo "swell render $name: no picture" >&2; exit 1; }
  rm frames/by-name.png
  echo "rendered the preset '$name' by its name"
done
# A file in the working folder wins over a preset of the same name.
printf '[fog]\nstart_m = 1\nend_m = 2\n[camera]\nposition_m = [0.0, 40.0, 0.0]\n' > storm.toml
"$swell" render storm.toml -o frames/local.png --size 160x90 >/dev/null
"$swell" render storm -o frames/preset.png --size 160x90 >/dev/null
if cmp -s frames/local.png frames/preset.png; then
  echo "./storm.toml and the preset storm drew the same picture: the local file was not taken" >&2
  exit 1
fi
rm storm.toml
# Neither a file nor a preset: exit 2, the presets listed.
set +e
message=$("$swell" render no-such-sea -o frames/none.png --size 160x90 2>&1 >/dev/null)
status=$?
set -e
if [[ $status -ne 2 || $message != *"no-such-sea"*"calm"*"storm"*"sunset"* ]]; then
  echo "swell render no-such-sea: exit $status, '$message'; expected 2 and the presets listed" >&2
  exit 1
fi
echo "an unknown scene name is refused with the presets listed: $message"

# The docs, with the README's links intact.
docs=$prefix/share/doc/swell
for doc in README.md LICENSE docs/GETTING_STARTED.md docs/VIEWER.md docs/SCENE.md docs/PERFORMANCE.md \
           docs/images/default.png; do
  test -f "$docs/$doc" || { echo "$docs/$doc is not installed" >&2; exit 1; }
done
echo "the docs are installed in $docs"
