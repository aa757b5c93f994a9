#!/bin/sh
# Fails when a built-in lesson (a line of `frictionlab list --tsv`) is missing from the
# students' guide's table of built-in lessons, or has no frame shown in README.md's
# catalogue (a thumbnail, <img src="docs/frames/NAME.png" ...>) and in docs/teachers.md's
# lessons frame by frame.
#   tests/lessons_documented.sh FRICTIONLAB SOURCE_DIR
set -eu
frictionlab=$1
source_dir=$2
names=$("$frictionlab" list --tsv | cut -f1)
test -n "$names"
missing=0
for name in $names; do
  if ! grep -qF "| \`$name\` | \`$name.lua\` |" "$source_dir/lessons/README.md"; then
    echo "lessons/README.md: the table of built-in lessons has no row for $name" >&2
    missing=1
  fi
  if ! grep -qF "<img src=\"docs/frames/$name.png\"" "$source_dir/README.md" || ! test -f "$source_dir/docs/frames/$name.png"; then
    echo "README.md: no frame of $name; render it with scripts/readme_frames.sh and show docs/frames/$name.png" >&2
    missing=1
  fi
  if ! grep -qF "](frames/$name.png)" "$source_dir/docs/teachers.md"; then
    echo "docs/teachers.md: no frame of $name in \"The built-in lessons, frame by frame\"" >&2
    missing=1
  fi
done
exit $missing
