#!/usr/bin/env bash
# Takes the README's screenshots of the classroom window, in a real window on Xvfb (a virtual
# X display, so no screen is needed), into docs/screenshots/.
#   scripts/readme_screenshots.sh
# Look at the pictures before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."

FRICTIONLAB_TESTS=1 FRICTIONLAB_TARGET=frictionlab scripts/setup.sh build -DBUILD_TESTING=OFF
mkdir -p docs/screenshots
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Each shot gets settings of its own (the window keeps them in $XDG_CONFIG_HOME/frictionlab).
shot() {  # shot NAME "settings lines" frictionlab-arguments...
  local name=$1 settings=$2
  shift 2
  mkdir -p "$scratch/$name/frictionlab"
  printf '%b' "$settings" > "$scratch/$name/frictionlab/settings.ini"
  XDG_CONFIG_HOME="$scratch/$name" xvfb-run -a -s '-screen 0 2000x1200x24' \
    build/app/frictionlab "$@" --screenshot "docs/screenshots/$name.png"
  echo "docs/screenshots/$name.png"
}

shot window "help = off\n" spring_pull --at 2
shot window_help "help = on\n" incline --at 0.6
shot window_projector_dark "help = off\ntheme = dark\nprojector = on\nwidth = 1920\nheight = 1080\n" tipping_box --at 2.2
shot window_locked "help = off\n" spring_pull --lock mu_s,mu_k --at 1.2
# A mystery surface in projector mode: its values hidden, the class's answers asked for.
shot window_mystery "help = off\nprojector = on\nwidth = 1920\nheight = 1080\n" spring_pull --mystery aluminium/wood --seed 42 --at 3
# What a student sees after saving a script with a mistake: the error with its file and line,
# and a lesson that works still running.
sed 's/^local angle = parameter/local angle = parameter {/' lessons/incline.lua > "$scratch/my_incline.lua"
shot window_script_error "help = off\n" "$scratch/my_incline.lua" --at 1
