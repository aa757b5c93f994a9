#include "ui/user_lessons.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace frictionlab::ui {

namespace fs = std::filesystem;

std::string user_lessons_folder() {
  fs::path data;
  // The XDG rule: a relative XDG_DATA_HOME is invalid and ignored.
  if (const char* chosen = std::getenv("XDG_DATA_HOME"); chosen != nullptr && *chosen == '/') {
    data = chosen;
  } else if (const char* home = std::getenv("HOME"); home != nullptr && *home == '/') {
    data = fs::path(home) / ".local" / "share";
  } else {
    return "";
  }
  return (data / "frictionlab" / "lessons").string();
}

std::vector<UserLesson> user_lessons() {
  std::vector<UserLesson> found;
  const std::string folder = user_lessons_folder();
  if (folder.empty()) return found;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    std::error_code kind;
    if (it->path().extension() == ".lua" && it->is_regular_file(kind)) found.push_back({it->path().stem().string(), it->path().string()});
  }
  std::sort(found.begin(), found.end(), [](const UserLesson& a, const UserLesson& b) { return a.name < b.name; });
  return found;
}

}  // namespace frictionlab::ui
