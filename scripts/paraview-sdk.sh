#!/usr/bin/env bash
# ParaView's Python world beside Debian's VTK, without installing python3-paraview.
#
#   scripts/paraview-sdk.sh BUILD_DIR
#
# Debian's python3-paraview declares `Conflicts: python3-vtk9` (both ship a vtkmodules
# package), so installing it would remove python3-vtk9 and libvtk9-dev. This script
# unpacks it instead (apt-get download + dpkg -x, nothing installed) into
# BUILD_DIR/paraview-sdk/python, and makes BUILD_DIR/paraview-sdk/usr, a prefix of
# links to /usr whose lib/python3 is the unpacked one, and BUILD_DIR/paraview-sdk/bin/pvpython
# and pvbatch, which run ParaView's tools with it. Both are needed:
# - pvpython and pvbatch run from that prefix's Python packages (PYTHONPATH);
# - paraview-dev's CMake package names the Python modules of python3-paraview and
#   fails without them: the plugin is configured with
#   ParaView_DIR=BUILD_DIR/paraview-sdk/usr/lib/<multiarch>/cmake/paraview-5.11,
#   which finds everything else in /usr through the links.
# When python3-paraview is installed, neither is needed and nothing is done.
# Needs paraview-dev installed (scripts/packages.sh installs it).
set -euo pipefail

BUILD_DIR="${1:?usage: paraview-sdk.sh BUILD_DIR}"
SDK="$(mkdir -p "$BUILD_DIR" && cd "$BUILD_DIR" && pwd)/paraview-sdk"
MULTIARCH="$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -dumpmachine)"

if [ "$(dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null)" = "install ok installed" ]; then
  echo "paraview-sdk.sh: python3-paraview is installed, nothing to unpack"
  exit 0
fi
PV_VERSION="$(dpkg-query -W -f='${Version}' paraview 2>/dev/null || true)"
if [ -z "$PV_VERSION" ]; then
  echo "paraview-sdk.sh: ParaView (paraview-dev) is not installed, skipping" >&2
  exit 0
fi

# Unpacked once per ParaView version.
if [ "$(cat "$SDK/version" 2>/dev/null || true)" != "$PV_VERSION" ] || [ ! -x "$SDK/bin/pvpython" ]; then
  rm -rf "$SDK"
  mkdir -p "$SDK/download"
  # apt-get download writes into the working directory; _apt may not write there.
  (cd "$SDK/download" && chmod 777 . && apt-get download "python3-paraview=$PV_VERSION")
  dpkg-deb -x "$SDK"/download/python3-paraview_*.deb "$SDK/python"
  rm -rf "$SDK/download"
  # The prefix: links to /usr's entries, except the CMake package (a copy, so that
  # its imported targets find their prefix here and not through the links to /usr),
  # pvpython and lib/python3 (from the unpacked package) and the wrapping hierarchy files of
  # ParaView's VTK (python3-paraview ships them).
  local_lib="$SDK/usr/lib/$MULTIARCH"
  mkdir -p "$local_lib/cmake" "$local_lib/vtk/hierarchy"
  for dir in include share; do
    ln -s "/usr/$dir" "$SDK/usr/$dir"
  done
  mkdir -p "$SDK/usr/bin"
  for entry in /usr/bin/* "$SDK"/python/usr/bin/*; do
    ln -sfn "$entry" "$SDK/usr/bin/"
  done
  for entry in "/usr/lib/$MULTIARCH"/*; do
    case "${entry##*/}" in
      cmake | vtk) ;;
      *) ln -s "$entry" "$local_lib/" ;;
    esac
  done
  for entry in "/usr/lib/$MULTIARCH/cmake"/*; do
    case "${entry##*/}" in
      paraview-*) cp -r "$entry" "$local_lib/cmake/" ;;
      *) ln -s "$entry" "$local_lib/cmake/" ;;
    esac
  done
  for entry in "/usr/lib/$MULTIARCH/vtk/hierarchy"/* "$SDK/python/usr/lib/$MULTIARCH/vtk/hierarchy"/*; do
    ln -sfn "$entry" "$local_lib/vtk/hierarchy/"
  done
  ln -s "$SDK/python/usr/lib/python3" "$SDK/usr/lib/python3"
  echo "$PV_VERSION" > "$SDK/version"
fi
# pvpython, pvbatch and the paraview GUI with ParaView's Python: PYTHONPATH, and the
# libraries through the prefix's links, so that their search for the Python modules
# (relative to their libraries) finds the unpacked ones and not python3-vtk9's in /usr.
# Written on every run (cheap), so that an unpacked prefix gets new wrappers too.
mkdir -p "$SDK/bin"
for tool in pvpython pvbatch paraview; do
  [ -e "$SDK/usr/bin/$tool" ] || continue
  cat > "$SDK/bin/$tool" <<WRAPPER
#!/bin/sh
# $tool with ParaView's Python unpacked in $SDK (scripts/paraview-sdk.sh).
PYTHONPATH="$SDK/python/usr/lib/python3/dist-packages\${PYTHONPATH:+:\$PYTHONPATH}" \\
LD_LIBRARY_PATH="$SDK/usr/lib/$MULTIARCH\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}" \\
  exec "$SDK/usr/bin/$tool" "\$@"
WRAPPER
  chmod +x "$SDK/bin/$tool"
done
echo "paraview-sdk.sh: ParaView $PV_VERSION's Python in $SDK/python; run $SDK/bin/pvpython, pvbatch or paraview"
