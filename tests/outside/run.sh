#!/usr/bin/env bash
# The embedding example of docs/LIBRARY.md as an outside project: installs the
# Swell build at $1 into a fresh prefix, builds this folder against it with
# find_package(Swell), runs it, and checks the PNG. CMakeLists.txt and
# embed_example.cpp here must be exactly what docs/LIBRARY.md shows, so the
# documented example is the one that is built (no C++ standard or anything
# else set by the test).
set -euo pipefail
build=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
python3 "$here/check_docs_example.py" "$here/../../docs/LIBRARY.md" "$here/CMakeLists.txt" "$here/embed_example.cpp"
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$here" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/embed_example" "$work/frame.png"
# A PNG of 320x180: signature, then IHDR width and height.
python3 - "$work/frame.png" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read(32)
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = struct.unpack(">II", data[16:24])
assert (w, h) == (320, 180), (w, h)
print("outside project rendered", w, "x", h)
PY
