// The Lesson menu: the built-in lessons and the student's own, greyed under the teacher's lock
// (which it explains), opening a script or a setup, saving a setup, reloading, a screenshot, the
// history's export and Quit; the page's own items in a browser (its file chooser, a setup as a
// download, no Reload or Quit). It draws itself and says what was chosen; the classroom does it,
// since opening a lesson replaces what every panel reads.
#pragma once

#include <optional>
#include <string>

#include "classroom/control_places.h"
#include "classroom/lesson_lock.h"

namespace frictionlab::classroom {

struct LessonMenuChoice {
  std::optional<std::string> open;  // a built-in lesson's name, or the path of one of the student's own
  bool open_file = false;           // the page's file chooser
  bool open_script = false;         // the dialog that opens a script by its path
  bool open_setup = false, save_setup = false;  // the setup dialog, to open or to save one (the page: a download)
  bool reload = false, screenshot = false, export_history = false, quit = false;
};

// The menu in the menu bar being drawn, with the lesson at `lesson_path` running. `browser`: the
// page's items; `script_paths`: the student's folder named by its path (the desktop).
LessonMenuChoice lesson_menu(const std::string& lesson_path, const LessonLock& lock, bool browser, bool script_paths,
                             ControlPlaces& controls);

// Which file is running, so a student knows which script to edit: `path` (as the class sees it)
// at the right of the menu bar being drawn, as much of it as fits, never cut (the whole of it
// under the pointer). Drawn after the bar's last menu.
void running_script_path(const std::string& path);

}  // namespace frictionlab::classroom
