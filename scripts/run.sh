#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and runs the
# default scene: a window when a display is usable, otherwise a headless render
# to swell-default.png, whose path it prints. Arguments go to the swell executable.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" -DSWELL_BUILD_TESTS=OFF -DSWELL_BUILD_BENCHMARKS=OFF
exec "${SWELL_BUILD_DIR:-$root/build}/apps/swell/swell" "$@"
