#!/usr/bin/env bash
# The main job: sets up, builds, and runs the showcase pipeline on a bundled mesh, writing a .vtp
# with every computed array and a PNG into output/ (arguments go to `kerf showcase`).
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${KERF_BUILD_DIR:-$source_dir/build}
"$source_dir/Utilities/setup.sh"
"$source_dir/Utilities/build.sh" >/dev/null
exec xvfb-run -a "$build_dir/bin/kerf" showcase -o "$source_dir/output" "$@"
