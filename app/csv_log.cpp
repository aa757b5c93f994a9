#include "app/csv_log.h"

#include <filesystem>

#include "lessons/runtime/history_csv.h"
#include "physics/validation.h"

namespace frictionlab {

CsvLog::CsvLog(const std::string& path, const lessons::Lesson& lesson, std::ostream& standard_output,
               std::ostream& standard_error)
    : path_(path), standard_output_(standard_output), standard_error_(standard_error) {
  if (path == "-") return;
  namespace fs = std::filesystem;
  std::error_code same;
  if (fs::path(path).extension() == ".lua" || fs::equivalent(path, lesson.path(), same)) {
    throw InvalidInput("--csv " + path + ": that looks like a lesson script; give a .csv file so no script is overwritten");
  }
  try {
    // The settings file is written at the end, put in place just before the CSV (finish), but
    // refused now, before the run, and after the CSV would be, so that a message names the CSV
    // when both would: each opened and dropped at once, leaving no temporary file, then the
    // CSV's kept open (the interrupt handler removes one temporary file, the last opened).
    { files::OutputFile refused_now(path, lessons::frictionlab_csv_file); }
    { files::OutputFile refused_now(lessons::settings_path_for(path), lessons::frictionlab_settings_file); }
    file_ = std::make_unique<files::OutputFile>(path, lessons::frictionlab_csv_file);
  } catch (const std::runtime_error& error) {
    std::string message = "--csv ";
    message += error.what();
    throw InvalidInput(message);
  }
}

void CsvLog::put(const std::string& text) {
  if (file_) {
    file_->write(text);
  } else {
    standard_output_ << text;
  }
}

void CsvLog::header(const lessons::Lesson& lesson, const std::set<std::string>& hidden) {
  settings_ = lessons::run_settings(lesson, [&](const std::string& name) { return hidden.count(name) > 0; });
  if (!file_) standard_error_ << settings_;
  put(lessons::csv_header(lesson));
}

void CsvLog::row(const Scene& scene) { put(lessons::csv_row(scene, scene.times().size() - 1, std::nullopt)); }

void CsvLog::finish() {
  if (!file_) {
    standard_output_.flush();
    return;
  }
  try {
    // The settings first, then the CSV: a settings file that cannot be written leaves the last
    // run's CSV and its settings as they were, never a new CSV beside an old run's settings.
    files::OutputFile settings(lessons::settings_path_for(path_), lessons::frictionlab_settings_file);
    settings.write(settings_);
    settings.commit();
    file_->commit();
  } catch (const std::runtime_error& error) {
    throw InvalidInput(std::string("--csv ") + error.what());
  }
}

}  // namespace frictionlab
