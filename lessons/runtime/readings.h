// A lesson's theory rows as read at a moment, with why they may not answer yet: plain data the
// window's playback keeps and the drawn frame shows (draw/frame.h).
#pragma once

#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

// What the theory table shows of a lesson at a moment: its rows worked out, and why they may
// not answer yet. The window's playback works them out a few times a second; a headless frame
// works them out once.
struct LessonReadings {
  std::vector<ExpectationResult> expectations;
  double duration = 1.0;  // s
  std::string error;      // the script failed to work them out
  std::string caveat;     // why the measurements do not answer the predictions yet
};

}  // namespace frictionlab::lessons
