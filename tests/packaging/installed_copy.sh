#!/usr/bin/env bash
# tests/packaging/installed_copy.sh CMAKE BUILD_DIR SOURCE_DIR
# `cmake --install` into a temporary prefix, then the installed tree moved elsewhere, as a
# technician might: its desktop entry and metainfo pass Debian's validators, its icons are the
# sizes their folders say, its manual page is whole, and the program runs list, check and render
# from there with the source and build trees out of reach (run_installed.sh).
# Writes only in its temporary folder (and CMake's own install_manifest.txt in BUILD_DIR, which
# every `cmake --install` rewrites).
set -euo pipefail
cmake=$1 build=$(cd "$2" && pwd) source=$(cd "$3" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/frictionlab_installed.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
mkdir "$work/elsewhere"
mv "$work/prefix" "$work/elsewhere/usr"
root="$work/elsewhere/usr"

test -x "$root/bin/frictionlab" || fail "no bin/frictionlab"
desktop=$(ls "$root"/share/applications/*.desktop)
desktop-file-validate "$desktop" || fail "desktop-file-validate $desktop"
grep -qx 'Categories=Education;Science;Physics;' "$desktop" || fail "$desktop: Categories"
grep -qx 'Exec=frictionlab --projector %f' "$desktop" || fail "$desktop: no projector action"
appstreamcli validate --no-net "$root"/share/metainfo/*.metainfo.xml || fail "appstreamcli validate"
for size in 16 24 32 48 64 128 256; do
  icon=$(ls "$root/share/icons/hicolor/${size}x${size}/apps/"*.png)
  dims=$(printf '%08x%08x' "$size" "$size")
  [[ $(head -c 24 "$icon" | od -An -tx1 | tr -d ' \n') == *"$dims" ]] || fail "$icon is not ${size}x${size}"
  [[ $(basename "$icon" .png) == $(basename "$desktop" .desktop) ]] || fail "$icon is not named as the desktop entry's Icon"
done
gzip -t "$root/share/man/man1/frictionlab.1.gz" || fail "the manual page"
# The students' guide: every .md of the source's lessons/ (the reference's pages in reference/ too).
guides=0
while IFS= read -r guide; do
  test -f "$root/share/frictionlab/lessons/$guide" || fail "no students' guide's $guide"
  guides=$((guides + 1))
done < <(cd "$source/lessons" && find . -path ./runtime -prune -o -name '*.md' -print | sed 's|^\./||')
((guides >= 4)) || fail "found $guides pages of the students' guide in $source/lessons, not the guide, the cheat sheet and the reference"

"$here/run_installed.sh" "$root/bin/frictionlab" "$work" "$build" "$source"
