// The View menu (classroom/view_menu.h) in the window, clicked as a teacher clicks it: each item
// changes what its key changes (D, P, F1, F11), and says nothing else.
#include <gtest/gtest.h>

#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// The View menu opened and one of its items clicked.
void choose(ClassroomHands& hands, const std::string& item) {
  hands.frame();
  hands.click("View menu");
  hands.click(item);
  hands.frame();
}

TEST(ViewMenu, EachItemChangesWhatItsKeyChanges) {
  ClassroomOptions options;
  options.lesson = "incline";
  ClassroomHands hands(options);
  const WindowSettings& window = hands.classroom().window_settings();
  ASSERT_EQ(window.theme, draw::ThemeName::light);
  ASSERT_FALSE(window.projector);
  ASSERT_FALSE(window.help);  // the hands open without the help panel

  choose(hands, "Dark theme");
  EXPECT_EQ(window.theme, draw::ThemeName::dark);
  choose(hands, "Projector mode");
  EXPECT_TRUE(window.projector);
  EXPECT_EQ(window.theme, draw::ThemeName::dark) << "the theme kept";
  EXPECT_FALSE(hands.classroom().take_full_screen_toggle()) << "nothing asked of the host yet";
  choose(hands, "Full screen");
  EXPECT_TRUE(hands.classroom().take_full_screen_toggle());

  // And back, each as it was.
  choose(hands, "Dark theme");
  EXPECT_EQ(window.theme, draw::ThemeName::light);
  choose(hands, "Projector mode");
  EXPECT_FALSE(window.projector);
  EXPECT_FALSE(window.help);
  choose(hands, "Help");
  EXPECT_TRUE(window.help);
  EXPECT_TRUE(window.predictions) << "the predictions item untouched";
}

}  // namespace
}  // namespace frictionlab::classroom
