#!/usr/bin/env bash
# The example host (examples/host/) as the outside project it is: installs
# the Swell build at $1 into a fresh prefix, builds the example's installed
# sources (share/doc/swell/examples/host) against it
# with find_package(Swell) and the system's GLFW, runs its compositing checks
# (--check: its own cube mirrored by the water within 2 px, its wall hiding
# the water, nothing else of its frame changed; level, rolled 30 degrees,
# reversed-Z, the sea at 100 m), renders its picture headless, and, where
# xvfb-run is, opens its GLFW window for a few frames (its loader through
# glfwGetProcAddress). Built with -Werror, as CI builds the project.
set -euo pipefail
build=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
# The installed copy must be the source tree's.
diff -r "$here/../../examples/host" "$work/prefix/share/doc/swell/examples/host"
cmake -S "$work/prefix/share/doc/swell/examples/host" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-Werror >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/swell_host_example" --check
"$work/build/swell_host_example" --headless "$work/harbour.png" --size 320x180 --time 20
if command -v xvfb-run >/dev/null; then
  xvfb-run -a -s '-screen 0 1280x720x24' "$work/build/swell_host_example" --frames 3 --size 320x180
  echo "example host's window drew 3 frames"
else
  echo "no xvfb-run: the window is not tried"
fi
# A PNG of 320x180 that is a picture, not one flat colour.
python3 - "$work/harbour.png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = struct.unpack(">II", data[16:24])
assert (w, h) == (320, 180), (w, h)
idat, i = b"", 8
while i < len(data):
    n, kind = struct.unpack(">I4s", data[i:i + 8])
    if kind == b"IDAT":
        idat += data[i + 8:i + 8 + n]
    i += 12 + n
rows = zlib.decompress(idat)
assert len(set(rows[1:1 + w * 4 * 4])) > 8 or len(set(rows)) > 64, "the picture is one flat colour"
print("example host rendered", w, "x", h)
PY
