#include "web/browser_files.h"

#include <emscripten.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace frictionlab::web {

void keep_home_folder() {
  // page.js owns the syncing: one write to IndexedDB at a time, a second request remembered.
  EM_ASM(frictionlabPage.keepHomeFolder(););
}

void offer_downloads() {
  namespace fs = std::filesystem;
  // Listed first, handed over and removed after: removing entries while the folder is being
  // read leaves what the iterator sees next unspecified.
  std::error_code error;
  std::vector<fs::path> files;
  for (fs::directory_iterator file(downloads_folder, error), end; !error && file != end; file.increment(error)) {
    if (file->is_regular_file(error)) files.push_back(file->path());
  }
  if (files.empty()) return;
  // One key's files (a CSV and its settings) in name order: the CSV's name is the settings
  // file's stem, so it comes first and is the one saved at once (page.html's downloadAll).
  std::sort(files.begin(), files.end());
  // One line each: the names are FrictionLab's own (lesson, time, extension), never a line break.
  std::string paths;
  for (const fs::path& file : files) paths += (paths.empty() ? "" : "\n") + file.string();
  EM_ASM({ frictionlabPage.downloadAll(UTF8ToString($0).split('\n')); }, paths.c_str());
  for (const fs::path& file : files) fs::remove(file, error);
}

}  // namespace frictionlab::web
