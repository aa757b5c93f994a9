#include "ui/user_lessons.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

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

std::string written_title(const std::string& script) {
  // The lesson{} call: "lesson" at a line's start, then "{" or "(" (a plot's title before it is not the lesson's).
  std::size_t at = std::string::npos;
  for (std::size_t line = 0; line < script.size(); line = script.find('\n', line) + 1) {
    if (script.compare(line, 6, "lesson") == 0) {
      const std::size_t next = script.find_first_not_of(" \t", line + 6);
      if (next != std::string::npos && (script[next] == '{' || script[next] == '(')) {
        at = next;
        break;
      }
    }
    if (script.find('\n', line) == std::string::npos) break;
  }
  if (at == std::string::npos) return "";
  for (std::size_t found = script.find("title", at); found != std::string::npos; found = script.find("title", found + 5)) {
    std::size_t i = script.find_first_not_of(" \t", found + 5);
    if (i == std::string::npos || script[i] != '=') continue;
    i = script.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || (script[i] != '"' && script[i] != '\'')) return "";
    const std::size_t end = script.find_first_of(std::string(1, script[i]) + "\n\\", i + 1);
    if (end == std::string::npos || script[end] != script[i]) return "";
    return script.substr(i + 1, end - i - 1);
  }
  return "";
}

std::vector<UserLesson> user_lessons() {
  std::vector<UserLesson> found;
  const std::string folder = user_lessons_folder();
  if (folder.empty()) return found;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    std::error_code kind;
    if (it->path().extension() != ".lua" || !it->is_regular_file(kind)) continue;
    std::ifstream file(it->path(), std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    std::string title = written_title(text.str());
    const std::string name = it->path().stem().string();
    found.push_back({name, it->path().string(), title.empty() ? name : std::move(title)});
  }
  std::sort(found.begin(), found.end(), [](const UserLesson& a, const UserLesson& b) { return a.name < b.name; });
  return found;
}

}  // namespace frictionlab::ui
