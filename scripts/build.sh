#!/usr/bin/env bash
# Configures and builds Swell into build/ (Release), or the folder in
# SWELL_BUILD_DIR. Extra arguments go to CMake's configure step.
#
# Every script that builds into one folder uses this one configuration, with
# everything the docs name turned on (the swell executable, the tests, the
# CPU benchmarks): a script that turned an option off would leave the next
# script's programs missing or stale in the same CMake cache.
# SWELL_WERROR=ON (as CI sets it) turns compiler warnings into errors.
# SWELL_BUILD_TARGETS (space-separated) builds only those targets, still in
# this one configuration: scripts/run.sh builds the swell executable alone
# first, so that the first picture does not wait for the tests.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SWELL_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${SWELL_BUILD_TYPE:-Release} \
  -DSWELL_BUILD_APPS=ON -DSWELL_BUILD_TESTS=ON -DSWELL_BUILD_BENCHMARKS=ON \
  -DSWELL_WERROR=${SWELL_WERROR:-OFF} "$@" >&2
targets=()
for t in ${SWELL_BUILD_TARGETS:-}; do
  targets+=(--target "$t")
done
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}" >&2
