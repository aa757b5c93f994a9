// The Lesson menu's dialogs: open a script by its path, and open or save a prepared setup.
//
// Each keeps its own state (whether it was asked for, the path as typed, the last error) and
// draws itself, as each of Dear ImGui's demo windows does: the menu asks for one, and the
// classroom draws both after the frame's panels, acting through its public calls (open,
// open_setup, save_setup).
#pragma once

#include <string>

#include "classroom/control_places.h"
#include "draw/theme.h"

namespace frictionlab::ui {

class Classroom;

struct OpenScriptDialog {
  bool asked = false;    // the menu asked for it this frame
  bool refocus = false;  // a path that failed: back into the box next frame, to correct it
  char path[512] = {};
  std::string error;

  void ask() { asked = true; }
  // The dialog while it is open; `scale` is the fonts' scale.
  void draw(Classroom& classroom, float scale, const Theme& colours);
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
  // The dialog while it is open; a save's path is first suggested in `output_folder`. Returns
  // what the status line should say ("" for nothing new).
  std::string draw(Classroom& classroom, const std::string& output_folder, float scale, const Theme& colours,
                   ControlPlaces& controls);
};

}  // namespace frictionlab::ui
