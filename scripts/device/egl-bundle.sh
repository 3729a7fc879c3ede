#!/usr/bin/env bash
# Packs the OpenGL and re-sampling benchmarks for a Linux machine with a GPU driver and
# no VTK (a compute node): the programs, the project's and VTK's libraries (not the C
# and C++ runtimes, not the GPU driver) and the bundled meshes, with a script that runs
# them there through EGL (no X display).
#
#   scripts/device/egl-bundle.sh [BUILD_DIR] [OUTPUT]   (default build, build/ofb-benchmarks.tar.xz)
#
# On the other machine:  tar -xJf ofb-benchmarks.tar.xz && ofb-benchmarks/run.sh [OUT_DIR]
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD_DIR="$(cd "${1:-$ROOT/build}" && pwd)"
OUTPUT="${2:-$BUILD_DIR/ofb-benchmarks.tar.xz}"
PROGRAMS=(ofbBuilderBenchmark ofbMapperBenchmark ofbResampleBenchmark)

STAGE="$(mktemp -d)"
trap 'rm -rf "$STAGE"' EXIT
B="$STAGE/ofb-benchmarks"
mkdir -p "$B/bin" "$B/lib" "$B/meshes"
for p in "${PROGRAMS[@]}"; do
  cp "$BUILD_DIR/bin/$p" "$B/bin/"
done
cp -a "$BUILD_DIR"/lib/libvtkOFB*.so* "$B/lib/"
(cd "$BUILD_DIR/bin" && ldd "${PROGRAMS[@]}") | awk '$3 ~ /^\// {print $3}' | sort -u |
  grep -v "^$BUILD_DIR/" |
  grep -Ev '/(libc|libm|libstdc\+\+|libgcc_s|ld-linux-x86-64|libpthread|libdl|librt)\.so' |
  while read -r f; do cp -L "$f" "$B/lib/"; done
cp "$ROOT"/../shared/data/meshes/*.obj "$ROOT"/../shared/data/meshes/*.ply "$B/meshes/" 2>/dev/null ||
  cp "$ROOT"/Testing/Data/*.obj "$ROOT"/Testing/Data/*.ply "$B/meshes/"

cat > "$B/run.sh" <<'RUN'
#!/usr/bin/env bash
# Runs the benchmarks of this bundle through EGL device 0; their tables go to OUT_DIR.
set -uo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
OUT="${1:-.}"
mkdir -p "$OUT"
# The NVIDIA EGL vendor library, where the driver put it.
json=$(ls /usr/share/glvnd/egl_vendor.d/*nvidia*.json \
  /usr/local/nvidia/share/glvnd/egl_vendor.d/*nvidia*.json 2>/dev/null | head -1)
[ -n "$json" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$json"
export LD_LIBRARY_PATH="$HERE/lib:/usr/local/nvidia/lib64:${LD_LIBRARY_PATH:-}"
unset DISPLAY
m="$HERE/meshes"
MESHES=("$m"/stanford-bunny.obj "$m"/horse.ply "$m"/spot.obj "$m"/teapot.obj "$m"/fandisk.obj
  "$m"/rocker-arm.obj "$m"/cow.obj)
"$HERE/bin/ofbBuilderBenchmark" --egl --phases --repetitions 7 --resolutions 512,1024,2048 \
  "${MESHES[@]}" | tee "$OUT/builder.txt"
"$HERE/bin/ofbMapperBenchmark" --egl --frames 60 --rounds 3 --mesh "$m/stanford-bunny.obj" \
  | tee "$OUT/mapper.txt"
"$HERE/bin/ofbMapperBenchmark" --egl --lic --modes smooth --zoom 4 --frames 30 --rounds 3 \
  --mesh "$m/stanford-bunny.obj" | tee "$OUT/mapper-lic-close.txt"
for threads in 1 2 0; do
  if [ "$threads" = 1 ]; then
    env VTK_SMP_BACKEND_IN_USE=Sequential "$HERE/bin/ofbResampleBenchmark" --repetitions 7 \
      --resolutions 1024 "${MESHES[@]}"
  elif [ "$threads" = 2 ]; then
    env VTK_SMP_MAX_THREADS=2 "$HERE/bin/ofbResampleBenchmark" --repetitions 7 \
      --resolutions 1024 "${MESHES[@]}"
  else
    "$HERE/bin/ofbResampleBenchmark" --repetitions 7 --resolutions 1024 "${MESHES[@]}"
  fi
done | tee "$OUT/resample.txt"
RUN
chmod +x "$B/run.sh"
tar -cf - -C "$STAGE" ofb-benchmarks | xz -T0 -6 > "$OUTPUT"
echo "egl-bundle.sh: $OUTPUT ($(du -h "$OUTPUT" | cut -f1)); run ofb-benchmarks/run.sh there"
