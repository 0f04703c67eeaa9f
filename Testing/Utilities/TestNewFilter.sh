#!/usr/bin/env bash
# The filter generator works: in a copy of the sources, Utilities/new-filter.sh makes a filter
# that builds, whose Core and filter tests pass and whose proxy loads with the plugin.
#   TestNewFilter.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1
work=$2
rm -rf "$work"
mkdir -p "$work/src"
# The tracked files only (no build trees).
(cd "$source_dir" && git ls-files -z --cached --others --exclude-standard 2>/dev/null || find . -path ./build -prune -o -type f -print0) |
  (cd "$source_dir" && xargs -0 cp --parents -t "$work/src")
cd "$work/src"
./Utilities/new-filter.sh ExampleValence Geometry
# Refuses to make the same filter twice, and bad names.
! ./Utilities/new-filter.sh ExampleValence Geometry 2>/dev/null
! ./Utilities/new-filter.sh example Geometry 2>/dev/null
# The lists it touched agree with the files.
/usr/bin/python3 Testing/Utilities/CheckLists.py .
# The copy builds in its own build/ with the main build's base directory, as Utilities/build.sh
# does: through ccache its unchanged sources compile to the main build's cached objects.
build=$work/src/build
source "$source_dir/Utilities/compiler-cache.sh" "$source_dir"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DKERF_BUILD_BENCHMARKS=OFF "${compiler_cache[@]}" > "$work/configure.log"
cmake --build "$build" --target KerfCoreTests KerfFilterTests Kerf > "$build.log"
"$build/bin/KerfCoreTests" --gtest_filter='ExampleValence.*'
"$build/bin/KerfFilterTests" TestExampleValenceFilter
grep -q "ExampleValence.xml" "$build/Plugins/ParaView/CMakeFiles/Kerf.dir/"*.* 2>/dev/null ||
  grep -rq "KerfExampleValence" "$build/Plugins" || { echo "the proxy is not in the plugin" >&2; exit 1; }
echo "generated filter ExampleValence builds and its tests pass"
