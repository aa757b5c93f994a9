// A student's script in the window: its mistakes said in plain words with Lua's own, a save
// reloading the lesson, a broken save or a lost file keeping the last good lesson running.
#include <gtest/gtest.h>
#include <imgui_internal.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "classroom/classroom.h"
#include "classroom_state/plain_words.h"
#include "draw/headless.h"
#include "draw/imgui_host.h"
#include "lessons/runtime/catalog.h"
#include "tests/classroom_hands.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::classroom {
namespace {

using lessons::replaced;
using lessons::ScriptFile;

// One expect row whose function raises an error is that row's "?" alone: the other rows are
// read as ever, the error is said once, and the command line's check still fails on it.
TEST(Playback, AnExpectRowThatFailsLeavesTheOtherRowsRead) {
  const lessons::ScriptFile script(lessons::with_heading(R"(
local floor = ground { material = "wood" }
local block = box { "block", material = "wood", width = 0.4, height = 0.2, on = floor, at = 0 }
expect { "first", unit = "N", predicted = function() return 1 end, measured = function() return 1 end, tolerance = 0.1 }
expect { "broken", unit = "N", predicted = function() return 2 end,
  measured = function() if time() > 0.05 then return nothing_here.value end end, tolerance = 0.1 }
expect { "last", predicted = function() return "stays" end, measured = function() return "stays" end }
)"));
  classroom_state::Playback playback(script.path(), {}, {});
  playback.run_to(0.1);
  const lessons::LessonReadings& readings = playback.readings();
  ASSERT_EQ(readings.expectations.size(), 3u);
  EXPECT_FALSE(readings.expectations[0].failed);
  EXPECT_TRUE(readings.expectations[0].passes);
  EXPECT_TRUE(readings.expectations[1].failed);
  EXPECT_EQ(readings.expectations[1].name, "broken");
  EXPECT_FALSE(readings.expectations[2].failed);
  EXPECT_TRUE(readings.expectations[2].passes);
  EXPECT_NE(readings.error.find("nothing_here"), std::string::npos) << readings.error;
  EXPECT_THROW(playback.lesson().expectations(), InvalidInput);

  // In the window, the theory table gives the failed row "?" under measured too, as the class's
  // table does (a student's trial found "?" in one and "not yet" in the other).
  ClassroomHands hands(script.path());
  hands.classroom().window_settings().predictions = false;
  hands.playback().run_to(0.1);
  hands.frame();
  hands.frame();
  draw::FrameRecord record;
  hands.frame(0.0, ImVec2(1280.0f, 720.0f), &record);
  const auto row = std::find_if(record.texts.begin(), record.texts.end(), [](const draw::ShownText& text) { return text.text == "broken"; });
  ASSERT_NE(row, record.texts.end()) << "the theory table drew no row \"broken\"";
  ASSERT_GE(std::distance(row, record.texts.end()), 3) << "the row has no cells";
  EXPECT_EQ(row[1].text, "?");
  EXPECT_EQ(row[2].text, "?") << "the failed row's measured cell";
}

// Lua's commonest messages come with plain words in the window too, as in the page's editor: a
// misspelt field (indexing a nil one) and a missing bracket, each from a script that does not
// build; and Lua's own words are kept (they name the line).
TEST(ScriptMessages, AScriptsMistakeComesWithPlainWordsBesideLuasOwn) {
  const std::string good = read_file(lessons::resolve_lesson("incline"));
  const std::vector<std::pair<std::string, std::string>> mistakes = {
      {replaced(good, "local angle = parameter {", "local angle = math.nothing.x or parameter {"),
       "the table before \".nothing\" has nothing called nothing"},
      {replaced(good, "local angle = parameter {", "local angle = parameter { {"), "a bracket is not closed"},
  };
  for (const auto& [text, plain] : mistakes) {
    ScriptFile script(text);
    ClassroomHands hands(script.path());
    hands.frame();
    ASSERT_EQ(hands.classroom().failed_script().path, script.path()) << plain;
    draw::FrameRecord record;
    hands.frame(0.0, ImVec2(1280.0f, 720.0f), &record);
    // Lua's message from the script's name on: "NAME.lua:LINE: ...", its folders left out.
    const std::string error = hands.classroom().failed_script().error;
    const std::string luas_words = error.substr(error.find(".lua:"));
    bool luas = false, said = false;
    // The panel breaks its lines between words itself (a line break for a space), each line no
    // wider than the panel, so that ImGui's wrapping, which also breaks after a full stop, never
    // splits the script's name ("my_incline." and "lua" on two lines).
    const ImGuiWindow* panel = ImGui::FindWindowByName("###messages");
    ASSERT_NE(panel, nullptr) << plain;
    int lines = 0;
    bool broken = false;
    for (const draw::ShownText& shown : record.texts) {
      if (shown.panel.find("###messages") == std::string::npos) continue;
      std::string drawn = shown.text;
      broken = broken || (drawn.find(".lua:") != std::string::npos && drawn.find('\n') != std::string::npos);
      for (std::size_t start = 0; start <= drawn.size(); ++lines) {
        const std::size_t end = std::min(drawn.find('\n', start), drawn.size());
        const std::string line = drawn.substr(start, end - start);
        EXPECT_LE(ImGui::CalcTextSize(line.c_str()).x, panel->WorkRect.GetWidth())
            << "\"" << line << "\" is wider than the message's panel: ImGui would wrap it where it likes";
        start = end + 1;
      }
      std::replace(drawn.begin(), drawn.end(), '\n', ' ');
      luas = luas || drawn.find(luas_words) != std::string::npos;
      said = said || drawn.rfind("In plain words: " + plain, 0) == 0;
    }
    EXPECT_GT(lines, 2) << "the message was not drawn on lines of its own";
    // (Three lines come from three messages too: Lua's own must be broken by the panel.)
    EXPECT_TRUE(broken) << "Lua's message was drawn on one line, for ImGui to wrap where it likes";
    EXPECT_TRUE(said) << "no plain words \"" << plain << "\" for " << hands.classroom().failed_script().error;
    EXPECT_TRUE(luas) << "Lua's own message is gone: " << hands.classroom().failed_script().error;
    EXPECT_EQ(classroom_state::plain_words(error).rfind("In plain words: " + plain, 0), 0u);
  }
}

TEST(ScriptMessages, AScriptThatDoesNotBuildYetOpensWithItsSetValuesAndLockOnceFixed) {
  const std::string good = read_file(lessons::resolve_lesson("incline"));
  ScriptFile script(replaced(good, "local angle = parameter {", "local angle = parameter"));
  ClassroomHands hands(script.path(), {"angle"}, {{"angle", "20"}});
  hands.frame();
  EXPECT_EQ(hands.classroom().failed_script().path, script.path());
  EXPECT_EQ(hands.classroom().failed_script().error.rfind(script.path() + ":", 0), 0u) << hands.classroom().failed_script().error;
  EXPECT_NE(hands.lesson().path(), script.path());
  ASSERT_TRUE(hands.classroom().control("messages").has_value());
  script.rewrite(good);
  for (int i = 0; i < 3; ++i) hands.frame(0.15);
  EXPECT_EQ(hands.lesson().path(), script.path());
  EXPECT_EQ(hands.lesson().parameter("angle").value, 20.0);
  hands.frame();
  EXPECT_TRUE(hands.classroom().control("angle slider").has_value());
  EXPECT_FALSE(hands.classroom().control("mass slider").has_value());
}

// A copy of a built-in lesson a student can edit, opened in the classroom.
struct StudentCopy {
  ScriptFile script{read_file(lessons::resolve_lesson("incline"))};
  ClassroomHands hands{script.path()};
  // Playing, as in a class: the running lesson must keep running whatever the student saves.
  StudentCopy() { hands.playback().play(); }
  // Time for the file watcher to look (it looks four times a second).
  void let_it_notice() {
    for (int i = 0; i < 3; ++i) hands.frame(0.15);
  }
};

TEST(ScriptMessages, SavingTheScriptReloadsTheLesson) {
  StudentCopy copy;
  const std::string original = read_file(copy.script.path());
  const std::string old_title = copy.hands.lesson().title();
  copy.script.rewrite(replaced(original, old_title, "My own slope"));
  copy.let_it_notice();
  EXPECT_EQ(copy.hands.lesson().title(), "My own slope");
  EXPECT_EQ(copy.hands.playback().script_error(), "");
  EXPECT_NE(copy.hands.playback().notice().find("Reloaded"), std::string::npos);
  EXPECT_LT(copy.hands.lesson().scene().time(), 0.5);  // a new lesson starts from t = 0
}

// Paused and untouched, the window waits for input and its frames pass no wall time; the time
// it waited still runs the file watcher's clock. The trial's student saved a fixed script and
// the old error stayed up until the mouse moved. And a paused window draws nothing while
// nothing changes (issue 31: it drew four frames a second, 12 % of a core on llvmpipe): the
// watchers' look asks for a frame only when what they found changes the picture.
TEST(ScriptMessages, APausedWindowSeesASavedScriptWhileNobodyTouchesIt) {
  StudentCopy copy;
  copy.hands.key(Key::space);
  ASSERT_TRUE(copy.hands.classroom().idle());
  for (int i = 0; i < 8; ++i) EXPECT_FALSE(copy.hands.classroom().waited(0.25)) << "look " << i << " found nothing new";
  const std::string original = read_file(copy.script.path());
  copy.script.rewrite(replaced(original, copy.hands.lesson().title(), "Saved while paused"));
  bool frame_asked = false;
  for (int i = 0; i < 2 && !frame_asked; ++i) frame_asked = copy.hands.classroom().waited(0.25);  // the window's wait
  EXPECT_TRUE(frame_asked);
  copy.hands.frame(0.0);
  EXPECT_EQ(copy.hands.lesson().title(), "Saved while paused");
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(copy.hands.classroom().waited(0.25)) << "seen once, then quiet again";
  // Gone (an editor's save half-way, a file moved): said once, then quiet.
  std::filesystem::rename(copy.script.path(), copy.script.path() + ".away");
  frame_asked = false;
  for (int i = 0; i < 2 && !frame_asked; ++i) frame_asked = copy.hands.classroom().waited(0.25);
  EXPECT_TRUE(frame_asked);
  EXPECT_NE(copy.hands.playback().script_error().find("moved or deleted"), std::string::npos);
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(copy.hands.classroom().waited(0.25)) << "still gone: nothing new to draw";
  std::filesystem::rename(copy.script.path() + ".away", copy.script.path());
  frame_asked = false;
  for (int i = 0; i < 2 && !frame_asked; ++i) frame_asked = copy.hands.classroom().waited(0.25);
  EXPECT_TRUE(frame_asked) << "back: the message goes";
  EXPECT_EQ(copy.hands.playback().script_error(), "");
}

TEST(ScriptMessages, ABrokenSaveShowsTheErrorWithItsLineAndTheLastGoodLessonKeepsRunning) {
  StudentCopy copy;
  const std::string original = read_file(copy.script.path());
  const std::string title = copy.hands.lesson().title();
  // Line 3 gets a statement Lua cannot parse.
  std::istringstream lines(original);
  std::string broken, line;
  for (int n = 1; std::getline(lines, line); ++n) broken += (n == 3 ? "local = 5\n" : "") + line + "\n";
  copy.script.rewrite(broken);
  copy.let_it_notice();
  const std::string error = copy.hands.playback().script_error();
  EXPECT_EQ(error.rfind(copy.script.path() + ":3:", 0), 0u) << error;
  EXPECT_EQ(copy.hands.lesson().title(), title);
  ASSERT_TRUE(copy.hands.classroom().control("messages").has_value()) << "the error is not shown in the window";
  const double before = copy.hands.lesson().scene().time();
  copy.hands.frame(0.1);
  EXPECT_GT(copy.hands.lesson().scene().time(), before) << "the last good lesson stopped";
  // Fixed and saved again: the error goes.
  copy.script.rewrite(original);
  copy.let_it_notice();
  EXPECT_EQ(copy.hands.playback().script_error(), "");
}

TEST(ScriptMessages, AScriptThatLoopsForeverEndsInAnErrorNotAHang) {
  StudentCopy copy;
  const std::string title = copy.hands.lesson().title();
  copy.script.rewrite(read_file(copy.script.path()) + "\nwhile true do end\n");
  copy.let_it_notice();
  EXPECT_NE(copy.hands.playback().script_error().find("instruction"), std::string::npos)
      << copy.hands.playback().script_error();
  EXPECT_EQ(copy.hands.lesson().title(), title);
}

TEST(ScriptMessages, ALostFileIsSaidAndTheLessonKeepsRunning) {
  StudentCopy copy;
  const std::string text = read_file(copy.script.path());
  std::filesystem::remove(copy.script.path());
  copy.let_it_notice();
  EXPECT_EQ(copy.hands.playback().script_error().rfind("cannot read " + copy.script.path(), 0), 0u);
  const double before = copy.hands.lesson().scene().time();
  copy.hands.frame(0.1);
  EXPECT_GT(copy.hands.lesson().scene().time(), before);
  copy.script.rewrite(text);  // back again: it loads
  copy.let_it_notice();
  EXPECT_EQ(copy.hands.playback().script_error(), "");
}

TEST(ScriptMessages, AFunctionThatLoopsForeverWhileTheLessonRunsStopsItWithItsLine) {
  ScriptFile script(lessons::with_heading(R"(ground { material = "wood" }
box { "block", material = "wood", width = 0.2, height = 0.2, x = 0, y = 0.1 }
every_step(function(t)
  if t > 0.5 then
    while true do end
  end
end)
)"));
  ClassroomHands hands(script.path());
  hands.playback().play();
  for (int i = 0; i < 10 && hands.playback().problem().empty(); ++i) hands.frame(0.1);
  EXPECT_EQ(hands.playback().problem().rfind(script.path() + ":6:", 0), 0u) << hands.playback().problem();
  EXPECT_FALSE(hands.playback().playing());
  hands.key(Key::r);  // back to t = 0: it runs again until the loop
  EXPECT_EQ(hands.playback().problem(), "");
  EXPECT_EQ(hands.lesson().scene().frame(), 0);
}

}  // namespace
}  // namespace frictionlab::classroom
