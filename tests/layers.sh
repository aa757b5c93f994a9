#!/bin/bash
# Fails when a layer includes one it must not (the top-level CMakeLists.txt lists the layers):
# a folder's files may include only the folders named for it below, and only the folders that
# draw may include Dear ImGui, only desktop/ GLFW. The lesson commands (list, run, check, link)
# and the fuzzers are followed through every header they reach: none of them may reach a
# drawing header, so the terminal's commands and the fuzzers never pull the drawing in.
#   tests/layers.sh SOURCE_DIR
set -u
cd "$1" || exit 2
failed=0

# What each folder may include of the project's folders, and which outside headers are barred.
declare -A allowed=(
  [physics]="physics"
  [lessons]="physics lessons"
  [bench]="physics lessons bench"
  [bench/reports]="physics lessons bench files classroom_state draw classroom app bench/reports"
  [files]="files"
  [classroom_state]="physics lessons files classroom_state"
  [draw]="physics lessons files draw"
  [classroom]="physics lessons bench files classroom_state draw classroom"
  [desktop]="physics lessons bench files classroom_state draw classroom desktop"
)
declare -A barred=(
  [physics]="imgui GLFW EGL"
  [lessons]="imgui GLFW EGL"
  [bench]="imgui GLFW EGL"
  [bench/reports]="GLFW"
  [files]="imgui GLFW EGL"
  [classroom_state]="imgui GLFW EGL"
  [draw]="GLFW"
  [classroom]="GLFW EGL"
  [desktop]=""
)

# The project's headers a file includes, as paths from the source folder.
project_includes() {
  sed -n 's/^#include "\([^"]*\)".*/\1/p' "$1"
}

# The layer a path belongs to: the longest folder with rules of its own that holds it
# (bench/reports/reports.h is bench/reports's, bench/problems.h bench's), else its top folder.
layer_of() {
  local layer=${1%%/*} key
  for key in "${!allowed[@]}"; do
    [[ $1 == "$key"/* && ${#key} -gt ${#layer} ]] && layer=$key
  done
  echo "$layer"
}

# A folder's own files: a subfolder with rules of its own (bench/reports) is left to them.
files_of() {
  local prune=() key
  for key in "${!allowed[@]}"; do
    [[ $key == "$1"/* ]] && prune+=(-path "$key" -prune -o)
  done
  find "$1" "${prune[@]}" \( -name '*.h' -o -name '*.cpp' \) -print
}

for folder in "${!allowed[@]}"; do
  while IFS= read -r file; do
    while IFS= read -r included; do
      top=${included%%/*}
      [[ -d $top ]] || continue  # a header beside the file, or not the project's
      layer=$(layer_of "$included")
      [[ " ${allowed[$folder]} " == *" $layer "* ]] && continue
      echo "$file includes $included ($layer/): $folder/ may include only ${allowed[$folder]}" >&2
      failed=1
    done < <(project_includes "$file")
    for outside in ${barred[$folder]}; do
      if grep -qE "^#include <$outside[/._a-z0-9]*>" "$file"; then
        echo "$file includes <$outside…>: $folder/ must not" >&2
        failed=1
      fi
    done
  done < <(files_of "$folder")
done

# Every project header a file reaches, through the headers it includes.
reached() {
  local -A seen=()
  local queue=("$@") file included
  while ((${#queue[@]})); do
    file=${queue[0]}
    queue=("${queue[@]:1}")
    while IFS= read -r included; do
      [[ -f $included && -z ${seen[$included]:-} ]] || continue
      seen[$included]=1
      queue+=("$included")
    done < <(project_includes "$file")
  done
  printf '%s\n' "${!seen[@]}"
}

for entry in app/lesson_commands.cpp app/csv_log.cpp app/table.cpp app/options.cpp app/command_line.cpp \
             app/link_command.cpp fuzz/*.cpp; do
  while IFS= read -r header; do
    case $header in
      draw/* | classroom/* | desktop/*)
        echo "$entry reaches $header: the terminal's commands and the fuzzers draw nothing" >&2
        failed=1
        ;;
    esac
    if grep -qE '^#include <(imgui|GLFW)' "$header"; then
      echo "$entry reaches $header, which includes Dear ImGui or GLFW" >&2
      failed=1
    fi
  done < <(reached "$entry")
done
exit $failed
