#!/usr/bin/env bash
# Configures and builds Kerf (Release, Ninja) into build/ or $KERF_BUILD_DIR, through ccache when it
# is installed (Utilities/compiler-cache.sh).
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${KERF_BUILD_DIR:-$source_dir/build}
source "$source_dir/Utilities/compiler-cache.sh" "$source_dir"
if [ ! -f "$build_dir/build.ninja" ]; then
  cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 "${compiler_cache[@]}" >"$build_dir.configure.log" 2>&1 || {
    cat "$build_dir.configure.log"
    exit 1
  }
fi
cmake --build "$build_dir" -- -j"$(nproc)"
