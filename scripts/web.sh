#!/usr/bin/env bash
# Builds FrictionLab for the browser and for node, in build-web/ (or the folder given):
#   build-web/site/              index.html, frictionlab.js, .wasm and .data for any static web server
#   build-web/frictionlab.html   one self-contained file that opens from disk (file://), no server
#   build-web/frictionlab-cli.js the command line under node: list, run, check, demo
# It installs what it needs from Debian 12 (emscripten, and node's acorn for emcc's optimizer),
# fetches the source packages of Box2D, Lua, Dear ImGui (and GoogleTest, for the tests) with an apt configuration private to
# the build folder (the machine's apt sources are left alone), Debian's patches applied, and
# builds them with the project. Nothing fetched is copied into the repository.
#   scripts/web.sh [BUILD_DIR] [extra CMake options...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:-build-web}"
shift || true

packages=(emscripten node-acorn nodejs dpkg-dev cmake make fonts-dejavu-core libstb-dev pkg-config xz-utils)
scripts/install_missing.sh web "${packages[@]}"

# Debian's source packages, once per build folder. The private apt state lists the same
# archives as the machine's own sources, for source packages (deb-src).
sources="$PWD/$build_dir/debian-sources"
# Each source package and the folder it unpacks to (the versions Debian 12 ships).
declare -A folders=([box2d]=box2d-2.4.1 [lua5.4]=lua5.4-5.4.4 [imgui]=imgui-1.86+ds [googletest]=googletest-1.12.1)
fetch=()
for package in "${!folders[@]}"; do [[ -d $sources/${folders[$package]} ]] || fetch+=("$package"); done
if ((${#fetch[@]})); then
  echo "web: fetching the Debian sources of ${fetch[*]} into $sources"
  mkdir -p "$sources/apt/lists/partial" "$sources/apt/cache/archives/partial" "$sources/apt/sources.list.d"
  rm -f "$sources/apt/sources.list.d/"*
  shopt -s nullglob
  for list in /etc/apt/sources.list.d/*.sources; do
    sed -E 's/^Types:.*/Types: deb-src/' "$list" > "$sources/apt/sources.list.d/$(basename "$list")"
  done
  for list in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -f $list ]] && sed -nE 's/^deb (.*)/deb-src \1/p' "$list" >> "$sources/apt/sources.list.d/from-lists.list"
  done
  shopt -u nullglob
  touch "$sources/apt/none.list"
  apt_private=(-o "Dir::Etc::SourceList=$sources/apt/none.list" -o "Dir::Etc::SourceParts=$sources/apt/sources.list.d"
               -o "Dir::State::Lists=$sources/apt/lists" -o "Dir::Cache=$sources/apt/cache" -o "Debug::NoLocking=1"
               -o "APT::Sandbox::User=root")
  apt-get "${apt_private[@]}" update -qq
  # dpkg-source unpacks each and applies Debian's patches (Lua's C++ linkage among them).
  (cd "$sources" && apt-get "${apt_private[@]}" source -qq "${fetch[@]}" > apt/source.log 2>&1) ||
    { cat "$sources/apt/source.log"; echo "web: could not fetch the Debian source packages" >&2; exit 1; }
  for package in "${fetch[@]}"; do
    [[ -d $sources/${folders[$package]} ]] || { echo "web: Debian's $package source is not ${folders[$package]} (another version?)" >&2; exit 1; }
  done
fi

# emcc's JavaScript optimizer needs acorn, which Debian installs for node under /usr/share/nodejs.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# C++ exceptions in WebAssembly itself, for every file (Lua's errors are exceptions too).
emcmake cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
  -DFRICTIONLAB_WEB_SOURCES="$sources" -DCMAKE_CXX_FLAGS="-fwasm-exceptions" "$@" > /dev/null
echo "web: building in $build_dir (a first build takes several minutes on two cores; later ones only what changed)"
cmake --build "$build_dir" --parallel "$(nproc)" ${FRICTIONLAB_TARGET:+--target "$FRICTIONLAB_TARGET"} > "$build_dir/build.log" 2>&1 ||
  { tail -n 60 "$build_dir/build.log"; echo "web: the build failed; the log is $build_dir/build.log" >&2; exit 1; }
echo "web: built $build_dir/site/index.html, $build_dir/frictionlab.html and $build_dir/frictionlab-cli.js"
