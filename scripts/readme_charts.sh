#!/usr/bin/env bash
# Runs the whole benchmark and copies its charts into docs/charts/ for docs/physics.md.
#   scripts/readme_charts.sh
# Look at the pictures before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."

FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
build/app/frictionlab bench --out "$out"
mkdir -p docs/charts
for chart in stability work_precision problems; do
  cp "$out/$chart.png" "docs/charts/$chart.png"
  echo "docs/charts/$chart.png"
done
