#!/usr/bin/env bash
# Renders the icon's PNG sizes from frictionlab.svg (the drawing itself), for the hicolor theme.
# The PNGs are kept in the repository so that building needs no SVG renderer; run this again
# after editing the SVG (it needs Debian's librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")"
for size in 16 24 32 48 64 128 256; do
  mkdir -p "${size}x${size}"
  rsvg-convert --width "$size" --height "$size" frictionlab.svg --output "${size}x${size}/frictionlab.png"
done
