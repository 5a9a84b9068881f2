#!/bin/sh
# Esc quits the interactive viewer: `swell view` under a virtual X server,
# the Escape key pressed into its window (xdotool, through the XTEST
# extension, as a keyboard would), then the viewer must exit 0 on its own.
# Usage: under_xvfb.sh sh test_viewer_quit.sh SWELL (CTest runs it so: it needs an X server)
# Exit 0: passed; 1: failed; 77: skipped (no xdotool; under_xvfb.sh: no xvfb-run).
set -u
swell=$1
if ! command -v xdotool >/dev/null 2>&1; then
    echo "xdotool is not installed (scripts/install-deps.sh installs it): skipped"
    exit 77
fi

"$swell" view --size 320x180 &
viewer=$!
# Its window, once mapped (the first frames on software GL take seconds).
window=$(timeout 120 xdotool search --sync --onlyvisible --name '^Swell$' | head -n 1)
if [ -z "$window" ]; then
    echo "no viewer window appeared"
    kill "$viewer" 2>/dev/null
    exit 1
fi
sleep 2
# No window manager here: give the window the keyboard focus directly.
xdotool windowfocus --sync "$window" && xdotool key Escape
# The viewer must be gone within a minute (a few frames at most).
for _ in $(seq 1 60); do
    if ! kill -0 "$viewer" 2>/dev/null; then
        wait "$viewer"
        status=$?
        if [ "$status" -ne 0 ]; then
            echo "the viewer quit on Esc but exited with $status"
            exit 1
        fi
        echo "Esc quit the viewer (exit 0)"
        exit 0
    fi
    sleep 1
done
echo "the viewer was still running 60 s after Esc"
kill "$viewer"
exit 1
