#!/usr/bin/env bash
# The README's first command: installs what is missing, builds the swell
# executable (only it: the tests and benchmarks wait for scripts/test.sh),
# and runs the default scene: a window when a display is usable, otherwise a
# headless render to swell-default.png. swell says which path it took, and
# the render's path. Arguments go to the swell executable.
# The build uses scripts/build.sh's one configuration, which scripts/test.sh
# shares, so that neither script leaves the other's programs stale.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SWELL_BUILD_DIR:-$root/build}
"$root/scripts/install-deps.sh"
echo "swell: building the swell executable into $build (the tests are built by scripts/test.sh)" >&2
SWELL_BUILD_TARGETS=swell_app "$root/scripts/build.sh"
exec "$build/apps/swell/swell" "$@"
