// frictionlab_manual_options TEMPLATE PAGE: writes the manual page, TEMPLATE (frictionlab.1.in as
// CMake configured it) with its @FRICTIONLAB_MAN_OPTIONS@ line replaced by the OPTIONS section
// written from the options table (app/command_line.cpp). Run by the build, so that the page and
// `frictionlab help`, written from the same table, cannot drift apart.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "app/command_line.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: frictionlab_manual_options TEMPLATE PAGE\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string page = text.str();
  const std::string mark = "@FRICTIONLAB_MAN_OPTIONS@\n";
  const std::size_t at = page.find(mark);
  if (!in || at == std::string::npos) {
    std::cerr << "frictionlab_manual_options: " << argv[1] << " has no line " << mark;
    return 1;
  }
  page.replace(at, mark.size(), frictionlab::manual_options());
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
