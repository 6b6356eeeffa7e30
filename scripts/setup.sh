#!/usr/bin/env bash
# Installs the Debian 12 packages penumbra needs (skips the install when all are present),
# then configures and builds into ./build (./build-sanitize with --sanitize; nothing with --deps-only).
# Used by run.sh, test.sh and fuzz.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(cmake ninja-build g++ pkg-config libegl-dev libegl-mesa0 libgl1-mesa-dri libgles-dev libopengl-dev
  libepoxy-dev libstb-dev libjpeg62-turbo-dev libglm-dev libglfw3-dev libimgui-dev libtinyobjloader-dev libtinygltf-dev
  libassimp-dev libmeshoptimizer-dev libcli11-dev nlohmann-json3-dev libembree-dev libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth dpkg-dev file libjs-chart.js chromium openscenegraph clang libclang-rt-14-dev)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

[ "${1:-}" = "--deps-only" ] && exit 0  # scripts/fuzz.sh configures its own clang build

BUILD_TYPE="${PENUMBRA_BUILD_TYPE:-RelWithDebInfo}"
if [ "${1:-}" = "--sanitize" ]; then
  # AddressSanitizer + UndefinedBehaviorSanitizer (any UB report aborts), in a folder of its own.
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" >/dev/null
  cmake --build build-sanitize -j "$(nproc)"
  exit 0
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" >/dev/null
cmake --build build -j "$(nproc)"
