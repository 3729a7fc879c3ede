#!/bin/sh
# Makes the images that the failing image tests rendered the new baselines.
#
#   scripts/update-baselines.sh --run [BUILD_DIR] [NAME_PATTERN]   build, run, copy
#   scripts/update-baselines.sh [BUILD_DIR] [NAME_PATTERN]         copy only
#
# A failing image test writes its rendered image to the build's Temporary directory
# (BUILD_DIR/Testing/Cxx/Temporary/TestX.png, beside TestX.diff.png). This copies each
# such image over the committed baseline of the same name
# (<module folder>/Testing/Data/Baseline/TestX.png) and prints what it copied. Only
# images whose name matches NAME_PATTERN (a shell pattern, default 'Test*') are copied;
# images without a committed baseline are listed and left. BUILD_DIR defaults to build/.
#
# --run first builds BUILD_DIR, removes the images of earlier runs from its Temporary
# directories and runs the regression-image tests (ctest -R 'Cxx-Test', under xvfb-run
# when there is no DISPLAY), so that only the images of this run are copied.
# Look at the images and at `git diff --stat` before committing.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
run=0
if [ "${1:-}" = "--run" ]; then
  run=1
  shift
fi
build=${1:-"$root/build"}
pattern=${2:-'Test*'}
if [ ! -d "$build" ]; then
  echo "update-baselines.sh: no build directory $build" >&2
  exit 1
fi
if [ "$run" = 1 ]; then
  cmake --build "$build" -j "${JOBS:-$(nproc)}"
  find "$build" -path '*/Temporary/*.png' -delete
  if [ -n "${DISPLAY:-}" ]; then
    (cd "$build" && ctest -R 'Cxx-Test' --output-on-failure) || true
  else
    (cd "$build" && xvfb-run -a -s "-screen 0 1280x1024x24" \
      ctest -R 'Cxx-Test' --output-on-failure) || true
  fi
fi
copied=0
for image in $(find "$build" -path '*/Temporary/*.png' ! -name '*.diff.png' | sort); do
  name=$(basename "$image")
  case "${name%.png}" in
    $pattern) ;;
    *) continue ;;
  esac
  baselines=$(git -C "$root" ls-files "*/Testing/Data/Baseline/$name")
  if [ -z "$baselines" ]; then
    echo "no committed baseline named $name (left: $image)"
    continue
  fi
  for baseline in $baselines; do
    cp "$image" "$root/$baseline"
    echo "$image -> $baseline"
    copied=$((copied + 1))
  done
done
echo "$copied baseline(s) updated"
