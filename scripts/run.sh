#!/usr/bin/env bash
# Sets everything up and opens FrictionLab's classroom window on the first lesson (or on the
# lesson and options given). Without a display it says so and draws the lesson to a PNG instead.
#   scripts/run.sh --web [PORT]   builds the web version instead and serves its page on
#                                 127.0.0.1 (port 8080 unless given), printing the address.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ ${1:-} == --web ]]; then
  scripts/web.sh build-web
  command -v node > /dev/null || { echo "run: node is missing (Debian's nodejs)" >&2; exit 1; }
  echo "run: the page in one file, to open from a folder or hand out: $PWD/build-web/frictionlab.html"
  exec node web/serve.js build-web/site "${2:-8080}"
fi
FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
exec build/app/frictionlab "$@"
