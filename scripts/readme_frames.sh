#!/usr/bin/env bash
# Renders each built-in lesson's README frame, into docs/frames/LESSON.png, headless: every
# lesson `frictionlab list` gives, at the moment it marks with readme = true (its time, its
# parameter values and its theme, as its golden snapshot shows it).
#   scripts/readme_frames.sh
# Look at the pictures before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."

FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
mkdir -p docs/frames
# One line a lesson: name, title, README moment, moments, tab-separated (cut keeps an empty field).
build/app/frictionlab list --tsv | while IFS= read -r line; do
  lesson=$(cut -f1 <<<"$line")
  readme=$(cut -f3 <<<"$line")
  if [ -z "$readme" ]; then
    echo "readme_frames.sh: $lesson marks none of its moments ($(cut -f4 <<<"$line")) with readme = true" >&2
    exit 2
  fi
  build/app/frictionlab render "$lesson" --moment "$readme" --out "docs/frames/$lesson.png"
done
