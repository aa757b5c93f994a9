#!/usr/bin/env bash
# Sets everything up and opens FrictionLab's classroom window on the first lesson (or on the
# lesson and options given). Without a display it says so and draws the lesson to a PNG instead.
set -euo pipefail
cd "$(dirname "$0")/.."
FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
exec build/app/frictionlab "$@"
