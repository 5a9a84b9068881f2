#!/usr/bin/env bash
# The installed Python package works away from the build and source trees:
# installs the build at $1 into a fresh prefix and, from a folder outside
# both, runs the interpreter $2 with PYTHONPATH at the package's folder $3
# (relative to the prefix, SWELL_INSTALL_PYTHONDIR): swell is imported from
# there, its module loads the installed libswell (its RPATH), the presets
# are the installed ones, and a preset found by name renders a frame and its
# labels.
set -euo pipefail
build=$1
python=$2
pythondir=$3
prefix=$(mktemp -d /tmp/swell-python-installed-XXXXXX)
work=$(mktemp -d /tmp/swell-python-outside-XXXXXX)
trap 'rm -rf "$prefix" "$work"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
cd "$work"
PYTHONPATH="$prefix/$pythondir" PYTHONDONTWRITEBYTECODE=1 "$python" - "$prefix" <<'PY'
import os
import sys

import numpy as np

import swell

prefix = os.path.realpath(sys.argv[1])


def inside(path):
    return os.path.realpath(path).startswith(prefix + os.sep)


assert inside(swell.__file__), "swell imported from " + swell.__file__
assert os.path.realpath(swell.presets_folder()) == os.path.join(prefix, "share", "swell", "scenes"), \
    "presets in " + swell.presets_folder()
with open("/proc/self/maps") as maps:
    libraries = {line.split()[-1] for line in maps if "libswell.so" in line}
assert libraries and all(inside(path) for path in libraries), "libswell loaded from %s" % libraries

scene = swell.load("storm")
assert inside(scene.file), scene.file
renderer = swell.Renderer(scene)
camera = scene.camera_at(2.0)
rgba = renderer.render(camera, 2.0, (64, 36))
labels = renderer.render_labels(camera, (64, 36))
assert rgba.shape == (36, 64, 4) and rgba.dtype == np.uint8
assert labels.range_m.shape == (36, 64) and (labels.semantic == swell.CLASS_WATER).any()
print("installed package: %s, presets %s" % (os.path.dirname(swell.__file__), swell.presets_folder()))
PY
