// What the window asks of its host (desktop/window.h, web/browser_window.h) once a frame is
// drawn: full screen turned on or off (F11, the View menu), the page's file chooser (the Lesson
// menu in a browser), and quitting. The screenshot it asks for is Exports' (exports.h), which
// names its file.
#pragma once

#include <utility>

namespace frictionlab::classroom {

struct HostRequests {
  bool full_screen_toggle = false;
  bool open_file = false;  // the page's file chooser (ClassroomOptions::browser)
  bool quit = false;       // kept: the host asks again each frame

  // Each taken once, by the host that carries it out.
  bool take_full_screen_toggle() { return std::exchange(full_screen_toggle, false); }
  bool take_open_file() { return std::exchange(open_file, false); }
};

}  // namespace frictionlab::classroom
