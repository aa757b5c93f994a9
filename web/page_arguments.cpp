// The page's arguments (web/page_arguments.h).
#include "web/page_arguments.h"

#include "app/command_line.h"
#include "physics/materials.h"

namespace frictionlab::web {

PageArguments page_arguments(const std::vector<std::string>& args) {
  PageArguments given;
  try {
    // The window's options: page.html writes no other, and the reader refuses any it does not take.
    read_options(
        Command::window, args, [&](const std::string& word) { given.lesson = word; },
        [&](const Option& option, const std::string& value) {
          if (option.name == "--projector") {
            given.projector = true;
          } else if (option.name == "--setup") {
            given.setup = value;
          } else if (option.name == "--at") {
            given.at = option.number(value);
          }
        });
  } catch (const InvalidInput& error) {
    given.problem = error.what();
  }
  return given;
}

}  // namespace frictionlab::web
