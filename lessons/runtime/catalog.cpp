#include "lessons/runtime/catalog.h"

#include <cstdlib>
#include <filesystem>

#include "physics/materials.h"

namespace frictionlab::lessons {

const std::vector<std::string>& builtin_lessons() {
  static const std::vector<std::string> names = {"spring_pull", "incline", "tipping_box", "where_methods_fail"};
  return names;
}

std::string lessons_directory() {
  if (const char* chosen = std::getenv("FRICTIONLAB_LESSONS"); chosen != nullptr && *chosen != '\0') return chosen;
  return FRICTIONLAB_LESSONS_DIR;
}

std::string resolve_lesson(const std::string& name_or_path) {
  namespace fs = std::filesystem;
  for (const std::string& name : builtin_lessons()) {
    if (name == name_or_path) return (fs::path(lessons_directory()) / (name + ".lua")).string();
  }
  if (fs::path(name_or_path).extension() == ".lua") {
    std::error_code error;
    if (!fs::is_regular_file(name_or_path, error)) throw InvalidInput("lesson " + name_or_path + ": no such file");
    return name_or_path;
  }
  std::string known;
  for (const std::string& name : builtin_lessons()) known += (known.empty() ? "" : ", ") + name;
  throw InvalidInput("unknown lesson '" + name_or_path + "'; built-in lessons: " + known +
                     ", or give the path of a .lua file");
}

}  // namespace frictionlab::lessons
