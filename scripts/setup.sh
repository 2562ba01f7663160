#!/usr/bin/env bash
# Installs the Debian packages Marchbox needs (when missing), then configures and builds it.
# Usage: scripts/setup.sh [BUILD_DIR] [extra cmake args...]
#        scripts/setup.sh --install PACKAGE...   (only installs those, when missing: CI's extras)
set -euo pipefail
cd "$(dirname "$0")/.."

# The tests also need ffmpeg (render to .mp4, ffprobe) and GNU parallel (ranges split across
# processes): without them those tests skip. `marchbox export` meshes with OpenVDB (which brings
# TBB, Blosc and Imath; its CMake module also asks for Boost.Iostreams) and writes glTF with
# TinyGLTF. Bullet runs beside the simulator in `marchbox report physics`. assimp-utils gives the
# export tests a second reader of every mesh format (`assimp info`); without it those checks skip.
PACKAGES=(g++ cmake pkg-config libglfw3-dev libglew-dev libglm-dev libimgui-dev
          libosmesa6-dev libegl-dev libgtest-dev libstb-dev libpng-dev xvfb xauth xdotool
          x11-utils python3 ffmpeg parallel libopenvdb-dev libboost-iostreams-dev libtinygltf-dev
          libbullet-dev assimp-utils)

# install_missing PACKAGE...: apt-get install those not installed; without root, print the
# command to run and fail.
install_missing() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  if [[ $(id -u) -ne 0 ]]; then
    echo "setup: missing packages; run:"
    echo "  sudo apt-get install -y ${missing[*]}"
    exit 1
  fi
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

if [[ ${1:-} == --install ]]; then
  shift
  install_missing "$@"
  exit 0
fi
install_missing "${PACKAGES[@]}"

build=${1:-build}
shift || true
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
# The export tests check .glb files with Khronos's glTF validator, an npm package kept in the
# build folder, never committed. Where npm or its registry is missing those checks skip.
validator="$build/gltf-validator"
if command -v npm >/dev/null && [[ ! -d $validator/node_modules/gltf-validator ]]; then
  npm install --prefix "$validator" --no-audit --no-fund --no-save gltf-validator@2.0.0-dev.3.10 \
      >/dev/null 2>&1 || echo "setup: npm could not install gltf-validator; the glTF checks will skip"
fi
cmake --build "$build" -j"$(nproc)"
