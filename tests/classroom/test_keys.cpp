// The classroom window's keyboard as a teacher's trial found it: the keys while a menu is open
// (Escape closes it; a shortcut acts and closes it) and Space in the boxes the class types in (a
// number's box: the typing ends, the value kept as Enter keeps it, and the run plays; a box of
// free text: a space is typed). The stopwatch the keys and Play drive is test_stopwatch.cpp's.
// Keys come as the window layer passes them on: the key, and for Space the character it types.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

namespace fs = std::filesystem;

bool any_popup_open() { return ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId); }

// Space as GLFW reports it: the key to the window layer, and its character to ImGui's queue.
void press_space(ClassroomHands& hands) {
  hands.classroom().key_pressed(Key::space, false);
  ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(' '));
  hands.frame();
}

// Typing in a box: ImGui tells what the frame before asked for.
bool typing(ClassroomHands& hands) {
  hands.frame();
  hands.frame();
  return ImGui::GetIO().WantTextInput;
}

ClassroomOptions lesson_options(const std::string& lesson) {
  ClassroomOptions options;
  options.lesson = lesson;
  options.window.predictions = false;
  return options;
}

TEST(WindowKeys, EscapeClosesAnOpenMenuAndNothingElse) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  hands.click("Tools menu");
  ASSERT_TRUE(any_popup_open()) << "the Tools menu is open";
  const bool help = hands.classroom().window_settings().help;
  hands.key(Key::escape);
  hands.frame();
  EXPECT_FALSE(any_popup_open()) << "Escape closed the menu";
  EXPECT_FALSE(hands.classroom().playback().playing());
  EXPECT_EQ(hands.lesson().scene().frame(), 0);
  EXPECT_EQ(hands.classroom().window_settings().help, help);
}

// The trial: Escape closed a menu but not a dialog. Each of the Lesson menu's dialogs, opened and
// given a path to act on (a setup of another lesson to open, a file to save, a script to open),
// closes on Escape as on its Cancel: nothing is opened or saved, nothing plays, nothing else
// changes, and the dialog opens again when asked.
TEST(WindowKeys, EscapeClosesAnOpenDialogWithoutActing) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  const std::string lesson_path = hands.lesson().path();
  // Something for each dialog to act on, were it to act: a setup of another lesson, a script.
  const std::string setup = hands.folder() + "/push.setup";
  {
    std::ofstream file(setup);
    file << "# FrictionLab setup\nlesson push\n";
  }
  const std::string script = lessons::resolve_lesson("spring_pull");
  const auto files = [&] {
    int count = 0;
    for ([[maybe_unused]] const fs::directory_entry& entry : fs::directory_iterator(hands.folder())) ++count;
    return count;
  };
  struct Case {
    const char* menu_item;
    std::string path;  // typed into its path box (a save's suggested name stays before it)
  };
  const Case cases[] = {{"Open a setup", setup}, {"Save as a setup", "x.setup"}, {"Open a script", script}};
  for (const Case& dialog : cases) {
    for (int round = 0; round < 2; ++round) {  // the second time: it opens again after Escape
      hands.click("Lesson menu");
      hands.click(dialog.menu_item);
      hands.frame();  // a dialog sizes itself in the frame it appears, and is drawn where it goes in the next
      ASSERT_TRUE(any_popup_open()) << dialog.menu_item << " opened, round " << round;
      hands.type(dialog.path);  // each dialog puts the typing in its path box as it appears
      ASSERT_TRUE(typing(hands)) << dialog.menu_item << ": typing in its path";
      const std::string status = hands.classroom().status();
      hands.key(Key::escape);
      hands.frame();
      EXPECT_FALSE(any_popup_open()) << "Escape closed " << dialog.menu_item << ", round " << round;
      EXPECT_FALSE(typing(hands)) << dialog.menu_item;
      EXPECT_EQ(hands.lesson().path(), lesson_path) << dialog.menu_item << " opened nothing";
      EXPECT_EQ(files(), 1) << dialog.menu_item << " saved nothing";
      EXPECT_EQ(hands.classroom().status(), status) << dialog.menu_item;
      EXPECT_FALSE(hands.classroom().playback().playing()) << dialog.menu_item;
      EXPECT_EQ(hands.lesson().scene().frame(), 0) << dialog.menu_item;
    }
  }
}

// Escape and then Space, both before the next frame (a quick hand, or a window that waited for
// input and gets both at once): the dialog closes, and the Space is the window's, not lost.
TEST(WindowKeys, AKeyPressedAfterEscapeInTheSameFrameActsOnTheWindow) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  hands.click("Lesson menu");
  hands.click("Save as a setup");
  hands.frame();
  ASSERT_TRUE(any_popup_open());
  hands.classroom().key_pressed(Key::escape, false);
  hands.classroom().key_pressed(Key::space, false);
  hands.frame();
  EXPECT_FALSE(any_popup_open()) << "Escape closed the dialog";
  EXPECT_TRUE(hands.classroom().playback().playing()) << "the Space after it played";
}

