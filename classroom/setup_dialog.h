// The Lesson menu's setup dialog (classroom_state/setup_file.h): it opens a prepared setup or
// saves the window as one, and makes a setup from the window's parts (which setup the teacher's
// lock came from is the lock's, classroom/lesson_lock.h). It owns that state and draws itself, as each of Dear ImGui's demo
// windows does: the menu asks for it, and the classroom draws it after the frame's panels.
// Opening a setup replaces the lesson every panel reads, and a setup holds every panel's state,
// so the classroom composes those (Classroom::open_setup, current_setup, save_setup in
// classroom.cpp, with its other openings) from what this gives.
#pragma once

#include <functional>
#include <set>
#include <string>

#include "classroom/control_places.h"
#include "classroom/mystery_panel.h"
#include "classroom_state/class_predictions.h"
#include "classroom_state/setup_file.h"
#include "draw/theme.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

// What the dialog does with the path typed, each returning "" or why not (shown in the dialog,
// which stays open to correct the path): the classroom's, since a setup opened replaces the
// lesson every panel reads, and one saved holds every panel's state.
struct SetupFiles {
  std::function<std::string(const std::string& path)> open, save;
};

struct SetupDialog {
  enum class Kind { none, open, save } kind = Kind::none;  // which one is open (or asked for)
  bool asked = false;                                       // asked for this frame
  char path[512] = {};
  std::string error;

  void ask(Kind which) {
    kind = which;
    asked = true;
  }
  // The dialog while it is open, with the lesson at `lesson_path` running; a save's path is first
  // suggested in `output_folder` under the lesson's name. Returns what the status line should say
  // ("" for nothing new).
  std::string draw(const std::string& lesson_path, const std::string& output_folder, const SetupFiles& files, float scale,
                   const draw::Theme& colours, ControlPlaces& controls);

  // The window as a setup saved at `path` would hold it: the lesson (named from there), every
  // value but a mystery's, the lock, the mystery's pair and seed, the step settings, whether
  // predictions are asked, the class's answers to the lesson's predict rows and the reveal.
  static classroom_state::PreparedSetup of_window(const std::string& path, const lessons::Lesson& lesson, const std::set<std::string>& lock,
                                 const MysteryPanel& mystery, bool ask_predictions, const classroom_state::ClassPredictions& predictions);
  // Writes `setup` to `path` (never over a .lua script or a file that is not a setup FrictionLab
  // wrote, nor with a typed prediction that is not a number). Returns "" or why not.
  static std::string save(const std::string& path, const classroom_state::PreparedSetup& setup, const lessons::Lesson& lesson);
};

}  // namespace frictionlab::classroom
