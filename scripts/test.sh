#!/usr/bin/env bash
# Sets everything up and runs the whole test suite twice, in build folders of its own: a warnings-as-errors release build,
# then the web version (scripts/web_test.sh), then an AddressSanitizer + UndefinedBehaviorSanitizer build; then each libFuzzer target for half a
# minute, from the seed corpus with a fixed seed, so that a crash on the seeds cannot land.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each part's minutes, printed as it ends and again at the end: the whole must stay well under
# 45 minutes on two cores, and a part that grows shows here first.
parts=()
part_started=$SECONDS
part_done() {
  local took=$((SECONDS - part_started))
  parts+=("$(printf '%-44s %2d min %02d s' "$1" $((took / 60)) $((took % 60)))")
  echo "test: $1 took $((took / 60)) min $((took % 60)) s"
  part_started=$SECONDS
}
trap 'for part in "${parts[@]}"; do echo "test: $part"; done; echo "test: $((SECONDS / 60)) min $((SECONDS % 60)) s in all"' EXIT

FRICTIONLAB_TESTS=1 scripts/setup.sh build-test -DFRICTIONLAB_WERROR=ON
part_done "packages and the release build"
ctest --test-dir build-test --output-on-failure --parallel "$(nproc)"
part_done "the release build's tests"

# The web version: built with emscripten, its command line under node beside the native
# program just built, its page in headless Chromium.
scripts/web_test.sh build-test
part_done "the web version: build and tests"

# -O1 -g1, not RelWithDebInfo's -O2 -g: the sanitizers' own advice is -O1 for speed, and line
# tables are all a report's stack needs. Measured on two cores: the build took 16 minutes
# with -O2 -g (tests/scenarios/test_builtin_lessons.cpp alone 95 s, 46 s with -O1 -g1). That is
# the libraries' level; the test files themselves are -O0 there (tests/CMakeLists.txt says why).
scripts/setup.sh build-sanitize -DFRICTIONLAB_WERROR=ON -DFRICTIONLAB_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
part_done "the sanitizer build"
# The window's layout tests (Screens/...) run at every screen size and in projector mode in the
# release build, where what they check, the layout, is decided; here at 1024x768 alone, for what
# the sanitizers check, the memory and arithmetic of the code that lays out. The layout has no
# size thresholds, only a scale, min(height/720, width/1280) (draw/theme.cpp), so every size runs
# the same code; projector mode's own paths (one plot a page, the verdict columns, the column's
# foot) run under the sanitizers in tests/scenarios/test_projector.cpp, every lesson in projector
# mode at 1920x1080. The other sizes were 310 s of the 1 350 s this part's tests took on two
# cores, in a CI run that had grown past 45 minutes (stop 57: 49 min 46 s). (A parameterised
# test's CTest name goes on after a space with its parameter's bytes, hence no $ alone.)
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" \
  --exclude-regex '^Screens/[^ ]*/(1280x720|1920x1080|projector_1920x1080|window_projector_1920x1080)( |$)'
part_done "the sanitizer build's tests"

FRICTIONLAB_FUZZ=1 FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build-test -DFRICTIONLAB_WERROR=ON
# Half a minute each: the seeds run first, in seconds, so a crash on them cannot land either way;
# what a longer run finds belongs to scripts/fuzz.sh run on its own.
FRICTIONLAB_FUZZ_SEED=1 scripts/fuzz.sh 30
part_done "the fuzzers: build and half a minute each"
