#!/bin/sh
# `swell view` end to end: a scripted run under a virtual X server exits 0,
# prints the screenshot's absolute path, and leaves a PNG of the requested
# size that shows sky above water; with --scale 0.5 as well.
# Usage: test_viewer.sh SWELL PNG_CHECK OUTPUT_DIR (OUTPUT_DIR absolute)
# Exit 0: passed; 1: failed; 77: skipped (no xvfb-run).
set -u
swell=$1
check=$2
out=$3

if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "xvfb-run is not installed (apt-get install xvfb xauth): skipped"
    exit 77
fi

mkdir -p "$out" || exit 1
png="$out/viewer.png"
rm -f "$png"
printed=$(xvfb-run -a -s "-screen 0 1280x1024x24" \
    "$swell" view --size 640x360 --exit-after-frames 5 --screenshot "$png")
status=$?
if [ "$status" -ne 0 ]; then
    echo "swell view exited with $status"
    exit 1
fi
if [ ! -f "$png" ]; then
    echo "no screenshot at $png"
    exit 1
fi
if [ "$printed" != "$png" ]; then
    echo "swell view printed '$printed', expected the screenshot's path '$png'"
    exit 1
fi
"$check" "$png" 640 360 || exit 1

# --scale: the window keeps its size, the frame is drawn at half of it, and
# the frame-time line at the end names the scale the frames were drawn at.
scaled="$out/viewer-scaled.png"
rm -f "$scaled"
report=$(xvfb-run -a -s "-screen 0 1280x1024x24" \
    "$swell" view --size 640x360 --scale 0.5 --exit-after-frames 3 --screenshot "$scaled" 2>&1 >/dev/null)
status=$?
if [ "$status" -ne 0 ]; then
    echo "swell view --scale 0.5 exited with $status: $report"
    exit 1
fi
case "$report" in
*"timed at 640x360, render scale 0.50"*) ;;
*) echo "swell view --scale 0.5 did not report drawing at scale 0.50: $report"; exit 1 ;;
esac
exec "$check" "$scaled" 640 360
