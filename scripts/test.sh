#!/usr/bin/env bash
# Build vtkOFB and run its tests, on a fresh Debian bookworm machine.
#
#   scripts/test.sh            install the packages it needs (when any is missing),
#                              unpack ParaView's Python into build/ (paraview-sdk.sh),
#                              configure a Release build in build/ (with the ParaView
#                              plugin), build it and run ctest under Xvfb (the
#                              rendering tests need a display).
#
# Extra arguments go to ctest, e.g. `scripts/test.sh -R Python` or `-L Python`.
# Environment: BUILD_DIR (default build), JOBS (default: the number of cores),
# CTEST_PARALLEL_LEVEL (ctest's own, default 1).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"

# shellcheck source=scripts/packages.sh
source "$ROOT/scripts/packages.sh"
# The ParaView plugin is built and tested too: paraview-dev (ParaView 5.11 and its VTK,
# installed beside Debian's VTK, nothing removed) and ParaView's Python unpacked into
# the build tree (python3-paraview conflicts with python3-vtk9: it is not installed).
PACKAGES+=(paraview-dev)
install_packages test.sh
bash "$ROOT/scripts/paraview-sdk.sh" "$BUILD_DIR"

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -- -j"$JOBS"

cd "$BUILD_DIR"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure "$@"
