// The classroom window on an EGL context with no display, driven by a user's hands: frames
// drawn with every text recorded, clicks, drags, keys and typing written to ImGui's io across
// frames (Dear ImGui 1.86 has no event API). For the mystery, setup and force gauge tests; a
// teacher's prepared setup for the setup tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <backends/imgui_impl_opengl3.h>

#include "classroom/classroom.h"
#include "draw/headless.h"
#include "draw/image.h"
#include "draw/imgui_host.h"
#include "lessons/runtime/catalog.h"

namespace frictionlab::classroom {

// One display frame of `window` at `display` on a headless context, as the window layer draws
// one: the fonts for its scale and theme, ImGui's frame, the window's, rendered. `wall` seconds
// of real time pass (the lesson plays that long when playing); with `record`, where the frame
// put things and every text it drew.
inline void draw_window_frame(draw::HeadlessContext& gl, draw::ImGuiHost& host, Classroom& window, ImVec2 display, double wall = 0.0,
                              draw::FrameRecord* record = nullptr) {
  gl.make_current();
  const draw::Fonts& fonts = host.prepare(window.ui_scale(display), window.window_settings().theme);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = display;
  io.DeltaTime = 1.0f / 60.0f;
  host.begin_frame();
  window.frame(fonts, display, wall, record);
  ImGui::Render();
}

// A file's whole text (a saved setup, an export, a script), for tests that read what was written.
inline std::string read_file(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// A lesson with the theory table shown from the start (no predictions asked first; the force
// gauge marks the table), in projector mode when asked: what the gauge and tools tests open.
inline ClassroomOptions gauge_options(const std::string& lesson, std::map<std::string, std::string> overrides = {},
                                      bool projector = false) {
  ClassroomOptions options;
  options.lesson = lesson;
  options.overrides = std::move(overrides);
  options.window.projector = projector;
  options.window.predictions = false;
  return options;
}

// A teacher's preparation, as the setup tests save and open it: values, a lock, a mystery and
// step settings of their own.
inline ClassroomOptions prepared_setup_options() {
  ClassroomOptions options;
  options.lesson = "spring_pull";
  options.overrides = {{"mass", "1.5"}, {"k", "80"}, {"block", "plastic"}};
  options.lock = {"mass", "k", "friction"};
  options.mystery = classroom_state::MysteryChoice{"plastic/wood", 42};
  options.settings.hz = 480.0;
  options.settings.substeps = 2;
  options.settings.treatment = FrictionTreatment::threshold;
  return options;
}

// Everything prepared_setup_options holds, as the window has it now.
inline void expect_prepared_setup(Classroom& window, const std::string& where) {
  const lessons::Lesson& lesson = window.playback().lesson();
  EXPECT_EQ(std::filesystem::path(lesson.path()).filename(), "spring_pull.lua") << where;
  EXPECT_EQ(lesson.parameter("mass").value, 1.5) << where;
  EXPECT_EQ(lesson.parameter("k").value, 80.0) << where;
  EXPECT_EQ(lesson.parameter("block").shown(), "plastic") << where;
  EXPECT_EQ(lesson.parameter("pull_speed").value, 0.1) << where << ": a value the teacher left is the script's";
  EXPECT_TRUE(window.shown("mass") && window.shown("k") && window.shown("friction")) << where;
  EXPECT_FALSE(window.shown("mu_s") || window.shown("pull_speed") || window.shown("hz")) << where << ": the lock";
  ASSERT_TRUE(window.mystery().has_value()) << where;
  EXPECT_EQ(window.mystery()->choice(), (classroom_state::MysteryChoice{"plastic/wood", 42})) << where;
  EXPECT_FALSE(window.mystery()->revealed()) << where;
  EXPECT_EQ(lesson.parameter("mu_s").value, classroom_state::mystery_values(42).mu_s) << where << ": drawn again from the seed";
  EXPECT_EQ(lesson.parameter("mu_k").value, classroom_state::mystery_values(42).mu_k) << where;
  EXPECT_EQ(lesson.settings().hz, 480.0) << where;
  EXPECT_EQ(lesson.settings().substeps, 2) << where;
  EXPECT_EQ(lesson.settings().treatment, FrictionTreatment::threshold) << where;
  EXPECT_EQ(lesson.scene().frame(), 0) << where << ": it opens at t = 0";
  EXPECT_FALSE(window.playback().playing()) << where;
}

class ClassroomHands {
 public:
  // `options.lesson` is a built-in name or a path; the output folder is a fresh one of the test's own.
  explicit ClassroomHands(ClassroomOptions options, ImVec2 display = ImVec2(1280.0f, 720.0f))
      : host_(nullptr), display_(display) {
    options.lesson = lessons::resolve_lesson(options.lesson);
    options.window.help = false;
    // Given as a path relative to the working folder, as the desktop window's own "." is: what
    // the window tells a teacher of its files is then the whole path it made of it.
    options.output_folder = std::filesystem::relative(folder_.path).string();
    classroom_ = std::make_unique<Classroom>(options);
  }
  // The lesson `lesson` (a built-in name or a path) under a teacher's `lock` (the controls left
  // shown) with the command line's --set values `overrides`.
  explicit ClassroomHands(const std::string& lesson, std::vector<std::string> lock = {},
                          std::map<std::string, std::string> overrides = {})
      : ClassroomHands(options_for(lesson, std::move(lock), std::move(overrides))) {}
  ClassroomHands(const ClassroomHands&) = delete;
  ClassroomHands& operator=(const ClassroomHands&) = delete;

  Classroom& classroom() { return *classroom_; }
  classroom_state::Playback& playback() { return classroom_->playback(); }
  lessons::Lesson& lesson() { return classroom_->playback().lesson(); }
  const std::string& folder() const { return folder_.path; }

  // One display frame, `wall` seconds after the last (the lesson plays that long when playing);
  // with `record`, every text it drew.
  void frame(double wall = 0.0, draw::FrameRecord* record = nullptr) { draw_window_frame(gl_, host_, *classroom_, display_, wall, record); }
  // The same at another display's size for this frame only ((0, 0): the hands' own display).
  void frame(double wall, ImVec2 display, draw::FrameRecord* record = nullptr) {
    draw_window_frame(gl_, host_, *classroom_, display.x == 0.0f ? display_ : display, wall, record);
  }
  // The frame drawn at `display`: the pixels the window would show.
  draw::Image picture(ImVec2 display = ImVec2(1280.0f, 720.0f)) {
    frame(0.0, display);
    gl_.make_current();
    const int width = static_cast<int>(display.x), height = static_cast<int>(display.y);
    gl_.bind_framebuffer(width, height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return gl_.read_pixels();
  }
  // Every text of a frame drawn after a few have let tables and tab bars settle, each on a line.
  std::string texts() {
    frame();
    frame();
    draw::FrameRecord record;
    frame(0.0, &record);
    std::string all;
    for (const draw::ShownText& text : record.texts) all += text.text + "\n";
    return all;
  }
  ImRect control(const std::string& name) {
    const auto rect = classroom_->control(name);
    EXPECT_TRUE(rect.has_value()) << "no control named '" << name << "' was drawn";
    return rect.value_or(ImRect());
  }
  // Press and release on the named control, a frame for each, as a hand does.
  void click(const std::string& name) { click_at(control(name).GetCenter()); }
  void click(ImVec2 at) { click_at(at); }
  // The same on a text the last frames drew (a tab's name): its middle.
  void click_text(const std::string& text) {
    frame();
    draw::FrameRecord record;
    frame(0.0, &record);
    for (const draw::ShownText& shown : record.texts) {
      if (shown.text != text) continue;
      click_at(ImVec2(0.5f * (shown.needed.x + shown.needed.z), 0.5f * (shown.needed.y + shown.needed.w)));
      return;
    }
    ADD_FAILURE() << "no text '" << text << "' was drawn";
  }
  void click_at(ImVec2 point) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = point;
    frame();
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
  }
  void mouse_at(ImVec2 at) {
    ImGui::GetIO().MousePos = at;
    frame();
  }
  void button(bool down) {
    ImGui::GetIO().MouseDown[0] = down;
    frame();
  }
  // A shortcut, as the window's layer passes it on (with Ctrl held: Ctrl+E), then a frame with
  // every key let go.
  void key(Key key, bool ctrl = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    classroom_->key_pressed(key, ctrl);
    frame();
    io.KeyCtrl = false;
    frame();
  }
  void set_display(ImVec2 display) { display_ = display; }
  // Takes hold of the body at its centre with the mouse and plays; where the hand took hold.
  ImVec2 take_hold_and_play(const std::string& body_name) {
    const b2Body* body = lesson().scene().body(body_name);
    const ImVec2 held = classroom_->world_camera().to_screen(body->GetWorldCenter());
    mouse_at(held);
    button(true);
    EXPECT_EQ(lesson().scene().grabbed(), body);
    key(Key::space);
    return held;
  }
  // Takes hold of the body at its centre, plays, and pulls the mouse `pixels_per_frame` to the
  // right each display frame (60 a second) for `seconds` of lesson time at speed 1, then holds
  // the mouse still for `held_still` s more before letting go.
  void pull_right(const std::string& body_name, float pixels_per_frame, double seconds, double held_still = 0.0) {
    const ImVec2 held = take_hold_and_play(body_name);
    const int frames = static_cast<int>(std::lround(seconds * 60.0));
    for (int i = 1; i <= frames; ++i) {
      ImGui::GetIO().MousePos = ImVec2(held.x + pixels_per_frame * static_cast<float>(i), held.y);
      frame(1.0 / 60.0);
    }
    for (int i = 0; i < static_cast<int>(std::lround(held_still * 60.0)); ++i) frame(1.0 / 60.0);
    button(false);
  }
  void type(const std::string& text) {
    for (const char c : text) ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(c));
    frame();
  }
  // A key ImGui itself reads (Enter in a text box), down for a frame and up for the next.
  void press(ImGuiKey key) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown[io.KeyMap[key]] = true;
    frame();
    io.KeysDown[io.KeyMap[key]] = false;
    frame();
  }
  void press_enter() { press(ImGuiKey_Enter); }

