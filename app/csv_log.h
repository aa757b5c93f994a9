// `frictionlab run --csv FILE`: one row per step, for a spreadsheet. Written whole or not at
// all (files/output_file.h), only over a CSV this program wrote, or to standard output with `-`.
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
  // Throws InvalidInput, naming the option and the path, when it cannot or must not write there.
  CsvLog(const std::string& path, const lessons::Lesson& lesson, std::ostream& standard_output);
  // The run's settings and the columns' names with their units. The `hidden` parameters' values
  // (a mystery pair's) are written as "?".
  void header(const lessons::Lesson& lesson, const std::set<std::string>& hidden = {});
  void row(const Scene& scene);
  // Puts the file in place (or flushes standard output). Throws InvalidInput.
  void finish();

 private:
  void put(const std::string& text);

  std::string path_;
  std::unique_ptr<ui::OutputFile> file_;  // null: standard output
  std::ostream& standard_output_;
};

// Whether the file at `path` is a CSV this program wrote (its first line says so): only such a
// file is replaced by a new run.
bool written_by_frictionlab(const std::string& path);

}  // namespace frictionlab
