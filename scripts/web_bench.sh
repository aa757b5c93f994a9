#!/usr/bin/env bash
# The web version's figures, measured (not asserted anywhere): the sizes of what it hands out,
# and each lesson's physics in WebAssembly against the native program, side by side.
#   scripts/web_bench.sh [NATIVE_BUILD_DIR] [SECONDS]
# Each lesson's `check --random N` (the same N settings, seed 1, everywhere; each a whole run at
# the lesson's own step rate: the script built, the world stepped, the theory worked out) runs
# natively, in Chromium (the engine the page runs in: web/bench/, driven by puppeteer-core) and
# under node, three times each; the table gives the fastest of each in wall-clock seconds and
# native time over WebAssembly time (1: as fast). N is chosen per lesson so that the native run
# takes about SECONDS (default 1). A JavaScript engine runs new code unoptimized for its first
# fraction of a second, then optimizes what is hot: in Chromium the three calls are in one page,
# so the fastest is past that, as a class's page is after its first second; under node each
# call is a new process, whose start (timed on `list`) is taken off, its warm-up not.
set -euo pipefail
cd "$(dirname "$0")/.."
native="${1:-build}/app/frictionlab"
seconds="${2:-1}"
web=build-web/frictionlab-cli.js
modules=build-web/page-test/node_modules
[[ -x $native && -f $web ]] || { echo "web_bench: build both first (scripts/setup.sh, scripts/web.sh)" >&2; exit 2; }
[[ -d $modules/puppeteer-core ]] || { echo "web_bench: puppeteer-core is installed by scripts/web_test.sh; run it first" >&2; exit 2; }
NODE_PATH=/usr/share/nodejs cmake --build build-web --target frictionlab-cli-browser > build-web/bench-build.log 2>&1 ||
  { tail -n 30 build-web/bench-build.log; echo "web_bench: could not build the benchmark's page" >&2; exit 1; }

# bash's own time: wall-clock seconds of the command.
wall() { local TIMEFORMAT='%R' taken; taken=$( { time "$@" > /dev/null 2>&1; } 2>&1 ); echo "$taken"; }
fastest() { local best=1e9 t; for _ in 1 2 3; do t=$(wall "$@"); best=$(awk -v a="$best" -v b="$t" 'BEGIN{print (b<a)?b:a}'); done; echo "$best"; }

gzipped=$(cat build-web/site/frictionlab.{wasm,data,js} build-web/site/index.html | gzip -9 | wc -c)
echo "site: $(du -cb build-web/site/* | tail -1 | cut -f1) bytes, $gzipped gzip-compressed; frictionlab.html: $(stat -c %s build-web/frictionlab.html) bytes"
startup=$(fastest node "$web" list)
declare -A count native_s node_s
lessons=$("$native" list --tsv | cut -f1)
for lesson in $lessons; do
  # How many settings make about `seconds` of native work (from 20, at most 5000).
  trial=$(wall "$native" check "$lesson" --random 20)
  count[$lesson]=$(awk -v t="$trial" -v s="$seconds" 'BEGIN{n=int(20*s/(t>0.001?t:0.001)); print (n<20)?20:(n>5000)?5000:n}')
  native_s[$lesson]=$(fastest "$native" check "$lesson" --random "${count[$lesson]}")
  node_s[$lesson]=$(fastest node "$web" check "$lesson" --random "${count[$lesson]}")
done
work=()
for lesson in $lessons; do work+=("$lesson:${count[$lesson]}"); done
declare -A browser_s
while read -r lesson taken; do browser_s[$lesson]=$taken; done < <(NODE_PATH=$modules node web/bench/browser_bench.js build-web/bench "${work[@]}")
printf '%-20s %9s %9s %10s %14s %9s %11s\n' lesson settings "native s" "Chromium s" "native/Chromium" "node s" "native/node"
for lesson in $lessons; do
  awk -v l="$lesson" -v c="${count[$lesson]}" -v n="${native_s[$lesson]}" -v b="${browser_s[$lesson]}" -v w="${node_s[$lesson]}" -v s="$startup" \
    'BEGIN{ww=w-s; if (ww<0.001) ww=0.001; printf "%-20s %9d %9.2f %10.2f %14.2f %9.2f %11.2f\n", l, c, n, b, n/b, ww, n/ww}'
done
