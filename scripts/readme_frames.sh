#!/usr/bin/env bash
# Renders the frame of each built-in lesson the README shows, into docs/frames/, headless.
#   scripts/readme_frames.sh
# Look at the pictures before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."

FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
mkdir -p docs/frames
# Moments that show each lesson's point: the second slip of the block, the block sliding down
# the slope, the box tipping about its front edge.
build/app/frictionlab render spring_pull --at 2.5 --out docs/frames/spring_pull.png
build/app/frictionlab render incline --at 1 --out docs/frames/incline.png
build/app/frictionlab render tipping_box --at 2.2 --out docs/frames/tipping_box.png
