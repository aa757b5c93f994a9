#include "lessons/runtime/catalog.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

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