// The class watches the run, not the menu: with the Tools menu open, Space plays and R rewinds,
// and each closes the menu.
TEST(WindowKeys, AShortcutWithAMenuOpenActsAndClosesIt) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  hands.click("Tools menu");
  ASSERT_TRUE(any_popup_open());
  hands.key(Key::space);
  EXPECT_TRUE(hands.classroom().playback().playing()) << "Space played with the menu open";
  hands.frame(0.25);
  EXPECT_FALSE(any_popup_open()) << "and closed it";
  EXPECT_GT(hands.lesson().scene().time(), 0.2);
  hands.click("View menu");
  ASSERT_TRUE(any_popup_open());
  hands.key(Key::r);
  EXPECT_EQ(hands.lesson().scene().frame(), 0) << "R rewound with the menu open";
  EXPECT_FALSE(hands.classroom().playback().playing());
  hands.frame();
  EXPECT_FALSE(any_popup_open());
}

// A parameter's box: Space keeps the typed value exactly as Enter would, ends the typing and plays.
TEST(WindowKeys, SpaceInAParametersBoxSetsTheValueAndPlays) {
  ClassroomHands hands(lesson_options("spring_pull"));
  hands.frame();
  hands.click("mu_k value");
  hands.type("0.3125");
  ASSERT_TRUE(typing(hands));
  press_space(hands);
  EXPECT_EQ(hands.lesson().parameter("mu_k").value, 0.3125) << "the value typed, kept as Enter keeps it";
  EXPECT_TRUE(hands.classroom().playback().playing()) << "Space played";
  EXPECT_FALSE(typing(hands)) << "the typing ended";
  EXPECT_TRUE(hands.classroom().control_error("mu_k").empty()) << hands.classroom().control_error("mu_k");
}

// The Mystery tab's answers are numbers too.
TEST(WindowKeys, SpaceInAMysteryAnswerKeepsItAndPlays) {
  ClassroomOptions options = lesson_options("spring_pull");
  options.mystery = classroom_state::MysteryChoice{"aluminium/wood", 42};
  ClassroomHands hands(options);
  hands.texts();
  hands.click_text("Mystery###mystery");
  hands.click("mystery answer mu_s");
  hands.type("0.5");
  ASSERT_TRUE(typing(hands));
  press_space(hands);
  const std::optional<classroom_state::Mystery>& mystery = hands.classroom().mystery();
  ASSERT_TRUE(mystery.has_value());
  ASSERT_TRUE(mystery->answer_mu_s.has_value()) << "the answer was kept";
  EXPECT_EQ(*mystery->answer_mu_s, 0.5);
  EXPECT_TRUE(hands.classroom().playback().playing());
  EXPECT_FALSE(typing(hands));
}

// A slider with no box of its own takes a typed value on Ctrl+click (ImGui's own number box).
TEST(WindowKeys, SpaceInASlidersTypedValueKeepsItAndPlays) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  ImGui::GetIO().KeyCtrl = true;
  hands.click("speed");
  ImGui::GetIO().KeyCtrl = false;
  ASSERT_TRUE(typing(hands)) << "Ctrl+click opened the slider's box";
  // Its text is selected as it opens: what is typed replaces it.
  hands.type("0.5");
  press_space(hands);
  EXPECT_DOUBLE_EQ(hands.classroom().playback().speed(), 0.5);
  EXPECT_TRUE(hands.classroom().playback().playing());
  EXPECT_FALSE(typing(hands));
}

// ImGui's own number box (InputDouble): the Cheapest setting tab's tolerance.
TEST(WindowKeys, SpaceInTheCheapestSettingsToleranceKeepsItAndPlays) {
  ClassroomHands hands(lesson_options("spring_pull"));
  hands.frame();
  hands.frame();  // the tab bar settles
  hands.click("Cheapest setting tab");
  hands.click("tolerance");
  ASSERT_TRUE(typing(hands)) << "its text selected as it opens: what is typed replaces it";
  hands.type("0.25");
  press_space(hands);
  EXPECT_EQ(hands.classroom().cheapest_setting_tab().tolerance, 0.25);
  EXPECT_TRUE(hands.classroom().playback().playing());
  EXPECT_FALSE(typing(hands));
}

// A number's box inside a menu (the Mystery menu's seed): Space ends the typing, plays, and closes
// the menu once the box has kept its value.
TEST(WindowKeys, SpaceInTheMysteryMenusSeedKeepsItPlaysAndClosesTheMenu) {
  ClassroomHands hands(lesson_options("spring_pull"));
  hands.frame();
  hands.click("Mystery menu");
  hands.click("mystery seed");
  ASSERT_TRUE(typing(hands));
  ImGuiIO& io = ImGui::GetIO();
  io.KeysDown[io.KeyMap[ImGuiKey_Backspace]] = true;  // the seed shown, 1, taken out
  hands.frame();
  io.KeysDown[io.KeyMap[ImGuiKey_Backspace]] = false;
  hands.type("42");
  press_space(hands);
  EXPECT_TRUE(hands.classroom().playback().playing());
  hands.frame();
  EXPECT_FALSE(any_popup_open()) << "the menu closed";
  EXPECT_FALSE(typing(hands));
  hands.click("Mystery menu");
  hands.click("mystery aluminium/wood");
  ASSERT_TRUE(hands.classroom().mystery().has_value());
  EXPECT_EQ(hands.classroom().mystery()->choice().seed, 42u) << "the seed typed was kept";
}

