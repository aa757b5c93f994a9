// The built-in lessons are the scripts in the lessons folder: adding one is adding its file.
// Each says where it comes in the teaching order (lesson{ order = ... }) and its teaching
// moments. Also: how a name on the command line becomes a script path.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lessons/runtime/lesson.h"

namespace frictionlab::lessons {

// What the list of lessons shows of one, read from its script at its defaults.
struct CatalogEntry {
  std::string name;  // the file's name without .lua
  std::string path;
  std::string title;
  std::optional<double> order;
  std::vector<Moment> moments;
};

// Every *.lua file in lessons_directory(), in teaching order: by their `order`, those without
// one after, by name. Each script is run once, the first time the folder is listed. Throws
// InvalidInput naming the lesson when a built-in script fails to build.
const std::vector<CatalogEntry>& catalog();
// Their names, in the same order.
const std::vector<std::string>& builtin_lessons();
// Whether `name` is a built-in lesson's name; looks for the file only, runs no script.
bool is_builtin_lesson(const std::string& name);

// Where the built-in scripts live: $FRICTIONLAB_LESSONS if set, else the source tree's
// lessons/ folder this program was built from.
std::string lessons_directory();

// A built-in lesson's name, or a path to a .lua file, to the path of its script. Throws
// InvalidInput listing the built-in lessons when it is neither.
std::string resolve_lesson(const std::string& name_or_path);

}  // namespace frictionlab::lessons
