// frictionlab_manual_options TEMPLATE PAGE: writes the manual page, TEMPLATE (frictionlab.1.in as
// CMake configured it) with its @FRICTIONLAB_MAN_SYNOPSIS@ line replaced by the SYNOPSIS written
// from the usage's forms and its @FRICTIONLAB_MAN_OPTIONS@ line by the OPTIONS section written
// from the options table (both app/command_line.cpp), and its @FRICTIONLAB_MAN_KEYS@ line by the
// window's keys (classroom_state/window_keys.h). Run by the build, so that the page,
// `frictionlab help` and the window's help panel, written from the same lists, cannot drift apart.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "app/command_line.h"
#include "classroom_state/window_keys.h"

namespace {

// A line of roff's text: a leading period or apostrophe would be read as a request.
std::string roff_text(std::string_view words) {
  std::string text;
  if (!words.empty() && (words.front() == '.' || words.front() == '\'')) text = "\\&";
  for (const char c : words) text += c == '\\' ? std::string("\\e") : c == '-' ? std::string("\\-") : std::string(1, c);
  // The arrows as roff's own glyphs: groff without preconv read their UTF-8 bytes as "â".
  for (const auto& [arrow, glyph] : {std::pair<std::string, std::string>{"\u2190", "\\(<-"}, {"\u2192", "\\(->"}}) {
    for (std::size_t at = text.find(arrow); at != std::string::npos; at = text.find(arrow, at + glyph.size())) {
      text.replace(at, arrow.size(), glyph);
    }
  }
  return text;
}

// The keys as a two-column tbl table, each row's words in a text block (T{ ... T}) so that long
// ones wrap.
std::string keys_table() {
  std::string table = ".TS\nl lx.\n";
  for (const frictionlab::classroom_state::WindowKey& key : frictionlab::classroom_state::window_keys()) {
    table += roff_text(key.key) + "\tT{\n" + roff_text(key.does) + "\nT}\n";
  }
  return table + ".TE\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: frictionlab_manual_options TEMPLATE PAGE\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) {
    std::cerr << "frictionlab_manual_options: cannot read " << argv[1] << '\n';
    return 1;
  }
  std::string page = text.str();
  for (const auto& [mark, section] : {std::pair<std::string, std::string>{"@FRICTIONLAB_MAN_SYNOPSIS@\n", frictionlab::manual_synopsis()},
                                      {"@FRICTIONLAB_MAN_OPTIONS@\n", frictionlab::manual_options()},
                                      {"@FRICTIONLAB_MAN_KEYS@\n", keys_table()}}) {
    const std::size_t at = page.find(mark);
    if (at == std::string::npos) {
      std::cerr << "frictionlab_manual_options: " << argv[1] << " has no line " << mark;
      return 1;
    }
    page.replace(at, mark.size(), section);
  }
  // Whole or not at all: a page cut short would still be installed by the next build.
  const std::string partial = std::string(argv[2]) + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    out << page;
    if (!out.flush()) {
      std::cerr << "frictionlab_manual_options: cannot write " << partial << '\n';
      return 1;
    }
  }
  if (std::rename(partial.c_str(), argv[2]) != 0) {
    std::cerr << "frictionlab_manual_options: cannot write " << argv[2] << '\n';
    return 1;
  }
  return 0;
}
