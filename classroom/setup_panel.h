// The prepared setups' part of the window (classroom_state/setup_file.h): the Lesson menu's
// dialog that opens or saves one, which setup the teacher's lock came from, and a setup made
// from the window's parts and written. It owns that state, as each of Dear ImGui's demo windows
// owns its own. Opening a setup replaces the lesson every panel reads, and a setup holds every
// panel's state, so the classroom composes those (Classroom::open_setup, current_setup,
// save_setup in setup_panel.cpp) from what this gives.
#pragma once

#include <set>
#include <string>

#include "classroom/dialogs.h"
#include "classroom/mystery_panel.h"
#include "classroom_state/class_predictions.h"
#include "classroom_state/setup_file.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::ui {

struct SetupPanel {
  SetupDialog dialog;
  std::string lock_from;  // the setup file the lock came from; "": the command line's --lock

  // The window as a setup saved at `path` would hold it: the lesson (named from there), every
  // value but a mystery's, the lock, the mystery's pair and seed, the step settings, whether
  // predictions are asked, the class's answers to the lesson's predict rows and the reveal.
  static PreparedSetup of_window(const std::string& path, const lessons::Lesson& lesson, const std::set<std::string>& lock,
                                 const MysteryPanel& mystery, bool ask_predictions, const ClassPredictions& predictions);
  // Writes `setup` to `path` (never over a .lua script or a file that is not a setup FrictionLab
  // wrote, nor with a typed prediction that is not a number). Returns "" or why not.
  static std::string save(const std::string& path, const PreparedSetup& setup, const lessons::Lesson& lesson);
};

}  // namespace frictionlab::ui
