// The page's arguments, from its link (page.html's linkArguments): [LESSON] [--setup FILE]
// [--projector] [--at S]. Read through the command line's options table and reader
// (app/command_line.h), as the desktop window reads its own, so that --at's range and the
// message for a value outside it are said in one place.
#pragma once

#include <string>
#include <vector>

namespace frictionlab::web {

struct PageArguments {
  std::string lesson, setup;
  bool projector = false;
  double at = 0.0;      // play the lesson on to this time, paused there (a picture's moment)
  std::string problem;  // why a word of the link was refused, as the window's command line says it; "" when none
};

// A link's words. A word refused (an --at out of range or not a number) is said in `problem`,
// never thrown: the page opens all the same, with what was read before it and no time asked.
PageArguments page_arguments(const std::vector<std::string>& args);

}  // namespace frictionlab::web
