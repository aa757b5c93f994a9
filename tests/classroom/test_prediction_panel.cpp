// Predict first's panel (classroom/prediction_panel.h) in the window: the column planned for the
// class's answers is kept from a lesson's opening (a slider's value does not move it), and
// planned anew when the script is read again or a setup opens, whose questions may read
// otherwise: the answers then have the room they need, with no scroll bar.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "tests/classroom_hands.h"
#include "tests/lesson_scripts.h"

namespace frictionlab::ui {
namespace {

const std::string breakaway_question = "The push grows steadily. How hard is it when the block starts to move?";

// push.lua as it is, or with its first question three sentences longer: lines more at any width.
std::string push_script(bool long_question) {
  std::ifstream file(lessons::resolve_lesson("push"));
  std::stringstream text;
  text << file.rdbuf();
  std::string script = text.str();
  const std::size_t at = script.find(breakaway_question);
  EXPECT_NE(at, std::string::npos) << "push.lua's question changed; this test lengthens it";
  if (long_question && at != std::string::npos) {
    script.insert(at + breakaway_question.size(),
                  " Watch the force gauge, not the block: the block may not seem to move at first. Say the number of"
                  " newtons you expect on the gauge at that moment. Then say whether it will slide faster and faster.");
  }
  return script;
}

// The class's answers as the window shows them: every text of the panel that asks the first
// question, and whether any of it is cut or a scroll away.
struct AnswersShown {
  bool asked = false;     // the question was drawn
  bool scrolls = false;   // its panel has a scroll bar
  bool whole = true;      // every text of it whole
};

AnswersShown answers_shown(ClassroomHands& hands, const std::string& question_start) {
  hands.frame();
  hands.frame();
  FrameRecord record;
  hands.frame(0.0, &record);
  AnswersShown shown;
  std::string panel;
  for (const ShownText& text : record.texts) {
    if (text.text.rfind(question_start, 0) == 0) panel = text.panel;
  }
  for (const ShownText& text : record.texts) {
    if (panel.empty() || text.panel != panel) continue;
    shown.asked = true;
    shown.scrolls = shown.scrolls || text.scrolls;
    shown.whole = shown.whole && text.whole();
  }
  return shown;
}

// F5 after the student lengthened a question: planned for the question as it now reads. (Before,
// the column kept the height planned for the short question, and the answers scrolled.)
TEST(PredictionPanel, TheAnswersArePlannedAnewWhenTheScriptIsReloaded) {
  const lessons::ScriptFile script(push_script(false));
  ClassroomOptions options;  // predictions asked, as by default
  options.lesson = script.path();
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  const AnswersShown before = answers_shown(hands, breakaway_question);
  ASSERT_TRUE(before.asked);
  EXPECT_FALSE(before.scrolls);
  script.rewrite(push_script(true));
  hands.key(Key::f5);
  ASSERT_EQ(hands.classroom().playback().script_error(), "");
  const AnswersShown after = answers_shown(hands, breakaway_question + " Watch the force gauge");
  ASSERT_TRUE(after.asked) << "the reloaded question is not shown";
  EXPECT_FALSE(after.scrolls) << "the answers scroll in a column planned for the script before F5";
  EXPECT_TRUE(after.whole);
}

// A setup of the same script, opened after the script was lengthened: planned for it too.
TEST(PredictionPanel, TheAnswersArePlannedAnewWhenASetupOpens) {
  const lessons::ScriptFile script(push_script(false));
  ClassroomOptions options;  // predictions asked, as by default
  options.lesson = script.path();
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  ASSERT_TRUE(answers_shown(hands, breakaway_question).asked);
  const std::string setup = hands.folder() + "/long.setup";
  std::ofstream(setup) << "# FrictionLab setup\nlesson " << script.path() << "\npredictions on\n";
  script.rewrite(push_script(true));
  ASSERT_EQ(hands.classroom().open_setup(setup), "");
  const AnswersShown after = answers_shown(hands, breakaway_question + " Watch the force gauge");
  ASSERT_TRUE(after.asked) << "the setup's lesson does not ask the lengthened question";
  EXPECT_FALSE(after.scrolls) << "the answers scroll in a column planned for the lesson before the setup";
  EXPECT_TRUE(after.whole);
}

// Issue 31, a teacher's trial: "measured: 3.92 N" showed beside the empty answer box mid-run,
// before the class had answered: it is the answer. Beside an empty box the measurement waits
// for the class's answer (typed at t = 0: R); beside an answer it shows as the run measures it.
TEST(PredictionPanel, TheMeasurementWaitsForTheClasssAnswer) {
  ClassroomOptions options;  // predictions asked, as by default
  options.lesson = "push";
  ClassroomHands hands(options, ImVec2(1920.0f, 1080.0f));
  hands.frame();
  hands.classroom().playback().run_to(3.0);  // theory's breakaway: 3.92 N at 1.96 s
  ASSERT_TRUE(hands.classroom().theory_hidden());
  const auto note = [&] {
    const std::string texts = hands.texts();
    const std::size_t at = texts.find("measured: ");
    return at == std::string::npos ? std::string("(none)") : texts.substr(at, texts.find('\n', at) - at);
  };
  EXPECT_EQ(note(), "measured: hidden") << "the breakaway push given away";
  hands.key(Key::r);
  hands.click("prediction breakaway push");
  hands.type("4");
  hands.press_enter();
  ASSERT_EQ(hands.classroom().predictions().answers["breakaway push"], "4");
  hands.classroom().playback().run_to(3.0);
  EXPECT_EQ(note().rfind("measured: 3.9", 0), 0u) << note();
}

}  // namespace
}  // namespace frictionlab::ui
