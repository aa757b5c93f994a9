#!/usr/bin/env bash
# Builds FrictionLab's Debian package with CPack and checks it with Debian's own tools.
#   scripts/package.sh [BUILD_DIR]            (default: build-package)
# Writes BUILD_DIR/frictionlab_VERSION_ARCH.deb; install it with
#   sudo apt install ./BUILD_DIR/frictionlab_VERSION_ARCH.deb
# The build uses Debian's hardening flags (dpkg-buildflags) and installs under /usr. Set
# -DFRICTIONLAB_HOMEPAGE=... and -DFRICTIONLAB_MAINTAINER=... as extra arguments to publish it
# elsewhere (docs/install.md, "The Debian package").
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir="${1:-build-package}"
shift || true

# Debian's compiler and linker flags for packages (stack protector, fortify, relro, bind now),
# read by CMake when it first configures the folder.
export DEB_BUILD_MAINT_OPTIONS=hardening=+all
if command -v dpkg-buildflags > /dev/null; then
  CXXFLAGS="$(dpkg-buildflags --get CPPFLAGS) $(dpkg-buildflags --get CXXFLAGS)"
  LDFLAGS="$(dpkg-buildflags --get LDFLAGS)"
  export CXXFLAGS LDFLAGS
fi
FRICTIONLAB_PACKAGING=1 scripts/setup.sh "$build_dir" -DCMAKE_INSTALL_PREFIX=/usr -DBUILD_TESTING=OFF "$@"

echo "package: building the .deb with CPack"
(cd "$build_dir" && cpack -G DEB > cpack.log 2>&1) ||
  { cat "$build_dir/cpack.log"; echo "package: cpack failed; the log is $build_dir/cpack.log" >&2; exit 1; }
version=$(sed -n 's/^set(CPACK_PACKAGE_VERSION "\(.*\)")$/\1/p' "$build_dir/CPackConfig.cmake")
deb="$build_dir/frictionlab_${version}_$(dpkg --print-architecture).deb"
test -f "$deb" || { echo "package: $deb was not made; see $build_dir/cpack.log" >&2; exit 1; }

# The desktop entry and the metainfo as installed, checked by their validators; then the whole
# package by lintian (errors fail; its info notes are explained in docs/install.md).
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root"
desktop-file-validate "$root"/usr/share/applications/*.desktop
appstreamcli validate --no-net "$root"/usr/share/metainfo/*.metainfo.xml
lintian --fail-on error,warning "$deb"
echo "package: $deb"
dpkg-deb --field "$deb" Package Version Section Depends
