#!/usr/bin/env bash
# Sets up, builds, and runs the whole test suite under a virtual X display.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${KERF_BUILD_DIR:-$source_dir/build}
"$source_dir/Utilities/setup.sh"
"$source_dir/Utilities/build.sh"
cd "$build_dir"
exec xvfb-run -a ctest --output-on-failure -j"$(nproc)" "$@"
