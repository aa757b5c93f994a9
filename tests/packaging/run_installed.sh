#!/usr/bin/env bash
# tests/packaging/run_installed.sh FRICTIONLAB WORK HIDDEN_FOLDER...
# Runs an installed frictionlab as a user would (--version, list, check, render, and the
# FRICTIONLAB_LESSONS override) from a folder in WORK, with each HIDDEN_FOLDER (the build tree,
# then the source tree) covered by an empty folder for the whole run, so that nothing in them
# can be read: the installed copy must stand on its own. Nothing is written outside WORK (HOME
# and the XDG folders point into it, for Mesa's shader cache and the like).
#
# The folders are covered in a private mount namespace (unshare, as root or in a user
# namespace), which changes nothing on disk and nothing for other processes. Where the system
# allows neither (a container without those rights), it says so and runs with them in reach:
# the other checks still hold, the "out of reach" one is then not made.
set -euo pipefail

if [[ ${1:-} == --inside ]]; then
  shift
  frictionlab=$1 work=$2
  shift 2
  for folder; do
    if [[ -n $(ls -A "$folder" 2> /dev/null) ]]; then echo "FAIL: $folder is still in reach" >&2; exit 1; fi
  done
  export HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config" XDG_CACHE_HOME="$work/home/.cache"
  export XDG_DATA_HOME="$work/home/.local/share"
  unset FRICTIONLAB_LESSONS
  mkdir -p "$HOME" "$work/run"
  cd "$work/run"
  fail() { echo "FAIL: $*" >&2; exit 1; }

  lessons=$(cd "$(dirname "$frictionlab")/../share/frictionlab/lessons" && pwd) || fail "no share/frictionlab/lessons beside $frictionlab"
  "$frictionlab" --version | grep -qx 'frictionlab [0-9][0-9.]*' || fail "--version: $("$frictionlab" --version 2>&1)"

  # list: the installed lessons, found relative to the binary, every one of them.
  "$frictionlab" list > list.txt || fail "list exited $?"
  grep -qF "Scripts are in $lessons;" list.txt || fail "list does not read the installed lessons: $(tail -1 list.txt)"
  count=0
  for script in "$lessons"/*.lua; do
    name=$(basename "$script" .lua)
    grep -q "^$name " list.txt || fail "list lacks $name"
    count=$((count + 1))
  done
  ((count > 0)) || fail "no lessons installed in $lessons"

  # check: every installed lesson meets its expectations.
  "$frictionlab" check > check.txt || fail "check exited $?: $(tail -3 check.txt)"
  grep -q '^every lesson meets its expectations' check.txt || fail "check: $(tail -1 check.txt)"

  # render: the first lesson's README moment, headless, a whole PNG of the asked size.
  IFS=$'\t' read -r name _ moment _ < <("$frictionlab" list --tsv | head -1)
  "$frictionlab" render "$name" --moment "$moment" --size 640x360 --out frame.png > render.txt || fail "render exited $?"
  [[ $(head -c 24 frame.png | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a0000000d494844520000028000000168 ]] ||
    fail "render: frame.png is not a 640x360 PNG"

  # The override still wins over the installed folder.
  mkdir -p own
  cp "$lessons/$name.lua" own/my_copy.lua
  FRICTIONLAB_LESSONS="$work/run/own" "$frictionlab" list --tsv | cut -f1 > own.txt
  [[ $(cat own.txt) == my_copy ]] || fail "FRICTIONLAB_LESSONS=own: list gives $(tr '\n' ' ' < own.txt)"

  echo "ok: $frictionlab (version $("$frictionlab" --version | cut -d' ' -f2)): $count lessons listed from $lessons, check passes, $name rendered at its moment $moment; out of reach: ${*:-nothing (no mount namespace here)}"
  exit 0
fi

frictionlab=$1 work=$2
shift 2
# The checks run from a copy in WORK: this script's own folder is hidden too.
cp "$0" "$work/run_installed.sh"
cover='frictionlab=$1 work=$2; shift 2
for folder; do mount -t tmpfs -o size=64k,mode=0555 frictionlab-out-of-reach "$folder" || exit 1; done
exec bash "$work/run_installed.sh" --inside "$frictionlab" "$work" "$@"'
if unshare --mount --propagation private true 2> /dev/null; then
  exec unshare --mount --propagation private bash -c "$cover" cover "$frictionlab" "$work" "$@"
elif unshare --user --map-root-user --mount true 2> /dev/null; then
  exec unshare --user --map-root-user --mount bash -c "$cover" cover "$frictionlab" "$work" "$@"
fi
echo "NOTE: no mount namespace allowed here (unshare failed); running with $* in reach" >&2
exec bash "$work/run_installed.sh" --inside "$frictionlab" "$work"
