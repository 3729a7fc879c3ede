#!/usr/bin/env bash
# Build vtkOFB and run its demo, on a fresh Debian bookworm machine.
#
#   scripts/demo.sh            install the packages it needs (when any is missing),
#                              configure a Release build in build/, build it, then run
#                              ofbDemo on the bundled Stanford bunny under Xvfb: it
#                              prints the OFB's statistics and the mapper's frame time
#                              and writes ofb-demo.png (the samples coloured by grid
#                              beside the surface drawn by vtkOFBPolyDataMapper) in the
#                              project root.
#
# Extra arguments go to ofbDemo, e.g. `scripts/demo.sh --resolution 2048` or
# `scripts/demo.sh Testing/Data/horse.ply --output horse.png` (relative paths are
# taken from the directory the script is run from). Environment: BUILD_DIR (default build), JOBS (default: the cores).
set -euo pipefail

CALLER_DIR="$(pwd)"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"

# Debian packages the build needs. libvtk9-dev's CMake package needs the -dev
# packages it depends on (TBB for vtkSMPTools among them); libgl1-mesa-dri gives
# llvmpipe, the OpenGL implementation under Xvfb. The list is the same as in
# scripts/test.sh, so one build directory serves both.
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
    echo "demo.sh: all ${#PACKAGES[@]} packages are installed, skipping apt-get"
    return
  fi
  echo "demo.sh: installing packages (missing: ${missing[*]})"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo=(sudo)
    else
      echo "demo.sh: not root and no sudo: install ${missing[*]} first" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${PACKAGES[@]}"
}

install_packages

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" --target ofbDemo -- -j"$JOBS"

# Defaults: the bundled bunny and ofb-demo.png in the project root; the arguments
# may name another mesh or output (relative to the directory the script was run from).
ARGS=("$@")
HAVE_MESH=0
HAVE_OUTPUT=0
i=0
while [ "$i" -lt "${#ARGS[@]}" ]; do
  case "${ARGS[$i]}" in
    -o|--output) HAVE_OUTPUT=1; i=$((i + 1)) ;;
    -r|--resolution|-b|--backend|-l|--lookup|--width|--height) i=$((i + 1)) ;;
    -*) ;;
    *) HAVE_MESH=1 ;;
  esac
  i=$((i + 1))
done
if [ "$HAVE_MESH" -eq 0 ]; then
  ARGS=("$ROOT/Testing/Data/stanford-bunny.obj" "${ARGS[@]+"${ARGS[@]}"}")
fi
if [ "$HAVE_OUTPUT" -eq 0 ]; then
  ARGS+=(--output "$ROOT/ofb-demo.png")
fi

case "$BUILD_DIR" in
  /*) DEMO="$BUILD_DIR/bin/ofbDemo" ;;
  *) DEMO="$ROOT/$BUILD_DIR/bin/ofbDemo" ;;
esac
cd "$CALLER_DIR"
xvfb-run -a -s "-screen 0 1280x1024x24" "$DEMO" "${ARGS[@]}"
