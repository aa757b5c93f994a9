// The window's keyboard shortcuts (classroom/shortcut_keys.h): each key chooses the one menu item
// whose key it is, as clicking the item would (or its own action), and nothing else; Ctrl makes
// S and E the saves and nothing without it; D turns the theme over from either side; ← and →
// turn the plots' pages. The keys' routing past menus, dialogs and boxes is test_keys'.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "classroom/shortcut_keys.h"

namespace frictionlab::classroom {
namespace {

// The items a choice holds, by name, in a fixed order.
std::vector<std::string> chosen_items(const WindowChoice& chosen) {
  std::vector<std::string> items;
  const auto note = [&](bool on, const char* name) {
    if (on) items.emplace_back(name);
  };
  note(chosen.lesson.open.has_value(), "open");
  note(chosen.lesson.open_file, "open file");
  note(chosen.lesson.open_script, "open script");
  note(chosen.lesson.open_setup, "open setup");
  note(chosen.lesson.save_setup, "save setup");
  note(chosen.lesson.reload, "reload");
  note(chosen.lesson.screenshot, "screenshot");
  note(chosen.lesson.export_history, "export history");
  note(chosen.lesson.quit, "quit");
  note(chosen.simulation.settings.has_value(), "settings");
  note(chosen.simulation.reset, "reset");
  note(chosen.mystery.make.has_value(), "make mystery");
  note(chosen.mystery.reveal, "reveal mystery");
  note(chosen.view.theme.has_value(), "theme");
  note(chosen.view.projector, "projector");
  note(chosen.view.help, "help");
  note(chosen.view.full_screen, "full screen");
  note(chosen.view.forces_on.has_value(), "forces on");
  note(chosen.view.forces_on_next, "forces on next");
  note(chosen.said.has_value(), "said");
  note(chosen.play_pause, "play pause");
  note(chosen.step, "step");
  note(chosen.step_back, "step back");
  note(chosen.reveal, "reveal");
  note(chosen.stopwatch_start_stop, "stopwatch start stop");
  note(chosen.stopwatch_lap, "stopwatch lap");
  return items;
}

Shortcuts tapped(Key key, bool ctrl = false) { return Shortcuts{{{key, ctrl}}}; }

TEST(ShortcutKeys, EachKeyChoosesItsOneItem) {
  const struct {
    Key key;
    bool ctrl;
    const char* item;
  } keys[] = {
      {Key::s, true, "screenshot"},      {Key::e, true, "export history"}, {Key::f5, false, "reload"},
      {Key::r, false, "reset"},          {Key::f11, false, "full screen"}, {Key::f1, false, "help"},
      {Key::p, false, "projector"},      {Key::d, false, "theme"},         {Key::space, false, "play pause"},
      {Key::period, false, "step"},      {Key::comma, false, "step back"}, {Key::t, false, "reveal"},
      {Key::w, false, "stopwatch start stop"}, {Key::l, false, "stopwatch lap"}, {Key::b, false, "forces on next"},
  };
  for (const auto& [key, ctrl, item] : keys) {
    EXPECT_EQ(chosen_items(ShortcutKeys::choose(tapped(key, ctrl), draw::ThemeName::light)), std::vector<std::string>{item})
        << item;
  }
}

TEST(ShortcutKeys, SAndEAreSavesOnlyWithCtrl) {
  EXPECT_TRUE(chosen_items(ShortcutKeys::choose(tapped(Key::s), draw::ThemeName::light)).empty());
  EXPECT_TRUE(chosen_items(ShortcutKeys::choose(tapped(Key::e), draw::ThemeName::light)).empty());
  EXPECT_TRUE(chosen_items(ShortcutKeys::choose(tapped(Key::space, true), draw::ThemeName::light)).empty())
      << "Ctrl+Space is no shortcut";
}

TEST(ShortcutKeys, DTurnsTheThemeOverFromEitherSide) {
  EXPECT_EQ(ShortcutKeys::choose(tapped(Key::d), draw::ThemeName::light).view.theme, draw::ThemeName::dark);
  EXPECT_EQ(ShortcutKeys::choose(tapped(Key::d), draw::ThemeName::dark).view.theme, draw::ThemeName::light);
}

TEST(ShortcutKeys, SeveralKeysOfOneFrameChooseTogether) {
  const Shortcuts keys{{{Key::r, false}, {Key::space, false}, {Key::s, true}}};
  EXPECT_EQ(chosen_items(ShortcutKeys::choose(keys, draw::ThemeName::light)),
            (std::vector<std::string>{"screenshot", "reset", "play pause"}));
}

TEST(ShortcutKeys, ArrowsTurnThePlotsPagesAndNothingElse) {
  EXPECT_EQ(ShortcutKeys::pages_turned(tapped(Key::right)), 1);
  EXPECT_EQ(ShortcutKeys::pages_turned(tapped(Key::left)), -1);
  EXPECT_EQ(ShortcutKeys::pages_turned(Shortcuts{{{Key::left, false}, {Key::right, false}}}), 0);
  EXPECT_EQ(ShortcutKeys::pages_turned(tapped(Key::space)), 0);
  EXPECT_TRUE(chosen_items(ShortcutKeys::choose(tapped(Key::right), draw::ThemeName::light)).empty());
  EXPECT_TRUE(chosen_items(ShortcutKeys::choose(tapped(Key::left), draw::ThemeName::light)).empty());
}

}  // namespace
}  // namespace frictionlab::classroom
