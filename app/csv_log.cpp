#include "app/csv_log.h"

#include <filesystem>
#include <fstream>

#include "lessons/runtime/history_csv.h"
#include "physics/validation.h"

namespace frictionlab {
namespace {

std::string first_line(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string line;
  std::getline(file, line);
  return line;
}

}  // namespace

bool written_by_frictionlab(const std::string& path) { return lessons::starts_frictionlab_csv(first_line(path)); }

bool settings_written_by_frictionlab(const std::string& path) {
  return lessons::starts_frictionlab_settings(first_line(path));
}

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
    // The settings file is written once the CSV is in place (finish), but refused now, before
    // the run, and after the CSV would be, so that a message names the CSV when both would:
    // each opened and dropped at once, leaving no temporary file, then the CSV's kept open last
    // (the interrupt handler removes one temporary file, the last opened).
    { ui::OutputFile refused_now(path, written_by_frictionlab); }
    { ui::OutputFile refused_now(lessons::settings_path_for(path), settings_written_by_frictionlab); }
    file_ = std::make_unique<ui::OutputFile>(path, written_by_frictionlab);
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
    file_->commit();
    ui::OutputFile settings(lessons::settings_path_for(path_), settings_written_by_frictionlab);
    settings.write(settings_);
    settings.commit();
  } catch (const std::runtime_error& error) {
    throw InvalidInput(std::string("--csv ") + error.what());
  }
}

}  // namespace frictionlab
