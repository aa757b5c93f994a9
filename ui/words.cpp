#include "ui/words.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

namespace frictionlab::ui {

namespace {

// The Greek letters a script spells out in its names (theta0 is θ0, omega ω), with any digits
// that follow kept; nothing when the part is no such letter.
std::optional<std::string> greek(std::string_view part) {
  static const std::pair<std::string_view, std::string_view> letters[] = {
      {"alpha", "\u03b1"}, {"epsilon", "\u03b5"}, {"theta", "\u03b8"}, {"omega", "\u03c9"}};
  for (const auto& [spelt, letter] : letters) {
    if (part.substr(0, spelt.size()) != spelt) continue;
    const std::string_view rest = part.substr(spelt.size());
    if (std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      return std::string(letter) + std::string(rest);
    }
  }
  return std::nullopt;
}

// A letter as an index below the line, where Unicode has one (a_x is aₓ); "" where not.
std::string_view subscript(char letter) {
  switch (letter) {
    case 'a': return "\u2090";
    case 'e': return "\u2091";
    case 'o': return "\u2092";
    case 'x': return "\u2093";
    case 'h': return "\u2095";
    case 'k': return "\u2096";
    case 'l': return "\u2097";
    case 'm': return "\u2098";
    case 'n': return "\u2099";
    case 'p': return "\u209a";
    case 's': return "\u209b";
    case 't': return "\u209c";
    default: return "";
  }
}

}  // namespace

std::string class_words(std::string_view name) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0; start <= name.size();) {
    const std::size_t end = std::min(name.find('_', start), name.size());
    if (end > start) parts.push_back(name.substr(start, end - start));
    start = end + 1;
  }
  std::string words;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!words.empty()) words += ' ';
    const bool index_follows = i + 1 < parts.size() && parts[i + 1].size() == 1;
    // μ, with its index when it has one: mu_s is the static coefficient, written μs beside the
    // sliders; lubricated_mu is the oiled table's μ.
    if (parts[i] == "mu") {
      words += "\u03bc";
      if (index_follows && (parts[i + 1] == "s" || parts[i + 1] == "k")) words += parts[++i];
    } else if (const std::optional<std::string> letter = greek(parts[i])) {
      words += *letter;
    } else if (parts[i].size() == 1 && index_follows && !subscript(parts[i + 1][0]).empty()) {
      // A quantity's letter and its index, as the books write them: a_x is aₓ.
      words += parts[i];
      words += subscript(parts[++i][0]);
    } else {
      words += parts[i];
    }
  }
  return words;
}

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

}  // namespace frictionlab::ui
