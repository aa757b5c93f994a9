// The menu bar at the window's top: the Lesson, Simulation, Mystery, View and Tools menus, each
// drawn by its own part (lesson_menu.h, simulation_menu.h, MysteryTab's, view_menu.h with
// PredictionPanel's items, MeasuringTools'), then the running script's path at its right.
//
// It keeps nothing between frames: the classroom makes one for each frame from the parts the
// menus show. The Tools menu and the View menu's prediction items act on their own parts, as
// those parts' menus do; what the other menus chose is handed to the classroom, which carries
// it out (opening a lesson replaces what every panel reads) before the path is drawn, so a
// lesson opened from the menu names its script at once.
#pragma once

#include <functional>
#include <memory>

#include "classroom/control_places.h"
#include "classroom/lesson_lock.h"
#include "classroom/measuring_tools.h"
#include "classroom/mystery_panel.h"
#include "classroom/prediction_panel.h"
#include "classroom/script_messages.h"
#include "classroom/settings.h"
#include "classroom/window_choice.h"
#include "classroom_state/playback.h"

namespace frictionlab::classroom {

struct MenuBar {
  const std::unique_ptr<classroom_state::Playback>& playback;  // the running lesson, which a choice may replace
  WindowSettings& window;        // what the View menu ticks; the Tools menu's tools, whether predictions are asked
  const LessonLock& lock;        // what the menus grey
  bool browser = false;          // the page's Lesson menu
  const ScriptWords& script_words;
  MysteryPanel& mystery;         // its Mystery menu
  PredictionPanel& predictions;  // its View menu items
  MeasuringTools& tools;         // its Tools menu
  const ForcesShown& forces;     // whose forces the world draws, which the View menu ticks
  ControlPlaces& controls;

  // The bar, in the frame being built; `carry_out` is handed what its menus chose.
  void draw(const std::function<void(const WindowChoice&)>& carry_out) const;
};

}  // namespace frictionlab::classroom
