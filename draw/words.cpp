#include "draw/words.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

namespace frictionlab::draw {

namespace {

// Where each UTF-8 character of `text` begins, and its end: a cut never splits one.
std::vector<std::size_t> character_starts(const std::string& text) {
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) starts.push_back(i);
  }
  starts.push_back(text.size());
  return starts;
}

float width_of(const std::string& text) { return ImGui::CalcTextSize(text.c_str()).x; }

}  // namespace

std::string path_that_fits(const std::string& path, float room) {
  if (width_of(path) <= room) return path;
  const std::string ellipsis = "\u2026";
  const std::string name = std::filesystem::path(path).filename().string();
  const std::string folder = path.substr(0, path.size() - name.size());
  // The folder's start, whole folders as far as they fit, before the name.
  const std::string tail = ellipsis + "/" + name;
  if (!folder.empty() && width_of(tail) <= room) {
    std::size_t fits = 0;
    for (std::size_t slash = folder.find('/'); slash != std::string::npos; slash = folder.find('/', slash + 1)) {
      if (width_of(folder.substr(0, slash + 1) + tail) > room) break;
      fits = slash + 1;
    }
    return folder.substr(0, fits) + tail;
  }
  // The name alone is too wide: its start and end, as many characters of each as fit.
  const std::vector<std::size_t> starts = character_starts(name);
  const std::size_t characters = starts.size() - 1;
  std::string best = width_of(ellipsis) <= room ? ellipsis : "";
  for (std::size_t kept = 1; kept < characters; ++kept) {
    const std::size_t head = (kept + 1) / 2, tail_count = kept - head;
    const std::string shown = name.substr(0, starts[head]) + ellipsis + name.substr(starts[characters - tail_count]);
    if (width_of(shown) > room) break;
    best = shown;
  }
  return best;
}

}  // namespace frictionlab::draw