 private:
  static ClassroomOptions options_for(const std::string& lesson, std::vector<std::string> lock,
                                      std::map<std::string, std::string> overrides) {
    ClassroomOptions options;
    options.lesson = lesson;
    options.lock = std::move(lock);
    options.overrides = std::move(overrides);
    return options;
  }

  draw::HeadlessContext gl_;
  draw::ImGuiHost host_;
  ImVec2 display_;
  // The test's own output folder, made before the window and removed after it is gone, and
  // also when the window's constructor throws (a refused mystery pair left its folder in the
  // temporary folder at every run of the suite, the hands' destructor never having run). One
  // folder, not two: a parameterized test's name holds its parameter after a '/', and
  // "…UntilReset/push" made a folder in a folder, of which only the inner one was removed.
  // Two hands in one test share it (a teacher's window saves a setup that the other opens); the
  // first to go, at the test's end, removes it for both.
  struct OutputFolder {
    static std::string own_name() {
      std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
      std::replace(test.begin(), test.end(), '/', '_');
      return "frictionlab_hands_" + std::to_string(::getpid()) + "_" + test;
    }
    std::string path = (std::filesystem::temp_directory_path() / own_name()).string();
    OutputFolder() { std::filesystem::create_directories(path); }
    ~OutputFolder() { std::filesystem::remove_all(path); }
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;
  };
  OutputFolder folder_;
  std::unique_ptr<Classroom> classroom_;
};

}  // namespace frictionlab::classroom
