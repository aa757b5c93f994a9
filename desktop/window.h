// The classroom in a GLFW window: OpenGL 3.3 through GLX (Mesa's llvmpipe needs no GPU), Dear
// ImGui's GLFW input, a fixed-step lesson paced by the wall clock, and what only a window can
// do (full screen, screenshots of itself, keeping its size between runs).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "classroom/classroom.h"

namespace frictionlab::desktop {

// There is no display to open a window on (no X server or Wayland compositor reachable), or
// it refused an OpenGL 3.3 context. The message says which.
struct NoDisplay : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WindowRun {
  // Take a picture of the window and close it: the lesson stepped to `at` seconds and paused,
  // a few frames drawn so every panel has settled, then the window saved to `screenshot`.
  // For the README's screenshots and the smoke test; a teacher leaves these empty.
  std::optional<double> at;
  std::string screenshot;
  std::string settings_path;  // where the window's settings are kept; empty: nowhere
  std::string imgui_ini;      // ImGui's window places; empty: nowhere
  // Open over the whole screen but its panels and task bars (frictionlab --projector: the
  // class's screen is the projector's), rather than at the size the settings keep.
  bool fill_screen = false;
};

// Returns when the window is closed. Throws NoDisplay before anything is shown when it cannot
// open, std::runtime_error if the screenshot asked for cannot be written.
void run_window(classroom::Classroom& classroom, const WindowRun& run);

}  // namespace frictionlab::desktop
