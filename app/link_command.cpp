// frictionlab link: a prepared setup file as a link to the web page, and a link as a setup
// file, so a teacher can hand a class either.
#include <iostream>
#include <sstream>

#include "app/command_line.h"
#include "app/modes.h"
#include "classroom_state/setup_file.h"
#include "physics/validation.h"

namespace frictionlab {

int run_link(const std::vector<std::string>& args, std::ostream& out) {
  std::string source, page;
  read_options(
      Command::link, args,
      [&](const std::string& word) {
        if (!source.empty()) {
          throw InvalidInput("link: one setup file or link at a time, got '" + source + "' and '" + word + "'");
        }
        source = word;
      },
      [&](const Option&, const std::string& value) { page = value; });  // --page, its only option
  if (source.empty()) throw InvalidInput("link: name a setup file (to make its link) or give a link (to write its setup)");
  // "-": the link from the standard input. A link carrying a long lesson is longer than one
  // command-line argument may be on Linux (128 KB; the page's links carry up to 200 KB).
  if (source == "-") {
    std::ostringstream given;
    given << std::cin.rdbuf();
    source = given.str();
    source.erase(0, source.find_first_not_of(" \t\r\n"));
    source.erase(source.find_last_not_of(" \t\r\n") + 1);
    if (!classroom_state::setup_text_from_link(source)) throw InvalidInput("link: the standard input holds no link (an address with #setup=...)");
  }
  // A link in: its setup's text out, checked as a setup file is. A lesson the link carries (a
  // student's own, from the page's Copy link) is kept among this user's lessons, as the page
  // keeps it, and the setup names it there.
  if (classroom_state::setup_text_from_link(source)) {
    if (!page.empty()) throw InvalidInput("link: --page goes with a setup file, not with a link");
    std::string kept;
    const std::string text = *classroom_state::received_setup_text(source, &kept);
    classroom_state::parse_setup(text, "setup link");
    out << text;
    if (!text.empty() && text.back() != '\n') out << '\n';
    if (!kept.empty()) std::cerr << "link: the link's lesson is kept as " << kept << " (the window's Lesson > Your lessons)\n";
    return 0;
  }
  std::string left_out;
  out << classroom_state::setup_file_link(source, page, &left_out) << '\n';
  if (!left_out.empty()) {
    std::cerr << "link: " << left_out << " is too long to go in a link (at most " << classroom_state::largest_linked_script / 1024
              << " KB as encoded); the link opens it only where that file is: hand out the .lua file with it\n";
  }
  return 0;
}

}  // namespace frictionlab
