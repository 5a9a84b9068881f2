#!/usr/bin/env bash
# Installs the Debian packages Swell needs to build, test and run, only those
# that are missing. Idempotent; runs apt-get update once when it installs.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  # Compiles once what two builds in one run share (scripts/build.sh).
  ccache
  libepoxy-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri libglfw3-dev
  libglm-dev libimgui-dev libstb-dev libtomlplusplus-dev libcli11-dev libfmt-dev
  libtinygltf-dev libkissfft-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool python3
  python3-dev python3-numpy pybind11-dev
  # Datasets across machines: scripts/dataset-dask.py, and its test.
  python3-distributed
)
# Extra packages for `scripts/test.sh --sanitize` and the fuzzers.
if [[ "${SWELL_WITH_CLANG:-0}" == 1 ]]; then
  packages+=(clang libclang-rt-14-dev)
fi
if [[ "${SWELL_WITH_FFMPEG:-0}" == 1 ]]; then
  packages+=(ffmpeg)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

sudo=""
if [[ $(id -u) != 0 ]]; then
  sudo="sudo"
fi
echo "swell: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
