#!/bin/bash
# Installs every Debian 12 package that yade-rbsm needs to build, test and run (idempotent: apt-get
# install leaves installed packages alone). Runs as root, or through sudo otherwise.
set -euo pipefail

PACKAGES=(
  yade                                  # Debian's YADE 2023.02a: the host of the plugin
  cmake make g++ ccache binutils        # build; binutils (nm, objdump, readelf, c++filt) for the ABI tests
  libeigen3-dev libboost-python-dev libboost-serialization-dev python3-dev libcgal-dev
  libgtest-dev googletest               # C++ unit tests
  python3-pytest python3-numpy python3-matplotlib python3-vtk9   # Python tests, post-processing
  python3-scipy                         # yade_rbsm.safety: connected joints (scipy.sparse.csgraph)
  python3-ezdxf                         # yade_rbsm.io: DXF import and export
  python3-getfem                        # scripts/fe_stress_fs.py: the elastic FE stress field of a slope (issue 21)
  dpkg-dev                              # the Debian package: dpkg-shlibdeps (cpack DEB), dpkg-deb
  valgrind                              # benchmarks: instruction counts (callgrind; scripts/benchmarks/)
  libgl-dev                             # the qt view's functors (Gl1_*) draw with OpenGL
  xvfb python3-pil                      # GUI tests (tests/gui, scripts/run_in_qt_view.py): virtual X display, PNG pixels
  openmpi-bin python3-mpi4py            # distributed runs with yade.mpy (mpiexec; tests/mpi/)
  python3-sphinx python3-myst-parser python3-sphinx-rtd-theme   # the manual (scripts/build_docs.sh)
  chromium                              # tests/docs: the manual's pages rendered headless (a screenshot)
)

if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null; then
  SUDO=(sudo)
else
  echo "setup.sh: run as root or install sudo" >&2
  exit 1
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all ${#PACKAGES[@]} packages are installed"
  exit 0
fi
echo "setup.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update
"${SUDO[@]}" apt-get install -y "${PACKAGES[@]}"
