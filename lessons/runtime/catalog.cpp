#include "lessons/runtime/catalog.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>

#include "physics/materials.h"

namespace frictionlab::lessons {
namespace {

namespace fs = std::filesystem;

struct Listing {
  std::vector<CatalogEntry> entries;
  std::vector<std::string> names;
};

Listing list_folder(const std::string& folder) {
  std::vector<fs::path> scripts;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() == ".lua" && it->is_regular_file()) scripts.push_back(it->path());
  }
  if (error) throw InvalidInput("cannot list the lessons in " + folder + ": " + error.message());
  Listing listing;
  for (const fs::path& script : scripts) {
    const std::string name = script.stem().string();
    try {
      const Lesson lesson(script.string());
      listing.entries.push_back({name, script.string(), lesson.title(), lesson.order(), lesson.moments()});
    } catch (const InvalidInput& failure) {
      throw InvalidInput("built-in lesson '" + name + "' cannot be built: " + failure.what());
    }
  }
  std::sort(listing.entries.begin(), listing.entries.end(), [](const CatalogEntry& a, const CatalogEntry& b) {
    if (a.order.has_value() != b.order.has_value()) return a.order.has_value();
    if (a.order && *a.order != *b.order) return *a.order < *b.order;
    return a.name < b.name;
  });
  for (const CatalogEntry& entry : listing.entries) listing.names.push_back(entry.name);
  return listing;
}

// One listing per folder ($FRICTIONLAB_LESSONS may change between tests), made once: entries
// are never removed, so references to them stay valid.
const Listing& listing() {
  static std::mutex guard;
  static std::map<std::string, Listing> listings;
  const std::string folder = lessons_directory();
  const std::lock_guard<std::mutex> lock(guard);
  auto found = listings.find(folder);
  if (found == listings.end()) found = listings.emplace(folder, list_folder(folder)).first;
  return found->second;
}

// Why `path` cannot be read as a script, in words, or "" when it can: a folder, a FIFO (whose
// reading would wait for a writer for ever), a device or a loop of links is not "no such file".
std::string why_not_a_script(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // through links
  if (error == std::errc::too_many_symbolic_link_levels) {
    return "a loop of symbolic links (each points on to the next, and back); give the script itself";
  }
  if (status.type() == fs::file_type::not_found) {
    std::error_code ignored;
    return fs::is_symlink(fs::symlink_status(path, ignored)) ? "a symbolic link to nothing (its target is missing)"
                                                               : "no such file";
  }
  if (error) return "cannot be read: " + error.message();
  switch (status.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::directory: return "that is a folder, not a script; give the .lua file inside it";
    case fs::file_type::fifo: return "that is a FIFO (named pipe), not a script file";
    case fs::file_type::character:
    case fs::file_type::block: return "that is a device, not a script file";
    case fs::file_type::socket: return "that is a socket, not a script file";
    default: return "that is not a regular file";
  }
}

}  // namespace

const std::vector<CatalogEntry>& catalog() { return listing().entries; }
const std::vector<std::string>& builtin_lessons() { return listing().names; }

std::string lessons_directory() {
  if (const char* chosen = std::getenv("FRICTIONLAB_LESSONS"); chosen != nullptr && *chosen != '\0') return chosen;
  return FRICTIONLAB_LESSONS_DIR;
}

bool is_builtin_lesson(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.find_first_of("/\\") != std::string::npos) return false;
  std::error_code error;
  return fs::is_regular_file(fs::path(lessons_directory()) / (name + ".lua"), error);
}

std::string resolve_lesson(const std::string& name_or_path) {
  if (is_builtin_lesson(name_or_path)) return (fs::path(lessons_directory()) / (name_or_path + ".lua")).string();
  if (fs::path(name_or_path).extension() == ".lua") {
    const std::string problem = why_not_a_script(name_or_path);
    if (!problem.empty()) throw InvalidInput("lesson " + name_or_path + ": " + problem);
    return name_or_path;
  }
  std::string known;
  for (const std::string& name : builtin_lessons()) known += (known.empty() ? "" : ", ") + name;
  throw InvalidInput("unknown lesson '" + name_or_path + "'; built-in lessons: " + known +
                     ", or give the path of a .lua file");
}

}  // namespace frictionlab::lessons
