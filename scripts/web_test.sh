#!/usr/bin/env bash
# Tests the web version, as scripts/test.sh's last part: builds it (scripts/web.sh), runs the
# command line under node (every lesson's check, and run's CSV beside the native program's
# when a native build is given), then drives the page in Debian's Chromium, headless
# (puppeteer-core from npm, which brings no browser of its own).
#   scripts/web_test.sh [NATIVE_BUILD_DIR]
# Pictures the page test takes are left in build-web/page-shots/ to look at.
set -euo pipefail
cd "$(dirname "$0")/.."
native_build="${1:-}"

packages=(chromium fonts-dejavu-core)
# node and npm: Debian's nodejs and npm, unless a node with its npm is here already (NodeSource's
# nodejs brings both, and Debian's npm would not install beside it).
if ! command -v node > /dev/null || ! command -v npm > /dev/null; then packages+=(nodejs npm); fi
scripts/install_missing.sh web_test "${packages[@]}"

scripts/web.sh build-web -DFRICTIONLAB_WERROR=ON -DFRICTIONLAB_WEB_TESTS=ON
# The GoogleTest suites that need no window, in WebAssembly under node.
ctest --test-dir build-web/web --output-on-failure --parallel "$(nproc)"
build="$PWD/build-web"
mkdir -p "$build/page-test"
cp web/test/package.json "$build/page-test/package.json"
(cd "$build/page-test" && npm install --no-audit --no-fund --loglevel=error > npm.log 2>&1) ||
  { cat "$build/page-test/npm.log"; echo "web_test: npm could not install puppeteer-core" >&2; exit 1; }
# One test file at a time where node can be told so (20 and later; Debian 12's node 18 cannot).
one_at_a_time=()
if node --help | grep -- --test-concurrency > /dev/null; then one_at_a_time=(--test-concurrency=1); fi
rm -rf "$build/page-shots"
mkdir -p "$build/page-shots"
FRICTIONLAB_WEB_BUILD="$build" FRICTIONLAB_PAGE_SHOTS="$build/page-shots" FRICTIONLAB_NATIVE_BUILD="${native_build:+$(realpath "$native_build")}" \
  NODE_PATH="$build/page-test/node_modules" node --test "${one_at_a_time[@]}" web/test/
