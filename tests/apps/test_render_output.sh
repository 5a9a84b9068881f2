#!/bin/sh
# `swell render -o`: missing parent folders are created (as --help says),
# and a path through a file is refused as bad input (exit 2) with a message
# that says so in words, not a raw filesystem error.
# Usage: test_render_output.sh SWELL WORK_DIR
set -u
swell=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

"$swell" render -o new/folders/frame.png --size 16x16 >/dev/null || { echo "render into new folders failed"; exit 1; }
[ -f new/folders/frame.png ] || { echo "no frame in the created folders"; exit 1; }

: > afile
"$swell" render -o afile/x.png --size 16x16 >out.txt 2>err.txt
status=$?
[ "$status" -eq 2 ] || { echo "a path through a file: exit $status, expected 2"; cat err.txt; exit 1; }
grep -q "'afile' is a file, not a folder" err.txt || { echo "unclear message:"; cat err.txt; exit 1; }
if grep -q "filesystem error" err.txt; then echo "raw filesystem error shown:"; cat err.txt; exit 1; fi
"$swell" render --help | grep -q "Missing parent folders are created" || { echo "--help does not say -o creates folders"; exit 1; }
echo "render -o: folders created; a path through a file refused with exit 2"
