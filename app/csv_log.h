// `frictionlab run --csv FILE`: one row per step, for a spreadsheet, in the one format the
// window's export writes too (lessons/runtime/history_csv.h). Written whole or not at all
// (files/output_file.h), only over files this program wrote, or to standard output with `-`.
// What made the run goes to FILE's settings file beside it (run.csv: run_settings.txt), or to
// standard error with `-`.
#pragma once

#include <memory>
#include <ostream>
#include <set>
#include <string>

#include "files/output_file.h"
#include "lessons/runtime/lesson.h"

namespace frictionlab {

class CsvLog {
 public:
  // Throws InvalidInput, naming the option and the path, when it cannot or must not write
  // there (the CSV or its settings file). `standard_error` gets the settings with `-`.
  CsvLog(const std::string& path, const lessons::Lesson& lesson, std::ostream& standard_output, std::ostream& standard_error);
  // The run's settings (kept until finish) and the columns' names with their units. The
  // `hidden` parameters' values (a mystery pair's) are written as "?".
  void header(const lessons::Lesson& lesson, const std::set<std::string>& hidden = {});
  void row(const Scene& scene);
  // Puts the file and its settings file in place (or flushes standard output). Throws InvalidInput.
  void finish();

 private:
  void put(const std::string& text);

  std::string path_;
  std::unique_ptr<files::OutputFile> file_;  // null: standard output
  std::ostream& standard_output_;
  std::ostream& standard_error_;
  std::string settings_;
};

}  // namespace frictionlab
