#!/usr/bin/env bash
# Build vtkOFB with AddressSanitizer and UndefinedBehaviorSanitizer (clang), run its tests
# there under Xvfb, and fuzz its parsers with libFuzzer (Testing/Fuzz), on a fresh Debian
# bookworm machine.
#
#   scripts/sanitize.sh --ci     the bounded run of CI: the OFB library modules, the unit
#                                tests of OFB::Core, OFB::Paint, OFB::FlowPaths,
#                                OFB::Export and OFB::IOImage, and each fuzz target for
#                                FUZZ_SECONDS (default 60).
#   scripts/sanitize.sh --long   everything: the whole project (examples, rendering and
#                                interaction modules; no Python wrapping), the whole test
#                                suite but the install tests, and each fuzz target for
#                                FUZZ_SECONDS (default 1800).
#
# The build (build-asan/ unless BUILD_DIR says otherwise) is RelWithDebInfo at -O1 with
# -fsanitize=address,undefined -fno-omit-frame-pointer, and libFuzzer's coverage
# instrumentation (-fsanitize=fuzzer-no-link) so that the fuzzers see the library's
# branches. VTK, Mesa and the system libraries are not instrumented: ASan still checks
# every access that vtkOFB's code makes. Leaks of Mesa, X11, TBB and VTK's rendering
# caches are suppressed (scripts/sanitize/lsan.supp). Any report fails the run; the fuzz
# targets' crash inputs are kept in BUILD_DIR/Testing/Fuzz/fuzz-artifacts.
#
# Environment: BUILD_DIR (build-asan), JOBS (the number of cores), FUZZ_SECONDS.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

MODE="${1:---ci}"
case "$MODE" in
  --ci) FUZZ_SECONDS="${FUZZ_SECONDS:-60}" ;;
  --long) FUZZ_SECONDS="${FUZZ_SECONDS:-1800}" ;;
  *)
    echo "usage: scripts/sanitize.sh [--ci | --long]" >&2
    exit 2
    ;;
esac
BUILD_DIR="${BUILD_DIR:-build-asan}"
JOBS="${JOBS:-$(nproc)}"

# shellcheck source=scripts/packages.sh
source "$ROOT/scripts/packages.sh"
# clang and its sanitizer and libFuzzer runtimes.
PACKAGES+=(clang-14 libclang-rt-14-dev)
install_packages sanitize.sh

SANITIZE="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$ROOT/scripts/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

start=$SECONDS
cmake -S . -B "$BUILD_DIR" \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_C_FLAGS="$SANITIZE" \
  -DCMAKE_CXX_FLAGS="$SANITIZE -fsanitize=fuzzer-no-link" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DVTKOFB_WRAP_PYTHON=OFF -DVTKOFB_BUILD_BENCHMARKS=OFF \
  -DVTKOFB_FUZZ_ENGINE=libFuzzer -DVTKOFB_FUZZ_RUNS=-1 -DVTKOFB_FUZZ_SECONDS="$FUZZ_SECONDS"

# Mesa unloads its DRI driver when the last window closes, and the driver's allocations
# then show as leaks from "<unknown module>", which no suppression can name. Loaded
# from the start, the driver stays: its allocations are still referenced at exit.
dri=$(ls /usr/lib/*-linux-gnu/dri/swrast_dri.so 2>/dev/null | head -n 1 || true)
xvfb() { xvfb-run -a -s "-screen 0 1280x1024x24" env ${dri:+LD_PRELOAD="$dri"} "$@"; }
if [ "$MODE" = --ci ]; then
  # The unit tests list their tests when built (gtest_discover_tests), under the sanitizers.
  cmake --build "$BUILD_DIR" -- -j"$JOBS" vtkOFBCoreGTests vtkOFBPaintGTests \
    vtkOFBFlowPathsGTests vtkOFBExportGTests vtkOFBIOImageGTests ofbFuzzReader ofbFuzzStrokes \
    ofbFuzzImageHeader
  echo "sanitize.sh: built in $((SECONDS - start)) s"
  (cd "$BUILD_DIR" && xvfb ctest -j"$JOBS" --output-on-failure \
    -R '^OFB\.(Core|Paint|FlowPaths|Export|IOImage)\.')
else
  cmake --build "$BUILD_DIR" -- -j"$JOBS"
  echo "sanitize.sh: built in $((SECONDS - start)) s"
  # Not the install and package tests: they install and package the build, which says
  # nothing more about memory safety.
  (cd "$BUILD_DIR" && xvfb ctest -j"$JOBS" --output-on-failure -LE 'fuzz|Install')
fi
echo "sanitize.sh: tests passed after $((SECONDS - start)) s"
# Each fuzz target on its own core (FUZZ_SECONDS each); the whole output in fuzz.log.
log="$BUILD_DIR/fuzz.log"
set +e
(cd "$BUILD_DIR" && ctest -j"$JOBS" --output-on-failure -V -L fuzz) >"$log" 2>&1
status=$?
set -e
grep -E 'Test +#|Done [0-9]+ runs|ofbFuzzDriver:|stat::number_of_executed_units|tests passed' "$log" || true
if [ "$status" -ne 0 ]; then
  grep -E -B2 -A40 'ERROR: (Address|Leak|libFuzzer)|runtime error|deadly signal|check failed' "$log" |
    head -200 || true
  echo "sanitize.sh: a fuzz target failed: see $log and $BUILD_DIR/Testing/Fuzz/fuzz-artifacts" >&2
fi
echo "sanitize.sh: $MODE finished in $((SECONDS - start)) s"
exit "$status"
