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

# shellcheck source=scripts/packages.sh
source "$ROOT/scripts/packages.sh"
install_packages test.sh

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -- -j"$JOBS"

cd "$BUILD_DIR"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure "$@"
