// The lesson files the window watches: the running lesson's script (Playback's watcher, which
// reloads it when saved) and the script named on the command line that failed to build, tried
// again each time it is saved until it builds, with the --set values it was named with.
//
// It owns the failed script, as each of Dear ImGui's demo windows owns its state; opening it
// replaces the lesson every panel reads, so the classroom hands it what opens a lesson
// (Classroom::open), as it hands the open-script dialog.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "classroom/script_messages.h"
#include "classroom_state/playback.h"

namespace frictionlab::classroom {

struct LessonFileWatch {
  FailedScript failed;                            // the command line's script that does not build yet
  std::map<std::string, std::string> overrides;   // its --set values, for when it builds

  // The --set values a lesson at `path` opens with: the command line's for the script it
  // named, none for any other.
  std::map<std::string, std::string> overrides_for(const std::string& path) const;
  // The watchers, given the wall time since they last looked: the running lesson's script, then
  // the failed one, which when saved again is handed to `open` (it returns "" or why it still
  // fails; `playback` is then replaced, and not read again here). True when what they found
  // changes what the window shows (a script reloaded, gone or back, a failed script tried).
  bool look(classroom_state::Playback& playback, double wall_seconds,
            const std::function<std::string(const std::string&)>& open);
};

}  // namespace frictionlab::classroom
