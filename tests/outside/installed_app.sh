#!/usr/bin/env bash
# The installed swell works away from the source tree: installs the build at
# $1 into a fresh prefix outside the source tree, and from another folder
# outside it checks that swell finds its installed presets and shaders (not
# the source tree's) and renders every installed preset, and a scene that
# places an installed example model.
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
test -f "$data/include/swell/shader_constants.h"   # the shaders' shared header, for hot reload
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
