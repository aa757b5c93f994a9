#!/usr/bin/env bash
# Sets everything up and runs FrictionLab's main job. Until the window exists, that is the
# first lesson (spring_pull) run headless, with its theory-against-simulation table.
set -euo pipefail
cd "$(dirname "$0")/.."
FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
exec build/app/frictionlab "$@"
