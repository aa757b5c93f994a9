// The window's files (classroom/exports.h): screenshots asked of the host and the history's CSV.
#include "classroom/exports.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "draw/image.h"
#include "files/output_file.h"
#include "lessons/runtime/history_csv.h"

namespace frictionlab::classroom {

std::string lesson_name(const std::string& script_path) { return std::filesystem::path(script_path).stem().string(); }

std::string Exports::output_path(const lessons::Lesson& lesson, const std::string& stem, const std::string& extension) const {
  char time[32];
  std::snprintf(time, sizeof time, "_t%.2f", lesson.scene().time());
  return draw::unused_path(folder, stem + time, extension);
}

std::string Exports::request_screenshot(const lessons::Lesson& lesson) {
  try {
    screenshot_request_ = output_path(lesson, "frictionlab_" + lesson_name(lesson.path()), ".png");
    return "";
  } catch (const std::exception& error) {
    return std::string("Could not take a screenshot: ") + error.what();
  }
}

std::string Exports::save_history(const classroom_state::Playback& playback, const draw::HiddenValues& hidden) const {
  try {
    return "History saved to " + export_history(playback, hidden);
  } catch (const std::exception& error) {
    return std::string("Could not save the history: ") + error.what();
  }
}

std::string Exports::export_history(const classroom_state::Playback& playback, const draw::HiddenValues& hidden) const {
  const lessons::Lesson& lesson = playback.lesson();
  const Scene& scene = lesson.scene();
  // The one format `frictionlab run --csv` writes too (lessons/runtime/history_csv.h), with the
  // mouse's hand's columns filled in: whether it pulled in the step that ended at the row's
  // time, and what its force gauge read.
  std::string csv = lessons::csv_header(lesson);
  const std::vector<classroom_state::GaugeSample>& gauge = playback.gauge().samples();
  std::size_t next_sample = 0;
  for (std::size_t i = 0; i < scene.times().size(); ++i) {
    const long frame = static_cast<long>(i) + 1;  // row i is the end of the scene's frame i + 1
    while (next_sample < gauge.size() && gauge[next_sample].frame < frame) ++next_sample;
    const bool pulled = next_sample < gauge.size() && gauge[next_sample].frame == frame;
    csv += lessons::csv_row(scene, i, pulled ? std::optional<double>(gauge[next_sample].force) : std::nullopt);
  }
  const std::string path = output_path(lesson, "frictionlab_" + lesson_name(lesson.path()) + "_history", ".csv");
  // The values that made the run, beside it, so a file found later says which run it is; a
  // mystery's are "?". Only a settings file FrictionLab wrote is replaced there, and it is put
  // in place before the CSV, so no CSV is ever left without its settings.
  const std::string settings = lessons::run_settings(lesson, [&](const std::string& name) { return hidden.hides(name); });
  {
    files::OutputFile settings_file(lessons::settings_path_for(path), lessons::frictionlab_settings_file);
    settings_file.write(settings);
    settings_file.commit();
  }
  files::write_whole_file(path, csv.data(), csv.size());
  return path;
}

}  // namespace frictionlab::classroom
