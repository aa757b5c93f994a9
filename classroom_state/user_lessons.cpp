#include "classroom_state/user_lessons.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "physics/validation.h"

namespace frictionlab::classroom_state {

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
  // Its own title = "...": at the table's first level (a plot's title inside it is not), a
  // whole word (not plot_title), outside strings and comments.
  const auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  int depth = 0;
  for (std::size_t i = at; i < script.size(); ++i) {
    const char c = script[i];
    if (c == '"' || c == '\'') {  // a string: skipped to its closing quote, past escaped ones
      std::size_t close = script.find_first_of(std::string(1, c) + "\n\\", i + 1);
      while (close != std::string::npos && script[close] == '\\') close = script.find_first_of(std::string(1, c) + "\n\\", close + 2);
      if (close == std::string::npos || script[close] != c) return "";
      i = close;
    } else if (script.compare(i, 2, "--") == 0) {  // a comment: skipped to the line's end
      i = script.find('\n', i);
      if (i == std::string::npos) return "";
    } else if (c == '{' || c == '(' || c == '[') {
      ++depth;
    } else if (c == '}' || c == ')' || c == ']') {
      if (--depth == 0) return "";
    } else if (depth == 1 && script.compare(i, 5, "title") == 0 && !word_char(script[i - 1]) &&
               (i + 5 == script.size() || !word_char(script[i + 5]))) {
      std::size_t value = script.find_first_not_of(" \t", i + 5);
      if (value == std::string::npos || script[value] != '=') continue;
      value = script.find_first_not_of(" \t", value + 1);
      if (value == std::string::npos || (script[value] != '"' && script[value] != '\'')) return "";
      const std::size_t close = script.find_first_of(std::string(1, script[value]) + "\n\\", value + 1);
      if (close == std::string::npos || script[close] != script[value]) return "";
      return script.substr(value + 1, close - value - 1);
    }
  }
  return "";
}

std::string lesson_file_stem(const std::string& name) {
  std::string stem = fs::path(name).filename().string();
  if (stem.size() >= 4 && stem.compare(stem.size() - 4, 4, ".lua") == 0) stem.resize(stem.size() - 4);
  // Character by character as the page does it (JavaScript counts a character beyond U+FFFF
  // as two): each one outside A-Z, a-z, 0-9, '_', '-' and '.' becomes '_'.
  std::string safe;
  for (std::size_t i = 0; i < stem.size(); ++i) {
    const auto byte = static_cast<unsigned char>(stem[i]);
    if (byte < 0x80) {
      safe += std::isalnum(byte) != 0 || byte == '_' || byte == '-' || byte == '.' ? stem[i] : '_';
    } else if ((byte & 0xC0) != 0x80) {  // a UTF-8 sequence's first byte: one character
      safe += byte >= 0xF0 ? "__" : "_";
    }
  }
  // No hidden file (".bashrc"), and a name a menu and a message can hold.
  safe.erase(0, safe.find_first_not_of('.'));
  if (safe.size() > 100) safe.resize(100);
  return safe.empty() ? "linked_lesson" : safe;
}

std::string keep_user_lesson(const std::string& name, const std::string& script) {
  const std::string folder = user_lessons_folder();
  if (folder.empty()) throw InvalidInput("no home folder (HOME or XDG_DATA_HOME) to keep the lesson " + name + " in");
  if (script.empty()) throw InvalidInput("the lesson " + name + " came empty: nothing to keep");
  const std::string stem = lesson_file_stem(name);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw InvalidInput("cannot make the lessons folder " + folder + ": " + error.message());
  for (int copy = 1; copy < 1000; ++copy) {
    const fs::path path = fs::path(folder) / (copy == 1 ? stem + ".lua" : stem + "_" + std::to_string(copy) + ".lua");
    // Made only where nothing is, a link (even a dangling one) included: nothing outside the
    // folder is written through a link placed in it.
    const int made = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (made < 0) {
      if (errno != EEXIST) throw InvalidInput("cannot write the lesson " + path.string() + ": " + std::strerror(errno));
      // Taken: the same lesson if it is a plain file holding that very text.
      if (fs::is_symlink(fs::symlink_status(path, error))) continue;
      std::ifstream held(path, std::ios::binary);
      const std::string text{std::istreambuf_iterator<char>(held), std::istreambuf_iterator<char>()};
      if (held && text == script) return path.string();
      continue;
    }
    std::size_t written = 0;
    while (written < script.size()) {
      const ssize_t wrote = ::write(made, script.data() + written, script.size() - written);
      if (wrote < 0 && errno == EINTR) continue;
      if (wrote <= 0) break;
      written += static_cast<std::size_t>(wrote);
    }
    const bool closed = ::close(made) == 0;
    if (written != script.size() || !closed) {
      const std::string why = std::strerror(errno);
      ::unlink(path.c_str());  // no cut lesson left in the menu
      throw InvalidInput("cannot write the lesson " + path.string() + ": " + why);
    }
    return path.string();
  }
  throw InvalidInput("the lessons folder " + folder + " already holds 999 lessons named " + stem);
}

std::vector<UserLesson> user_lessons() {
  std::vector<UserLesson> found;
  const std::string folder = user_lessons_folder();
  if (folder.empty()) return found;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    std::error_code kind;
    if (it->path().extension() != ".lua" || !it->is_regular_file(kind)) continue;
    // The menu reads these at every frame it is open: a lesson's heading is in its first lines.
    std::ifstream file(it->path(), std::ios::binary);
    std::string text(16 * 1024, '\0');
    file.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(file.gcount()));
    std::string title = written_title(text);
    const std::string name = it->path().stem().string();
    found.push_back({name, it->path().string(), title.empty() ? name : std::move(title)});
  }
  std::sort(found.begin(), found.end(), [](const UserLesson& a, const UserLesson& b) { return a.name < b.name; });
  return found;
}

}  // namespace frictionlab::classroom_state
