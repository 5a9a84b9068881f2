#!/usr/bin/env bash
# Rewrites the golden images in tests/goldens/ from what the renderer draws now.
# Deliberate only: look at every image it writes (git diff shows which) before
# committing them.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SWELL_BUILD_DIR:-$root/build}
"$root/scripts/build.sh"
SWELL_UPDATE_GOLDENS=1 "$build/tests/gl/swell_golden_tests" "$@"
git -C "$root" status --short tests/goldens
