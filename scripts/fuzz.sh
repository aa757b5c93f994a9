#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with Clang in build-fuzz/ and runs each for a while.
#   scripts/fuzz.sh [SECONDS] [TARGET...]     default: 60 s each, every target
# Targets: fuzz_lesson_loader (a lesson script from bytes), fuzz_command_line (list/run/check
# arguments), fuzz_numbers (the command line's and --set's numbers), fuzz_setup_file (a prepared
# setup file, read and written back). Seeds: the built-in lessons,
# the broken-script corpus and the command-line test lessons; the lesson API's names as a
# dictionary. The corpus grows in build-fuzz/corpus/TARGET; a crash, sanitizer report, leak or
# hang is saved in build-fuzz/findings/ and makes the script fail. Each target's figures
# (executions, coverage, corpus) end its log in build-fuzz/logs/.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_lesson_loader fuzz_command_line fuzz_numbers fuzz_setup_file)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 with line tables (CMakeLists.txt), as libFuzzer's own guide builds its targets, not -O2 -g:
# the test command waits for this build every time, and fuzzes for seconds. physics/scene.cpp
# compiled in 4.7 s and lessons/runtime/script_lesson.cpp in 5.6 s, now 3.8 and 5.1 (one core).
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRICTIONLAB_FUZZ=ON \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DBUILD_TESTING=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

seeds=build-fuzz/seeds
rm -rf "$seeds" && mkdir -p "$seeds"/{fuzz_lesson_loader,fuzz_command_line,fuzz_numbers,fuzz_setup_file}
cp lessons/*.lua tests/broken_lessons/*.lua tests/cli_lessons/*.lua "$seeds/fuzz_lesson_loader/"
# Command lines: the first byte picks list (0), run (1) or check (2); arguments are split at newlines.
i=0
for line in '\000--tsv' '\001incline\n--hz\n480' '\001spring_pull\n--set\nmu_s=0.3\n--set\nmu_k=0.5' \
             '\002tipping_box\n--set\npush_height=2\n--friction\nthreshold' '\001push\n--duration\n1\n--substeps\n2' \
             '\002where_methods_fail\n--set\nmu_s=0' '\001tests/cli_lessons/comma_in_a_name.lua' '\002ramp\n--hz\n0x10'; do
  printf "$line" > "$seeds/fuzz_command_line/seed$((i += 1))"
done
for number in 0.5 -2 1e-3 1e-320 1e999 0x10 inf 1,5 '' 100000 3.5e2 .5 5. +1 --1; do
  printf '%s' "$number" > "$seeds/fuzz_numbers/seed$((i += 1))"
done

for setup in '# FrictionLab setup\nlesson spring_pull\nset mass = 1.5\nlock mu_s, mu_k\nmystery aluminium/wood seed 42\nhz 240\nsubsteps 1\nfriction stick-slip\n' \
             'lesson my.lua\r\nset a = b = c\r\n# note\r\nlock x,y\n' 'lesson incline\nmystery block/slope seed 999999\nhz 1e5\n' 'sett x\nlesson\n'; do
  printf "$setup" > "$seeds/fuzz_setup_file/seed$((i += 1))"
done

mkdir -p build-fuzz/findings build-fuzz/logs
# One target a core at once: each libFuzzer run is one process on one core, so on two cores
# the four minutes of fuzzing take two, with every target fuzzed as long as before.
fuzz_one() {  # only ever started with &
  local target=$1 corpus=build-fuzz/corpus/$1 log=build-fuzz/logs/$1.log dictionary=()
  mkdir -p "$corpus"
  [ "$target" = fuzz_lesson_loader ] && dictionary=(-dict=fuzz/lesson.dict)
  # -timeout: an input that takes longer than this is a hang; the fuzzing budgets end any script call in 0.5 s.
  # FRICTIONLAB_FUZZ_SEED fixes libFuzzer's random seed (the test command's runs repeat); unset, each run differs.
  # exec: run in the background (its own subshell), the fuzzer takes the subshell's place, so the
  # pid the script waits for and may stop is the fuzzer's own.
  ASAN_OPTIONS=detect_leaks=1:quarantine_size_mb=64 exec "build-fuzz/fuzz/$target" "${dictionary[@]}" \
    -seed="${FRICTIONLAB_FUZZ_SEED:-0}" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="build-fuzz/findings/$target-" \
    "$corpus" "$seeds/$target" >"$log" 2>&1
}
report_one() {
  local target=$1 status=$2 log=build-fuzz/logs/$1.log
  echo "== $target for $seconds s"
  if [ "$status" -ne 0 ]; then
    failed=1
    echo "   FOUND a crash, leak or hang: see $log and build-fuzz/findings/"
  fi
  # A fuzzer that never started has no figures: say nothing more, and go on to the others.
  grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' "$log" | sed 's/^/   /' || true
  grep -E '#[0-9]+.*(DONE|pulse|NEW|REDUCE).*cov:' "$log" | tail -1 | sed 's/^/   last: /' || true
}
at_once=$(nproc)
failed=0
# Stopped early (Ctrl+C, or an error here), the script leaves no fuzzer of its own running.
pids=()
trap 'kill "${pids[@]}" 2>/dev/null || true' EXIT
pending=("${targets[@]}")
while [ ${#pending[@]} -gt 0 ]; do
  batch=("${pending[@]:0:at_once}")
  pending=("${pending[@]:at_once}")
  pids=()
  for target in "${batch[@]}"; do
    fuzz_one "$target" &
    pids+=($!)
  done
  for i in "${!batch[@]}"; do
    status=0
    wait "${pids[$i]}" || status=$?
    report_one "${batch[$i]}" "$status"
  done
done
exit $failed
