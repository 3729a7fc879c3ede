#!/usr/bin/env bash
# Build vtkOFB and run its tests, on a fresh Debian bookworm machine.
#
#   scripts/test.sh            install the packages it needs (when any is missing),
#                              configure a Release build in build/, build it and run
#                              ctest under Xvfb (the rendering tests need a display).
#
# Extra arguments go to ctest, e.g. `scripts/test.sh -R Python` or `-L Python`.
# Environment: BUILD_DIR (default build), JOBS (default: the number of cores),
# CTEST_PARALLEL_LEVEL (ctest's own, default 1).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"

# Debian packages the build, the tests and the benchmarks need. libvtk9-dev's CMake
# package needs the -dev packages it depends on (TBB for vtkSMPTools among them);
# python3-numpy is for vtkmodules.util.numpy_support in the Python tests;
# libgl1-mesa-dri gives llvmpipe, the OpenGL implementation under Xvfb.
PACKAGES=(
  cmake g++ make
  libvtk9-dev python3-vtk9 python3-numpy libtbb-dev
  libglm-dev libopenimageio-dev libopenvdb-dev libgtest-dev
  xvfb xauth libgl1-mesa-dri
)

install_packages() {
  local missing=() pkg
  for pkg in "${PACKAGES[@]}"; do
    if [ "$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null)" != "install ok installed" ]; then
      missing+=("$pkg")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    echo "test.sh: all ${#PACKAGES[@]} packages are installed, skipping apt-get"
    return
  fi
  echo "test.sh: installing packages (missing: ${missing[*]})"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo=(sudo)
    else
      echo "test.sh: not root and no sudo: install ${missing[*]} first" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${PACKAGES[@]}"
}

install_packages

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -- -j"$JOBS"

cd "$BUILD_DIR"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure "$@"
