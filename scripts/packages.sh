# Sourced by scripts/demo.sh and scripts/test.sh: the Debian bookworm packages
# vtkOFB needs and `install_packages NAME`, which installs them when any is missing
# (apt-get update first), as root or through sudo.
#
# libvtk9-dev's CMake package needs the -dev packages it depends on (TBB for
# vtkSMPTools among them); python3-numpy is for vtkmodules.util.numpy_support in
# the Python tests; libgl1-mesa-dri gives llvmpipe, the OpenGL implementation under
# Xvfb; libopenvdb-dev is the benchmark's peer. One list for both scripts, so one
# build directory serves both.
PACKAGES=(
  cmake g++ make
  libvtk9-dev python3-vtk9 python3-numpy libtbb-dev
  libglm-dev libopenimageio-dev libopenvdb-dev libgtest-dev
  xvfb xauth libgl1-mesa-dri
)

install_packages() {
  local name="$1" missing=() pkg
  for pkg in "${PACKAGES[@]}"; do
    if [ "$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null)" != "install ok installed" ]; then
      missing+=("$pkg")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    echo "$name: all ${#PACKAGES[@]} packages are installed, skipping apt-get"
    return
  fi
  echo "$name: installing packages (missing: ${missing[*]})"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo=(sudo)
    else
      echo "$name: not root and no sudo: install ${missing[*]} first" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${PACKAGES[@]}"
}
