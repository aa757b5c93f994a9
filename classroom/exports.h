// What the window writes into its output folder: screenshots (taken by the host, which asks for
// them after the frame) and the record's history as CSV beside the settings that made the run,
// each a new file named after the lesson and its moment.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "classroom_state/playback.h"
#include "draw/panels.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab::classroom {

// A lesson's name as the lesson list gives it: its script's file name without ".lua".
std::string lesson_name(const std::string& script_path);

struct Exports {
  std::string folder = ".";  // the output folder

  // A new file in the folder named after the lesson's moment ("_t1.25"); never an existing one.
  std::string output_path(const lessons::Lesson& lesson, const std::string& stem, const std::string& extension) const;
  // Ctrl+S: a screenshot asked of the host. Returns what the status line says: "", or why not.
  std::string request_screenshot(const lessons::Lesson& lesson);
  // The path the host is asked to save the window to, taken once.
  std::optional<std::string> take_screenshot_request() { return std::exchange(screenshot_request_, std::nullopt); }
  bool screenshot_asked() const { return screenshot_request_.has_value(); }
  // Ctrl+E: writes the record (time and every probe, one row per frame, with the hand's force
  // gauge) as CSV, and the run's settings beside it, a mystery's values "?"; returns the path, or
  // throws std::runtime_error.
  std::string export_history(const classroom_state::Playback& playback, const draw::HiddenValues& hidden) const;
  // The same, said in the status line: where it went, or why not.
  std::string save_history(const classroom_state::Playback& playback, const draw::HiddenValues& hidden) const;

 private:
  std::optional<std::string> screenshot_request_;
};

}  // namespace frictionlab::classroom
