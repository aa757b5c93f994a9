#!/bin/bash
# Fails when a test file cannot be found from the code it tests (tests/README.md is the map):
# every GoogleTest file tests/FOLDER/test_X.cpp must name a unit of that code folder, FOLDER/X.h
# or FOLDER/X.cpp (or one a folder deeper, as lessons/runtime/X.cpp), and be in the map. The
# files in tests/scenarios/ test a whole scenario rather than one unit: each must be in the map,
# which says what it runs. No test file sits in tests/ itself.
#   tests/test_names.sh SOURCE_DIR
set -u
cd "$1" || exit 2
failed=0
map=tests/README.md
[[ -f $map ]] || { echo "$map: missing" >&2; exit 1; }

for file in tests/test_*.cpp; do
  [[ -e $file ]] || continue
  echo "$file: a test file goes in the folder of the code it tests (tests/FOLDER/), or in tests/scenarios/" >&2
  failed=1
done

while IFS= read -r file; do
  path=${file#tests/}          # physics/test_scene.cpp
  folder=${path%%/*}           # physics
  unit=$(basename "$file" .cpp)
  unit=${unit#test_}           # scene
  if ! grep -qF "($path)" "$map"; then
    echo "$file: not in $map; add it to the map, linked as ($path)" >&2
    failed=1
  fi
  [[ $folder == scenarios ]] && continue
  found=$(find "$folder" -maxdepth 2 \( -name "$unit.h" -o -name "$unit.cpp" \) -print -quit 2>/dev/null)
  if [[ -z $found ]]; then
    echo "$file: no unit $folder/$unit.h or $folder/$unit.cpp (nor $folder/*/$unit.*); name the file after the unit it tests, or put a scenario in tests/scenarios/" >&2
    failed=1
  fi
done < <(find tests -mindepth 2 -name 'test_*.cpp' | sort)
exit $failed
