#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and runs the
# default scene: a window when a display is usable, otherwise a headless render
# to swell-default.png, whose path it prints. Arguments go to the swell executable.
# It builds everything (tests and benchmarks too), in the same configuration as
# scripts/test.sh, so that neither script leaves the other's programs stale.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
exec "${SWELL_BUILD_DIR:-$root/build}/apps/swell/swell" "$@"
