#!/usr/bin/env bash
# tests/packaging/deb_package.sh CPACK BUILD_DIR SOURCE_DIR
# The .deb as CPack builds it (scripts/package.sh makes the same, with Debian's hardening flags):
# its control fields (Section science, Depends from shlibdeps plus the font and the Mesa drivers
# loaded at run time), lintian with no errors, and the package unpacked with dpkg-deb -x into a
# temporary root and run from there with the source and build trees out of reach.
set -euo pipefail
cpack=$1 build=$(cd "$2" && pwd) source=$(cd "$3" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/frictionlab_deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$cpack" --config "$build/CPackConfig.cmake" -G DEB -B "$work/package" > "$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack"; }
deb=$(ls "$work"/package/frictionlab_*.deb)
[[ $(dpkg-deb --field "$deb" Package) == frictionlab ]] || fail "Package"
[[ $(dpkg-deb --field "$deb" Section) == science ]] || fail "Section"
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
# Loaded at run time, which shlibdeps cannot see; and some of what it does see.
for package in fonts-dejavu-core libgl1 libegl-mesa0 libglx-mesa0 libgl1-mesa-dri libbox2d2 liblua5.4-0 libglfw3 libc6; do
  [[ ", $depends," == *", $package"[\ ,]* ]] || fail "Depends lacks $package"
done
status=0
lintian --fail-on error "$deb" > "$work/lintian.txt" 2>&1 || status=$?
grep -v '^running with root privileges' "$work/lintian.txt" || true
((status == 0)) || fail "lintian finds errors (exit $status)"

mkdir "$work/root"
dpkg-deb -x "$deb" "$work/root"
"$here/run_installed.sh" "$work/root/usr/bin/frictionlab" "$work" "$build" "$source"
