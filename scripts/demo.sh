#!/usr/bin/env bash
# Build vtkOFB and run its demo, on a fresh Debian bookworm machine.
#
#   scripts/demo.sh            install the packages it needs (when any is missing),
#                              configure a Release build in build/, build it, then run
#                              OFBDemo on the bundled Stanford bunny under Xvfb: it
#                              prints the OFB's statistics and the mapper's frame time
#                              and writes ofb-demo.png (the samples coloured by grid
#                              beside the surface drawn by vtkOFBPolyDataMapper) in the
#                              project root.
#
# Extra arguments go to OFBDemo, e.g. `scripts/demo.sh --resolution 2048` or
# `scripts/demo.sh Testing/Data/horse.ply --output horse.png` (relative paths are
# taken from the directory the script is run from). Environment: BUILD_DIR (default build), JOBS (default: the cores).
set -euo pipefail

CALLER_DIR="$(pwd)"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"

# shellcheck source=scripts/packages.sh
source "$ROOT/scripts/packages.sh"
install_packages demo.sh

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" --target OFBDemo -- -j"$JOBS"

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
  /*) DEMO="$BUILD_DIR/bin/OFBDemo" ;;
  *) DEMO="$ROOT/$BUILD_DIR/bin/OFBDemo" ;;
esac
cd "$CALLER_DIR"
xvfb-run -a -s "-screen 0 1280x1024x24" "$DEMO" "${ARGS[@]}"
