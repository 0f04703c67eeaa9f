#!/usr/bin/env bash
# Installs every Debian 12 package that Kerf's build, tests and benchmarks need; idempotent.
set -euo pipefail

packages=(
  # compilers and build tools
  g++ cmake ninja-build pkg-config
  # compiler cache: the generator test's copy of the project reuses the main build's objects
  ccache
  # ParaView 5.11 with its own VTK, its Python modules, and the Qt development files its CMake needs
  paraview paraview-dev python3-paraview qtbase5-dev qttools5-dev libqt5svg5-dev
  qtxmlpatterns5-dev-tools
  # the plugin's panels link ParaView's Qt components, whose CMake package wants these too
  libqt5opengl5-dev libhdf5-dev libnetcdf-dev
  # development files of the libraries ParaView's VTK links, which its CMake package looks for
  libopenmpi-dev libdouble-conversion-dev liblz4-dev liblzma-dev libjpeg-dev libtiff-dev
  libpng-dev libfreetype-dev libglew-dev libgl2ps-dev libutfcpp-dev libxml2-dev libexpat1-dev
  zlib1g-dev libx11-dev libxt-dev libgl-dev python3-dev
  # Core dependencies; OpenBLAS makes CHOLMOD's supernodal factorization fast; Spectra (header-only)
  # is the spectral segmentation's eigensolver
  libeigen3-dev libopenmesh-dev libsuitesparse-dev libopenblas-dev libspectra-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth valgrind
  # the code's format, checked by the tests (Utilities.Formatting, .clang-format); Clang and its
  # sanitizer runtimes build the sanitized Core tests (Utilities/test.sh)
  clang-format clang libclang-rt-14-dev
  # CGAL's heat method, benchmarked beside Kerf's (header-only)
  libcgal-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "kerf setup: all ${#packages[@]} packages present"
else
  echo "kerf setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# CHOLMOD calls whichever BLAS the alternatives system points at: prefer OpenBLAS.
blas=$(readlink -f /etc/alternatives/libblas.so.3-x86_64-linux-gnu 2>/dev/null || true)
case "$blas" in
  *openblas*) echo "kerf setup: BLAS is OpenBLAS ($blas)" ;;
  *) echo "kerf setup: warning: BLAS is not OpenBLAS ($blas); sparse factorizations will be slower" ;;
esac
