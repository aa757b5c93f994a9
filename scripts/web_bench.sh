#!/usr/bin/env bash
# The web version's figures, measured (not asserted anywhere): the sizes of what it hands out,
# and each lesson's physics in WebAssembly (node) against the native program, side by side.
#   scripts/web_bench.sh [NATIVE_BUILD_DIR] [SECONDS]
# Each lesson's `check --random N` (the same N settings, seed 1, in both; each a whole run at the
# lesson's own step rate: the script built, the world stepped, the theory worked out) runs
# natively and under node, alternately, three times each; the table gives the fastest of each
# (CPU seconds, user + system, so the other core's load counts less) and their ratio, native
# time over WebAssembly time (1: as fast). N is chosen per lesson so that the native run takes
# about SECONDS (default 1): node's engine runs new code unoptimized for its first fraction of a
# second and then optimizes what is hot, so a run of a few milliseconds measures that warm-up,
# not the lesson, while a page a class uses for minutes runs optimized. Node's start (timed on
# `list`, which loads and compiles the same program) is taken off the WebAssembly figure.
set -euo pipefail
cd "$(dirname "$0")/.."
native="${1:-build}/app/frictionlab"
seconds="${2:-1}"
web=build-web/frictionlab-cli.js
[[ -x $native && -f $web ]] || { echo "web_bench: build both first (scripts/setup.sh, scripts/web.sh)" >&2; exit 2; }

# bash's own time: user and system CPU seconds of the command.
cpu() { local TIMEFORMAT='%U %S' taken; taken=$( { time "$@" > /dev/null 2>&1; } 2>&1 ); echo "$taken" | awk '{print $1 + $2}'; }
fastest() { local best=1e9 t; for _ in 1 2 3; do t=$(cpu "$@"); best=$(awk -v a="$best" -v b="$t" 'BEGIN{print (b<a)?b:a}'); done; echo "$best"; }

gzipped=$(cat build-web/site/frictionlab.{wasm,data,js} build-web/site/index.html | gzip -9 | wc -c)
echo "site: $(du -cb build-web/site/* | tail -1 | cut -f1) bytes, $gzipped gzip-compressed; frictionlab.html: $(stat -c %s build-web/frictionlab.html) bytes"
startup=$(fastest node "$web" list)
printf '%-20s %9s %10s %10s %12s\n' lesson settings "native s" "wasm s" "native/wasm"
for lesson in $("$native" list --tsv | cut -f1); do
  # How many settings make about `seconds` of native work (from 20, at most 5000).
  trial=$(cpu "$native" check "$lesson" --random 20)
  settings=$(awk -v t="$trial" -v s="$seconds" 'BEGIN{n=int(20*s/(t>0.001?t:0.001)); print (n<20)?20:(n>5000)?5000:n}')
  n=$(fastest "$native" check "$lesson" --random "$settings")
  w=$(fastest node "$web" check "$lesson" --random "$settings")
  awk -v l="$lesson" -v c="$settings" -v n="$n" -v w="$w" -v s="$startup" 'BEGIN{ww=w-s; if (ww<0.001) ww=0.001; printf "%-20s %9d %10.2f %10.2f %12.2f\n", l, c, n, ww, n/ww}'
done
