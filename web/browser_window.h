// The classroom in a web page: the browser's platform adapter, as desktop/window.h is the desktop's.
// The canvas (#canvas) through emscripten's GLFW and WebGL 2, ImGui's GLFW input, touch as the
// mouse, the canvas following the page's size at the screen's own pixel density, the browser's
// full screen, and a loop that stops drawing while nothing can change.
#pragma once

#include <optional>
#include <string>

#include "classroom/classroom.h"

namespace frictionlab::web {

struct PageRun {
  std::string settings_path;  // the window's settings, kept in the browser; empty: nowhere
  // Where the page writes a link's setup before opening it: the lesson in the page's address
  // is named from there.
  std::string link_setup_path;
  // The help panel's remembered setting while a link opened the page with it closed: saved in
  // its place until the user shows the help (F1), so one link does not hide it for good.
  std::optional<bool> help_to_save;
};

// Starts the page's frame loop and returns to the browser (the loop runs from its events).
// The classroom must outlive the page.
void run_page(classroom::Classroom& classroom, const PageRun& run);

// The loop's counts, for the page's tests: frames drawn since the page opened.
long frames_drawn();
// Whether the loop is asleep: nothing can change until input wakes it.
bool sleeping();

}  // namespace frictionlab::web

// Wakes the page's loop after JavaScript changed something the picture shows.
extern "C" void frictionlab_wake();
