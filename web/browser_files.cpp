#include "web/browser_files.h"

#include <emscripten.h>

#include <filesystem>
#include <system_error>

namespace frictionlab::web {

void keep_home_folder() {
  // page.js owns the syncing: one write to IndexedDB at a time, a second request remembered.
  EM_ASM(frictionlabPage.keepHomeFolder(););
}

void offer_downloads() {
  namespace fs = std::filesystem;
  std::error_code error;
  for (fs::directory_iterator file(downloads_folder, error), end; !error && file != end; file.increment(error)) {
    if (!file->is_regular_file(error)) continue;
    const std::string path = file->path().string();
    EM_ASM({ frictionlabPage.download(UTF8ToString($0)); }, path.c_str());
    fs::remove(file->path(), error);
  }
}

}  // namespace frictionlab::web
