// Text fitted to the room the drawing has for it. A script's names in the class's words are
// lessons/runtime/class_words.h.
#pragma once

#include <string>
#include <string_view>

namespace frictionlab::draw {

// A file's path as it fits in `room` points of the current ImGui font, never cut: the whole
// path; else its first folders, "…" and the whole file name ("/home/ann/…/wedge.lua"); else the
// file name with "…" in its middle ("check_t…article.lua"); "" when not even "…" fits.
std::string path_that_fits(const std::string& path, float room);

}  // namespace frictionlab::draw
