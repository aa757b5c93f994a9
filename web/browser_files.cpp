#include "web/browser_files.h"

#include <emscripten.h>

#include <filesystem>
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
  for (const fs::path& file : files) {
    EM_ASM({ frictionlabPage.download(UTF8ToString($0)); }, file.string().c_str());
    fs::remove(file, error);
  }
}

}  // namespace frictionlab::web
