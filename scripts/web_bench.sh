#!/usr/bin/env bash
# The web version's figures, measured (not asserted anywhere): the sizes of what it hands out,
# and each lesson's physics in WebAssembly (node) against the native program, side by side.
#   scripts/web_bench.sh [NATIVE_BUILD_DIR] [SETTINGS]
# Each lesson's `check --random SETTINGS` (default 20: the same settings, seed 1, in both; each
# a whole run at the lesson's own step rate) runs natively and under node, alternately, three
# times each; the table gives the fastest of each (CPU seconds, user + system, so the other
# core's load counts less) and their ratio, native time over WebAssembly time (1: as fast).
# Node's start (about 0.1 s, timed on `list`) is taken off the WebAssembly figure.
set -euo pipefail
cd "$(dirname "$0")/.."
native="${1:-build}/app/frictionlab"
settings="${2:-20}"
web=build-web/frictionlab-cli.js
[[ -x $native && -f $web ]] || { echo "web_bench: build both first (scripts/setup.sh, scripts/web.sh)" >&2; exit 2; }

# bash's own time: user and system CPU seconds of the command.
cpu() { local TIMEFORMAT='%U %S' taken; taken=$( { time "$@" > /dev/null 2>&1; } 2>&1 ); echo "$taken" | awk '{print $1 + $2}'; }
fastest() { local best=1e9 t; for _ in 1 2 3; do t=$(cpu "$@"); best=$(awk -v a="$best" -v b="$t" 'BEGIN{print (b<a)?b:a}'); done; echo "$best"; }

gzipped=$(cat build-web/site/frictionlab.{wasm,data,js} build-web/site/index.html | gzip -9 | wc -c)
echo "site: $(du -cb build-web/site/* | tail -1 | cut -f1) bytes, $gzipped gzip-compressed; frictionlab.html: $(stat -c %s build-web/frictionlab.html) bytes"
startup=$(fastest node "$web" list)
printf '%-20s %10s %10s %12s\n' lesson "native s" "wasm s" "native/wasm"
for lesson in $("$native" list --tsv | cut -f1); do
  n=$(fastest "$native" check "$lesson" --random "$settings")
  w=$(fastest node "$web" check "$lesson" --random "$settings")
  awk -v l="$lesson" -v n="$n" -v w="$w" -v s="$startup" 'BEGIN{ww=w-s; if (ww<0.001) ww=0.001; printf "%-20s %10.2f %10.2f %12.2f\n", l, n, ww, n/ww}'
done
