// The Lesson menu's setup dialog (classroom/setup_dialog.h), driven by a teacher's mouse and
// keys: a prepared setup opened from it in place of the running lesson, whole, and said in the
// status line; a setup it cannot open said in the dialog, which stays open, the lesson running on;
// a save suggested beside the screenshots under the lesson's name. The dialog alone, with no
// window around it: it hands the path typed to what opens or saves a setup, and closes only when
// that succeeds. What a setup file holds and how it is read are
// tests/classroom_state/test_setup_file.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "classroom/setup_dialog.h"
#include "classroom_state/setup_file.h"
#include "tests/classroom_hands.h"

namespace frictionlab::classroom {
namespace {

namespace fs = std::filesystem;

// The Lesson menu's "Open a setup...", the path typed and Open clicked.
void open_from_the_menu(ClassroomHands& hands, const std::string& path) {
  hands.frame();
  hands.click("Lesson menu");
  hands.click("Open a setup");
  hands.frame();  // a dialog sizes itself in the frame it appears, and is drawn where it goes in the next
  hands.click("setup path");
  hands.type(path);
  hands.click("setup go");
}

TEST(SetupDialog, OpensASavedSetupInPlaceOfTheRunningLesson) {
  ClassroomHands teacher(prepared_setup_options());
  const std::string path = teacher.folder() + "/class.setup";
  ASSERT_EQ(teacher.classroom().save_setup(path), "");

  ClassroomOptions plain;
  plain.lesson = "incline";
  ClassroomHands hands(plain);
  open_from_the_menu(hands, path);
  expect_prepared_setup(hands.classroom(), "opened from the menu");
  EXPECT_EQ(hands.classroom().status(), "Opened the setup " + path);
  hands.frame();  // the controls of the frame after the click
  EXPECT_FALSE(hands.classroom().control("setup go").has_value()) << "the dialog closed";
}

TEST(SetupDialog, ASetupItCannotOpenIsSaidInTheDialogAndTheLessonRunsOn) {
  ClassroomOptions options;
  options.lesson = "spring_pull";
  ClassroomHands hands(options);
  hands.classroom().playback().run_to(0.5);
  const std::string absent = hands.folder() + "/absent.setup";
  open_from_the_menu(hands, absent);
  const std::string texts = hands.texts();
  EXPECT_NE(texts.find("setup " + absent + ": no such file"), std::string::npos) << texts;
  EXPECT_TRUE(hands.classroom().control("setup go").has_value()) << "the dialog stays open to correct the path";
  EXPECT_EQ(fs::path(hands.lesson().path()).filename(), "spring_pull.lua");
  EXPECT_NEAR(hands.lesson().scene().time(), 0.5, 1e-9);
}

TEST(SetupDialog, SavesBesideTheScreenshotsUnderTheLessonsName) {
  ClassroomOptions options;
  options.lesson = "incline";
  options.overrides = {{"angle", "31"}};
  ClassroomHands hands(options);
  hands.frame();
  hands.click("Lesson menu");
  hands.click("Save as a setup");
  hands.frame();  // a dialog sizes itself in the frame it appears, and is drawn where it goes in the next
  hands.click("setup go");
  const std::string path = hands.folder() + "/incline.setup";
  ASSERT_TRUE(fs::is_regular_file(path));
  EXPECT_EQ(hands.classroom().status(), "Setup saved to " + path);
  const classroom_state::PreparedSetup setup = classroom_state::read_setup(path);
  EXPECT_EQ(setup.lesson, "incline");
  const auto angle = std::find_if(setup.values.begin(), setup.values.end(), [](const classroom_state::PreparedSetup::Value& v) { return v.name == "angle"; });
  ASSERT_NE(angle, setup.values.end());
  EXPECT_EQ(angle->text, "31");
  EXPECT_FALSE(setup.mystery.has_value());
  EXPECT_TRUE(setup.lock.empty());
}

// The dialog drawn alone on a headless context, frame after frame, with a mouse to click it.
struct DialogAlone {
  draw::HeadlessContext gl;
  draw::ImGuiHost host{nullptr};
  SetupDialog dialog;
  ControlPlaces controls;
  std::vector<std::string> opened, saved;  // the paths handed to each
  std::string open_answer, save_answer;    // what those say back ("" for done)
  std::string said;                        // what the dialog said for the status line last

  void frame() {
    gl.make_current();
    const draw::Fonts& fonts = host.prepare(1.0f, draw::ThemeName::light);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1280.0f, 720.0f);
    io.DeltaTime = 1.0f / 60.0f;
    host.begin_frame();
    ImGui::PushFont(fonts.body);
    controls.clear();
    const SetupFiles files{[this](const std::string& path) { opened.push_back(path); return open_answer; },
                           [this](const std::string& path) { saved.push_back(path); return save_answer; }};
    said = dialog.draw("/lessons/incline.lua", "/class/output", files, 1.0f, draw::theme(draw::ThemeName::light), controls);
    ImGui::PopFont();
    ImGui::Render();
  }
  void click(const std::string& name) {
    const auto place = controls.find(name);
    ASSERT_NE(place, controls.end()) << "no control named '" << name << "' was drawn";
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = place->second.GetCenter();
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
  }
};

TEST(SetupDialog, AloneItHandsThePathToWhatSavesAndClosesOnlyOnceItIsDone) {
  DialogAlone alone;
  alone.dialog.ask(SetupDialog::Kind::save);
  alone.frame();
  alone.frame();  // a dialog sizes itself in the frame it appears, and is drawn where it goes in the next
  EXPECT_STREQ(alone.dialog.path, "/class/output/incline.setup") << "suggested under the lesson's name";
  alone.save_answer = "/class/output/incline.setup: cannot write there";
  alone.click("setup go");
  ASSERT_EQ(alone.saved, std::vector<std::string>{"/class/output/incline.setup"});
  EXPECT_TRUE(alone.opened.empty());
  EXPECT_EQ(alone.dialog.kind, SetupDialog::Kind::save) << "still open, to correct the path";
  EXPECT_EQ(alone.dialog.error, alone.save_answer);
  alone.save_answer.clear();
  alone.click("setup go");
  EXPECT_EQ(alone.saved.size(), 2u);
  EXPECT_EQ(alone.dialog.kind, SetupDialog::Kind::none) << "closed once saved";

  alone.dialog.ask(SetupDialog::Kind::open);
  std::snprintf(alone.dialog.path, sizeof alone.dialog.path, "%s", "/class/monday.setup");
  alone.frame();
  alone.frame();
  alone.click("setup go");  // the click is let go in its last frame, whose answer is `said`
  EXPECT_EQ(alone.opened, std::vector<std::string>{"/class/monday.setup"});
  EXPECT_EQ(alone.said, "Opened the setup /class/monday.setup");
  EXPECT_EQ(alone.dialog.kind, SetupDialog::Kind::none);
}

}  // namespace
}  // namespace frictionlab::classroom
