#include "app/install_paths.h"

#include <cstdlib>
#include <filesystem>

namespace frictionlab {

namespace fs = std::filesystem;

std::string executable_folder() {
  std::error_code error;
  const fs::path binary = fs::read_symlink("/proc/self/exe", error);
  return error ? "" : binary.parent_path().string();
}

std::string installed_lessons_directory() {
  const std::string folder = executable_folder();
  if (folder.empty()) return "";
  const fs::path lessons = (fs::path(folder) / FRICTIONLAB_DATA_FROM_BIN / "lessons").lexically_normal();
  std::error_code error;
  return fs::is_directory(lessons, error) ? lessons.string() : "";
}

void use_installed_lessons() {
  if (const char* chosen = std::getenv("FRICTIONLAB_LESSONS"); chosen != nullptr && *chosen != '\0') return;
  const std::string installed = installed_lessons_directory();
  if (!installed.empty()) ::setenv("FRICTIONLAB_LESSONS", installed.c_str(), 1);
}

}  // namespace frictionlab
