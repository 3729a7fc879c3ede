#!/usr/bin/env bash
# Runs the frame-time benchmarks on a Linux machine with an NVIDIA driver and no VTK, from
# the folder scripts/device/pack.sh filled (DEST), copied to that machine:
#
#   bash DEST/run.sh [PART...]     PART: probe mapper lic paint mapper-offscreen
#                                       lic-offscreen (default all)
# Environment: ROUNDS (default 3), LIC_FRAMES (default 20), MAPPER_FRAMES (default 30):
# the benchmarks' --rounds and --frames.
#
# Sets up: glvnd from gl/*.deb (unpacked into /), the
# archive into /tmp/ofb, Xvfb on :99 with Mesa's swrast for its GLX extension, then
# DISPLAY=:99 and __GLX_VENDOR_LIBRARY_NAME=nvidia so that VTK's GLX window renders on the
# NVIDIA driver (libGLX_nvidia from the driver's folder). glprobe prints the renderer
# VTK got; unless it is NVIDIA's, nothing is timed (an llvmpipe number there is worthless).
# Each part's output goes to $OUT/<part>.txt (and to stdout).
set -u
CARRY="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
OUT="${OUT:-/tmp/out}"
mkdir -p "$OUT"
PARTS="${*:-probe mapper lic paint mapper-offscreen lic-offscreen}"
R="${ROUNDS:-3}" LF="${LIC_FRAMES:-20}" MF="${MAPPER_FRAMES:-30}"
T0=$(date +%s)
stamp() { echo "== $(($(date +%s) - T0)) s: $*"; }

stamp "setup"
for f in "$CARRY"/gl/*.deb; do dpkg -x "$f" /; done
ldconfig
mkdir -p /tmp/ofb && tar -xJf "$CARRY/ofbgpu.tar.xz" -C /tmp/ofb || exit 2
O=/tmp/ofb
# The driver's GL libraries (libGLX_nvidia.so.0 and what it loads).
NV="$(find /usr/local/nvidia /usr/lib /usr/lib64 -name 'libGLX_nvidia.so.0' 2>/dev/null | head -1)"
[ -z "$NV" ] && NV="$(ldconfig -p | awk '/libGLX_nvidia.so.0/ {print $NF; exit}')"
[ -n "$NV" ] && NV="$(dirname "$NV")"
LIBS="$O/lib:${NV:-/usr/local/nvidia/lib64}"
# Our libstdc++/libgcc_s only where the machine's own lack the versions the build needs.
need="$(grep -ao 'GLIBCXX_3\.4\.[0-9]*' "$O/compat/libstdc++.so.6" | sort -uV | tail -1)"
sys="$(ldconfig -p | awk '/libstdc\+\+\.so\.6 .*x86-64/ {print $NF; exit}')"
if [ -z "$sys" ] || ! grep -aq "$need" "$sys"; then LIBS="$LIBS:$O/compat"; fi
# Only our programs see the carried (Debian bookworm) libraries, not the machine's own tools.
with_libs() { env LD_LIBRARY_PATH="$LIBS" "$@"; }
{
  uname -r; ldd --version | head -1; nvidia-smi -L
  echo "driver GL folder: $NV"; ls "$NV" 2>/dev/null | grep -i 'glx\|egl\|glcore' | tr '\n' ' '
  echo; echo "needs $need; system libstdc++: $sys; our LD_LIBRARY_PATH=$LIBS"
  nproc; grep -m1 'model name' /proc/cpuinfo
} 2>&1 | tee "$OUT/setup.txt"

# Xvfb wants xkbcomp in /usr/bin; its GLX extension wants swrast_dri.so (LIBGL_DRIVERS_PATH).
[ -x /usr/bin/xkbcomp ] || cp "$O/bin/xkbcomp" /usr/bin/xkbcomp
export LIBGL_DRIVERS_PATH="$O/dri"
with_libs "$O/bin/Xvfb" :99 -screen 0 1280x1024x24 -nolisten tcp -xkbdir "$O/xkb" \
  > "$OUT/xvfb.txt" 2>&1 &
XPID=$!
for _ in $(seq 50); do [ -e /tmp/.X11-unix/X99 ] && break; sleep 0.2; done
export DISPLAY=:99

# The renderer VTK gets: NVIDIA's, or stop.
stamp "probe"
__GLX_VENDOR_LIBRARY_NAME=nvidia timeout 60 env LD_LIBRARY_PATH="$LIBS" "$O/bin/glprobe" > "$OUT/probe.txt" 2>&1
echo "glprobe exit $?"; grep -E 'vendor string|renderer string|version string' "$OUT/probe.txt" | cut -c1-160
if ! grep -q 'OpenGL renderer string:.*NVIDIA' "$OUT/probe.txt"; then
  head -c 3000 "$OUT/probe.txt"; echo; cat "$OUT/xvfb.txt"
  echo "-- for comparison, Mesa's client library:"
  __GLX_VENDOR_LIBRARY_NAME=mesa timeout 60 env LD_LIBRARY_PATH="$LIBS" "$O/bin/glprobe" 2>&1 | grep -E 'renderer string|rror' | head
  kill "$XPID"; exit 3
fi
export __GLX_VENDOR_LIBRARY_NAME=nvidia

# The benchmarks read VTKOFB_DATA_DIR (compiled in): link it to this tree's meshes.
DATA="$(cat "$O/datadir.txt")"
if [ ! -e "$DATA" ]; then mkdir -p "$(dirname "$DATA")" && ln -s "$PWD/Testing/Data" "$DATA"; fi

part() { # name timeout command...
  local name=$1 limit=$2; shift 2
  stamp "$name: $*"
  timeout "$limit" env LD_LIBRARY_PATH="$LIBS" "$@" 2>&1 | tee "$OUT/$name.txt"
}
for p in $PARTS; do
  case $p in
    probe) ;;
    mapper) part mapper 120 "$O/bin/ofbMapperBenchmark" --frames "$MF" --rounds "$R" ;;
    lic) part lic 400 "$O/bin/ofbLICBenchmark" --frames-only --rounds "$R" --frames "$LF" ;;
    paint) part paint 180 "$O/bin/ofbPaintBenchmark" --resolutions 2048 --dabs5 100 \
      --dabs25 10 --no-openvdb ;;
    mapper-offscreen) part mapper-offscreen 120 "$O/bin/ofbMapperBenchmark" --frames "$MF" \
      --rounds "$R" --offscreen ;;
    lic-offscreen) part lic-offscreen 400 "$O/bin/ofbLICBenchmark" --frames-only --rounds "$R" \
      --frames "$LF" --offscreen ;;
  esac
done
stamp "done"
kill "$XPID"
