#!/usr/bin/env bash
# Configures and builds Swell into build/ (Release), or the folder in
# SWELL_BUILD_DIR. Extra arguments go to CMake's configure step.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SWELL_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${SWELL_BUILD_TYPE:-Release} "$@" >&2
cmake --build "$build" --parallel "$(nproc)" >&2
