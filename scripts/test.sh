#!/usr/bin/env bash
# Sets everything up and runs the whole test suite twice, in build folders of its own: a warnings-as-errors release build,
# then the web version (scripts/web_test.sh), then an AddressSanitizer + UndefinedBehaviorSanitizer build; then each libFuzzer target for a
# minute, from the seed corpus with a fixed seed, so that a crash on the seeds cannot land.
set -euo pipefail
cd "$(dirname "$0")/.."

FRICTIONLAB_TESTS=1 scripts/setup.sh build-test -DFRICTIONLAB_WERROR=ON
ctest --test-dir build-test --output-on-failure --parallel "$(nproc)"

# The web version: built with emscripten, its command line under node beside the native
# program just built, its page in headless Chromium.
scripts/web_test.sh build-test

scripts/setup.sh build-sanitize -DFRICTIONLAB_WERROR=ON -DFRICTIONLAB_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)"

FRICTIONLAB_FUZZ=1 FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build-test -DFRICTIONLAB_WERROR=ON
FRICTIONLAB_FUZZ_SEED=1 scripts/fuzz.sh 60
