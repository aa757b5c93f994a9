// The page's link arguments (web/page_arguments.h) read as the desktop window reads its command
// line: an --at the window refuses, the page refuses with the window's very message (its range
// said once, in app/command_line.cpp's table), and opens all the same with no time asked; one it
// takes, it takes as the window does.
#include "web/page_arguments.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/modes.h"
#include "physics/materials.h"

namespace frictionlab::web {
namespace {

// What the desktop window says of `args`, "" when it takes them.
std::string window_says(const std::vector<std::string>& args) {
  try {
    parse_window_arguments(args);
    return "";
  } catch (const InvalidInput& error) {
    return error.what();
  }
}

TEST(PageArguments, ABadAtIsRefusedWithTheWindowsMessage) {
  const Option& at = option_for(Command::window, "--at");
  const auto number = [](double value) { return std::to_string(value); };
  for (const std::string& refused : {number(at.range.high + 1.0), std::string("5000"), std::string("-1"), number(at.range.low - 0.5),
                                     std::string("soon"), std::string("nan"), std::string("inf"), std::string("1e9")}) {
    SCOPED_TRACE("--at " + refused);
    const std::vector<std::string> args{"incline", "--projector", "--at", refused};
    const std::string message = window_says(args);
    ASSERT_FALSE(message.empty()) << "the window takes it";
    const PageArguments given = page_arguments(args);
    EXPECT_EQ(given.problem, message);
    EXPECT_EQ(given.at, 0.0) << "no time asked";
    EXPECT_EQ(given.lesson, "incline") << "what came before is kept";
    EXPECT_TRUE(given.projector);
  }
}

TEST(PageArguments, AnAtTheWindowTakesThePageTakesAlike) {
  const Option& at = option_for(Command::window, "--at");
  for (const double time : {at.range.low, 2.5, at.range.high}) {
    const std::string text = std::to_string(time);
    ASSERT_EQ(window_says({"incline", "--at", text}), "");
    const PageArguments given = page_arguments({"--setup", "/link/frictionlab.setup", "--at", text});
    EXPECT_EQ(given.problem, "");
    EXPECT_EQ(given.at, at.number(text));
    EXPECT_EQ(given.setup, "/link/frictionlab.setup");
    EXPECT_EQ(given.lesson, "");
    EXPECT_FALSE(given.projector);
  }
}

}  // namespace
}  // namespace frictionlab::web
