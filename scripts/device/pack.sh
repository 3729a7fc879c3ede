#!/usr/bin/env bash
# Bundles the built frame-time benchmarks, the shared libraries they need and a GL probe,
# for a Linux x86-64 machine with an NVIDIA driver and no VTK (no X server either).
#
#   scripts/device/pack.sh DEST     (DEST: the folder to copy to that machine, e.g. a
#                                    folder of the checkout that git ignores)
#
# Writes into DEST:
#   ofbgpu.tar.xz  the benchmarks (build/bin; ofbPaintBenchmark compiled again without
#                  OpenVDB, whose library alone is 57 MB), our libvtkOFB*.so, glprobe
#                  (VTK's renderer string, scripts/device/glprobe.cxx), Xvfb and xkbcomp
#                  with the keyboard data, Mesa's swrast_dri.so (Xvfb's GLX extension needs
#                  it) and libGLX_mesa (for a comparison run), and every shared library these
#                  load (ldd), except glibc's own and glvnd's (next line); libstdc++/libgcc_s
#                  go to compat/, used only where the device's own are older. libz3 and
#                  libicudata (30 MB, loaded by Mesa's LLVM but never called when it
#                  renders) are replaced by stubs that only satisfy the loader;
#   gl/*.deb       glvnd (libglvnd0 libgl1 libglx0 libopengl0 libegl1), which run.sh
#                  unpacks into / on the target machine;
#   run.sh         scripts/device/run.sh, so that DEST runs on its own.
# Needs a Release build in BUILD_DIR (default build) with the targets ofbLICBenchmark,
# ofbMapperBenchmark and ofbPaintBenchmark. The archive is compressed with xz to keep it
# small enough to copy (tens of MB).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
DEST="${1:?usage: pack.sh DEST}"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
mkdir -p "$DEST"
DEST="$(cd "$DEST" && pwd)"
STAGE="$(mktemp -d)"
trap 'rm -rf "$STAGE"' EXIT
ARCH=/usr/lib/x86_64-linux-gnu

mkdir -p "$BUILD_DIR/device"
g++ -O2 -std=c++17 -I/usr/include/vtk-9.1 "$ROOT/scripts/device/glprobe.cxx" \
  -o "$BUILD_DIR/device/glprobe" -lvtkRenderingOpenGL2-9.1 -lvtkRenderingCore-9.1 \
  -lvtkFiltersSources-9.1 -lvtkCommonExecutionModel-9.1 -lvtkCommonCore-9.1 -lvtkRenderingUI-9.1

# ofbPaintBenchmark without OpenVDB: its compile and link lines from the build, minus
# the OpenVDB define and libraries.
pd="$BUILD_DIR/Testing/Benchmarks"
pf="$pd/CMakeFiles/ofbPaintBenchmark.dir"
flag() { sed -n "s/^$1 = //p" "$pf/flags.make"; }
(
  cd "$pd"
  eval "c++ $(flag CXX_FLAGS) $(flag CXX_DEFINES | sed 's/-DVTKOFB_BENCHMARK_HAVE_OPENVDB=1//') \
    $(flag CXX_INCLUDES) -c '$ROOT/Testing/Benchmarks/ofbPaintBenchmark.cxx' \
    -o '$BUILD_DIR/device/ofbPaintBenchmark.o'"
  eval "$(sed -e "s|CMakeFiles/ofbPaintBenchmark.dir/ofbPaintBenchmark.cxx.o|$BUILD_DIR/device/ofbPaintBenchmark.o|" \
    -e "s|-o ../../bin/ofbPaintBenchmark|-o $BUILD_DIR/device/ofbPaintBenchmark|" \
    -e 's|[^ ]*libopenvdb[^ ]*||; s|[^ ]*libImath[^ ]*||' "$pf/link.txt")"
)

mkdir -p "$STAGE/bin" "$STAGE/lib" "$STAGE/compat" "$STAGE/dri"
bins=("$BUILD_DIR/bin/ofbLICBenchmark" "$BUILD_DIR/bin/ofbMapperBenchmark"
  "$BUILD_DIR/device/ofbPaintBenchmark")
cp "${bins[@]}" "$STAGE/bin/"
cp "$BUILD_DIR/device/glprobe" /usr/bin/Xvfb /usr/bin/xkbcomp "$STAGE/bin/"
cp -L "$ARCH/dri/swrast_dri.so" "$STAGE/dri/"
cp -L "$ARCH/libGLX_mesa.so.0" "$STAGE/lib/"
cp -a /usr/share/X11/xkb "$STAGE/xkb"
# The data folder compiled into the benchmarks (VTKOFB_DATA_DIR): run.sh links it to the
# device tree's Testing/Data.
echo "$ROOT/Testing/Data" > "$STAGE/datadir.txt"

# Every library the programs load, resolved here.
ldd "${bins[@]}" "$BUILD_DIR/device/glprobe" /usr/bin/Xvfb /usr/bin/xkbcomp \
  "$STAGE/dri/swrast_dri.so" "$STAGE/lib/libGLX_mesa.so.0" |
  awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u |
  while read -r lib; do
    name="$(basename "$lib")"
    case "$name" in
      libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|ld-linux*|libresolv.so.*) ;;
      libGL.so.*|libGLX.so.*|libGLdispatch.so.*|libOpenGL.so.*|libEGL.so.*) ;;
      libstdc++.so.*|libgcc_s.so.*) cp -L "$lib" "$STAGE/compat/$name" ;;
      *) cp -L "$lib" "$STAGE/lib/$name" ;;
    esac
  done
# Stubs for Mesa's LLVM's never-called dependencies (exported names only).
nm -D --undefined-only "$ARCH/libLLVM-15.so.1" | awk '$2 ~ /^Z3_/ { print "void " $2 "(void) {}" }' \
  > "$STAGE/z3stub.c"
gcc -shared -fPIC -Wl,-soname,libz3.so.4 "$STAGE/z3stub.c" -o "$STAGE/lib/libz3.so.4"
echo 'const char icudt72_dat[64] __attribute__((aligned(16))) = { 0 };' > "$STAGE/icustub.c"
gcc -shared -fPIC -Wl,-soname,libicudata.so.72 "$STAGE/icustub.c" -o "$STAGE/lib/libicudata.so.72"
rm "$STAGE/z3stub.c" "$STAGE/icustub.c"

cp "$ROOT/scripts/device/run.sh" "$DEST/run.sh"
tar -C "$STAGE" -cf - . | xz -T2 -6 > "$DEST/ofbgpu.tar.xz"

# glvnd's packages for run.sh (downloaded with apt lists of their own, amd64).
mkdir -p "$DEST/gl" /tmp/amd64/partial
o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
if ! ls "$DEST"/gl/libglvnd0_*.deb >/dev/null 2>&1; then
  # shellcheck disable=SC2086
  apt-get $o update >/dev/null
  # shellcheck disable=SC2086
  (cd "$DEST/gl" && apt-get $o download libglvnd0 libgl1 libglx0 libopengl0 libegl1)
fi
du -sh "$DEST"/*
