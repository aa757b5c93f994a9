// The teacher's lock (classroom/lesson_lock.h): checked against the lesson, and said in words.
#include "classroom/lesson_lock.h"

#include <filesystem>

#include "classroom_state/setup_file.h"

namespace frictionlab::classroom {

void LessonLock::check(const lessons::Lesson& lesson) const {
  for (const std::string& name : names) {
    bool known = false;
    for (const char* setting : classroom_state::lockable_settings) known = known || name == setting;
    for (const lessons::Parameter& parameter : lesson.parameters()) known = known || name == parameter.name;
    if (!known) {
      std::string controls;
      for (const lessons::Parameter& parameter : lesson.parameters()) controls += parameter.name + ", ";
      throw InvalidInput("--lock " + name + ": " + lesson.path() + " has no control of that name; its controls: " +
                         controls + "hz, substeps, friction");
    }
  }
}

std::string LessonLock::words(bool browser) const {
  if (names.empty()) return "";
  // Nothing in the window unlocks it: the class cannot undo what the teacher prepared.
  if (!from.empty() && browser) {
    // The page's setups come from a link or a file from the computer, copied where nobody looks.
    return "Locked by the prepared setup this page opened, for the class to stay on this lesson. To unlock: open the "
           "page's address without its #setup= part, or a setup file without its lock line.";
  }
  if (!from.empty()) {
    return "Locked by the setup " + std::filesystem::path(from).filename().string() +
           ", for the class to stay on this lesson. To unlock: delete its lock line (in " + from +
           "), then quit and open the setup again.";
  }
  return "Locked by --lock on the command line, for the class to stay on this lesson. To unlock: quit and start "
         "FrictionLab without --lock.";
}

}  // namespace frictionlab::classroom
