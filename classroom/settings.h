// What the window remembers between runs: theme, projector mode, speed and whether the help
// panel is open. A small "name = value" file beside ImGui's own imgui.ini, in
// $XDG_CONFIG_HOME/frictionlab (or ~/.config/frictionlab).
#pragma once

#include <string>

#include "draw/theme.h"

namespace frictionlab::ui {

// The measuring tools that are on (classroom/measuring_tools.h), kept for the next class.
struct ToolSettings {
  bool stopwatch = false;
  bool distance_marks = false;
  bool speed = false;
  bool weight_components = false;
  bool operator==(const ToolSettings&) const = default;
};

struct WindowSettings {
  ThemeName theme = ThemeName::light;
  bool projector = false;
  bool help = true;  // a newcomer sees the shortcuts first
  double speed = 1.0;
  int width = 1280, height = 720;  // the window's size when it is not full screen
  bool full_screen = false;         // F11: a projector's whole screen, kept for the next class
  bool predictions = true;          // ask the class to predict before the theory shows (View menu)
  ToolSettings tools;               // the Tools menu

  bool operator==(const WindowSettings&) const = default;
};

// The folder for settings.ini and imgui.ini; made if missing. Empty when there is no home to
// keep them in (then nothing is kept).
std::string settings_folder();
// Lines it does not understand, or values out of range, are skipped: a damaged file must not
// keep the window from opening. A missing file gives the defaults.
WindowSettings load_settings(const std::string& path);
// Whole or not at all (written beside it, then renamed). Returns false when it cannot be written.
bool save_settings(const WindowSettings& settings, const std::string& path);

}  // namespace frictionlab::ui
