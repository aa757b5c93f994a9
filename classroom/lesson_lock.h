// The teacher's lock (--lock, or a prepared setup's lock line): the only controls the class is
// shown, and the Lesson menu's lessons greyed, so that the class stays on the lesson the teacher
// chose. It knows where it came from, to say how to undo it; nothing in the window undoes it.
#pragma once

#include <set>
#include <string>

#include "classroom/parameters_panel.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

struct LessonLock {
  std::set<std::string> names;  // the controls shown; empty: all of them, nothing locked
  std::string from;             // the setup file the lock came from; "": the command line's --lock

  bool locked() const { return !names.empty(); }
  // Whether a control (a parameter's name, "hz", "substeps", "friction") is shown.
  bool shown(const std::string& control_name) const { return unlocked(names, control_name); }
  // Throws InvalidInput naming a locked name that is none of the lesson's controls.
  void check(const lessons::Lesson& lesson) const;
  // Why the Lesson menu's lessons are greyed, and how to unlock them; "" when nothing is locked.
  // `browser`: the page, whose setups come from a link or a file the browser copied.
  std::string words(bool browser) const;
};

}  // namespace frictionlab::classroom
