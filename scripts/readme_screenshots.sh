#!/usr/bin/env bash
# Takes the screenshots of the classroom window shown in the README and docs/teachers.md, in a
# real window on Xvfb (a virtual X display, so no screen is needed), into docs/screenshots/.
#   scripts/readme_screenshots.sh
# FRICTIONLAB_BUILD_DIR names the build folder to build the program in (build by default).
# Look at the pictures before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."

# The tools and gauge shots drag and press keys with xdotool.
command -v xdotool >/dev/null || { echo "$0: needs xdotool (apt-get install xdotool)" >&2; exit 2; }
build_dir=${FRICTIONLAB_BUILD_DIR:-build}
FRICTIONLAB_TESTS=1 FRICTIONLAB_TARGET=frictionlab scripts/setup.sh "$build_dir" -DBUILD_TESTING=OFF
mkdir -p docs/screenshots
program=$(realpath "$build_dir/app/frictionlab")
shots=$(realpath docs/screenshots)
lessons=$(realpath lessons)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The menu bar shows the running lesson's file as the window was told it. Each shot runs in a
# folder of its own that holds the built-in lessons as lessons/ (a link to this checkout's),
# named so ($FRICTIONLAB_LESSONS): the pictures show "lessons/incline.lua", as a class running
# FrictionLab from its folder sees, not the path of the checkout that took them (the README
# showed /work/wt126/lessons/incline.lua).
export FRICTIONLAB_LESSONS=lessons
in_a_folder() {  # in_a_folder NAME: the shot's folder, made, with its lessons/ and settings
  mkdir -p "$scratch/$1/frictionlab" "$scratch/$1/out"
  ln -sfn "$lessons" "$scratch/$1/out/lessons"
}

# Each shot gets settings of its own (the window keeps them in $XDG_CONFIG_HOME/frictionlab).
shot() {  # shot NAME "settings lines" frictionlab-arguments...
  local name=$1 settings=$2
  shift 2
  in_a_folder "$name"
  printf '%b' "$settings" > "$scratch/$name/frictionlab/settings.ini"
  (cd "$scratch/$name/out" && XDG_CONFIG_HOME="$scratch/$name" xvfb-run -a -s '-screen 0 2000x1200x24' \
    "$program" "$@" --screenshot "$shots/$name.png")
  echo "docs/screenshots/$name.png"
}

# The theory as it always shows; predict first has shots of its own below.
shot window "help = off\npredictions = off\n" spring_pull --at 2
shot window_help "help = on\npredictions = off\n" incline --at 0.6
shot window_projector_dark "help = off\npredictions = off\ntheme = dark\nprojector = on\nwidth = 1920\nheight = 1080\n" tipping_box --at 2.2
shot window_locked "help = off\npredictions = off\n" spring_pull --lock mu_s,mu_k --at 1.2
# A mystery surface in projector mode: its values hidden, the class's answers asked for.
shot window_mystery "help = off\npredictions = off\nprojector = on\nwidth = 1920\nheight = 1080\n" spring_pull --mystery aluminium/wood --seed 42 --at 3
# What a student sees after saving a script with a mistake: the error with its file and line,
# and a lesson that works still running. The script in the shot's folder, named as a student
# names their own ("my_incline.lua:20: …", not the scratch folder's path).
in_a_folder window_script_error
sed 's/^local angle = parameter/local angle = parameter {/' lessons/incline.lua > "$scratch/window_script_error/out/my_incline.lua"
shot window_script_error "help = off\npredictions = off\n" my_incline.lua --at 1

# Predict, then reveal (projector mode, 1920 × 1080): the class's answers ("slides", 50 N) come
# from a prepared setup, as a teacher would have them typed, so no click has to land on a control
# whose place changes with the layout. The first picture is the run's end (its last step, 2.4875 s) with the theory kept
# back, the second the same moment revealed (T).
cat > "$scratch/predict.setup" <<'SETUP'
# FrictionLab setup
lesson tipping_box
predictions on
predict tips or slides = slides
predict push when it happens = 50
SETUP
shot window_predict "help = off\nprojector = on\nwidth = 1920\nheight = 1080\n" --setup "$scratch/predict.setup" --at 2.4875
shot window_reveal "help = off\nprojector = on\nwidth = 1920\nheight = 1080\n" --setup "$scratch/predict.setup" --at 2.4875 --reveal

# The force gauge and the measuring tools, in projector mode at 1920 × 1080, driven by a hand on
# the real window (xdotool on the same Xvfb display). The window saves them itself (Ctrl+S) into
# the folder it was started in.
live() {  # live NAME "settings lines" "xdotool steps" frictionlab-arguments...
  local name=$1 settings=$2 steps=$3
  shift 3
  in_a_folder "$name"
  printf '%b' "$settings" > "$scratch/$name/frictionlab/settings.ini"
  (cd "$scratch/$name/out" && XDG_CONFIG_HOME="$scratch/$name" xvfb-run -a -s '-screen 0 1920x1080x24' \
    bash -c "'$program' $* & window=\$!; sleep 4; $steps; xdotool key ctrl+s; sleep 1.5; kill \$window")
  mv "$(ls "$scratch/$name/out"/*.png | head -1)" "docs/screenshots/$name.png"
  echo "docs/screenshots/$name.png"
}
projector="help = off\npredictions = off\nprojector = on\nwidth = 1920\nheight = 1080\n"
# The tools are this session's only (settings.ini keeps none of them): each is turned on from the
# Tools menu, at its place in the projector's menu bar (read them off a first picture with the
# menu open if the layout changes).
# The pointer leaves the menu bar after each: a click on Tools while the bar still took the
# mouse closed the menu instead of opening it.
tool() {  # tool "Menu item's place, x y": opens Tools and clicks the item
  echo "xdotool mousemove 643 24 click 1; sleep 0.4; xdotool mousemove $1 click 1; sleep 0.4; xdotool mousemove 1900 1060; sleep 0.4"
}
stopwatch=$(tool "787 75") distance_marks=$(tool "857 241") speed=$(tool "786 281") weight_parts=$(tool "849 322")
# push's 10 kg block (its own push at its slowest, 0.2 N/s) pulled by hand at about 4 cm/s through
# the gauge: a peak of hand and push together at mu_s·m·g = 39.2 N, then the plateau at
# mu_k·m·g = 29.4 N. (581, 266) is the
# block's centre at t = 0 in this layout, the distance marks on; read it off a first picture if
# the layout changes. (In projector
# mode push's plots come a page at a time; while the hand pulls they show the gauge's.)
pull='xdotool mousemove 581 266; sleep 0.5; xdotool mousedown 1; sleep 0.3; xdotool key space;
  for i in $(seq 1 70); do xdotool mousemove $((581 + 2 * i)) 266; sleep 0.02; done; sleep 0.2'
live window_force_gauge "$projector" "$distance_marks; $speed; $pull" \
  push --set mass=10 --set push_rate=0.2
# The incline's block sliding, every tool on: the stopwatch, shown before the run, started with
# it (Space) and a lap taken (L); the run pauses at its end, 1 s, and so does the stopwatch.
watch='xdotool key space; sleep 0.6; xdotool key l; sleep 1.5'
live window_tools "$projector" "$stopwatch; $distance_marks; $speed; $weight_parts; $watch" incline
