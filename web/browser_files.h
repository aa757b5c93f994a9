// The page's files, kept in the browser: the student's lessons and the window's settings live
// in the emscripten file system under the home folder, which the page mounts on IndexedDB
// (IDBFS) before the program starts, so they survive a reload. What the classroom writes for
// the user (screenshots, CSV exports, setups) goes to one folder and leaves it as a download.
#pragma once

#include <string>

namespace frictionlab::web {

// Where the classroom writes what the user should receive as downloads, from the page's
// working folder (/).
inline constexpr const char* downloads_folder = "Downloads";

// Writes the home folder back to IndexedDB (asynchronously; a later call waits its turn).
void keep_home_folder();

// Hands every file in the downloads folder to the browser as a download, and removes it.
void offer_downloads();

}  // namespace frictionlab::web
