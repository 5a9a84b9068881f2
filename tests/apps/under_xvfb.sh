#!/bin/sh
# Runs a command under a virtual X server (1280x1024, 24-bit), passing its exit
# status through. Exit 77 (skipped) when xvfb-run is not installed.
# Usage: under_xvfb.sh COMMAND [ARGS...]
if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "xvfb-run is not installed (apt-get install xvfb xauth): skipped"
    exit 77
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
