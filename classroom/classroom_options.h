// What the classroom window opens with: the lesson and its values from the command line or a
// prepared setup file, the lock, the mystery, the class's predictions and the window's
// remembered settings. Plain data; the window (classroom/classroom.h) is built from it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "classroom/settings.h"
#include "classroom_state/class_predictions.h"
#include "classroom_state/mystery.h"
#include "classroom_state/setup_file.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

struct ClassroomOptions {
  std::string lesson;                               // the script's path
  std::map<std::string, std::string> overrides;     // --set
  StepSettings settings;                            // --hz, --substeps, --friction
  std::vector<std::string> lock;                    // --lock: the only controls shown; empty: all
  std::string lock_from;                            // the setup file that gave the lock; "": --lock
  WindowSettings window;                            // as remembered
  std::string output_folder = ".";                  // screenshots and history exports
  std::optional<classroom_state::MysteryChoice> mystery;             // --mystery PAIR --seed N
  classroom_state::ClassPredictions predictions;                     // the class's answers, from a prepared setup
  // Name scripts by their whole path (the desktop: the student finds the file there), or by
  // the file's name alone (the web page: its files live in the browser, not where anyone looks).
  bool script_paths = true;
  // The web page: the browser's files are not the student's to browse, so the Lesson menu
  // offers the page's own file chooser (not a path to type), saves a setup as a download, and
  // has no Reload or Quit; the script's advice says Apply (the page's editor), not save.
  bool browser = false;
  // Said in the status line as the window opens (a link's lesson kept among the user's lessons).
  std::string opening_notice;
};

// The options a prepared setup file gives (its lesson, values, lock, mystery, step settings and
// the class's predictions) in place of those in `base`; the window's own settings stay, but for
// whether predictions are asked when the file says (`predictions on|off`). Throws InvalidInput as
// "file:line: what is wrong", checked against the lesson before anything opens. A link that
// carries its lesson (the page's Copy link for a student's own) has it kept among the user's
// lessons (received_setup_text), and opening_notice says where.
ClassroomOptions setup_options(const std::string& setup_path, ClassroomOptions base);

}  // namespace frictionlab::classroom
