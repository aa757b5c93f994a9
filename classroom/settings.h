// What the window remembers between runs: how the room shows it (theme, projector mode, full
// screen, window size) and how the teacher runs a class (help panel, predictions asked). A small
// "name = value" file beside ImGui's own imgui.ini, in $XDG_CONFIG_HOME/frictionlab (or
// ~/.config/frictionlab).
//
// The speed and the measuring tools are this session's only: a class that opened at ×8 with
// yesterday's stopwatch rushed through its breakaway before anyone looked (issue 31). Each
// session starts at ×1 with the tools off, and the status line says what did come back.
#pragma once

#include <string>

#include "draw/theme.h"

namespace frictionlab::classroom {

// The measuring tools that are on (classroom/measuring_tools.h), for this session only.
struct ToolSettings {
  bool stopwatch = false;
  bool distance_marks = false;
  bool speed = false;
  bool weight_components = false;
  bool operator==(const ToolSettings&) const = default;
};

struct WindowSettings {
  draw::ThemeName theme = draw::ThemeName::light;
  bool projector = false;
  bool help = true;  // a newcomer sees the shortcuts first
  double speed = 1.0;                // this session only
  int width = 1280, height = 720;  // the window's size when it is not full screen
  bool full_screen = false;         // F11: a projector's whole screen, kept for the next class
  bool predictions = true;          // ask the class to predict before the theory shows (View menu)
  ToolSettings tools;               // the Tools menu; this session only

  bool operator==(const WindowSettings&) const = default;
};

// The folder for settings.ini and imgui.ini; made if missing. Empty when there is no home to
// keep them in (then nothing is kept).
std::string settings_folder();
// Lines it does not understand, or values out of range, are skipped: a damaged file must not
// keep the window from opening; so are the speed and the tools an older FrictionLab kept there.
// A missing file gives the defaults.
WindowSettings load_settings(const std::string& path);
// The file save_settings writes for `settings`: the part kept for the next session, the speed and
// the tools left out. The windows compare it, not the whole settings, to know when to save: a
// speed or a tool changed is not worth a write (on the web, a sync of the browser's storage).
std::string kept_settings_text(const WindowSettings& settings);
// Whole or not at all (written beside it, then renamed). Returns false when it cannot be written.
bool save_settings(const WindowSettings& settings, const std::string& path);

// Whether the help panel opens, where `kept` is what the settings file says (true for a first
// window, which has none: `first_window`). A newcomer's first window shows the shortcuts to the
// person at it; the first in projector mode is for a class in front of the screen, where the
// panel took the room the Parameters needed (a teacher's trial: tipping_box opened with its
// sliders folded and the help's last line cut), and a picture is for no one at the window. F1
// shows it either way, and the choice is kept as always.
bool opens_with_help(bool kept, bool first_window, bool projector, bool picture);

// What a session opened with `settings` kept from the last one, for the status line: "Kept from
// the last session: dark theme, projector mode." naming each setting that differs from a new
// window's; "" when none does.
std::string kept_from_last_session(const WindowSettings& settings);

}  // namespace frictionlab::classroom
