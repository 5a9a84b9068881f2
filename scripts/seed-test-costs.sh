#!/usr/bin/env bash
# Gives CTest the measured times of the slowest tests (tests/costs/*.txt) in
# a build folder that has none of its own yet, so that `ctest --parallel`
# starts them first. CTest orders tests by the times it recorded in earlier
# runs; in a fresh build (CI's clean clone) it has none and starts tests in
# the order they were declared, so a test of minutes started last keeps one
# core busy alone at the end. A folder that already has CTest's own figures
# keeps them (CTest updates them after every run).
#   scripts/seed-test-costs.sh BUILD_DIR COSTS_FILE
set -euo pipefail
data=$1/Testing/Temporary/CTestCostData.txt
if [[ ! -s "$data" ]]; then
  mkdir -p "$(dirname "$data")"
  cp "$2" "$data"
fi
