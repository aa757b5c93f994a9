// The lesson files the window watches (classroom/lesson_file_watch.h).
#include "classroom/lesson_file_watch.h"

namespace frictionlab::classroom {

std::map<std::string, std::string> LessonFileWatch::overrides_for(const std::string& path) const {
  return path == failed.path ? overrides : std::map<std::string, std::string>{};
}

bool LessonFileWatch::look(classroom_state::Playback& playback, double wall_seconds,
                           const std::function<std::string(const std::string&)>& open) {
  const bool reloaded = playback.watch_file(wall_seconds);
  if (!failed.changed(wall_seconds)) return reloaded;
  // The script named on the command line, saved again: opened if it builds now. Opened, the
  // classroom forgets it (the lesson that replaced it is no longer a stand-in); still failing,
  // it is watched on with its new error.
  const FailedScript was = failed;
  if (std::string error = open(was.path); !error.empty()) {
    failed = was;
    failed.error = error;
  }
  return true;
}

}  // namespace frictionlab::classroom
