#!/usr/bin/env bash
# Installs what FrictionLab needs from Debian 12's packages, then configures and builds it.
#   scripts/setup.sh [BUILD_DIR] [extra CMake options...]
# FRICTIONLAB_TARGET names one target to build instead of everything; FRICTIONLAB_TESTS=1 also
# installs what the test suite needs (Xvfb, to open a real window where there is no display,
# LibreOffice Calc, to open a CSV as a class's spreadsheet does, and the packaging tools); FRICTIONLAB_PACKAGING=1 installs the packaging tools alone;
# FRICTIONLAB_FUZZ=1 also installs Clang for the fuzzing targets.
# Safe to run again: packages already present are not fetched, builds are incremental.
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir="${1:-build}"
shift || true

packages=(build-essential cmake pkg-config libbox2d-dev libgtest-dev liblua5.4-dev
  # Drawing: Dear ImGui, stb_image_write, and the font that reads from the back of a room.
  libimgui-dev libstb-dev fonts-dejavu-core
  # Headless OpenGL through glvnd and Mesa's llvmpipe (libgl1-mesa-dri): no display, no GPU.
  # ImGui's OpenGL 3 renderer loads libGL.so.1 (libgl1) itself.
  libegl-dev libopengl-dev libgl-dev libgl1 libegl-mesa0 libgl1-mesa-dri
  # The classroom window: GLFW 3.3 on X11, its OpenGL through GLX (Mesa's libglx-mesa0).
  libglfw3-dev libglx-mesa0)
if [[ ${FRICTIONLAB_TESTS:-0} == 1 ]]; then packages+=(xvfb xauth); fi
# The spreadsheet a class opens the CSV in: LibreOffice Calc, headless (soffice), for the test
# that the header's units and the first number read right (cli_run_csv_opens_in_a_spreadsheet).
if [[ ${FRICTIONLAB_TESTS:-0} == 1 ]]; then packages+=(libreoffice-calc-nogui); fi
# Building the .deb and checking it with Debian's tools (scripts/package.sh, and the tests that
# install FrictionLab and build its package): dpkg-shlibdeps and file for CPack's Depends, the
# validators, unshare and mount (util-linux, mount) to run the installed copy with the source
# and build folders out of reach, and groff to set the manual page's synopsis for its test.
if [[ ${FRICTIONLAB_TESTS:-0} == 1 || ${FRICTIONLAB_PACKAGING:-0} == 1 ]]; then
  packages+=(dpkg-dev file lintian desktop-file-utils appstream util-linux mount gzip groff-base)
fi

# The libFuzzer targets (scripts/fuzz.sh, which the test command runs for half a minute each): Clang
# and its sanitizer and fuzzer runtimes.
if [[ ${FRICTIONLAB_FUZZ:-0} == 1 ]]; then packages+=(clang libclang-rt-14-dev); fi

scripts/install_missing.sh setup "${packages[@]}"

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" > /dev/null
# On two cores a first build takes about 3 minutes for the program alone, about 10 with the tests.
if [[ -n ${FRICTIONLAB_TARGET:-} ]]; then first="about 3 minutes on two cores"; else first="about 10 minutes on two cores, tests included"; fi
echo "setup: building in $build_dir (a first build takes $first; later ones only what changed)"
cmake --build "$build_dir" --parallel "$(nproc)" ${FRICTIONLAB_TARGET:+--target "$FRICTIONLAB_TARGET"} > "$build_dir/build.log" 2>&1 ||
  { cat "$build_dir/build.log"; echo "setup: the build failed; the log is $build_dir/build.log" >&2; exit 1; }
