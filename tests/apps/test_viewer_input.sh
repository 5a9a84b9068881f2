#!/bin/sh
# Key taps are not lost in a slow frame: `swell view` under a virtual X
# server, every frame made slow on purpose (--slow-frames 1500: each frame
# ends with a 1.5 s wait), and, during such a wait, a quick Enter tap and a
# quick Ctrl+click (press and release milliseconds apart, through xdotool's
# XTEST, as a keyboard and mouse would). The panel must see both, Ctrl held
# at the click (--log-input prints what ImGui saw each frame); then Esc quits.
# Usage: under_xvfb.sh sh test_viewer_input.sh SWELL (CTest runs it so: it needs an X server)
# Exit 0: passed; 1: failed; 77: skipped (no xdotool; under_xvfb.sh: no xvfb-run).
set -u
swell=$1
if ! command -v xdotool >/dev/null 2>&1; then
    echo "xdotool is not installed (scripts/install-deps.sh installs it): skipped"
    exit 77
fi

log=$(mktemp /tmp/swell-input-XXXXXX.log)
trap 'rm -f "$log"' EXIT
"$swell" view --size 640x360 --slow-frames 1500 --log-input 2>"$log" &
viewer=$!
window=$(timeout 120 xdotool search --sync --onlyvisible --name '^Swell$' | head -n 1)
if [ -z "$window" ]; then
    echo "no viewer window appeared"
    kill "$viewer" 2>/dev/null
    exit 1
fi
# A few frames in, so that the taps land in a frame's wait.
sleep 4
xdotool windowfocus --sync "$window"
# Over the ocean, right of the panel: the click changes nothing there.
xdotool mousemove --window "$window" 560 300
sleep 2
# The taps: each press and its release a few milliseconds apart, far
# shorter than the frame.
xdotool key Return
xdotool keydown ctrl click 1 keyup ctrl
# Seen within a few (slow) frames.
seen=0
for _ in $(seq 1 40); do
    if grep -q "Enter pressed" "$log" && grep -q "left click at .* with Ctrl" "$log"; then
        seen=1
        break
    fi
    sleep 1
done
xdotool key Escape
for _ in $(seq 1 60); do
    kill -0 "$viewer" 2>/dev/null || break
    sleep 1
done
if kill -0 "$viewer" 2>/dev/null; then
    kill "$viewer"
    echo "the viewer was still running 60 s after Esc"
    exit 1
fi
wait "$viewer"
status=$?
grep "swell view: input:" "$log"
if [ "$seen" -ne 1 ]; then
    echo "the panel did not see the Enter tap and the Ctrl+click of a slow frame; the viewer's stderr:"
    cat "$log"
    exit 1
fi
if [ "$status" -ne 0 ]; then
    echo "the viewer exited with $status"
    cat "$log"
    exit 1
fi
echo "a quick Enter and a quick Ctrl+click in a 1.5 s frame both reached the panel"
