#!/bin/sh
# Makes the images that the failing image tests rendered the new baselines.
#
#   scripts/update-baselines.sh [BUILD_DIR] [NAME_PATTERN]
#
# A failing image test writes its rendered image to the build's Temporary directory
# (BUILD_DIR/Testing/Cxx/Temporary/TestX.png, beside TestX.diff.png). This copies each
# such image over the committed baseline of the same name
# (<module folder>/Testing/Data/Baseline/TestX.png) and prints what it copied. Only
# images whose name matches NAME_PATTERN (a shell pattern, default 'Test*') are copied;
# images without a committed baseline are listed and left. BUILD_DIR defaults to build/.
# Look at the images and at `git diff --stat` before committing.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
pattern=${2:-'Test*'}
if [ ! -d "$build" ]; then
  echo "update-baselines.sh: no build directory $build" >&2
  exit 1
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
