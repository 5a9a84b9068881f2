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
#
# The compiler runs through ccache when it is installed (scripts/install-deps.sh
# installs it; SWELL_CCACHE=OFF turns it off), in its depend mode, which
# reads the compiler's dependency file instead of running the preprocessor,
# so a compile the cache has not seen costs no more than without it. Its use
# in one run: the static-library test (tests/outside/static.sh) compiles the
# library's sources again with this build's flags, and finds them cached.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SWELL_BUILD_DIR:-$root/build}
launcher=()
if [[ "${SWELL_CCACHE:-ON}" != OFF ]] && command -v ccache >/dev/null; then
  # Paths under the build folder written relative to where each compile
  # runs, unless the cache has a base folder of its own: the static
  # package's build (tests/outside/static.sh, a folder inside this one)
  # then compiles the same batched sources under the same relative names,
  # and finds them cached.
  basedir=()
  if [[ -z "$(ccache -k base_dir 2>/dev/null)" ]]; then
    basedir=("CCACHE_BASEDIR=$(realpath -m "$build")")
  fi
  launcher=("-DCMAKE_CXX_COMPILER_LAUNCHER=env;${basedir[*]:+${basedir[*]};}CCACHE_DEPEND=true;ccache"
            "-DCMAKE_C_COMPILER_LAUNCHER=env;${basedir[*]:+${basedir[*]};}CCACHE_DEPEND=true;ccache")
elif [[ "${SWELL_CCACHE:-ON}" == OFF ]]; then
  # Off again in a folder configured with it before.
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER= -DCMAKE_C_COMPILER_LAUNCHER=)
fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${SWELL_BUILD_TYPE:-Release} \
  -DSWELL_BUILD_APPS=ON -DSWELL_BUILD_TESTS=ON -DSWELL_BUILD_BENCHMARKS=ON \
  -DSWELL_WERROR=${SWELL_WERROR:-OFF} "${launcher[@]}" "$@" >&2
targets=()
for t in ${SWELL_BUILD_TARGETS:-}; do
  targets+=(--target "$t")
done
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}" >&2
