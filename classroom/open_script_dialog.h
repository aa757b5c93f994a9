// The Lesson menu's dialog that opens a script by its path (the other, which opens or saves a
// prepared setup, is classroom/setup_dialog.h).
//
// It keeps its own state (whether it was asked for, the path as typed, the last error) and draws
// itself, as each of Dear ImGui's demo windows does: the menu asks for it, and the classroom
// draws it after the frame's panels, handing it what opens a lesson (Classroom::open).
#pragma once

#include <functional>
#include <string>

#include "draw/theme.h"

namespace frictionlab::classroom {

struct OpenScriptDialog {
  bool asked = false;    // the menu asked for it this frame
  bool refocus = false;  // a path that failed: back into the box next frame, to correct it
  char path[512] = {};
  std::string error;

  void ask() { asked = true; }
  // The dialog while it is open; `scale` is the fonts' scale. `open` opens the script at the path
  // chosen, returning "" or why not (shown in the dialog, which stays open to correct the path).
  void draw(const std::function<std::string(const std::string& path)>& open, float scale, const draw::Theme& colours);
};

}  // namespace frictionlab::classroom
