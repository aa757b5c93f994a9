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

# The other way round: every unit of the code (a .cpp outside tests/ and fuzz/, and outside any
# build folder) has a test file of its name or is named in the map, in backquotes, as `X` or
# `FOLDER/X`, beside what tests it.
while IFS= read -r code; do
  code=${code#./}              # physics/validation.cpp
  unit=$(basename "$code" .cpp)
  [[ -n $(find tests -mindepth 2 -name "test_$unit.cpp" -print -quit) ]] && continue
  grep -qF -e "\`$unit\`" -e "\`${code%.cpp}\`" "$map" && continue
  echo "$code: no test file tests/FOLDER/test_$unit.cpp, and $map does not name it; write one, or say in $map what tests it (as \`$unit\`)" >&2
  failed=1
done < <(find . -type d \( -name .git -o -name tests -o -name fuzz -o -name CMakeFiles -o -name 'build*' \) -prune \
              -o -name '*.cpp' -print | sort)
exit $failed
