#!/usr/bin/env bash
# Creates a new Kerf filter from Utilities/FilterTemplate and adds it to the build:
#   Utilities/new-filter.sh NAME AREA
# NAME is the algorithm in CamelCase (VertexValence), AREA the Core folder (Geometry, Harmonic,
# Geodesic, Segmentation, ...). It writes the Core function and its unit test, the filter and
# its test, the ParaView proxy with its menu icon and the documentation page, and adds them to the one list of
# filters (Source/Filters/CMakeLists.txt), the Core sources and the README's table of filters (the
# test lists are globbed; Utilities.ListsAgree checks the rest). The result builds
# and its tests pass; then replace the stub algorithm (each neighbour count) with the real one.
set -euo pipefail
usage="usage: Utilities/new-filter.sh NAME AREA   (e.g. VertexValence Geometry)"
[ $# -eq 2 ] || { echo "$usage" >&2; exit 2; }
name=$1
area=$2
[[ $name =~ ^[A-Z][A-Za-z0-9]+$ ]] || { echo "NAME must be CamelCase letters and digits: $name" >&2; exit 2; }
[[ $area =~ ^[A-Z][A-Za-z0-9]+$ ]] || { echo "AREA must be CamelCase letters and digits: $area" >&2; exit 2; }
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
templates=Utilities/FilterTemplate
label=$(echo "$name" | sed -E 's/([a-z0-9])([A-Z])/\1 \2/g')

for existing in "Source/Core/$area/$name.h" "Source/Filters/vtk$name.h" "Plugins/ParaView/$name.xml" \
  "Testing/Core/Test$name.cxx" "Testing/Filters/Test${name}Filter.cxx" "Documentation/filters/$name.md" \
  "Plugins/ParaView/Icons/$name.svg"; do
  [ ! -e "$existing" ] || { echo "$existing exists already" >&2; exit 1; }
done
grep -q "\"$name:" Source/Filters/CMakeLists.txt && { echo "$name is already a filter" >&2; exit 1; }

render() { # template -> file, with the placeholders replaced
  mkdir -p "$(dirname "$2")"
  sed -e "s/@NAME@/$name/g" -e "s/@AREA@/$area/g" -e "s/@LABEL@/$label/g" "$templates/$1" > "$2"
  echo "created $2"
}
render Core.h.in "Source/Core/$area/$name.h"
render Core.cxx.in "Source/Core/$area/$name.cxx"
render CoreTest.cxx.in "Testing/Core/Test$name.cxx"
render Filter.h.in "Source/Filters/vtk$name.h"
render Filter.cxx.in "Source/Filters/vtk$name.cxx"
render FilterTest.cxx.in "Testing/Filters/Test${name}Filter.cxx"
render Proxy.xml.in "Plugins/ParaView/$name.xml"
render Icon.svg.in "Plugins/ParaView/Icons/$name.svg"
render Page.md.in "Documentation/filters/$name.md"

# Adds `item` to the sorted list that starts at the line `opening` in `file`.
add_to_list() {
  local file=$1 opening=$2 item=$3
  /usr/bin/python3 - "$file" "$opening" "$item" <<'PY'
import sys
path, opening, item = sys.argv[1:]
lines = open(path).read().split("\n")
start = next(i for i, line in enumerate(lines) if line.strip() == opening)
end = start + 1
while not lines[end].rstrip().endswith(")"):
    end += 1
entries = [line.strip() for line in lines[start + 1:end]] + [lines[end].strip()[:-1].strip()]
entries = sorted(e for e in entries + [item] if e)
lines[start + 1:end + 1] = ["  " + e for e in entries[:-1]] + ["  " + entries[-1] + ")"]
open(path, "w").write("\n".join(lines))
PY
  echo "added $item to $file"
}
add_to_list Source/Filters/CMakeLists.txt "set(kerf_filters" "\"$name:surface,alone\""
add_to_list Source/Core/CMakeLists.txt "set(core_sources" "$area/$name.cxx"
# A row of the README's table of filters, after its last filter row.
/usr/bin/python3 - README.md "| \`vtk$name\` | $label (say what it does) | [$name](Documentation/filters/$name.md) |" <<'PY'
import sys
path, row = sys.argv[1:]
lines = open(path).read().split("\n")
last = max(i for i, line in enumerate(lines) if line.startswith("| `vtk"))
lines.insert(last + 1, row)
open(path, "w").write("\n".join(lines))
PY
echo "added vtk$name to README.md"
echo "Next: write the algorithm (Source/Core/$area/$name.cxx) and its tests, then the filter's"
echo "parameters, a Python or pvbatch test, an image test, the page and the menu icon"
echo "(Plugins/ParaView/Icons/$name.svg; Documentation/new-filter.md)."
