#!/bin/sh
# The students' guide's worked example (lessons/README.md, "Here is the whole file"), copied as a
# student copies it, passes `check` at its defaults and at 30 random settings inside its own
# sliders: a tutorial whose example fails its own --random teaches students that failing rows
# are normal. It once offered c and b sliders up to 1000 its rows could not follow, and ran
# for ever at mu_k = 0 (0 of 30 passed).
#   guide_example.sh FRICTIONLAB GUIDE
set -u
frictionlab=$1 guide=$2
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
fence=$(printf '\140\140\140')
awk -v fence_lua="${fence}lua" -v fence_end="$fence" '
  /^Here is the whole file/ { found = 1 }
  found && $0 == fence_lua { inside = 1; next }
  inside && $0 == fence_end { exit }
  inside { print }' "$guide" > "$d/sliding_block.lua"
grep -q '^lesson {' "$d/sliding_block.lua" || fail "no lesson found after \"Here is the whole file\" in $guide"
"$frictionlab" check "$d/sliding_block.lua" > "$d/out" 2>&1 || fail "check at its defaults: $(cat "$d/out")"
"$frictionlab" check "$d/sliding_block.lua" --random 30 --seed 1 > "$d/out" 2>&1 || fail "check --random 30: $(grep -A3 '^FAIL' "$d/out" | head -12)"
grep -q '30 of 30 random settings' "$d/out" || fail "not 30 of 30: $(tail -3 "$d/out")"
echo ok
