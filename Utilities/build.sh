#!/usr/bin/env bash
# Configures and builds Kerf (Release, Ninja) into build/ or $KERF_BUILD_DIR, through ccache when it
# is installed. Paths under the source directory reach ccache relative to the build directory
# (CCACHE_BASEDIR), so a copy of the sources built in its own build/ (the filter generator's test,
# Testing/Utilities/TestNewFilter.sh) finds this build's objects.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${KERF_BUILD_DIR:-$source_dir/build}
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=$source_dir
fi
if [ ! -f "$build_dir/build.ninja" ]; then
  cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" >"$build_dir.configure.log" 2>&1 || {
    cat "$build_dir.configure.log"
    exit 1
  }
fi
cmake --build "$build_dir" -- -j"$(nproc)"
