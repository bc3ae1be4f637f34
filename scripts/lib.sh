# Shared by scripts/demo.sh, scripts/test.sh and the CI jobs in .ci/: Debian 12 packages for
# each VTK flavour (and the CI jobs' own), installed with apt-get when missing (as root, or
# through sudo).
#
# The two flavours cannot be installed together (python3-paraview conflicts with python3-vtk9,
# which libvtk9-dev needs); installing one removes the other.

COMMON_PACKAGES="cmake g++ make pkg-config git xvfb xauth libmeshoptimizer-dev python3
  python3-numpy valgrind libcli11-dev nlohmann-json3-dev"
VTK_PACKAGES="libvtk9-dev python3-vtk9"
# find_package(ParaView) loads ParaView's VTK, whose package looks for all of VTK's third-party
# libraries: their -dev packages are not dependencies of paraview-dev, hence the long list.
PARAVIEW_PACKAGES="paraview-dev python3-paraview qtbase5-dev qttools5-dev libqt5svg5-dev
  qttools5-dev-tools qtxmlpatterns5-dev-tools libxml2-dev libhdf5-openmpi-dev libnetcdf-dev
  libgl2ps-dev libglew-dev libtheora-dev libogg-dev libavcodec-dev libavformat-dev libavutil-dev
  libswscale-dev libavdevice-dev libavfilter-dev libswresample-dev libgdal-dev libutfcpp-dev
  libdouble-conversion-dev liblz4-dev liblzma-dev libjpeg-dev libpng-dev libtiff-dev
  libfreetype-dev libopenmpi-dev"

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    echo "error: packages are missing and this is not root (and there is no sudo): $*" >&2
    exit 1
  fi
}

missing_packages() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

# ensure_packages PKG... [-- REMOVE...]: install what is missing, removing conflicting ones.
ensure_packages() {
  local install=() remove=() seen_sep=0 p
  for p in "$@"; do
    if [ "$p" = "--" ]; then seen_sep=1; continue; fi
    if [ $seen_sep -eq 0 ]; then install+=("$p"); else remove+=("$p"); fi
  done
  local missing present_removals=()
  missing=$(missing_packages "${install[@]}")
  for p in "${remove[@]}"; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q "install ok installed" \
      && present_removals+=("$p-")
  done
  if [ -z "$missing" ] && [ ${#present_removals[@]} -eq 0 ]; then
    return 0
  fi
  echo "== apt-get install: ${missing//$'\n'/ } ${present_removals[*]}"
  # Refresh the package lists when they are absent or older than a day.
  if [ -z "$(find /var/lib/apt/lists -maxdepth 1 -name '*_Packages*' -mmin -1440 2>/dev/null | head -1)" ]; then
    apt_get update -q
  fi
  apt_get install -y -q "${install[@]}" "${present_removals[@]}"
}

# apt_get ARGS...: apt-get as root, never prompting (also through sudo, which drops the
# environment), waiting up to 10 minutes for another apt or dpkg (a fresh machine's own
# updates) to finish.
apt_get() {
  as_root env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 "$@"
}

# ensure_flavour vtk|paraview
ensure_flavour() {
  case "$1" in
    vtk) ensure_packages $COMMON_PACKAGES $VTK_PACKAGES -- python3-paraview paraview paraview-dev ;;
    paraview) ensure_packages $COMMON_PACKAGES $PARAVIEW_PACKAGES -- python3-vtk9 libvtk9-dev ;;
    *) echo "error: unknown flavour '$1' (vtk or paraview)" >&2; exit 2 ;;
  esac
}

# The flavour installed now (vtk, paraview or none).
installed_flavour() {
  if [ -z "$(missing_packages paraview-dev)" ]; then echo paraview
  elif [ -z "$(missing_packages libvtk9-dev)" ]; then echo vtk
  else echo none; fi
}

cmake_flavour() {
  case "$1" in vtk) echo VTK ;; paraview) echo ParaView ;; esac
}
