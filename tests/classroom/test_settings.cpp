// The window's settings: what is kept between sessions (the theme, full screen, projector mode)
// and what belongs to one session only (the speed and the tools).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "classroom/classroom.h"
#include "draw/headless.h"
#include "draw/imgui_host.h"
#include "lessons/runtime/catalog.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

// F11 asks the window (once a press) to toggle full screen; the window keeps the result in its
// settings (window_opens_full_screen_when_the_settings_say_so checks that under Xvfb).
TEST(Settings, F11TogglesFullScreen) {
  ClassroomHands hands("incline");
  hands.frame();
  hands.key(Key::f11);
  EXPECT_TRUE(hands.classroom().take_full_screen_toggle());
  EXPECT_FALSE(hands.classroom().take_full_screen_toggle());  // once per press
}

TEST(Settings, SettingsSurviveARoundTripAndADamagedFileGivesTheDefaults) {
  const std::string path = (std::filesystem::temp_directory_path() / ("frictionlab_settings_" + std::to_string(::getpid()) + ".ini")).string();
  WindowSettings settings;
  settings.theme = draw::ThemeName::dark;
  settings.projector = true;
  settings.width = 1920;
  settings.full_screen = true;  // a projector's whole screen, kept for the next class
  settings.help = false;
  settings.predictions = false;
  ASSERT_TRUE(save_settings(settings, path));
  EXPECT_EQ(load_settings(path), settings);
  std::ofstream(path) << "theme = pink\nwidth = 99999\nprojector = on\ngarbage\n";
  WindowSettings expected;
  expected.projector = true;
  EXPECT_EQ(load_settings(path), expected);
  std::filesystem::remove(path);
}

// Issue 31: a class opened at yesterday's ×8 with yesterday's tools rushed through its breakaway.
// The speed and the tools belong to one session; the status line says what did come back.
// The windows save when the kept part changes, judged by the text they would write: a speed or a
// tool changed is this session's only and rewrote settings.ini each time (on the web, a sync of
// the browser's storage too).
TEST(Settings, TheSpeedAndTheToolsChangeNothingThatIsKept) {
  const WindowSettings before;
  WindowSettings faster = before;
  faster.speed = 8.0;
  faster.tools = ToolSettings{true, true, true, true};
  EXPECT_EQ(kept_settings_text(faster), kept_settings_text(before));
  for (const auto& [what, change] : std::vector<std::pair<std::string, void (*)(WindowSettings&)>>{
           {"theme", [](WindowSettings& s) { s.theme = draw::ThemeName::dark; }},
           {"projector", [](WindowSettings& s) { s.projector = true; }},
           {"help", [](WindowSettings& s) { s.help = !s.help; }},
           {"predictions", [](WindowSettings& s) { s.predictions = !s.predictions; }},
           {"full screen", [](WindowSettings& s) { s.full_screen = true; }},
           {"width", [](WindowSettings& s) { s.width += 1; }},
           {"height", [](WindowSettings& s) { s.height += 1; }}}) {
    WindowSettings changed = before;
    change(changed);
    EXPECT_NE(kept_settings_text(changed), kept_settings_text(before)) << what << " is kept, so its change is saved";
    // What is written is what comes back.
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("frictionlab_kept_" + std::to_string(::getpid()) + ".ini")).string();
    ASSERT_TRUE(save_settings(changed, path));
    EXPECT_EQ(kept_settings_text(load_settings(path)), kept_settings_text(changed)) << what;
    std::filesystem::remove(path);
  }
}

TEST(Settings, ANewSessionStartsAtOneTimesWithTheToolsOffAndSaysWhatWasKept) {
  const std::string path = (std::filesystem::temp_directory_path() / ("frictionlab_session_" + std::to_string(::getpid()) + ".ini")).string();
  WindowSettings yesterday;
  yesterday.theme = draw::ThemeName::dark;
  yesterday.projector = true;
  yesterday.speed = 8.0;
  yesterday.tools = ToolSettings{true, true, true, true};
  ASSERT_TRUE(save_settings(yesterday, path));
  const WindowSettings today = load_settings(path);
  EXPECT_EQ(today.speed, 1.0);
  EXPECT_EQ(today.tools, ToolSettings{});
  EXPECT_EQ(today.theme, draw::ThemeName::dark);
  EXPECT_TRUE(today.projector);
  EXPECT_EQ(kept_from_last_session(today),
            "As last time: dark theme, projector mode.");
  // A file an older FrictionLab wrote, with the speed and the tools in it.
  std::ofstream(path) << "speed = 8\nstopwatch = on\ndistance_marks = on\nspeed_readout = on\nweight_components = on\n";
  EXPECT_EQ(load_settings(path), WindowSettings{});
  EXPECT_EQ(kept_from_last_session(load_settings(path)), "") << "nothing kept, nothing to say";
  std::filesystem::remove(path);

  // The window says it on its status line when it opens.
  ClassroomOptions options;
  options.lesson = lessons::resolve_lesson("push");
  options.window = today;
  options.opening_notice = kept_from_last_session(today);
  Classroom classroom(options);
  EXPECT_EQ(classroom.status(), options.opening_notice);
  EXPECT_EQ(classroom.playback().speed(), 1.0);
  EXPECT_FALSE(classroom.tools().on.stopwatch);
}

}  // namespace
}  // namespace frictionlab::classroom