// A file's name is free text: Space is typed into it, and nothing plays.
TEST(WindowKeys, SpaceInAFilesNameIsTyped) {
  ClassroomHands hands(lesson_options("incline"));
  hands.frame();
  const std::string path = hands.folder() + "/class one.setup";
  ASSERT_EQ(hands.classroom().save_setup(path), "");
  hands.click("Lesson menu");
  hands.click("Open a setup");
  hands.frame();  // a dialog sizes itself in the frame it appears, and is drawn where it goes in the next
  hands.click("setup path");
  hands.type(hands.folder() + "/class");
  press_space(hands);
  EXPECT_FALSE(hands.classroom().playback().playing()) << "Space in a file's name does not play";
  ASSERT_TRUE(typing(hands)) << "the typing goes on";
  hands.type("one.setup");
  hands.click("setup go");
  EXPECT_EQ(hands.classroom().status(), "Opened the setup " + path) << "the name with its space";
}

// The plots' page buttons are drawn as ← and →, and the trial's teacher pressed those keys: they
// turn the pages as the buttons do, and stop at the first and the last.
TEST(WindowKeys, TheArrowKeysTurnThePlotsPages) {
  ClassroomOptions options = lesson_options("spring_pull");
  options.window.projector = true;
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  const auto first_plot = [&] {
    draw::FrameRecord record;
    hands.frame();
    hands.frame(0.0, &record);
    return record.plots.empty() ? std::size_t{999} : record.plots.front().number;
  };
  const std::size_t start = first_plot();
  ASSERT_EQ(start, 0u) << "the first page shows the first plot";
  hands.key(Key::right);
  const std::size_t next = first_plot();
  ASSERT_GT(next, start) << "spring_pull's plots come a page at a time on a projector";
  hands.key(Key::right);
  hands.key(Key::right);
  EXPECT_GE(first_plot(), next) << "past the last page it stays there";
  for (int i = 0; i < 4; ++i) hands.key(Key::left);
  EXPECT_EQ(first_plot(), start);
}

// The web page's classroom (ClassroomOptions::browser): its Lesson menu offers the browser's
// file chooser, not a path to type in folders the student cannot see; a setup is saved at once
// (it leaves the page as a download); no Reload (F5) or Quit. Script paths read as file names.
TEST(WindowKeys, TheBrowsersLessonMenuOffersItsFileChooserAndNamesNoFolders) {
  ClassroomOptions options = lesson_options("incline");
  options.browser = true;
  options.script_paths = false;
  ClassroomHands hands(options);
  hands.frame();
  hands.click("Lesson menu");
  EXPECT_FALSE(hands.classroom().control("Open a script").has_value());
  EXPECT_FALSE(hands.classroom().control("Open a setup").has_value());
  hands.click("Open a file");
  EXPECT_TRUE(hands.classroom().take_open_file_request());
  EXPECT_FALSE(hands.classroom().take_open_file_request()) << "taken once";
  hands.frame();
  EXPECT_FALSE(any_popup_open());
  hands.click("Lesson menu");
  hands.click("Save as a setup");
  hands.frame();
  EXPECT_FALSE(any_popup_open()) << "a dialog asks for a path";
  int setups = 0;
  for (const auto& entry : std::filesystem::directory_iterator(hands.folder())) setups += entry.path().extension() == ".setup";
  EXPECT_EQ(setups, 1);
  EXPECT_EQ(hands.classroom().status().rfind("Setup saved to ", 0), 0u) << hands.classroom().status();
  EXPECT_EQ(hands.classroom().script_words("Reloaded /home/web_user/.local/share/frictionlab/lessons/my_push.lua."),
            "Reloaded my_push.lua.");
  EXPECT_EQ(hands.classroom().script_words("/lessons/push.lua:80: expect 'x': see '/lessons/incline.lua' (a.lua)"),
            "push.lua:80: expect 'x': see 'incline.lua' (a.lua)");
  // The desktop's names whole paths: the student finds the file there.
  ClassroomHands desktop(lesson_options("incline"));
  desktop.frame();
  desktop.click("Lesson menu");
  EXPECT_TRUE(desktop.classroom().control("Open a script").has_value());
  EXPECT_EQ(desktop.classroom().script_words("Reloaded /a/b.lua."), "Reloaded /a/b.lua.");
}


}  // namespace
}  // namespace frictionlab::classroom
