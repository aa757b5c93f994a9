// What the window's menus and its keys chose in a frame, for the classroom to carry out: the
// menu bar's menus each say what was chosen (menu_bar.h), the keys' shortcuts choose the same
// items (shortcut_keys.h) and a few of their own. The classroom carries them out in one place,
// since opening a lesson replaces what every panel reads.
#pragma once

#include <optional>
#include <string>

#include "classroom/lesson_menu.h"
#include "classroom/mystery_tab.h"
#include "classroom/simulation_menu.h"
#include "classroom/view_menu.h"

namespace frictionlab::classroom {

struct WindowChoice {
  LessonMenuChoice lesson;          // the Lesson menu's items; Ctrl+S, Ctrl+E and F5 choose theirs
  SimulationChoice simulation;      // the Simulation menu's; R its reset
  MysteryMenuChoice mystery;        // the Mystery menu's
  ViewMenuChoice view;              // the View menu's; F11, F1, P and D theirs
  std::optional<std::string> said;  // what the View menu's prediction items said of the run's moment
  // The keys' own.
  bool play_pause = false, step = false, step_back = false;  // Space, '.' and ',', as the transport bar's buttons
  bool reveal = false;                                       // T: the theory revealed, or hidden again
  bool stopwatch_start_stop = false, stopwatch_lap = false;  // W (the stopwatch then shown) and L
};

}  // namespace frictionlab::classroom
