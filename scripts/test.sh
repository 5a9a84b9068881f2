#!/usr/bin/env bash
# The README's second command: installs what is missing, builds everything and
# runs every test through CTest (CPU, headless GL, golden images, apps, the
# outside-project package test), ending with CTest's summary.
#   scripts/test.sh              the whole suite, Release
#   scripts/test.sh --sanitize   the whole suite under AddressSanitizer + UBSan (build-asan/)
# It prints the wall time of each step after CTest's summary ("test.sh: build
# N s", and install, tests), which CI's log keeps (.ci/run).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
start=$SECONDS
"$root/scripts/install-deps.sh"
installed=$((SECONDS - start))
start=$SECONDS
costs=$root/tests/costs/release.txt
if [[ "${1:-}" == "--sanitize" ]]; then
  export SWELL_BUILD_DIR=${SWELL_BUILD_DIR:-$root/build-asan} SWELL_BUILD_TYPE=Debug
  "$root/scripts/build.sh" -DSWELL_SANITIZE=ON
  costs=$root/tests/costs/sanitize.txt
else
  "$root/scripts/build.sh"
fi
built=$((SECONDS - start))
cd "${SWELL_BUILD_DIR:-$root/build}"
# The slowest tests first (a fresh build has no timings of its own).
"$root/scripts/seed-test-costs.sh" . "$costs"
# What scenes derive at a cost (the coast field, the breaking ramps) solved
# once for the build and read back by every other test process
# (docs/LIBRARY.md, "The cache of derived data"; docs/TESTING.md, "CI").
# 4 GB: the suite's distinct fields (26 MB each over the island) would churn
# through the default 512 MB, the soak's cycle of them among the first.
export SWELL_CACHE_DIR=${SWELL_CACHE_DIR-$PWD/derived-cache} SWELL_CACHE_MAX_MB=${SWELL_CACHE_MAX_MB-4096}
start=$SECONDS
rc=0
ctest --output-on-failure --parallel "$(nproc)" --timeout 600 || rc=$?
echo "test.sh: install $installed s" >&2
echo "test.sh: build $built s" >&2
echo "test.sh: tests $((SECONDS - start)) s" >&2
exit "$rc"
