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

// `text`'s start and end with "…" between, as many characters as fit: one in `parts` of them from
// the end, the rest from the start.
std::string characters_that_fit(const std::string& text, float room, std::size_t parts) {
  const std::vector<std::size_t> starts = character_starts(text);
  const std::size_t characters = starts.size() - 1;
  for (std::size_t kept = characters; kept-- > 0;) {
    const std::size_t tail = kept / parts, head = kept - tail;
    const std::string shown = text.substr(0, starts[head]) + "\u2026" + text.substr(starts[characters - tail]);
    if (width_of(shown) <= room) return shown;
  }
  return width_of("\u2026") <= room ? "\u2026" : "";
}

std::string joined(const std::vector<std::string>& words, std::size_t from, std::size_t to) {
  std::string line;
  for (std::size_t i = from; i < to; ++i) line += (i == from ? "" : " ") + words[i];
  return line;
}

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  for (std::size_t start = 0; start <= line.size();) {
    const std::size_t space = std::min(line.find(' ', start), line.size());
    if (space > start) words.push_back(line.substr(start, space - start));
    start = space + 1;
  }
  return words;
}

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
  return characters_that_fit(name, room, 2);
}

std::string words_that_fit(const std::string& line, float room) {
  if (width_of(line) <= room) return line;
  const std::vector<std::string> words = words_of(line);
  const std::size_t count = words.size();
  if (count < 2) return characters_that_fit(line, room, 3);
  const std::string gap = " \u2026 ";
  // A path at the end: the first words that leave it room, the path fitted to what is left.
  // Words go before the file's name is cut.
  if (count > 1 && words.back().find('/') != std::string::npos) {
    const std::string name = std::filesystem::path(words.back()).filename().string();
    for (const bool whole_name : {true, false}) {
      for (std::size_t head = count - 1; head > 0; --head) {
        const std::string start = joined(words, 0, head) + (head == count - 1 ? " " : gap);
        const std::string path = path_that_fits(words.back(), room - width_of(start));
        const bool name_kept = path.size() >= name.size() && path.compare(path.size() - name.size(), name.size(), name) == 0;
        if (!path.empty() && (name_kept || !whole_name)) return start + path;
      }
    }
  }
  // The most words kept, about two of the start for one of the end (the end says what to do next).
  for (std::size_t kept = count - 1; kept > 0; --kept) {
    const std::size_t tail = kept / 3, head = kept - tail;
    const std::string shown = joined(words, 0, head) + (tail == 0 ? " \u2026" : gap + joined(words, count - tail, count));
    if (width_of(shown) <= room) return shown;
  }
  return characters_that_fit(line, room, 3);
}

std::vector<std::string> lines_that_fit(const std::string& line, float room, int most_lines) {
  std::vector<std::string> lines;
  const std::vector<std::string> words = words_of(line);
  std::size_t next = 0;
  while (next < words.size() && static_cast<int>(lines.size()) < most_lines) {
    // The last line, or a word too wide for a line of its own: the rest, cut to fit.
    const bool last = static_cast<int>(lines.size()) + 1 == most_lines;
    if (last || width_of(words[next]) > room) {
      lines.push_back(words_that_fit(joined(words, next, words.size()), room));
      break;
    }
    std::size_t end = next + 1;
    while (end < words.size() && width_of(joined(words, next, end + 1)) <= room) ++end;
    lines.push_back(joined(words, next, end));
    next = end;
  }
  return lines;
}

std::string broken_at_spaces(std::string text, float room) {
  std::size_t line_start = 0, last_space = std::string::npos;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] == '\n') {
      line_start = i + 1;
      last_space = std::string::npos;
      continue;
    }
    if (i < text.size() && text[i] != ' ') continue;
    // A word ends at i: where the line up to it is too wide, it goes after the last space.
    if (last_space != std::string::npos && width_of(text.substr(line_start, i - line_start)) > room) {
      text[last_space] = '\n';
      line_start = last_space + 1;
    }
    if (i < text.size()) last_space = i;
  }
  return text;
}

}  // namespace frictionlab::draw
