#!/usr/bin/env bash
# A static Swell (BUILD_SHARED_LIBS=OFF) installs a package that an outside
# project can use: builds the library alone from the source tree at $1 into
# $2/swell-build, then runs the same outside-project check as run.sh on it.
# $3, the build folder that runs this test: the static build takes its
# compiler launcher and warnings-as-errors setting, so its compiles are the
# same commands as that build's (the library's objects do not depend on
# BUILD_SHARED_LIBS: both are position-independent with hidden visibility),
# and a compiler cache (scripts/build.sh) hands back those objects instead
# of compiling the library's sources a second time. The archive, the
# installed package and the outside project's link are made here.
set -euo pipefail
source=$1
work=$2
main_build=$3
here=$(cd "$(dirname "$0")" && pwd)
cached() { sed -n "s/^$1:[A-Z]*=//p" "$main_build/CMakeCache.txt"; }
mkdir -p "$work"
cmake -S "$source" -B "$work/swell-build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF \
  -DSWELL_BUILD_APPS=OFF -DSWELL_BUILD_TESTS=OFF -DSWELL_BUILD_BENCHMARKS=OFF -DSWELL_BUILD_PYTHON=OFF \
  "-DCMAKE_CXX_COMPILER_LAUNCHER=$(cached CMAKE_CXX_COMPILER_LAUNCHER)" \
  "-DCMAKE_C_COMPILER_LAUNCHER=$(cached CMAKE_C_COMPILER_LAUNCHER)" \
  "-DSWELL_WERROR=$(cached SWELL_WERROR)" >/dev/null
cmake --build "$work/swell-build" --target swell >/dev/null
"$here/run.sh" "$work/swell-build" "$work/outside"
# It was the static library that got linked: no libswell.so was installed.
if find "$work/outside/prefix" -name 'libswell.so*' | grep -q .; then
  echo "a static build installed a shared libswell" >&2
  exit 1
fi
test -n "$(find "$work/outside/prefix" -name 'libswell.a')"
echo "static package: libswell.a found and linked by the outside project"
