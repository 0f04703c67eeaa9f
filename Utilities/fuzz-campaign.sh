#!/usr/bin/env bash
# The full fuzzing campaign of Kerf's mesh readers: 10,080 generated files (420 per class), each
# through `kerf descriptors` and `kerf cut`, one process per run; prints the table per class.
#   Utilities/fuzz-campaign.sh [KERF_PROGRAM] [SEED] [COUNT]   (defaults: build/bin/kerf, 1, 10080)
# Set FUZZ_JOBS (default: nproc), FUZZ_TIMEOUT (seconds per run, default 60) and FUZZ_KEEP (a folder
# to copy failing inputs into).
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
kerf=${1:-${KERF_BUILD_DIR:-$source_dir/build}/bin/kerf}
seed=${2:-1}
count=${3:-10080}
keep=()
if [ -n "${FUZZ_KEEP:-}" ]; then
  keep=(--keep-failures "$FUZZ_KEEP")
fi
exec /usr/bin/python3 "$source_dir/Testing/Fuzz/fuzz_readers.py" --kerf "$kerf" --seed "$seed" \
  --count "$count" --jobs "${FUZZ_JOBS:-$(nproc)}" --timeout "${FUZZ_TIMEOUT:-60}" \
  --list-failures 100000 "${keep[@]}"
