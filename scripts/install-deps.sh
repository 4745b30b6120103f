#!/usr/bin/env bash
# Installs every Debian package the build, the tests and the plotting scripts need.
# Idempotent: packages already present are skipped, so repeat runs cost a second.
set -euo pipefail
# --help / -h: this text, nothing else (no install, no build).
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  echo "usage: bash scripts/install-deps.sh"
  sed -n '2,/^set -euo/p' "$0" | grep '^#' | grep -v -- '--help / -h' | sed 's/^# \{0,1\}//'
  exit 0
fi

PACKAGES=(
  build-essential cmake pkg-config ninja-build
  libpetsc-real-dev libslepc-real-dev   # PETSc/SLEPc, real scalars (the problem is real symmetric)
  libgmsh-dev                           # gmsh C++ API for meshing meridian sections
  patchelf                              # cavity-modes opens libgmsh at its first mesh, not at start (modes/CMakeLists.txt)
  libopenblas0-serial                   # optimised BLAS/LAPACK for MUMPS (Debian's alternatives pick it over the
                                        # reference BLAS): viscous LU factorisations 3.5x faster. Serial: the
                                        # threaded build made the dense sum-rule eigensolve 400x less exact
  libeigen3-dev                         # chain-rom linear algebra
  liblapack-dev                         # LAPACK zgeev (common/complex_eigen.hpp): chain-rom spectrum, the Krylov
                                        # response tables' reduced pencils
  libblas-dev                           # zgemm for the Krylov response basis (modes/fe/dense_blas.hpp)
  libhdf5-openmpi-dev                   # the HDF5 flavour PETSc links
  libcli11-dev libtomlplusplus-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev
  python3-h5py python3-matplotlib python3-numpy   # plotting scripts (Debian's /usr/bin/python3)
  # bench only, not installed here: python3-scipy (bench/cavity_modes_bench.py's Bessel functions,
  # bench/viscous_chain_response.py's quadrature; left out to keep the first run short)
  # optional, not installed here (~0.5 GB): paraview python3-paraview -- tests/modes/fields_test.sh then also
  # opens the --fields XDMF companion with ParaView's own readers
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
