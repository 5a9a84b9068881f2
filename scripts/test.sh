#!/usr/bin/env bash
# The README's second command: installs what is missing, builds everything and
# runs every test through CTest (CPU, headless GL, golden images, apps, the
# outside-project package test), ending with CTest's summary.
#   scripts/test.sh              the whole suite, Release
#   scripts/test.sh --sanitize   the whole suite under AddressSanitizer + UBSan (build-asan/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
costs=$root/tests/costs/release.txt
if [[ "${1:-}" == "--sanitize" ]]; then
  export SWELL_BUILD_DIR=${SWELL_BUILD_DIR:-$root/build-asan} SWELL_BUILD_TYPE=Debug
  "$root/scripts/build.sh" -DSWELL_SANITIZE=ON
  costs=$root/tests/costs/sanitize.txt
else
  "$root/scripts/build.sh"
fi
cd "${SWELL_BUILD_DIR:-$root/build}"
# The slowest tests first (a fresh build has no timings of its own).
"$root/scripts/seed-test-costs.sh" . "$costs"
exec ctest --output-on-failure --parallel "$(nproc)" --timeout 600
